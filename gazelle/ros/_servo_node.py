"""MoveIt Servo's ``servo_node`` (moveit_servo, Jazzy: src/servo_node.cpp), served by
:class:`gazelle.planning.ServoCore`.

A plain rclpy node named ``servo_node``. Its parameters are servo_parameters.yaml's under ``moveit_servo.``
(as launch files pass them: ``{"moveit_servo": servo_params}``), with the robot in ``robot_description``
and ``robot_description_semantic``. As MoveIt's node it:

* reads ``~/delta_joint_cmds`` (control_msgs/JointJog), ``~/delta_twist_cmds`` (TwistStamped) and
  ``~/pose_target_cmds`` (PoseStamped) (the ``*_command_in_topic`` parameters), the robot's state from
  ``joint_topic``; acts on the command of the type ``~/switch_command_type`` chose (JOINT_JOG at start),
  and warns "Command type has not been set, cannot accept input" for another;
* every ``publish_period`` of the node's clock (sim time under ``use_sim_time``; MoveIt's loop is a
  WallRate, the same at a real-time factor of 1, so a command means the same motion at any pace; a cycle
  after a longer step of the clock covers that time, up to 10 periods) turns the latest command into the move group's
  next joint state and publishes it on ``command_out_topic`` as ``trajectory_msgs/JointTrajectory`` (the
  sliding window of ``max_expected_latency``: common.cpp ``updateSlidingWindow`` and
  ``composeTrajectoryMessage``) or ``std_msgs/Float64MultiArray``; a command older than
  ``incoming_command_timeout`` (its header stamp, by the node's clock) halts;
* refuses, with one warning per topic and reason, a command stamped before 1970 (``sec`` < 0: MoveIt's
  rclcpp::Time throws) or more than :data:`FUTURE_STAMP_TOLERANCE` ahead of the node's clock (a publisher
  on another clock, such as ``ros2 topic pub``'s ``stamp: now`` in wall time against a node on sim time,
  which MoveIt's rule would keep fresh for as long as the clocks are apart); a stamp a little ahead counts
  from the command's arrival, so no command acts longer than ``incoming_command_timeout`` after it came. A
  zero stamp is MoveIt's: stale once the node's clock is past ``incoming_command_timeout``. A command already
  stale on arrival is said once (a publisher on another clock, the other way round);
* keeps the robot's joints only from ``joint_topic``, and refuses a position that is not finite (said once per
  joint), so the Jacobian never sees a NaN; a unitless twist outside [-1, 1] is INVALID (Humble's rule: Jazzy
  scaled one of 1e308 into NaN joint positions), and so is any command whose step is not finite, so no NaN
  reaches the controller; MoveIt's per-cycle warnings about commands are logged at most once a second per
  kind (:data:`WARNING_INTERVAL`), with the count held back;
* publishes a moveit_msgs/ServoStatus on ``~/status`` each cycle; ``~/pause_servo`` (std_srvs/SetBool)
  pauses and resumes.

Where gazelle differs, said once at start: no collision checking (``check_collisions``), no smoothing plugin
(``use_smoothing``), no ``active_subgroup``; the Jacobian's pseudo-inverse stands in for an IK plugin.
"""

from __future__ import annotations

import functools
import math
import sys
import threading
import time
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal, TypedDict

import numpy as np
import rclpy
from control_msgs.msg import JointJog
from geometry_msgs.msg import PoseStamped, TwistStamped
from moveit_msgs.msg import ServoStatus
from moveit_msgs.srv import ServoCommandType
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.time import Time
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64MultiArray
from std_srvs.srv import SetBool
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ..planning import PlanningError, RobotScene, ServoCore, ServoKinematics, ServoSettings
from ..planning import servo as core
from ._planning_scene import matrix as pose_matrix

if TYPE_CHECKING:
    from rclpy.context import Context

PREFIX = "moveit_servo."
MIN_POINTS_FOR_TRAJ_MSG = 3
"""moveit_servo utils/common.hpp: a trajectory is published once the window holds this many states."""
STOPPED_VELOCITY_EPS = 1e-4
"""servo.cpp: a halting robot has stopped when every velocity is below this."""
MAX_CYCLE_PERIODS = 10
"""A cycle covers at most this many periods of clock time (a clock that jumped, a node that was stopped)."""
OUT_TYPES = ("trajectory_msgs/JointTrajectory", "std_msgs/Float64MultiArray")
WARNING_INTERVAL = 1.0
"""gazelle (s, wall): a warning about commands is logged at most this often per kind (a stream of bad ones)."""
MAX_WARNING_CHARS = 300
"""gazelle: a warning quoting the wire is cut to this many characters."""
FUTURE_STAMP_TOLERANCE = 1.0
"""gazelle (s): a command stamped further ahead of the node's clock than this is refused (another clock's)."""
_CommandTopic = Literal["joint_command_in_topic", "cartesian_command_in_topic", "pose_command_in_topic"]
TOPIC_PARAMETERS: dict[int, _CommandTopic] = {
    core.JOINT_JOG: "joint_command_in_topic",
    core.TWIST: "cartesian_command_in_topic",
    core.POSE: "pose_command_in_topic",
}


class _NodeParameters(TypedDict):
    """The node's own parameters (topics, timeouts, what it publishes), read once by ``_read_parameters``."""

    move_group_name: str
    joint_topic: str
    joint_command_in_topic: str
    cartesian_command_in_topic: str
    pose_command_in_topic: str
    command_out_topic: str
    command_out_type: str
    status_topic: str
    incoming_command_timeout: float
    max_expected_latency: float
    publish_joint_positions: bool
    publish_joint_velocities: bool
    publish_joint_accelerations: bool


Command = JointJog | TwistStamped | PoseStamped
"""A servo command: a joint jog, a twist or a pose target (one subscription of each)."""


@dataclass
class _State:
    """moveit_servo's KinematicState: the group's positions and velocities, stamped (ns, node clock)."""

    positions: np.ndarray
    velocities: np.ndarray
    stamp_ns: int = 0


class ServoNode(Node):
    """servo_node (see the module docstring)."""

    def __init__(self, parameter_overrides: list[Parameter] | None = None, context: Context | None = None) -> None:
        """MoveIt Servo's ``servo_node`` (Jazzy): the ``moveit_servo.*`` parameters read and checked as its
        parameter library does, the robot from ``robot_description`` and ``robot_description_semantic``, the
        three command topics (JointJog, TwistStamped, PoseStamped), the output (a JointTrajectory or a
        Float64MultiArray), ``~/status``, and the ``~/switch_command_type`` and ``~/pause_servo`` services. What
        gazelle's servo does not do (collision checking, smoothing plugins, subgroups) is said once, at start."""
        super().__init__(
            "servo_node",
            context=context,
            parameter_overrides=parameter_overrides or [],
            automatically_declare_parameters_from_overrides=True,
        )
        self._lock = threading.Lock()
        self.settings, self.p = self._read_parameters()
        self.kinematics = self._robot()
        self.core = ServoCore(self.kinematics, self.settings)
        self.command_type = core.JOINT_JOG
        self.paused = False
        self._joints: dict[str, float] = {}
        self._latest: dict[int, Command] = {}
        self._stamps: dict[int, int] = {}  # the age of each newest command counts from here (ns, node clock)
        self._said: set[str] = set()  # the once-only warnings given
        self._warned: dict[str, tuple[float, int]] = {}  # key: (when last logged, how many held back since)
        self._robot_joints = set(self.kinematics.scene.joint_names)
        self._topics: dict[int, str] = {}
        self._new: dict[int, bool] = {core.JOINT_JOG: False, core.TWIST: False, core.POSE: False}
        self._window: deque[_State] = deque()
        self._last_commanded: _State | None = None
        self._waiting_said = False
        self._last_cycle_ns: int | None = None
        self._status = ServoStatus(code=core.NO_WARNING, message=core.STATUS_MESSAGES[core.NO_WARNING])
        self.create_subscription(JointState, self.p["joint_topic"], self._on_joints, 10)
        for kind, msg_type in ((core.JOINT_JOG, JointJog), (core.TWIST, TwistStamped), (core.POSE, PoseStamped)):
            topic = self.p[TOPIC_PARAMETERS[kind]]
            self._topics[kind] = self.resolve_topic_name(topic)  # ~/delta_twist_cmds: /servo_node/delta_twist_cmds
            self.create_subscription(msg_type, topic, functools.partial(self._on_command, kind), 10)
        out_type = self.p["command_out_type"]
        self._out = self.create_publisher(
            JointTrajectory if out_type == OUT_TYPES[0] else Float64MultiArray, self.p["command_out_topic"], 10
        )
        self._status_pub = self.create_publisher(ServoStatus, self.p["status_topic"], 10)
        self.create_service(ServoCommandType, "~/switch_command_type", self._switch_command_type)
        self.create_service(SetBool, "~/pause_servo", self._pause_servo)
        self._say_differences()
        # on the node's clock: sim time under use_sim_time (MoveIt's loop is a WallRate, which a simulation
        # running faster or slower than real time would make command more or less motion per sim second)
        self.create_timer(self.settings.publish_period, self._cycle)
        self.get_logger().info("Servo initialized successfully")

    # ------------------------------------------------------------------ set-up
    def _get(self, name: str, default: Any) -> Any:
        """The parameter ``moveit_servo.<name>``, or ``default`` when it is not set (or set to nothing)."""
        full = PREFIX + name
        if not self.has_parameter(full):
            return default
        value = self.get_parameter(full).value
        return default if value is None else value

    def _read_parameters(self) -> tuple[ServoSettings, _NodeParameters]:
        """The servo settings (the cycle, input scaling, singularity thresholds, joint limit margins) and the node's
        topics and timeouts, with MoveIt's defaults; the checks MoveIt's ``servo_parameters.yaml`` declares are
        enforced, and every violation is named in one ValueError."""
        s = ServoSettings()
        for name in (
            "publish_period",
            "command_in_type",
            "apply_twist_commands_about_ee_frame",
            "lower_singularity_threshold",
            "hard_stop_singularity_threshold",
            "leaving_singularity_threshold_multiplier",
            "singularity_step_scale",
            "halt_all_joints_in_joint_mode",
            "halt_all_joints_in_cartesian_mode",
            "override_velocity_scaling_factor",
        ):
            setattr(s, name, type(getattr(s, name))(self._get(name, getattr(s, name))))
        s.scale_linear = float(self._get("scale.linear", s.scale_linear))
        s.scale_rotational = float(self._get("scale.rotational", s.scale_rotational))
        s.scale_joint = float(self._get("scale.joint", s.scale_joint))
        s.joint_limit_margins = [float(m) for m in self._get("joint_limit_margins", s.joint_limit_margins)]
        p: _NodeParameters = {
            "move_group_name": str(self._get("move_group_name", "")),
            "joint_topic": str(self._get("joint_topic", "/joint_states")),
            "joint_command_in_topic": str(self._get("joint_command_in_topic", "~/delta_joint_cmds")),
            "cartesian_command_in_topic": str(self._get("cartesian_command_in_topic", "~/delta_twist_cmds")),
            "pose_command_in_topic": str(self._get("pose_command_in_topic", "~/pose_target_cmds")),
            "command_out_topic": str(self._get("command_out_topic", "/panda_arm_controller/joint_trajectory")),
            "command_out_type": str(self._get("command_out_type", OUT_TYPES[0])),
            "status_topic": str(self._get("status_topic", "~/status")),
            "incoming_command_timeout": float(self._get("incoming_command_timeout", 0.1)),
            "max_expected_latency": float(self._get("max_expected_latency", 0.1)),
            "publish_joint_positions": bool(self._get("publish_joint_positions", True)),
            "publish_joint_velocities": bool(self._get("publish_joint_velocities", True)),
            "publish_joint_accelerations": bool(self._get("publish_joint_accelerations", False)),
        }
        problems = []  # servo_parameters.yaml's validations, as generate_parameter_library enforces them
        if not p["move_group_name"]:
            problems.append("moveit_servo.move_group_name is not set")
        if s.command_in_type not in ("unitless", "speed_units"):
            problems.append(f"moveit_servo.command_in_type '{s.command_in_type}' is not unitless or speed_units")
        if p["command_out_type"] not in OUT_TYPES:
            problems.append(f"moveit_servo.command_out_type '{p['command_out_type']}' is not one of {OUT_TYPES}")
        if not (s.publish_period > 0 and math.isfinite(s.publish_period)):
            problems.append(f"moveit_servo.publish_period must be > 0, got {s.publish_period}")
        if s.hard_stop_singularity_threshold <= s.lower_singularity_threshold:
            problems.append("moveit_servo.hard_stop_singularity_threshold must be above lower_singularity_threshold")
        if problems:
            raise ValueError("; ".join(problems))
        return s, p

    def _robot(self) -> ServoKinematics:
        """The kinematics of the move group being servoed, from the URDF and SRDF parameters (as MoveIt's servo_node
        takes them; no meshes: only the kinematics are needed)."""
        urdf = self.get_parameter("robot_description").value if self.has_parameter("robot_description") else ""
        srdf = (
            self.get_parameter("robot_description_semantic").value
            if self.has_parameter("robot_description_semantic")
            else ""
        )
        if not urdf or not srdf:
            raise ValueError("servo_node needs the robot_description and robot_description_semantic parameters")
        scene = RobotScene(str(urdf), str(srdf), resolve_mesh=lambda _uri: None)
        return ServoKinematics(scene, self.p["move_group_name"])

    def _say_differences(self) -> None:
        """Warn, once at start, of the parameters whose MoveIt behaviour gazelle does not have, so a user's config
        is never silently half-applied."""
        log = self.get_logger()
        if bool(self._get("check_collisions", True)):
            log.warning("moveit_servo.check_collisions: gazelle's servo_node does not check collisions")
        if bool(self._get("use_smoothing", True)):
            log.warning(
                f"moveit_servo.use_smoothing: the smoothing plugin "
                f"{self._get('smoothing_filter_plugin_name', 'online_signal_smoothing::ButterworthFilterPlugin')} "
                "is MoveIt's and is not loaded"
            )
        if str(self._get("active_subgroup", "")):
            log.warning("moveit_servo.active_subgroup is not supported: the whole move group is servoed")

    # ------------------------------------------------------------------ inputs
    def _warn_once(self, key: str, text: str) -> None:
        """Log ``text`` the first time ``key`` comes up, never again (a flood of bad input is one line)."""
        if key not in self._said:
            self._said.add(key)
            self.get_logger().warning(f"{text} (said once)")

    def _warn_often(self, key: str, text: str) -> None:
        """Log ``text`` unless a warning of the same ``key`` (a command type and status, never the wire's text)
        was logged less than :data:`WARNING_INTERVAL` s ago (wall time); the next one says how many were held
        back. MoveIt warns each cycle (100 a second for a stream of bad commands)."""
        now = time.monotonic()
        last, held = self._warned.get(key, (-math.inf, 0))
        if now - last < WARNING_INTERVAL:
            self._warned[key] = (last, held + 1)
            return
        self._warned[key] = (now, 0)
        if len(text) > MAX_WARNING_CHARS:  # a joint name or frame from the wire, a megabyte long
            text = text[:MAX_WARNING_CHARS] + f"... ({len(text)} characters)"
        more = f" ({held} more like it in the last {now - last:.1f} s)" if held else ""
        self.get_logger().warning(text + more)

    def _on_joints(self, msg: JointState) -> None:
        """The robot's joints' positions; other names are not kept, and a position that is not finite is refused
        (the joint keeps its last reading) with one warning."""
        with self._lock:
            for name, value in zip(msg.name, msg.position):
                if name not in self._robot_joints:
                    continue
                if not math.isfinite(value):
                    self._warn_once(
                        f"joints:{name}",
                        f"{self.p['joint_topic']}: position {value} of joint '{name}' is not finite; "
                        "ignored (the joint keeps its last reading)",
                    )
                    continue
                self._joints[name] = float(value)

    def _on_command(self, kind: int, msg: Command) -> None:
        """A command becomes the newest of its type unless its stamp is refused (see the module docstring)."""
        now = self.get_clock().now().nanoseconds
        stamp = msg.header.stamp
        topic = self._topics[kind]
        what = f"{type(msg).__name__} on {topic}"
        if stamp.sec < 0:
            self._warn_once(
                f"{topic}:negative", f"{what} refused: header.stamp.sec {stamp.sec} is negative (before 1970)"
            )
            return
        stamp_ns = stamp.sec * 1_000_000_000 + stamp.nanosec
        ahead = (stamp_ns - now) / 1e9
        if ahead > FUTURE_STAMP_TOLERANCE:
            self._warn_once(
                f"{topic}:future",
                f"{what} refused: header.stamp {stamp_ns / 1e9:.3f} s is {ahead:.3f} s ahead of "
                f"{self._clock_reading(now)}: its publisher is on another clock (wall time against use_sim_time? "
                "`ros2 topic pub -s` stamps `now` with /clock's time)",
            )
            return
        timeout = self.p["incoming_command_timeout"]
        if -ahead >= timeout:
            self._warn_once(
                f"{topic}:stale",
                f"{what} is stale on arrival: header.stamp {stamp_ns / 1e9:.3f} s is {-ahead:.3f} s behind "
                f"{self._clock_reading(now)}, over incoming_command_timeout ({timeout} s), so it halts "
                "(a zero stamp, or a publisher on another clock?)",
            )
        with self._lock:
            self._latest[kind] = msg
            self._stamps[kind] = min(stamp_ns, now)  # a stamp a little ahead ages from the command's arrival
            self._new[kind] = True

    def _clock_reading(self, now_ns: int) -> str:
        """What the node's clock reads, and which clock it is: for a warning about a command's stamp."""
        which = "sim time" if self.get_parameter("use_sim_time").value else "wall time"
        return f"servo_node's clock ({which}, {now_ns / 1e9:.3f} s)"

    def _switch_command_type(
        self, req: ServoCommandType.Request, res: ServoCommandType.Response
    ) -> ServoCommandType.Response:
        """``~/switch_command_type``: joint jog (0), twist (1) or pose (2); another value is refused with a warning
        and the type stays."""
        if core.JOINT_JOG <= req.command_type <= core.POSE:
            self.command_type = int(req.command_type)
        else:
            self._warn_often("switch", f"Unknown command type {req.command_type} requested")
        res.success = req.command_type == self.command_type
        return res

    def _pause_servo(self, req: SetBool.Request, res: SetBool.Response) -> SetBool.Response:
        """``~/pause_servo``: pause or resume; resuming starts from the measured state (the commands sent before the
        pause are forgotten)."""
        if self.paused == req.data:
            res.success, res.message = True, "Requested pause state is already active."
            self.get_logger().info(res.message)
            return res
        with self._lock:
            self.paused = bool(req.data)
            if not self.paused:
                self._window.clear()
                self._last_commanded = None
        res.success = True
        res.message = "Servoing disabled" if self.paused else "Servoing enabled"
        return res

    # ------------------------------------------------------------------ the loop
    def _current(self) -> np.ndarray | None:
        """The move group's joint positions from the latest ``/joint_states``, in the group's order; None until
        every joint has been heard."""
        names = self.kinematics.joint_names
        if not all(n in self._joints for n in names):
            return None
        return np.array([self._joints[n] for n in names])

    def _cycle(self) -> None:
        """One servo cycle on the node's clock (sim time under ``use_sim_time``): from the state last commanded
        (while its trajectory is still ahead) or the measured one, the newest command becomes the next joint
        step, scaled by the time since the last cycle; it is published as a one-point trajectory (or
        positions/velocities), and the status code goes on ``~/status``. An invalid or stale command halts at the
        measured state."""
        with self._lock:
            measured = self._current()
            if measured is None:
                if not self._waiting_said:
                    self.get_logger().info("Waiting to receive robot state update.")
                    self._waiting_said = True
                return
            if self.paused:
                return
            now = self.get_clock().now().nanoseconds
            if self._last_cycle_ns is not None and now < self._last_cycle_ns:
                # the clock went back (a simulation reset): the window's states belong to the old time line
                self._window.clear()
                self._last_commanded = self._last_cycle_ns = None
            use_trajectory = self.p["command_out_type"] == OUT_TYPES[0]
            if use_trajectory and self._window and self._window[-1].stamp_ns > now:
                current = _State(self._window[-1].positions.copy(), self._window[-1].velocities.copy())
            else:
                self._window.clear()
                current = _State(measured, np.zeros(len(measured)))
            # the time since the last cycle, when the clock moved further than a period (sim time stepped in
            # chunks: the timer then fires once per chunk), so a command means the same motion per sim second
            period = self.settings.publish_period
            if self._last_cycle_ns is not None:
                elapsed = (now - self._last_cycle_ns) / 1e9
                period = min(max(period, elapsed), MAX_CYCLE_PERIODS * period)
            self._last_cycle_ns = now
            self.core.period = period
            step = self._next(current, now)
            if step is not None and step.status not in (core.INVALID, 5):  # 5: HALT_FOR_COLLISION
                state = _State(step.positions, step.velocities)
                if use_trajectory:
                    self._slide(state, now)
                    msg = self._trajectory()
                    if msg is not None:
                        self._out.publish(msg)
                else:
                    self._out.publish(self._multi_array(state))
                self._last_commanded = state
            else:
                state = _State(measured, np.zeros(len(measured)))
                self._last_commanded = state
                self._slide(state, now)
            code = step.status if step is not None else core.NO_WARNING
            self._status_pub.publish(ServoStatus(code=code, message=core.STATUS_MESSAGES[code]))

    def _stale(self, kind: int, now_ns: int) -> bool:
        """servo_node.cpp's rule: the command is at least ``incoming_command_timeout`` old. Its age is negative only
        when the clock went back past it (a simulation reset): a command of the old time line is stale too."""
        age = now_ns - self._stamps[kind]
        return age < 0 or age >= self.p["incoming_command_timeout"] * 1e9

    def _next(self, current: _State, now_ns: int) -> core.ServoStep | None:
        """servo_node.cpp's dispatch: the expected type's new command, else a warning for another type."""
        kind = self.command_type
        if not self._new[kind]:
            if any(self._new.values()):
                for k in self._new:
                    self._new[k] = False
                self._warn_often("type", "Command type has not been set, cannot accept input")
            return None
        for k in self._new:  # the other types that arrived meanwhile are rejected
            if k != kind:
                self._new[k] = False
        msg = self._latest[kind]
        if self._stale(kind, now_ns):
            return self._halt()
        q = current.positions
        if isinstance(msg, JointJog):  # _latest[kind] holds its kind's class: JOINT_JOG's, TWIST's, POSE's
            if list(msg.displacements):
                self._warn_often(
                    "displacements", "Joint jog command displacements field is not yet supported, ignoring."
                )
                msg.displacements = []  # servo_node.cpp: once per message, not once per cycle
            status, delta, warning = self.core.joint_jog(list(msg.joint_names), list(msg.velocities))
        elif isinstance(msg, TwistStamped):
            status, delta, warning = self._twist_delta(q, msg)
        else:
            status, delta, warning = self._pose_delta(q, msg)
        step = self.core.next_state(q, status, delta, kind, warning)
        if step.warning:
            self._warn_often(f"command type {kind}, status {step.status}", step.warning)
        if step.status == core.INVALID:
            self._new[kind] = False  # stop trying this message
        return step

    def _twist_delta(self, q: np.ndarray, msg: TwistStamped) -> tuple[int, np.ndarray, str]:
        """A twist command's joint step: in range (unitless), brought to the planning frame (an unknown frame is
        INVALID with MoveIt's message), then through the Jacobian."""
        t = msg.twist
        twist = [t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z]
        if self.core.out_of_range(twist):
            return core.INVALID, np.zeros(len(q)), core.UNITLESS_RANGE
        moved = self.core.twist_in_planning_frame(q, msg.header.frame_id, twist, self._joints)
        if moved is None:
            return core.INVALID, np.zeros(len(q)), "Could not transform twist command to planning frame."
        return self.core.twist(q, moved, self._joints)

    def _pose_delta(self, q: np.ndarray, msg: PoseStamped) -> tuple[int, np.ndarray, str]:
        """A pose command's joint step: the pose must be in the planning frame, finite and a unit quaternion
        (MoveIt's checks), else the step is INVALID with MoveIt's message."""
        frame = self.kinematics.planning_frame
        if msg.header.frame_id != frame:
            return core.INVALID, np.zeros(len(q)), f"Command frame is: {msg.header.frame_id} expected: {frame}"
        p, o = msg.pose.position, msg.pose.orientation
        values = [p.x, p.y, p.z, o.x, o.y, o.z, o.w]
        if not all(math.isfinite(v) for v in values) or abs(math.sqrt(o.x**2 + o.y**2 + o.z**2 + o.w**2) - 1) > 1e-3:
            return core.INVALID, np.zeros(len(q)), "Invalid pose command."
        return self.core.pose(q, pose_matrix(msg.pose), self._joints)

    def _halt(self) -> core.ServoStep | None:
        """servo.cpp smoothHalt: the last commanded positions with no velocity, until the robot has stopped."""
        last = self._last_commanded
        if last is None or bool(np.all(np.abs(last.velocities) < STOPPED_VELOCITY_EPS)):
            for k in self._new:
                self._new[k] = False
            return None
        return core.ServoStep(core.NO_WARNING, last.positions.copy(), np.zeros(len(last.positions)))

    # ------------------------------------------------------------------ outputs
    def _slide(self, state: _State, now_ns: int) -> None:
        """common.cpp updateSlidingWindow."""
        latency = int(self.p["max_expected_latency"] * 1e9)
        state.stamp_ns = now_ns + latency
        w = self._window
        while w and w[0].stamp_ns < now_ns - latency:
            w.popleft()
        while w and w[-1].stamp_ns == state.stamp_ns:
            w.pop()
        if len(w) >= 2:
            last, before = w[-1], w[-2]
            direction_1 = np.sign(before.positions - last.positions)
            direction_2 = np.sign(state.positions - last.positions)
            changed = np.round(direction_1 - direction_2) == 0.0
            dt1 = (state.stamp_ns - last.stamp_ns) / 1e9
            dt2 = (last.stamp_ns - before.stamp_ns) / 1e9
            for i in range(len(state.positions)):
                if changed[i] or dt1 <= 0 or dt2 <= 0:
                    last.velocities[i] = 0.0
                else:
                    v1 = (state.positions[i] - last.positions[i]) / dt1
                    v2 = (last.positions[i] - before.positions[i]) / dt2
                    last.velocities[i] = v1 if abs(v1) < abs(v2) else v2
                state.velocities[i] = last.velocities[i]
        w.append(state)

    def _trajectory(self) -> JointTrajectory | None:
        """common.cpp composeTrajectoryMessage: every state of the window but the newest."""
        w = self._window
        if len(w) < MIN_POINTS_FOR_TRAJ_MSG:
            return None
        msg = JointTrajectory(joint_names=list(self.kinematics.joint_names))
        start = w[0].stamp_ns
        msg.header.stamp = Time(nanoseconds=start).to_msg()
        points: list[JointTrajectoryPoint] = []
        for state in list(w)[:-1]:
            point = JointTrajectoryPoint()
            if self.p["publish_joint_positions"]:
                point.positions = [float(v) for v in state.positions]
            if self.p["publish_joint_velocities"]:
                point.velocities = [float(v) for v in state.velocities]
            if self.p["publish_joint_accelerations"]:
                point.accelerations = [0.0] * len(state.positions)
            point.time_from_start = Duration(nanoseconds=state.stamp_ns - start).to_msg()
            points.append(point)
        msg.points = points
        return msg

    def _multi_array(self, state: _State) -> Float64MultiArray:
        """common.cpp composeMultiArrayMessage: positions, else velocities."""
        if self.p["publish_joint_positions"]:
            return Float64MultiArray(data=[float(v) for v in state.positions])
        if self.p["publish_joint_velocities"]:
            return Float64MultiArray(data=[float(v) for v in state.velocities])
        return Float64MultiArray(data=[0.0] * len(state.positions))


def servo_main(argv: list[str]) -> int:
    """``servo_node``: MoveIt Servo's node, with ROS arguments (``--ros-args -p ... --params-file ...``);
    ``--urdf``/``--srdf`` name the robot's files when no launch file passes them as parameters."""
    import argparse

    from rclpy.utilities import try_shutdown

    from ..description import read_description_file
    from ._rsp_node import spin_until_interrupted

    parser = argparse.ArgumentParser(prog="servo_node", description="MoveIt Servo's servo_node (gazelle).")
    parser.add_argument("--urdf", help="the robot's URDF or xacro file (else the robot_description parameter)")
    parser.add_argument("--srdf", help="the robot's SRDF file (else robot_description_semantic)")
    ros_args = argv[argv.index("--ros-args") :] if "--ros-args" in argv else []
    args = parser.parse_args(argv[: len(argv) - len(ros_args)] if ros_args else argv)
    overrides = []
    try:
        for flag, name in ((args.urdf, "robot_description"), (args.srdf, "robot_description_semantic")):
            if flag:
                overrides.append(Parameter(name, value=read_description_file(flag)))
    except (OSError, ValueError) as err:
        print(f"servo_node: {err}", file=sys.stderr)
        return 2
    rclpy.init(args=["servo_node", *ros_args])
    try:
        node = ServoNode(overrides)
    except (ValueError, PlanningError) as err:
        print(
            f"[ERROR] [servo_node]: {getattr(err, 'message', err)}; Got invalid parameters, exiting.", file=sys.stderr
        )
        try_shutdown()
        return 1
    spin_until_interrupted(node)  # then the node is destroyed and rclpy shut down
    return 0
