"""move_group's execution waits, a bounded while, for its controller's action server or its joints' gz command
topics to be discovered: right after a robot is spawned, a busy machine's graph may not list them yet (seen
in a loaded test run as "controller action /panda_arm_controller/follow_joint_trajectory is not available"
for a gz Panda whose command topics were there a moment later)."""

from __future__ import annotations

import time

import pytest

from gazelle.ros import _move_group_trajectory_execution
from gazelle.ros._move_group_common import Controller
from gazelle.ros._move_group_execute_trajectory_action import ExecuteTrajectoryAction
from gazelle.ros._move_group_trajectory_execution import TrajectoryExecutionManager

JOINTS = ["panda_joint1", "panda_joint2"]
TOPICS = {j: f"/model/panda/joint/{j}/n0/cmd_pos" for j in JOINTS}


class _Graph:
    """What the graph shows the ``TrajectoryExecutionManager`` from the ``after``-th query on: the action, or the topics;
    the controller (from moveit_controllers.yaml, or from a controller manager's list) from the
    ``named_after``-th."""

    def __init__(self, action: bool, topics: bool, after: int, named_after: int = 0) -> None:
        self.action, self.topics, self.after, self.queries = action, topics, after, 0
        self.named_after, self.lookups = named_after, 0

    def controllers_for(self, joints: list[str]) -> list[Controller]:
        self.lookups += 1
        return [_controller()] if self.lookups > self.named_after else []

    def action_served(self, action: str) -> bool:
        return self.action and self.queries >= self.after

    def position_topics(self, joints: list[str]) -> dict[str, str] | None:
        self.queries += 1
        return dict(TOPICS) if self.topics and self.queries > self.after else None


def _wait(graph: _Graph) -> tuple[bool, dict[str, str] | None]:
    _, served, topics = TrajectoryExecutionManager.wait_for_execution(graph, JOINTS)  # type: ignore[arg-type]
    return served, topics


def _controller() -> Controller:
    return Controller("panda_arm_controller", "/panda_arm_controller/follow_joint_trajectory", tuple(JOINTS))


def test_gz_command_topics_discovered_late_are_streamed_to() -> None:
    graph = _Graph(action=False, topics=True, after=3)
    assert _wait(graph) == (False, TOPICS)
    assert graph.queries == 4


def test_an_action_server_discovered_late_is_used() -> None:
    graph = _Graph(action=True, topics=False, after=3)
    assert _wait(graph) == (True, None)


def test_a_controller_a_controller_manager_lists_late_is_used() -> None:
    graph = _Graph(action=True, topics=False, after=0, named_after=2)
    controllers, served, topics = TrajectoryExecutionManager.wait_for_execution(graph, JOINTS)  # type: ignore[arg-type]
    assert (controllers, served, topics) == ([_controller()], True, None)
    assert graph.lookups == 3


def test_with_neither_the_wait_ends_at_its_bound(monkeypatch) -> None:
    monkeypatch.setattr(_move_group_trajectory_execution, "CONTROLLER_WAIT", 0.3)
    graph = _Graph(action=False, topics=False, after=0)
    t0 = time.monotonic()
    assert _wait(graph) == (False, None)
    assert 0.3 <= time.monotonic() - t0 < 2.0
    assert graph.queries >= 2


@pytest.mark.parametrize("kind", ["action", "topics"])
def test_what_is_there_at_once_is_not_waited_for(kind) -> None:
    graph = _Graph(action=kind == "action", topics=kind == "topics", after=0)
    t0 = time.monotonic()
    served, topics = _wait(graph)
    assert (served, topics) == ((True, None) if kind == "action" else (False, TOPICS))
    assert time.monotonic() - t0 < 0.05


def test_execute_trajectory_reads_the_planners_scene_under_its_lock() -> None:
    """Issue 27 item 1: execute_trajectory checked the trajectory against roboplan's scene with no lock while
    the simulation's scene updates rebuilt that scene on another executor thread; YuMi's move_group died of
    "double free or corruption" 4 runs in 4. Every read of the scene now holds the planner's lock (the query
    planner's, since each kind of work has its own: issue 48)."""
    import threading
    from contextlib import contextmanager
    from types import SimpleNamespace

    import numpy as np
    from builtin_interfaces.msg import Duration
    from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

    lock = threading.Lock()
    reads: list[bool] = []

    class Scene:
        def getPositionLimitVectors(self, group: str):
            reads.append(lock.locked())
            return np.array([-3.0, -3.0]), np.array([3.0, 3.0])

    planner = SimpleNamespace(joint_names=JOINTS, scene=Scene(), velocity_limits=dict.fromkeys(JOINTS, 2.0))
    roles: list[str] = []

    @contextmanager
    def using(role: str):
        roles.append(role)
        with lock:
            yield planner

    node = SimpleNamespace(context=SimpleNamespace(pool=SimpleNamespace(using=using)))
    node.check_trajectory_locked = lambda t, p: ExecuteTrajectoryAction.check_trajectory_locked(node, t, p)  # type: ignore[arg-type]
    trajectory = JointTrajectory(
        joint_names=JOINTS,
        points=[
            JointTrajectoryPoint(positions=[0.0, 0.0], time_from_start=Duration(sec=0)),
            JointTrajectoryPoint(positions=[0.5, 0.5], time_from_start=Duration(sec=1)),
        ],
    )
    assert ExecuteTrajectoryAction.check_trajectory(node, trajectory) is None  # type: ignore[arg-type]
    assert reads and all(reads), "roboplan's scene was read without the planner's lock"
    assert roles == ["query"]


def test_a_two_arm_trajectory_goes_to_both_arms_controllers_each_with_its_part() -> None:
    """A dual arm's group of both arms (YuMi's both_arms, one joint_trajectory_controller an arm): no
    controller has every joint, so the trajectory is split by controller, as MoveIt's
    TrajectoryExecutionManager does, and each part keeps every point in time."""
    from builtin_interfaces.msg import Duration
    from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

    left = Controller("left_arm_controller", "/left_arm_controller/follow_joint_trajectory", ("l1", "l2"))
    right = Controller("right_arm_controller", "/right_arm_controller/follow_joint_trajectory", ("r1", "r2"))
    other = Controller("torso_controller", "/torso_controller/follow_joint_trajectory", ("t1",))
    assert _move_group_trajectory_execution._cover({"l1", "l2", "r1", "r2"}, [other, left, right]) == [left, right]
    assert _move_group_trajectory_execution._cover({"l1", "x"}, [left, right]) == []  # no controller has x
    trajectory = JointTrajectory(
        joint_names=["l1", "r1", "l2", "r2"],
        points=[
            JointTrajectoryPoint(positions=[1.0, 2.0, 3.0, 4.0], velocities=[0.1, 0.2, 0.3, 0.4]),
            JointTrajectoryPoint(positions=[5.0, 6.0, 7.0, 8.0], time_from_start=Duration(sec=2)),
        ],
    )
    part = _move_group_trajectory_execution._part(trajectory, ["r1", "r2"])
    assert part.joint_names == ["r1", "r2"]
    assert [list(p.positions) for p in part.points] == [[2.0, 4.0], [6.0, 8.0]]
    first, second = list(part.points)
    assert list(first.velocities) == [0.2, 0.4] and list(second.velocities) == []
    assert second.time_from_start.sec == 2


def test_the_execution_nodes_entities_are_made_on_the_thread_that_spins_it() -> None:
    """Issue 27 item 1, found by the YuMi soak under PYTHONMALLOC=debug: a client made from an action's worker
    thread while the execution executor waited aborted the process inside rcl ("Fatal Python error:
    Aborted" in create_client). Entities of the execution node are made on its spinning thread."""
    import threading
    from types import SimpleNamespace

    made_on: list[str] = []
    spinning = threading.Thread(target=lambda: None, name="spinner")

    class Executor:
        def create_task(self, fn):  # the spinning thread runs the task
            t = threading.Thread(target=fn, name="spinner")
            t.start()
            t.join()

    node = SimpleNamespace(_thread=spinning, executor=Executor())
    made = lambda: made_on.append(threading.current_thread().name) or 7
    got = TrajectoryExecutionManager.on_execution_thread(node, made)  # type: ignore[arg-type] - a stand-in manager
    assert got == 7 and made_on == ["spinner"]


def test_of_two_controllers_with_the_joints_the_one_marked_default_is_used() -> None:
    """Issue 51 item 3: moveit_simple_controller_manager's ``default: true`` was ignored and the first controller
    listed was used. MoveIt's TrajectoryExecutionManager ranks default controllers first, then those of fewer
    joints (trajectory_execution_manager.cpp, OrderPotentialControllerCombination)."""
    from types import SimpleNamespace

    plain = Controller(
        "joint_trajectory_controller", "/joint_trajectory_controller/follow_joint_trajectory", tuple(JOINTS)
    )
    scaled = Controller(
        "scaled_joint_trajectory_controller", "/scaled/follow_joint_trajectory", tuple(JOINTS), default=True
    )
    wide = Controller("whole_body_controller", "/whole/follow_joint_trajectory", (*JOINTS, "panda_joint3"))
    manager = SimpleNamespace(controllers=[plain, scaled, wide], ros2_control_controllers=list)
    assert TrajectoryExecutionManager.controllers_for(manager, JOINTS) == [scaled]  # type: ignore[arg-type]
    manager.controllers = [wide, plain]
    assert TrajectoryExecutionManager.controllers_for(manager, JOINTS) == [plain]  # type: ignore[arg-type]


def test_a_moveit_controllers_yaml_default_becomes_a_parameter(tmp_path) -> None:
    from gazelle.ros._move_group_config import config_parameters

    (tmp_path / "moveit_controllers.yaml").write_text(
        "moveit_simple_controller_manager:\n  controller_names: [a, b]\n"
        "  a: {action_ns: follow_joint_trajectory, joints: [j1], default: false}\n"
        "  b: {action_ns: follow_joint_trajectory, joints: [j1], default: true}\n"
    )
    params = {p.name: p.value for p in config_parameters(tmp_path)}
    assert params["moveit_simple_controller_manager.b.default"] is True
    assert params["moveit_simple_controller_manager.a.default"] is False
