"""The parts of ``move_group`` (see :mod:`._move_group`) share this: constants, message helpers, the
controllers' description, and :class:`_MoveGroupBase`, the node's state and its request and message
helpers. :mod:`._move_group_scene` keeps the planning scene, :mod:`._move_group_planning` serves
kinematics and plans, :mod:`._move_group_execution` runs trajectories on the controllers."""

from __future__ import annotations

import logging
import math
import re
import threading
import time
from dataclasses import dataclass
from typing import Any

import numpy as np
from action_msgs.msg import GoalStatus
from builtin_interfaces.msg import Duration as DurationMsg
from moveit_msgs.msg import (
    MoveItErrorCodes,
    RobotState,
    RobotTrajectory,
)
from rclpy.action.client import ActionClient
from rclpy.executors import ExternalShutdownException, ShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from trajectory_msgs.msg import JointTrajectoryPoint

from ..planning import ArmPlanner, PlannerPool, PlanningError, Trajectory, quoted
from ._joint_state_monitor import JointStateMonitor

_log = logging.getLogger("gazelle.move_group")

OBJECT_PADDING_PARAMETER = "robot_description_planning.default_object_padding"
"""MoveIt's parameter (m) by which world objects are grown for collision checking; 0 by default, as MoveIt's
planning_scene_monitor.cpp (configureDefaultPadding). Here it grows the simulation's objects (what
``gazelle sim`` publishes); objects a client applies are kept as given, as ``get_planning_scene`` reports
them. The simulated robot collides with the convex hulls of its meshes, a little fatter than the meshes
the planner checks: a plan that grazes an object may touch it in the simulation (an arm planned 5 mm past
a pillar brushed it); 0.01 keeps a centimetre."""
TWIN_CHECK_SEC = 2.0
"""s after start when move_group looks for another of its name on the domain (discovery has run)."""
SHUTDOWN_DEADLINE_SEC = 3.0
"""s after SIGINT/SIGTERM by which move_group has ended, however busy (its watchdog process kills it)."""
CURRENT_STATE_WAIT = 5.0
"""s a request waits for the first /joint_states (MoveIt's planning-scene monitor waits 1 s)."""
CONTROLLER_WAIT = 5.0
"""s an execution waits for its controller's action server, or its joints' gz command topics, to be
discovered."""
_ENDED = (GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED)
STREAM_RATE_HZ = 100.0
"""Set-points a second streamed to gz JointPositionController topics (wall time)."""
STREAM_GOAL_TOLERANCE = 0.01
"""rad (m): how near each joint must come to the trajectory's end for a streamed execution to succeed."""
GZ_CMD_POS = re.compile(r"/joint/(?P<joint>[^/]+)/n?\d+/cmd_pos$")
"""gz-sim JointPositionController's default command topic, ``/model/<model>/joint/<joint>/<index>/cmd_pos``
(on ROS ``.../n0/cmd_pos``: see ``gazelle.ros._names``)."""
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
MAX_FK_LINKS = 1_000
"""The most links one compute_fk request may name (a link may be named again): each is a pose in the reply."""
PLANNING_TIME = 5.0
"""s a plan searches when the request's ``allowed_planning_time`` is 0 or not a number (MoveIt's default)."""
MAX_SCENE_OBJECTS = 256
"""The most collision objects one planning-scene request may carry, and a scene may hold besides the
simulation's own. Adding one costs time in all the others (roboplan rebuilds its collision pairs): 200
take ~2 s; 3,000 in one request kept move_group deaf for over 15 minutes."""


def _code(name: str) -> MoveItErrorCodes:
    return MoveItErrorCodes(val=getattr(MoveItErrorCodes, name, MoveItErrorCodes.FAILURE))


def _same_shapes(a: tuple[Any, ...], b: tuple[Any, ...]) -> bool:
    return len(a) == len(b) and all(
        x.kind == y.kind and x.dimensions == y.dimensions and np.allclose(x.pose, y.pose) for x, y in zip(a, b)
    )


def _failed(response: Any, code: str, message: str) -> Any:
    """A service response that says why it failed: its error_code (GetMotionPlan's is in its
    motion_plan_response: an internal error there answered code 0 with no message), or ``success``."""
    if hasattr(response, "motion_plan_response"):
        response.motion_plan_response.error_code = _code(code)
        response.motion_plan_response.error_code.message = message
    elif hasattr(response, "error_code"):
        response.error_code = _code(code)
        response.error_code.message = message
    elif hasattr(response, "success"):
        response.success = False
    return response


def _duration(t: float) -> DurationMsg:
    sec = math.floor(t)
    return DurationMsg(sec=int(sec), nanosec=int(round((t - sec) * 1e9)) % 1_000_000_000)


def _seconds(d: DurationMsg) -> float:
    return d.sec + d.nanosec * 1e-9


@dataclass(frozen=True)
class Controller:
    """A FollowJointTrajectory controller from moveit_controllers.yaml."""

    name: str
    action: str
    joints: tuple[str, ...]


def _quat(q: np.ndarray) -> Any:
    from geometry_msgs.msg import Quaternion

    return Quaternion(x=float(q[0]), y=float(q[1]), z=float(q[2]), w=float(q[3]))


class _MoveGroupBase(Node):
    """What every part of move_group shares: its state (set up by :class:`MoveGroupNode`) and the helpers
    that turn requests into planner states and planner results into messages."""

    _pool: PlannerPool | None
    """The robot's planners, one per kind of work, each under its own lock (see gazelle.planning's _pool.py)."""
    _ready: threading.Event
    planner: ArmPlanner | None
    """The pool's primary planner: plans are made, and scene changes applied, on it."""
    _joint_states: JointStateMonitor
    """The current state's source: /joint_states, taken without an executor (see its module)."""
    _warned_no_state: bool
    _noted: set[str]
    _texts: dict[str, str]
    _sim_objects: set[str]
    _sim_world: Any
    object_padding: float
    _display: Any
    _controllers: list[Controller]
    _trajectory_clients: dict[str, ActionClient]
    _position_pubs: dict[str, Any]
    _controller_lists: dict[str, Any]
    _execution_node: Node
    _execution_executor: SingleThreadedExecutor
    _execution_thread: threading.Thread

    @property
    def _latest_joints(self) -> dict[str, float]:
        """Every joint's latest position heard on /joint_states (MoveIt's current state)."""
        return self._joint_states.positions()

    def _on_execution_thread(self, fn: Any, timeout: float = 10.0) -> Any:
        """``fn()`` run on the thread that spins the execution node, which is where that node's clients and
        publishers are made. Made from an action's worker thread while that executor waited on the node's
        entities, rcl aborted the process: YuMi's move_group died on execute_trajectory ("double free or
        corruption", "Fatal Python error: Aborted" in ``create_client`` under ``PYTHONMALLOC=debug``)."""
        if threading.current_thread() is self._execution_thread:
            return fn()
        done = threading.Event()
        box: dict[str, Any] = {}

        def task() -> None:
            try:
                box["value"] = fn()
            except BaseException as err:  # handed to the caller
                box["error"] = err
            finally:
                done.set()

        self._execution_executor.create_task(task)
        if not done.wait(timeout):
            raise TimeoutError("the execution thread did not run the task")
        if "error" in box:
            raise box["error"]
        return box.get("value")

    def _spin_execution(self) -> None:
        """The execution node's thread: spin until rclpy shuts down."""
        try:
            self._execution_executor.spin()
        except (ExternalShutdownException, ShutdownException):
            pass

    def _param(self, name: str) -> str:
        """A string parameter of the node, or "" when it is not set."""
        if not self.has_parameter(name):
            return ""
        value = self.get_parameter(name).value
        return value if isinstance(value, str) else ""

    def _start_state(self, state: RobotState, planner: ArmPlanner | None = None) -> np.ndarray:
        """The request's start state on ``planner`` (the primary by default): the current one with what the
        request gives put in."""
        planner = planner or self.planner
        assert planner is not None
        deadline = time.monotonic() + CURRENT_STATE_WAIT
        while not self._latest_joints and time.monotonic() < deadline:
            time.sleep(0.01)  # as MoveIt waits for a current state (the callback takes no lock)
        if self._latest_joints:
            planner.set_current(self._latest_joints)
        elif not self._warned_no_state:
            self._warned_no_state = True
            self.get_logger().warning(
                f"no /joint_states within {CURRENT_STATE_WAIT:g} s: planning from the model's zero positions"
            )
        js = state.joint_state
        given = dict(zip(js.name, js.position)) if js.name else None
        if len(js.name) != len(js.position):
            # MoveIt's robotStateMsgToRobotState refuses such a joint state with this error and the scene keeps
            # its current state (moveit_core/robot_state/src/conversions.cpp, jointStateToRobotStateImpl;
            # planning_scene.cpp's setCurrentState ignores the result): the current state, not a guess
            self.get_logger().error(
                f"Different number of names and positions in JointState message: {len(js.name)}, {len(js.position)}"
            )
            given = None
        # a start state read from /joint_states may be a hair past a limit: moved onto it, as the current
        # state is (MoveIt's start_state_max_bounds_error, 0.05)
        return planner.onto_limits(planner.state(given))

    def _frame(self, frame: str, q: np.ndarray, planner: ArmPlanner | None = None) -> np.ndarray:
        """The pose of ``frame`` in the planning frame: the root link, the SRDF's virtual joint parent
        (a fixed virtual joint is the identity, as in MoveIt) or another link of the robot (on ``planner``, the
        primary by default)."""
        planner = planner or self.planner
        assert planner is not None
        virtual = {v.parent_frame for v in planner.semantics.virtual_joints if v.type == "fixed"}
        if not frame or frame == planner.root_link or frame in virtual:
            return np.eye(4)
        try:
            return planner.fk(q, frame)
        except PlanningError:
            raise PlanningError("FRAME_TRANSFORM_FAILURE", f"unknown frame {quoted(frame)}") from None

    def _warn(self, text: str) -> None:
        self.get_logger().warning(text)

    # ------------------------------------------------------------------ messages
    def _robot_state(self, q: np.ndarray) -> RobotState:
        """moveit_msgs/RobotState of the planner's joints at ``q``."""
        assert self.planner is not None
        state = RobotState()
        state.joint_state.name = list(self.planner.joint_names)
        state.joint_state.position = [float(v) for v in q]
        return state

    def _robot_trajectory(self, traj: Trajectory) -> RobotTrajectory:
        """A planned trajectory as moveit_msgs/RobotTrajectory: its joint names and timed points, in the planning
        frame."""
        out = RobotTrajectory()
        jt = out.joint_trajectory
        jt.header.frame_id = self.planner.root_link if self.planner else ""
        jt.joint_names = list(traj.joint_names)
        jt.points = [
            JointTrajectoryPoint(
                positions=[float(v) for v in traj.positions[i]],
                velocities=[float(v) for v in traj.velocities[i]],
                accelerations=[float(v) for v in traj.accelerations[i]],
                time_from_start=_duration(float(t)),
            )
            for i, t in enumerate(traj.times)
        ]
        return out
