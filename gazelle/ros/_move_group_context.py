"""What every move_group capability uses: MoveIt's ``MoveGroupContext``
(moveit_ros/move_group/include/moveit/move_group/move_group_context.hpp, jazzy): the robot model and its
planners, the planning scene monitor, the planning pipeline and the trajectory execution manager, owned by
the node (:class:`~._move_group.MoveGroupNode`) and handed to each capability, which uses nothing else."""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any

import numpy as np
from moveit_msgs.msg import RobotState, RobotTrajectory
from rclpy.node import Node
from trajectory_msgs.msg import JointTrajectoryPoint

from ..planning import ArmPlanner, PlannerPool, PlanningError, Trajectory, quoted
from ._joint_state_monitor import JointStateMonitor
from ._move_group_common import CURRENT_STATE_WAIT, _duration

if TYPE_CHECKING:
    from rclpy.callback_groups import CallbackGroup
    from rclpy.impl.rcutils_logger import RcutilsLogger

    from ._move_group_pipeline import PlanningPipeline
    from ._move_group_scene_monitor import PlanningSceneMonitor
    from ._move_group_trajectory_execution import TrajectoryExecutionManager


class MoveGroupContext:
    """The shared state of move_group's capabilities.

    ``pool`` is None until the robot is known (the node builds it from ``robot_description`` and
    ``robot_description_semantic``); ``scene``, ``pipeline`` and ``execution`` are set by the node right
    after the context is made (each takes the context)."""

    scene: PlanningSceneMonitor
    """The planning scene: the simulation's world, the objects clients apply, the allowed collisions."""
    pipeline: PlanningPipeline
    """Turns a MotionPlanRequest into a start state and a timed trajectory."""
    execution: TrajectoryExecutionManager
    """Runs trajectories on the controllers (or gz command topics)."""

    def __init__(self, node: Node, callback_group: CallbackGroup) -> None:
        self.node = node
        """The move_group node: its parameters, its logger, where capabilities register."""
        self.callback_group = callback_group
        """The node's reentrant callback group: every service, topic and action of move_group is in it."""
        self.pool: PlannerPool | None = None
        """The robot's planners, one per kind of work, each under its own lock (gazelle.planning's _pool.py)."""
        self.ready = threading.Event()
        """Set once the robot is known and move_group says "You can start planning now!"."""
        self.urdf_text = ""
        """The robot_description the planners were built from (MoveIt's RDFLoader URDF string)."""
        self.noted: set[str] = set()
        """The kinds of things said once (request parts gazelle does not honour, ...)."""
        self.joint_states = JointStateMonitor(node, "joint_states")
        """The current state's source: /joint_states, taken without an executor (see its module)."""
        self._warned_no_state = False

    @property
    def planner(self) -> ArmPlanner | None:
        """The pool's primary planner: plans are made, and scene changes applied, on it (None: no robot yet)."""
        return self.pool.primary if self.pool is not None else None

    @property
    def latest_joints(self) -> dict[str, float]:
        """Every joint's latest position heard on /joint_states (MoveIt's current state)."""
        return self.joint_states.positions()

    @property
    def logger(self) -> RcutilsLogger:
        return self.node.get_logger()

    def warn(self, text: str) -> None:
        self.node.get_logger().warning(text)

    def note_once(self, kind: str, text: str) -> None:
        """Say ``text`` as a warning the first time ``kind`` comes: what a client sends never grows the set of
        kinds said, nor floods the log."""
        if kind not in self.noted:
            self.noted.add(kind)
            self.node.get_logger().warning(text)

    def param(self, name: str) -> str:
        """A string parameter of the node, or "" when it is not set."""
        if not self.node.has_parameter(name):
            return ""
        value = self.node.get_parameter(name).value
        return value if isinstance(value, str) else ""

    def parameter(self, name: str, default: Any = None) -> Any:
        """A parameter's value of any type, ``default`` when it is not set."""
        return self.node.get_parameter(name).value if self.node.has_parameter(name) else default

    def parameters(self) -> dict[str, object]:
        """Every parameter of the node, name -> value (MoveIt's configs are read from them)."""
        return {name: p.value for name, p in self.node._parameters.items()}

    def ik_timeout(self, group: str) -> float:
        """A group's IK time budget: kinematics.yaml's ``kinematics_solver_timeout`` (MoveIt's default for a
        request without a timeout), else 0.5 s."""
        value = self.parameter(f"robot_description_kinematics.{group}.kinematics_solver_timeout")
        if isinstance(value, (int, float)) and value > 0:
            return float(value)
        return 0.5

    def start_state(self, state: RobotState, planner: ArmPlanner | None = None) -> np.ndarray:
        """The request's start state on ``planner`` (the primary by default): the current one with what the
        request gives put in."""
        planner = planner or self.planner
        assert planner is not None
        deadline = time.monotonic() + CURRENT_STATE_WAIT
        while not self.latest_joints and time.monotonic() < deadline:
            time.sleep(0.01)  # as MoveIt waits for a current state (the callback takes no lock)
        if self.latest_joints:
            planner.set_current(self.latest_joints)
        elif not self._warned_no_state:
            self._warned_no_state = True
            self.warn(f"no /joint_states within {CURRENT_STATE_WAIT:g} s: planning from the model's zero positions")
        js = state.joint_state
        given = dict(zip(js.name, js.position)) if js.name else None
        if len(js.name) != len(js.position):
            # MoveIt's robotStateMsgToRobotState refuses such a joint state with this error and the scene keeps
            # its current state (moveit_core/robot_state/src/conversions.cpp, jointStateToRobotStateImpl;
            # planning_scene.cpp's setCurrentState ignores the result): the current state, not a guess
            self.logger.error(
                f"Different number of names and positions in JointState message: {len(js.name)}, {len(js.position)}"
            )
            given = None
        # a start state read from /joint_states may be a hair past a limit: moved onto it, as the current
        # state is (MoveIt's start_state_max_bounds_error, 0.05)
        return planner.onto_limits(planner.state(given))

    def frame(self, frame: str, q: np.ndarray, planner: ArmPlanner | None = None) -> np.ndarray:
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

    # ------------------------------------------------------------------ messages
    def robot_state(self, q: np.ndarray) -> RobotState:
        """moveit_msgs/RobotState of the planner's joints at ``q``."""
        assert self.planner is not None
        state = RobotState()
        state.joint_state.name = list(self.planner.joint_names)
        state.joint_state.position = [float(v) for v in q]
        return state

    def robot_trajectory(self, traj: Trajectory) -> RobotTrajectory:
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
