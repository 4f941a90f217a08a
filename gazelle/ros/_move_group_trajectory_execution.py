"""move_group's trajectory execution: MoveIt's ``TrajectoryExecutionManager``
(moveit_ros/planning/trajectory_execution_manager/src/trajectory_execution_manager.cpp, jazzy) with the
controllers ``moveit_simple_controller_manager`` (moveit_controllers.yaml) or a controller manager names:
a trajectory runs on their FollowJointTrajectory actions, or is streamed to gz-sim JointPositionController
command topics; a "stop" on ``/trajectory_execution_event`` stops what runs."""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np
import rclpy
from control_msgs.action import FollowJointTrajectory
from rclpy.action.client import ActionClient
from rclpy.executors import ExternalShutdownException, ShutdownException, SingleThreadedExecutor
from std_msgs.msg import Float64, String
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ..planning import quoted
from ._move_group_common import (
    _ENDED,
    CONTROLLER_WAIT,
    GZ_CMD_POS,
    STREAM_GOAL_TOLERANCE,
    STREAM_RATE_HZ,
    Controller,
    _seconds,
)

if TYPE_CHECKING:
    from rclpy.action.server import ServerGoalHandle
    from rclpy.client import Client
    from rclpy.publisher import Publisher
    from rclpy.task import Future

    from ._move_group_protocols import MoveGroupCore

T = TypeVar("T")


class TrajectoryExecutionManager:
    """The controllers and how a trajectory is run on them.

    The controllers' FollowJointTrajectory clients live on their own node and single-threaded executor: on
    move_group's multi-threaded one, busy with /joint_states, their status and result messages came seconds
    late or not at all (rclpy's executor is slow and its action client racy across threads: ros2/rclpy#1123)."""

    def __init__(self, context: MoveGroupCore) -> None:
        self.context = context
        self.controllers = self._read_controllers()
        """The controllers moveit_controllers.yaml lists (a controller manager's are asked when none fit)."""
        self._trajectory_clients: dict[str, ActionClient] = {}
        self._position_pubs: dict[str, Publisher] = {}  # gz JointPositionController command topics
        self._controller_lists: dict[str, Client] = {}  # list_controllers clients by service name
        self._stops = 0
        """How many "stop" events /trajectory_execution_event has brought: an execution that began before the
        latest one stops as a cancelled goal does."""
        node = context.node
        self.node = rclpy.create_node("move_group_trajectory_execution", context=node.context)
        self.executor = SingleThreadedExecutor(context=node.context)
        self.executor.add_node(self.node)
        self._thread = threading.Thread(target=self._spin, name="move_group execution", daemon=True)
        self._thread.start()

    def start(self) -> None:
        """Listen for "stop": MoveIt's trajectory execution manager listens on /trajectory_execution_event
        (pymoveit2's cancel_execution publishes it): trajectory_execution_manager.cpp, EXECUTION_EVENT_TOPIC."""
        self.context.node.create_subscription(
            String,
            "trajectory_execution_event",
            self._on_execution_event,
            10,
            callback_group=self.context.callback_group,
        )

    def destroy(self) -> None:
        """Stop the execution node's executor, wait for its thread to leave its wait (before destroying what the
        wait set may hold: the segmentation faults seen on Ctrl-C were another race, with rclpy's signal
        thread: see _signals.py), then destroy the clients and the node."""
        self.executor.shutdown()
        self._thread.join(timeout=2.0)
        for client in self._trajectory_clients.values():
            client.destroy()
        self.node.destroy_node()

    def _read_controllers(self) -> list[Controller]:
        """The controllers MoveIt's simple controller manager would use:
        ``moveit_simple_controller_manager.controller_names`` with each one's ``action_ns`` (default
        ``follow_joint_trajectory``), ``joints`` and ``default`` (false unless given:
        moveit_simple_controller_manager.cpp, jazzy, reads it with get_parameter_or(..., false))."""
        prefix = "moveit_simple_controller_manager."
        names = self.context.parameter(prefix + "controller_names", [])
        out = []
        for name in names if isinstance(names, (list, tuple)) else []:  # a string array (rclpy gives a list)
            ns = self.context.param(f"{prefix}{name}.action_ns") or "follow_joint_trajectory"
            joints = self.context.parameter(f"{prefix}{name}.joints", [])
            joints = tuple(joints) if isinstance(joints, (list, tuple)) else ()
            default = self.context.parameter(f"{prefix}{name}.default", False) is True
            out.append(Controller(name, f"/{name}/{ns}".replace("//", "/"), joints, default))
        return out

    def _spin(self) -> None:
        """The execution node's thread: spin until rclpy shuts down."""
        try:
            self.executor.spin()
        except (ExternalShutdownException, ShutdownException):
            pass

    def on_execution_thread(self, fn: Callable[[], T], timeout: float = 10.0) -> T:
        """``fn()`` run on the thread that spins the execution node, which is where that node's clients and
        publishers are made. Made from an action's worker thread while that executor waited on the node's
        entities, rcl aborted the process: YuMi's move_group died on execute_trajectory ("double free or
        corruption", "Fatal Python error: Aborted" in ``create_client`` under ``PYTHONMALLOC=debug``)."""
        if threading.current_thread() is self._thread:
            return fn()
        done = threading.Event()
        values: list[T] = []
        errors: list[BaseException] = []

        def task() -> None:
            try:
                values.append(fn())
            except BaseException as err:  # handed to the caller
                errors.append(err)
            finally:
                done.set()

        self.executor.create_task(task)
        if not done.wait(timeout):
            raise TimeoutError("the execution thread did not run the task")
        if errors:
            raise errors[0]
        return values[0]

    def _on_execution_event(self, msg: String) -> None:
        """MoveIt's ``TrajectoryExecutionManager::receiveEvent``/``processEvent``: "stop" stops every execution
        in progress (its goal ends with PREEMPTED); any other event is a warning."""
        self.context.logger.info(f"Received event {quoted(msg.data)}")
        if msg.data == "stop":
            self._stops += 1
        else:
            self.context.warn(f"Unknown event type: {quoted(msg.data)}")

    def controllers_for(self, joints: list[str]) -> list[Controller]:
        """The controllers that execute a trajectory of ``joints``, as MoveIt's TrajectoryExecutionManager
        picks them: one that has every joint, else the fewest that together have them (a dual arm's group
        of both arms, one joint_trajectory_controller an arm), each then given its own joints' part. From
        moveit_controllers.yaml first, then the controller manager's active ones; [] when none cover them."""
        wanted = set(joints)
        listed: list[Controller] | None = None
        for pool_of in ("yaml", "ros2_control"):
            if pool_of == "yaml":
                pool = list(self.controllers)
            else:
                listed = self.ros2_control_controllers()
                pool = listed
            # MoveIt's findControllers ranks the options: default controllers first, then the ones of fewer
            # joints (trajectory_execution_manager.cpp, OrderPotentialControllerCombination; the simple
            # controller manager reports every controller active); the listed order breaks ties
            singles = [c for c in pool if wanted <= set(c.joints)]
            if singles:
                return [min(singles, key=lambda c: (not c.default, len(c.joints)))]
            chosen = _cover(wanted, pool)
            if chosen:
                return chosen
        return _cover(wanted, [*self.controllers, *(listed or [])])

    def ros2_control_controllers(self) -> list[Controller]:
        """The active joint_trajectory_controllers of the controller manager, as MoveIt's
        Ros2ControlManager finds them (moveit_controllers.yaml names no controllers then)."""
        from controller_manager_msgs.srv import ListControllers

        namespace = (self.context.param("ros_control_namespace") or "/").rstrip("/")  # MoveIt's parameter
        name = f"{namespace}/controller_manager/list_controllers"
        client = self._controller_lists.get(name)
        if client is None:
            client = self._controller_lists[name] = self.on_execution_thread(
                lambda: self.node.create_client(ListControllers, name)
            )
        listed = any(n == name for n, _ in self.node.get_service_names_and_types())
        if not client.wait_for_service(timeout_sec=2.0 if listed else 0.3):  # none: gz arms, say
            return []
        done = threading.Event()
        box: dict[str, Any] = {}

        def call() -> None:
            future = client.call_async(ListControllers.Request())
            future.add_done_callback(lambda f: (box.__setitem__("result", f.result()), done.set()))

        self.executor.create_task(call)
        if not done.wait(5.0) or box.get("result") is None:
            return []
        out = []
        for c in box["result"].controller:
            if c.state != "active" or not c.type.endswith("JointTrajectoryController"):
                continue
            joints = tuple(dict.fromkeys(i.split("/")[0] for i in c.claimed_interfaces))
            out.append(Controller(c.name, f"{namespace}/{c.name}/follow_joint_trajectory", joints))
        return out

    def position_topics(self, joints: list[str]) -> dict[str, str] | None:
        """gz-sim JointPositionController command topics (std_msgs/Float64, the default names
        ``/model/<model>/joint/<joint>/n0/cmd_pos`` on ROS, with a subscriber) for every one of ``joints``; None
        unless each joint has exactly one."""
        found: dict[str, list[str]] = {}
        for topic, types in self.node.get_topic_names_and_types():
            m = GZ_CMD_POS.search(topic)
            if m and "std_msgs/msg/Float64" in types and m.group("joint") in joints:
                if self.node.count_subscribers(topic) > 0:
                    found.setdefault(m.group("joint"), []).append(topic)
        if set(found) != set(joints) or any(len(t) != 1 for t in found.values()):
            return None
        return {j: t[0] for j, t in found.items()}

    def wait_for_execution(self, joints: list[str]) -> tuple[list[Controller], bool, dict[str, str] | None]:
        """(the controllers of ``joints``, whether their actions are served, else the joints' gz command topics),
        waiting up to :data:`CONTROLLER_WAIT` for a served action or the topics to be discovered: right
        after a robot is spawned, a busy machine's graph may not list them, nor the controller manager
        that names the controller, yet (MoveIt's controller managers wait for their action servers
        likewise). Once the wait is over without either: (the controllers or [], False, None)."""
        deadline = time.monotonic() + CONTROLLER_WAIT
        while True:
            controllers = self.controllers_for(joints)
            if controllers and all(self.action_served(c.action) for c in controllers):
                return controllers, True, None
            topics = self.position_topics(joints)
            if topics is not None or time.monotonic() >= deadline:
                return controllers, False, topics
            time.sleep(0.1)  # the graph is kept by the middleware's threads

    def action_served(self, action: str) -> bool:
        """Whether an action server of that name is in the graph now."""
        from rclpy.action.graph import get_action_names_and_types

        return any(name == action for name, _ in get_action_names_and_types(self.node))

    def stream(
        self, trajectory: JointTrajectory, topics: dict[str, str], stop_requested: Callable[[], bool]
    ) -> tuple[str, str]:
        """Execute ``trajectory`` on gz JointPositionController arms: its positions, interpolated, streamed
        to each joint's command topic at :data:`STREAM_RATE_HZ` on the wall clock, then the end held until
        every joint is within :data:`STREAM_GOAL_TOLERANCE` of it (by /joint_states)."""
        joints = list(trajectory.joint_names)
        pubs = []
        for j in joints:
            pub = self._position_pubs.get(topics[j])
            if pub is None:
                pub = self._position_pubs[topics[j]] = self.on_execution_thread(
                    lambda t=topics[j]: self.node.create_publisher(Float64, t, 10)
                )
            pubs.append(pub)
        points = [p for p in trajectory.points if len(p.positions) == len(joints)]
        if not points:
            return "INVALID_MOTION_PLAN", "the trajectory has no positions"
        times = np.array([_seconds(p.time_from_start) for p in points])
        positions = np.array([list(p.positions) for p in points], dtype=float)
        goal = positions[-1]

        def send(q: np.ndarray) -> None:
            for pub, v in zip(pubs, q):
                pub.publish(Float64(data=float(v)))

        def measured() -> np.ndarray | None:
            latest = self.context.latest_joints
            return np.array([latest[j] for j in joints]) if all(j in latest for j in joints) else None

        started = time.monotonic()
        duration = float(times[-1])
        period = 1.0 / STREAM_RATE_HZ
        while True:
            if stop_requested():
                now = measured()
                if now is not None:
                    send(now)  # stop where the arm is
                return "PREEMPTED", "stopped"
            t = time.monotonic() - started
            send(np.array([np.interp(t, times, positions[:, i]) for i in range(len(joints))]))
            if t >= duration:
                break
            time.sleep(period)
        # MoveIt's allowed_goal_duration_margin and more: the servos settle after the last set-point
        deadline = time.monotonic() + 0.2 * duration + 3.0
        settled = 0
        while True:
            now = measured()
            error = float(np.max(np.abs(now - goal))) if now is not None else math.inf
            # within the tolerance for 0.1 s on end: a servo swinging through the goal is not there yet
            settled = settled + 1 if error <= STREAM_GOAL_TOLERANCE else 0
            if settled >= STREAM_RATE_HZ / 10:
                return "SUCCESS", ""
            if stop_requested():
                if now is not None:
                    send(now)
                return "PREEMPTED", "stopped"
            if time.monotonic() > deadline:
                what = "no /joint_states for them" if now is None else f"{error:.4f} from the end"
                return "TIMED_OUT", f"the joints' command topics were streamed, but the arm is {what}"
            send(goal)
            time.sleep(period)

    def run(self, trajectory: JointTrajectory, handle: ServerGoalHandle) -> tuple[str, str]:
        """Send ``trajectory`` to its FollowJointTrajectory controller and wait; cancel it when ``handle`` is,
        or when a "stop" event comes. Without a controller serving its joints, gz-sim JointPositionController
        arms get it streamed."""
        stops = self._stops

        def stop_requested() -> bool:  # the client cancelled, or a "stop" came since the execution began
            return bool(handle.is_cancel_requested or self._stops != stops)

        joints = list(trajectory.joint_names)
        controllers, served, topics = self.wait_for_execution(joints)
        if not served and topics is not None:
            return self.stream(trajectory, topics, stop_requested)
        if not controllers:
            return (
                "CONTROL_FAILED",
                f"no controller drives {joints} (moveit_controllers.yaml, an active joint_trajectory_controller "
                "of /controller_manager, or gz JointPositionController topics .../joint/<joint>/n0/cmd_pos)",
            )
        if len(controllers) == 1:
            return self.follow(controllers[0], trajectory, stop_requested, served)
        # each controller its joints' part, all at once (MoveIt's distributeTrajectory), as one execution
        parts, given = [], set()
        for c in controllers:
            mine = [j for j in joints if j in c.joints and j not in given]
            given.update(mine)
            parts.append((c, _part(trajectory, mine)))
        results: list[tuple[str, str]] = [("CONTROL_FAILED", "not run")] * len(parts)

        def follow(i: int, controller: Controller, part: JointTrajectory) -> None:
            results[i] = self.follow(controller, part, stop_requested, served)

        threads = [
            threading.Thread(target=follow, args=(i, c, part), name=f"execute {c.name}", daemon=True)
            for i, (c, part) in enumerate(parts)
        ]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        return next((r for r in results if r[0] == "PREEMPTED"), None) or next(
            (r for r in results if r[0] != "SUCCESS"), ("SUCCESS", "")
        )

    def _instead(self, missing: Controller) -> str:
        """What to use instead of ``missing``, said as MoveIt's user would fix it: another controller of
        moveit_controllers.yaml for the same joints whose action is up (UR's config makes
        scaled_joint_trajectory_controller the default while ur_sim_control.launch.py starts
        joint_trajectory_controller). MoveIt itself sends to the default controller only, and so does gazelle."""
        for other in self.controllers:
            if other is not missing and set(missing.joints) <= set(other.joints) and self.action_served(other.action):
                return (
                    f" ({other.name}, listed for the same joints, is running: start {missing.name} in its place, or "
                    f"make {other.name} MoveIt's default controller in moveit_controllers.yaml)"
                )
        return ""

    def follow(
        self, controller: Controller, trajectory: JointTrajectory, stop_requested: Callable[[], bool], served: bool
    ) -> tuple[str, str]:
        """Send ``trajectory`` to ``controller``'s FollowJointTrajectory action and wait; cancel it when
        ``handle`` is."""
        client = self._trajectory_clients.get(controller.action)
        if client is None:
            client = self._trajectory_clients[controller.action] = self.on_execution_thread(
                lambda: ActionClient(self.node, FollowJointTrajectory, controller.action)
            )
        if not client.wait_for_server(timeout_sec=5.0 if served else 0.1):  # the graph was waited on above
            return (
                "CONTROL_FAILED",
                f"controller action {controller.action} is not available{self._instead(controller)}",
            )
        goal = FollowJointTrajectory.Goal(trajectory=trajectory)
        done = threading.Event()
        box: dict[str, Any] = {}

        def on_result(f: Future) -> None:
            box["result"] = f.result()
            done.set()

        def on_goal(f: Any) -> None:
            goal_handle = f.result()
            box["goal"] = goal_handle
            if not goal_handle.accepted:
                done.set()
                return
            goal_handle.get_result_async().add_done_callback(on_result)

        def on_feedback(_msg: object) -> None:
            box["progress"] = time.monotonic()

        # every call on the client is made on its executor's thread: made from this one, a reply that came
        # back before rclpy filed the request was dropped and its future never completed (ros2/rclpy#1123)
        on_thread = self.executor.create_task
        on_thread(lambda: client.send_goal_async(goal, feedback_callback=on_feedback).add_done_callback(on_goal))
        points = list(trajectory.points)
        duration = _seconds(points[-1].time_from_start) if points else 0.0
        # MoveIt's allowed_execution_duration_scaling (1.2) and allowed_goal_duration_margin (0.5 s), in
        # wall time; a simulation running slower than real time still reports progress through the
        # controller's feedback, so the wait goes on while feedback comes, up to four times as long.
        started = time.monotonic()
        expected = duration * 1.2 + 0.5
        cancelled = False
        while not done.wait(0.02):
            if stop_requested() and not cancelled and "goal" in box:
                on_thread(box["goal"].cancel_goal_async)
                cancelled = True
            now = time.monotonic()
            handle_ = box.get("goal")
            silent = now - box.get("progress", started)
            ended = handle_ is not None and handle_.accepted and handle_.status in _ENDED
            if handle_ is not None and handle_.accepted and (ended or (now - started > expected and silent > 0.5)):
                # the controller says the goal ended, or its time is up and its feedback stopped, but no
                # result came: ask again every 0.5 s (a result response can be lost as a service reply
                # can; the server keeps results, and answers at once for a goal that is done)
                asked = box.setdefault("asked", now)
                if now - asked > 0.5:
                    box["asked"] = now
                    on_thread(lambda h=handle_: h.get_result_async().add_done_callback(on_result))
            quiet = silent > 3.0
            if now - started > expected and (quiet or now - started > 4 * expected + 5.0):
                if "goal" in box:
                    on_thread(box["goal"].cancel_goal_async)
                return (
                    "TIMED_OUT",
                    f"{controller.name} did not finish the {duration:.2f} s trajectory within {now - started:.1f} s",
                )
        if cancelled:
            return "PREEMPTED", "stopped"
        if "result" not in box:
            return "CONTROL_FAILED", f"{controller.name} rejected the trajectory"
        res = box["result"].result
        if res.error_code != FollowJointTrajectory.Result.SUCCESSFUL:
            return "CONTROL_FAILED", f"{controller.name}: {res.error_string or res.error_code}"
        return "SUCCESS", ""


def _cover(joints: set[str], controllers: list[Controller]) -> list[Controller]:
    """The fewest of ``controllers`` (greedy: the one with most of the joints left first) whose joints
    together are ``joints``; [] when they do not cover them."""
    left, pool, chosen = set(joints), list(controllers), []
    while left:
        best = max(pool, key=lambda c: len(left & set(c.joints)), default=None)
        if best is None or not left & set(best.joints):
            return []
        chosen.append(best)
        left -= set(best.joints)
        pool.remove(best)
    return chosen


def _part(trajectory: JointTrajectory, joints: list[str]) -> JointTrajectory:
    """``trajectory`` for ``joints`` alone (the same points in time, their columns)."""
    index = [list(trajectory.joint_names).index(j) for j in joints]
    points = []
    for p in trajectory.points:
        q = JointTrajectoryPoint(time_from_start=p.time_from_start)
        for field in ("positions", "velocities", "accelerations", "effort"):
            values = list(getattr(p, field))
            if len(values) == len(trajectory.joint_names):
                setattr(q, field, [values[i] for i in index])
        points.append(q)
    return JointTrajectory(header=trajectory.header, joint_names=list(joints), points=points)
