"""``joint_trajectory_controller/JointTrajectoryController`` (ros2_controllers Jazzy's parameters and behaviour).

* Trajectories come from the ``~/follow_joint_trajectory`` action (served by the ROS layer through
  :class:`TrajectoryGoal`) or the ``~/joint_trajectory`` topic; a new one replaces the one running.
* The first segment starts from the joints' state when the trajectory starts (one that replaces a trajectory still
  on its own first segment, waiting for a point ahead, starts from that segment's desired state: see
  ``_state_before``); a header stamp in the future makes that segment end there, so the arm holds meanwhile.
  Between points it interpolates as ``interpolation_method: splines`` does: linear with positions only, cubic with
  velocities, quintic with accelerations. After the last point it holds the last positions.
* Each cycle at time ``t`` commands the trajectory's sample at ``t + 1/update_rate`` (the set point the
  joints should have reached by the next cycle) and measures its errors, path and goal tolerances against
  the sample at ``t``, as Jazzy's controller does since ros2_controllers 4.17 (``update()``:
  ``command_next_`` sampled at ``traj_time_ + update_period_``, ``state_desired_`` at ``traj_time_``).
* Position commands are clamped to the joints' position limits (the URDF's ``<limit lower upper>``), as
  ros2_control's joint limiter would with ``enforce_command_limits``; a trajectory past them is warned about once.
* Command interfaces ``position`` (+ ``velocity``, + ``acceleration``), ``velocity`` or ``effort``;
  the last two close the loop with ``gains.<joint>.{p,i,d,ff_velocity_scale}``.
* ``constraints``: ``stopped_velocity_tolerance``, ``goal_time``, ``<joint>.trajectory`` (path) and
  ``<joint>.goal``; a goal's own tolerances override them (0: the default, -1: none). A path
  violation aborts with PATH_TOLERANCE_VIOLATED and holds where the joints are; missing the goal
  by more than ``goal_time`` after the end aborts with GOAL_TOLERANCE_VIOLATED.
* ``cmd_timeout`` (above ``goal_time``, else switched off with Jazzy's warning): that long after the last
  point, "Aborted due to command timeout" and a hold where the joints are.
* ``~/controller_state`` (control_msgs/JointTrajectoryControllerState) every cycle.
"""

from __future__ import annotations

import functools
import math
import threading
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .._bus import MsgType
from .._payloads import JointTrajectory, TrajectoryControllerState, TrajectoryPoint
from ._controller import Controller, GoalState, values_getter, values_or_zero
from ._goal import TrajectoryGoal as TrajectoryGoal
from ._goal import TrajectoryResult as TrajectoryResult
from ._hardware import ControlError
from ._segments import _Segmented
from ._tolerances import FLOAT_EPSILON, Tolerance, violates

_ALLOWED_COMMANDS = (
    ("position",),
    ("position", "velocity"),
    ("position", "velocity", "acceleration"),
    ("velocity",),
    ("effort",),
)


@dataclass(frozen=True)
class TrajectoryBlock:
    """The references of a planned block of cycles (rows: cycles; columns: the controller's joints)."""

    times: np.ndarray
    des_p: np.ndarray
    des_v: np.ndarray
    des_a: np.ndarray
    cmd_p: np.ndarray
    """The positions commanded at each cycle: the samples one controller period later."""
    cmd_v: np.ndarray
    """The velocities commanded with them (where the velocity interface is claimed too)."""
    tolerances: dict[str, tuple[float, float, np.ndarray, np.ndarray]] | None
    """Per joint with a path tolerance: (position, velocity, the position and velocity reference per cycle)."""


class JointTrajectoryController(Controller):
    """See the module docstring."""

    type_name = "joint_trajectory_controller/JointTrajectoryController"
    action_type = "control_msgs/action/FollowJointTrajectory"
    read_only_parameters = frozenset(
        {
            "joints",
            "command_joints",
            "command_interfaces",
            "state_interfaces",
            "open_loop_control",
            "interpolate_from_desired_state",
            "action_monitor_rate",
            "interpolation_method",
            "constraints.decelerate_on_cancel",
        }
    )
    """joint_trajectory_controller_parameters.yaml's ``read_only`` parameters (ros2_controllers jazzy)."""

    def on_configure(self) -> None:
        """Read Jazzy's parameters: ``joints``, the command interface combination (refused unless it is one the real
        controller accepts), the state interfaces (position required), ``allow_partial_joints_goal``,
        ``open_loop_control``, the ``constraints`` and, for velocity or effort commands, the per-joint PID
        ``gains``; declare ``~/joint_trajectory``, ``~/controller_state`` and the ``~/follow_joint_trajectory``
        action (served by the ROS layer)."""
        self.joints = self.string_list("joints")
        if not self.joints:
            raise ControlError(f"controller '{self.name}': 'joints' is empty")
        cmd = tuple(self.string_list("command_interfaces"))
        if cmd not in _ALLOWED_COMMANDS:
            raise ControlError(
                f"controller '{self.name}': command_interfaces {list(cmd)} is not a supported combination "
                f"({'; '.join(', '.join(c) for c in _ALLOWED_COMMANDS)})"
            )
        self.cmd_kinds = cmd
        self.state_kinds = tuple(self.string_list("state_interfaces")) or ("position", "velocity")
        if "position" not in self.state_kinds:
            raise ControlError(f"controller '{self.name}': state_interfaces must include 'position'")
        self.allow_partial = self.param("allow_partial_joints_goal", False, bool)
        self.open_loop = self.param("open_loop_control", False, bool)
        if self.open_loop:
            self.log.warning(  # Jazzy's on_configure
                "[deprecated] 'open_loop_control' parameter is deprecated. Instead, set the feedback gains "
                "to zero and use 'interpolate_from_desired_state' parameter"
            )
        # a new trajectory's first segment starts from the last commanded state instead of the measured one
        self.from_desired = self.param("interpolate_from_desired_state", False, bool) or self.open_loop
        self.allow_nonzero_end_velocity = self.param("allow_nonzero_velocity_at_trajectory_end", False, bool)
        self.allow_integration = self.param("allow_integration_in_goal_trajectories", False, bool)
        self._read_constraints()
        self._read_gains()
        rate = self.update_rate or self.ctx.manager_rate
        # ros2_controllers' update_period_: rclcpp::Duration(0, uint32(1e9 / rate)), whole nanoseconds
        self._lead = int(1.0e9 / rate) / 1.0e9
        self._integral = [0.0] * len(self.joints)
        self._traj: _Segmented | None = None
        self._incoming: tuple[JointTrajectory, TrajectoryGoal | None] | None = None
        self._lock = threading.Lock()
        self._hold: list[float] | None = None
        self._hold_effort: list[float] | None = None
        """The efforts held with :attr:`_hold` after a trajectory that had them ended (an effort interface's
        feedforward, as upstream keeps sampling the last point); None otherwise."""
        self._ended: float | None = None
        """When the trajectory whose last point is held ended (sim s), for ``cmd_timeout``; None while a
        trajectory runs or the joints hold where they were stopped."""
        self._last: tuple | None = None
        self._commanded: tuple[float, list[float], list[float]] | None = None
        """(cycle time, positions, velocities) last commanded: Jazzy's last_commanded_time_/_state_."""
        limits = [self.ctx.position_limits.get(j, (-math.inf, math.inf)) for j in self.joints]
        self._lower, self._upper = [lo for lo, _ in limits], [hi for _, hi in limits]
        self._limited = any(math.isfinite(v) for v in (*self._lower, *self._upper))
        self._pos_keys = [f"{j}/position" for j in self.joints]
        self._vel_keys = [f"{j}/velocity" for j in self.joints]
        self._out_keys = [f"{j}/{self.cmd_kinds[0]}" for j in self.joints]
        self._get_pos = values_getter(self._pos_keys)
        self._get_vel = values_getter(self._vel_keys)
        self._write_velocity = self.cmd_kinds[0] == "position" and "velocity" in self.cmd_kinds
        # compute_error_for_joint (Jazzy): velocity errors only with a velocity state interface and a velocity
        # or effort command interface; otherwise they stay 0, so a position-only controller's velocity
        # tolerances (stopped_velocity_tolerance among them) never fail
        self._velocity_error = "velocity" in self.state_kinds and (
            "velocity" in self.cmd_kinds or "effort" in self.cmd_kinds
        )
        self.subscribe("~/joint_trajectory", MsgType.JOINT_TRAJECTORY, lambda m: self._queue(m, None))
        self._state_pub = self.advertise("~/controller_state", MsgType.TRAJECTORY_CONTROLLER_STATE)
        self.action_name = self.topic("~/follow_joint_trajectory")
        self.ctx.add_component(self)

    def _read_constraints(self) -> None:
        """``constraints`` (``stopped_velocity_tolerance``, ``goal_time``, each joint's ``trajectory`` and
        ``goal``) and ``cmd_timeout``, which Jazzy's on_configure switches off (with its warning) unless it is
        above ``goal_time``: a timeout that would cut a goal's own time short."""
        self.stopped_velocity = self.param("constraints.stopped_velocity_tolerance", 0.01, float)
        self.goal_time = self.param("constraints.goal_time", 0.0, float)
        self.cmd_timeout = self.param("cmd_timeout", 0.0, float)
        if self.cmd_timeout > 0 and not self.cmd_timeout > self.goal_time:
            self.log.warning(
                f"Command timeout must be higher than goal_time tolerance ({self.cmd_timeout:f} vs. {self.goal_time:f})"
            )
            self.cmd_timeout = 0.0
        self.path_tol = {j: Tolerance(self.param(f"constraints.{j}.trajectory", 0.0, float)) for j in self.joints}
        self.goal_tol = {
            j: Tolerance(self.param(f"constraints.{j}.goal", 0.0, float), self.stopped_velocity) for j in self.joints
        }

    def _read_gains(self) -> None:
        """``gains.<joint>.{p,i,d,ff_velocity_scale}``, which close the loop on a velocity or effort command
        interface (a position one ignores them, as upstream's PID adapter exists only for those two)."""
        self.gains = {
            j: (
                self.param(f"gains.{j}.p", 0.0, float),
                self.param(f"gains.{j}.i", 0.0, float),
                self.param(f"gains.{j}.d", 0.0, float),
                self.param(f"gains.{j}.ff_velocity_scale", 0.0, float),
            )
            for j in self.joints
        }
        cmd = self.cmd_kinds
        if cmd in (("velocity",), ("effort",)) and all(g[0] == 0 for g in self.gains.values()):
            self.log.warning(
                f"{self.name}: {cmd[0]} command interface without gains.<joint>.p: only the feed-forward "
                "velocity is commanded"
            )

    def on_parameters_changed(self) -> None:
        """Jazzy's ``update()`` reads its parameters again when they changed (``param_listener_->is_old``): the
        default tolerances (``constraints``, ``cmd_timeout``) and the PID gains, from the next cycle on."""
        if self.state != "unconfigured":
            self._read_constraints()
            self._read_gains()

    def on_cleanup(self) -> None:
        self.ctx.remove_component(self)
        super().on_cleanup()

    def command_interfaces(self) -> list[str]:
        return [f"{j}/{k}" for k in self.cmd_kinds if k != "acceleration" for j in self.joints]

    def state_interfaces(self) -> list[str] | None:
        return [f"{j}/{k}" for k in self.state_kinds for j in self.joints]

    # ------------------------------------------------------------------ goals (from the ROS thread)
    def validate(self, traj: JointTrajectory, now: float | None = None) -> tuple[TrajectoryResult, str] | None:
        """Why a trajectory is refused (code, reason), or None when it is acceptable."""
        if self.state != "active":
            return TrajectoryResult.INVALID_GOAL, f"controller '{self.name}' is not active"
        # the checks of jazzy's validate_trajectory_msg (joint_trajectory_controller.cpp), with its texts (and
        # gazelle's joint list after them, which upstream's log leaves out); the action's goal callback rejects
        # with them and the topic logs them. A joint named twice and a value that is not finite are gazelle's
        # own refusals: upstream would send the NaN to the hardware, or command one joint twice
        if not self.allow_partial and len(traj.joint_names) != len(self.joints):  # upstream counts them
            missing = [j for j in self.joints if j not in traj.joint_names]
            return (
                TrajectoryResult.INVALID_JOINTS,
                f"Joints on incoming trajectory don't match the controller joints. (missing: {missing}; "
                "allow_partial_joints_goal is false)",
            )
        if not traj.joint_names:
            return TrajectoryResult.INVALID_JOINTS, "Empty joint names on incoming trajectory."
        if not traj.points:
            return TrajectoryResult.INVALID_GOAL, "Empty trajectory received."
        unknown = [j for j in traj.joint_names if j not in self.joints]
        if unknown:
            return (
                TrajectoryResult.INVALID_JOINTS,
                f"Incoming joint {unknown[0]} doesn't match the controller's joints. ('{self.name}' has {self.joints})",
            )
        if len(set(traj.joint_names)) != len(traj.joint_names):
            return TrajectoryResult.INVALID_JOINTS, "a joint is named twice"
        n = len(traj.joint_names)
        if not self.allow_nonzero_end_velocity:  # Jazzy's default: a trajectory must end at rest
            for name, v in zip(traj.joint_names, traj.points[-1].velocities):
                if abs(v) > FLOAT_EPSILON:
                    return (
                        TrajectoryResult.INVALID_GOAL,
                        f"Velocity of last trajectory point of joint {name} is not zero: {v:.15f} "
                        "(allow_nonzero_velocity_at_trajectory_end is false)",
                    )
        last = -math.inf
        for i, p in enumerate(traj.points):
            why = self._point_fields(i, p, n)
            if why is not None:
                return TrajectoryResult.INVALID_GOAL, why
            for label, values in (("velocities", p.velocities), ("accelerations", p.accelerations)):
                if values and len(values) != n:
                    return TrajectoryResult.INVALID_GOAL, _size_mismatch(n, label, len(values), i)
            if not all(math.isfinite(v) for v in (*p.positions, *p.velocities, *p.accelerations)):
                return TrajectoryResult.INVALID_GOAL, f"point {i} has a value that is not finite"
            if p.time_from_start_sec <= last:
                return (
                    TrajectoryResult.INVALID_GOAL,
                    f"Time between points {i - 1} and {i} is not strictly increasing, it is {last:f} and "
                    f"{p.time_from_start_sec:f} respectively",
                )
            last = p.time_from_start_sec
        if now is not None and traj.stamp_sec > 0 and traj.points:
            if traj.stamp_sec + traj.points[-1].time_from_start_sec < now:
                return (
                    TrajectoryResult.OLD_HEADER_TIMESTAMP,
                    "the trajectory ended before it arrived (header stamp in the past)",
                )
        return None

    def _point_fields(self, i: int, p: TrajectoryPoint, n: int) -> str | None:
        """Why point ``i``'s fields are refused (None: they are fine). Positions are required for every joint
        unless ``allow_integration_in_goal_trajectories`` (then a point needs one of positions, velocities or
        accelerations; gazelle integrates no positions, so only a velocity or effort controller may leave them
        out); efforts only for an effort controller (jazzy's rule)."""
        if "effort" not in self.cmd_kinds and p.effort:
            return (
                "Trajectories with effort fields are only supported for controllers using the 'effort' command "
                "interface."
            )
        if not p.positions and self.allow_integration:
            if not (p.velocities or p.accelerations):
                return "The given trajectory has no position, velocity, or acceleration points."
            if self.cmd_kinds not in (("velocity",), ("effort",)):
                return f"point {i} has no positions: gazelle integrates positions only for velocity or effort commands"
        elif len(p.positions) != n:
            return _size_mismatch(n, "positions", len(p.positions), i)
        return None

    def submit(self, goal: TrajectoryGoal) -> None:
        """Run ``goal`` from the next cycle (replacing whatever runs)."""
        self._queue(goal.trajectory, goal)

    def _queue(self, traj: JointTrajectory, goal: TrajectoryGoal | None) -> None:
        """Hand a trajectory to the next cycle (from the topic: checked here, and refused with a log line as the
        real one does; from the action: already checked). A trajectory still waiting is replaced, and its goal
        aborted."""
        if goal is None:
            why = self.validate(traj)
            if why is not None:
                self.log.error(f"{self.name}: trajectory on ~/joint_trajectory refused: {why[1]}")
                return
        with self._lock:
            old = self._incoming
            self._incoming = (traj, goal)
        if old is not None and old[1] is not None:
            old[1].finish(GoalState.ABORTED, TrajectoryResult.INVALID_GOAL, _preempted_by(goal))

    def cancel(self, goal: TrajectoryGoal) -> None:
        """Stop ``goal`` (the joints hold where they are)."""
        goal.finish(GoalState.CANCELED, TrajectoryResult.SUCCESSFUL, "canceled")

    # ------------------------------------------------------------------ the cycle
    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Going active: hold the joints where they are (no jump), with a fresh integral; without velocity state
        interfaces the velocity error reads zero velocities."""
        missing = [s for s in self.state_interfaces() or [] if s not in states]
        if missing:
            raise ControlError(f"controller '{self.name}': the hardware has no state interface {', '.join(missing)}")
        self._traj, self._ended = None, None
        self._commanded = None
        self._hold = [states[f"{j}/position"] for j in self.joints]
        self._hold_effort = None
        self._integral = [0.0] * len(self.joints)
        if not all(k in states for k in self._vel_keys):
            self._get_vel = functools.partial(values_or_zero, tuple(self._vel_keys))

    def on_deactivate(self) -> None:
        """Going inactive aborts the goal in progress (INVALID_GOAL, naming the controller) and drops the
        trajectory."""
        traj = self._traj
        if traj is not None and traj.goal is not None:
            traj.goal.finish(
                GoalState.ABORTED, TrajectoryResult.INVALID_GOAL, f"controller '{self.name}' was deactivated"
            )
        self._traj = None

    def _start(
        self,
        traj: JointTrajectory,
        goal: TrajectoryGoal | None,
        t: float,
        actual: list[float],
        actual_v: Sequence[float],
    ) -> None:
        """Start ``traj`` at cycle time ``t``, as Jazzy's Trajectory does (trajectory.cpp
        ``set_point_before_trajectory_msg`` and ``sample``): times are absolute (the header stamp, or now when
        it is 0); while the first point is ahead, a first segment runs to it from the state before the
        trajectory: the joints' measured positions and velocities at ``t``, or, with
        ``interpolate_from_desired_state`` (or the deprecated ``open_loop_control``), the state last commanded
        and its cycle's time. A trajectory whose first point is already past (a stamp in the past: MoveIt
        Servo's trajectories start ``max_expected_latency`` back) is sampled between its own points, the
        measured state unused. A joint the trajectory leaves out (a partial goal) keeps the position it was
        held at. An empty trajectory stops the one running and holds where the joints are."""
        old = self._traj
        if old is not None and old.goal is not None and old.goal is not goal:
            old.goal.finish(GoalState.ABORTED, TrajectoryResult.INVALID_GOAL, _preempted_by(goal))
        if not traj.points:
            self._hold_here(actual)
            if goal is not None:
                goal.finish(GoalState.SUCCEEDED, TrajectoryResult.SUCCESSFUL, "empty trajectory: holding")
            return
        start = traj.stamp_sec if traj.stamp_sec > 0 else t
        if goal is None and traj.stamp_sec > 0 and start + traj.points[-1].time_from_start_sec < t:
            # validate_trajectory_msg (Jazzy) refuses a topic trajectory that ends before the controller's now:
            # sampled, it would be a jump to its last point; the one running goes on
            end = start + traj.points[-1].time_from_start_sec
            self.log.error(f"Received trajectory with non-zero start time ({start:f}) that ends in the past ({end:f})")
            return
        index = {j: i for i, j in enumerate(traj.joint_names)}
        base = self._hold if self._hold is not None else actual
        n = len(self.joints)
        before_t, before_p, before_v = self._state_before(old, t, actual, actual_v)
        times: list[float] = []
        pos: list[list[float]] = []
        vel: list[list[float]] = []
        acc: list[list[float]] = []
        if start + traj.points[0].time_from_start_sec > before_t:
            times, pos, vel, acc = [before_t], [list(before_p)], [list(before_v)], [[0.0] * n]
        have_vel = all(p.velocities for p in traj.points)
        have_acc = have_vel and all(p.accelerations for p in traj.points)
        have_eff = all(p.effort for p in traj.points)  # validate() allows them for an effort interface only
        eff: list[list[float] | None] = [None] * len(times)  # the state before the trajectory has none
        for p in traj.points:
            eff.append([p.effort[index[j]] if j in index and have_eff else 0.0 for j in self.joints])
            times.append(start + p.time_from_start_sec)  # strictly increasing: validate() saw to it
            pos.append([p.positions[index[j]] if j in index else base[k] for k, j in enumerate(self.joints)])
            vel.append([p.velocities[index[j]] if j in index and have_vel else 0.0 for j in self.joints])
            acc.append([p.accelerations[index[j]] if j in index and have_acc else 0.0 for j in self.joints])
        if self._limited:
            self._warn_outside_limits(pos[len(pos) - len(traj.points) :])
        path_tol = None
        if goal is not None:
            tols = [goal.path_tolerance.get(j, self.path_tol[j]) for j in self.joints]
            if any(tol.position > 0 or tol.velocity > 0 for tol in tols):
                path_tol = tols
        self._traj = _Segmented(
            times,
            pos,
            vel if have_vel else None,
            acc if have_acc else None,
            goal,
            path_tol,
            eff if have_eff else None,
            first=len(times) - len(traj.points),
        )
        self._hold, self._hold_effort, self._ended = pos[-1], None, None
        if goal is not None:
            goal.status = GoalState.EXECUTING

    def _warn_outside_limits(self, points: list[list[float]]) -> None:
        """One warning for a trajectory that puts a joint outside its position limits (the first such point and
        joint): its position commands are clamped to them (see :meth:`_write`)."""
        for i, row in enumerate(points):
            for j, p, lo, hi in zip(self.joints, row, self._lower, self._upper, strict=True):
                if not lo <= p <= hi:
                    self.log.warning(
                        f"{self.name}: trajectory point {i} puts {j} at {p:.6g}, outside its limits "
                        f"[{lo:.6g}, {hi:.6g}]: its position commands are clamped to them"
                    )
                    return

    def _state_before(
        self, old: _Segmented | None, t: float, actual: list[float], actual_v: Sequence[float]
    ) -> tuple[float, list[float], list[float]]:
        """(time, positions, velocities) a new trajectory's first segment starts from.

        Jazzy's ``update()`` sets the point before the trajectory from the state interfaces (``state_current_``),
        or, with ``interpolate_from_desired_state``, from the state last commanded and its cycle's time. One
        case differs, and says why: a trajectory that replaces one the controller is still on the first segment
        of (on its way to, or waiting for, its first point: a header stamp in the future, a single point ahead)
        starts from that segment's desired state now, as the replaced one never reached its own points. On the
        mock hardware MoveIt's configurations run, the state interfaces mirror the commands, so upstream does
        the same there; on gazelle's simulated servos the measured state lags the command, and a stream of such
        replacements at the controller's rate (MoveIt Servo stamping wall-clock time against a sim-time
        controller, a teleop stream of single points) restarting each cycle from the measured position and
        velocity fed the servo's lag back into its own command: the Panda drifted past its joint limits."""
        if old is not None and old.on_first_segment(t):
            p, v, _a = old.sample(t)
            return t, p, v
        if self.from_desired and self._commanded is not None:
            return self._commanded
        return t, list(actual), list(actual_v)

    def _intake(self, t: float, actual: list[float], actual_v: Sequence[float]) -> _Segmented | None:
        """Start a trajectory that came in since the last cycle; stop one canceled from outside."""
        if self._incoming is not None:  # (a plain read first: no lock taken on the usual cycle)
            with self._lock:
                incoming, self._incoming = self._incoming, None
            if incoming is not None:
                self._start(incoming[0], incoming[1], t, actual, actual_v)
        traj = self._traj
        if traj is not None and traj.goal is not None and traj.goal.done.is_set():
            # canceled (or ended) from outside: hold where the joints are
            self._hold_here(actual)
            traj = None
        return traj

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle: the desired state from the running trajectory (or the hold position), the errors against the
        measured state, the commands written, the goal checked against its tolerances, and ``~/controller_state``
        published while it has a subscriber."""
        joints = self.joints
        actual = list(self._get_pos(states))
        actual_v = self._get_vel(states)
        traj = self._intake(t, actual, actual_v)
        end = traj.times[-1] if traj is not None else self._ended
        if self.cmd_timeout > 0 and end is not None and t - end > self.cmd_timeout:
            traj = self._command_timeout(actual)
        if traj is not None:
            des_p, des_v, des_a = traj.sample(t)
            cmd_p, cmd_v, _cmd_a = traj.sample(t + self._lead)  # where the joints should be next cycle
        else:
            hold = self._hold if self._hold is not None else actual
            des_p, des_v, des_a = list(hold), [0.0] * len(joints), [0.0] * len(joints)
            cmd_p, cmd_v = des_p, des_v
        err_p = [d - a for d, a in zip(des_p, actual, strict=True)]
        err_v = self._velocity_errors(des_v, actual_v)
        # an effort interface adds the trajectory's efforts of the next cycle as feedforward (command_next_)
        ff = traj.effort(t + self._lead) if traj is not None and traj.eff is not None else self._hold_effort
        self._write(commands, cmd_p, cmd_v, err_p, err_v, period, ff)
        self._commanded = (t, list(cmd_p), list(cmd_v))
        if traj is not None and traj.goal is not None:
            self._check(traj, t, err_p, err_v, actual)
        elif traj is not None and t >= traj.times[-1]:
            self._hold_last(traj, t)  # a topic trajectory ran out
        if self._state_pub.wanted:
            self._state_pub.publish(self._state(t, des_p, des_v, des_a, actual, actual_v, err_p, err_v, commands))
        self._last = (t, des_p, des_v, des_a, actual, actual_v, err_p, err_v, commands)

    # ------------------------------------------------------------------ planned blocks of cycles
    def plan_block(self, times: np.ndarray, states: dict[str, float]) -> TrajectoryBlock | None:
        """The cycles at ``times`` planned at once (the first is now): the trajectory's samples, which
        :meth:`update` would command cycle after cycle, and the goal's path tolerances. None when the
        next cycle must run in Python: other command interfaces than position (+ velocity), a
        ``~/controller_state`` listener, or a goal past its trajectory's end (its goal check runs each
        cycle). A goal's block ends before its trajectory's end."""
        if self.cmd_kinds[0] != "position" or self._state_pub.wanted:
            return None
        if self.cmd_timeout > 0 and (self._traj is not None or self._incoming is not None or self._ended is not None):
            return None  # a command timeout may fall inside the block: its check runs each cycle
        traj = self._intake(float(times[0]), list(self._get_pos(states)), self._get_vel(states))
        m = len(times)
        if traj is None:
            if self._hold is None:
                return None
            hold = np.asarray(self._hold, dtype=np.float64)
            des_p = np.repeat(hold[None, :], m, axis=0)
            zeros = np.zeros_like(des_p)
            return TrajectoryBlock(times, des_p, zeros, zeros.copy(), self._clamped(des_p), zeros, None)
        if traj.goal is not None:
            m = int(np.searchsorted(times, traj.times[-1], side="left"))
            if m == 0:
                return None
            times = times[:m]
        des_p, des_v, des_a = traj.sample_many(times)
        cmd_p, cmd_v, _cmd_a = traj.sample_many(times + self._lead)  # as update(): the next cycle's set point
        cmd_p = self._clamped(cmd_p)
        tolerances = None
        if traj.goal is not None and traj.path_tolerance is not None:
            tolerances = {
                j: (tol.position, tol.velocity if self._velocity_error else 0.0, des_p[:, k], des_v[:, k])
                for k, (j, tol) in enumerate(zip(self.joints, traj.path_tolerance, strict=True))
            }
        return TrajectoryBlock(times, des_p, des_v, des_a, cmd_p, cmd_v, tolerances)

    def _clamped(self, positions: np.ndarray) -> np.ndarray:
        """Planned position commands (rows: cycles) within the joints' limits, as :meth:`_write` clamps them."""
        if not self._limited:
            return positions
        return np.minimum(np.maximum(positions, np.asarray(self._lower)), np.asarray(self._upper))

    def interrupted(self) -> bool:
        """Whether a planned block must end for this controller: a new trajectory came in, or the running
        goal was canceled (read from the simulation thread between blocks; set from the ROS thread)."""
        if self._incoming is not None:
            return True
        traj = self._traj
        return traj is not None and traj.goal is not None and traj.goal.done.is_set()

    def finish_block(
        self, block: TrajectoryBlock, n: int, actual: np.ndarray, actual_v: np.ndarray, commands: dict[str, float]
    ) -> None:
        """Take back the first ``n`` cycles of ``block`` as the world ran them (``actual``, ``actual_v``:
        the joints' state at each, rows), as if :meth:`update` had run each: the last commands, the last
        state, a topic trajectory run out; a path tolerance left on the last cycle aborts the goal."""
        k = n - 1
        t = float(block.times[k])
        des_p, des_v, des_a = block.des_p[k].tolist(), block.des_v[k].tolist(), block.des_a[k].tolist()
        act, act_v = actual[k].tolist(), tuple(actual_v[k].tolist())
        err_p = [d - a for d, a in zip(des_p, act, strict=True)]
        err_v = self._velocity_errors(des_v, act_v)
        cmd_p, cmd_v = block.cmd_p[k].tolist(), block.cmd_v[k].tolist()
        self._write(commands, cmd_p, cmd_v, err_p, err_v, 0.0)
        self._commanded = (t, cmd_p, cmd_v)
        traj = self._traj
        if traj is not None and traj.goal is not None and t < traj.times[-1]:
            self._check(traj, t, err_p, err_v, act)
        elif traj is not None and traj.goal is None and t >= traj.times[-1]:
            self._hold_last(traj, t)
        self._last = (t, des_p, des_v, des_a, act, act_v, err_p, err_v, commands)

    @property
    def last_state(self) -> TrajectoryControllerState | None:
        """The reference, feedback and error of the last cycle (what the action's feedback reports)."""
        last = self._last
        return self._state(*last) if last is not None else None

    def _state(
        self,
        t: float,
        des_p: list[float],
        des_v: list[float],
        des_a: list[float],
        actual: list[float],
        actual_v: Sequence[float],
        err_p: list[float],
        err_v: list[float],
        commands: dict[str, float],
    ) -> TrajectoryControllerState:
        """control_msgs/JointTrajectoryControllerState of this cycle: reference (desired), feedback (measured),
        error, and output (what was commanded; NaN for a joint not commanded)."""
        return TrajectoryControllerState(
            t,
            tuple(self.joints),
            TrajectoryPoint(0.0, tuple(des_p), tuple(des_v), tuple(des_a)),
            TrajectoryPoint(0.0, tuple(actual), tuple(actual_v)),
            TrajectoryPoint(0.0, tuple(err_p), tuple(err_v)),
            TrajectoryPoint(0.0, tuple(commands.get(k, math.nan) for k in self._out_keys)),
        )

    def _write(
        self,
        commands: dict[str, float],
        des_p: list[float],
        des_v: list[float],
        err_p: list[float],
        err_v: list[float],
        period: float,
        effort: list[float] | None = None,
    ) -> None:
        """The commands of one cycle from the set point ``des_p``, ``des_v`` (the next cycle's sample) and the
        errors at this one: with position interfaces, the set point's positions (and velocities, when
        claimed), which the simulated hardware's servos follow, each clamped to its joint's position limits
        (the description's ``<limit lower upper>``: what ros2_control's joint limiter, ``joint_limits``'
        ``compute_position_limits``, saturates a position command to when the manager's
        ``enforce_command_limits`` is on; gazelle's trajectory controller always does, so no trajectory sent
        to it commands a joint past its range; the limiter's narrowing by the velocity limit is not applied);
        with velocity or effort interfaces,
        ``ff_velocity_scale·v_next + p·e + i·∫e + d·ė`` per joint, as the real controller's PID, plus, on an
        effort interface, the trajectory's ``effort`` at the next cycle (Jazzy's ``update()`` adds
        ``command_next_.effort`` when it has an effort command interface)."""
        kinds = self.cmd_kinds
        if kinds[0] == "position":
            if self._limited:
                des_p = [min(max(p, lo), hi) for p, lo, hi in zip(des_p, self._lower, self._upper, strict=True)]
            commands.update(zip(self._out_keys, des_p))
            if self._write_velocity:
                commands.update(zip(self._vel_keys, des_v))
            return
        for k, j in enumerate(self.joints):
            p, i, d, ff = self.gains[j]
            self._integral[k] += err_p[k] * period
            u = ff * des_v[k] + p * err_p[k] + i * self._integral[k] + d * err_v[k]
            if effort is not None and kinds[0] == "effort":
                u += effort[k]
            commands[self._out_keys[k]] = u

    def _hold_here(self, actual: list[float]) -> None:
        """Drop the trajectory and hold where the joints are (an abort, a cancel, a timeout, an empty
        trajectory): Jazzy's ``set_hold_position``, which carries no efforts and no end to time out from."""
        self._traj, self._hold, self._hold_effort, self._ended = None, list(actual), None, None

    def _hold_last(self, traj: _Segmented, t: float) -> None:
        """A trajectory that ended (a topic one run out, a goal reached): upstream keeps sampling its last
        point, so hold that position (set when it started) with its efforts, and time ``cmd_timeout`` from
        its end."""
        self._traj, self._ended = None, traj.times[-1]
        self._hold_effort = traj.effort(t) if traj.eff is not None else None

    def _command_timeout(self, actual: list[float]) -> None:
        """``cmd_timeout`` seconds after the last point's time (Jazzy ``update()``): "Aborted due to command
        timeout", and the joints hold where they are now (``set_hold_position``), the trajectory and its
        efforts dropped. A goal still waiting for its goal tolerances (``goal_time`` 0) then ends as
        upstream's next cycle ends it: holding turns the tolerance checks off, so it reports success."""
        self.log.warning("Aborted due to command timeout")
        traj = self._traj
        self._hold_here(actual)
        if traj is not None and traj.goal is not None and not traj.goal.done.is_set():
            self.log.info("Goal reached, success!")
            traj.goal.finish(GoalState.SUCCEEDED, TrajectoryResult.SUCCESSFUL, "Goal successfully reached!")

    def _velocity_errors(self, des_v: Sequence[float], actual_v: Sequence[float]) -> list[float]:
        """Desired minus measured velocities, or zeros where Jazzy's controller does not compute them (see
        ``_velocity_error``)."""
        if not self._velocity_error:
            return [0.0] * len(des_v)
        return [d - a for d, a in zip(des_v, actual_v, strict=True)]

    def _check(self, traj: _Segmented, t: float, err_p: list[float], err_v: list[float], actual: list[float]) -> None:
        """The goal's tolerances at cycle time ``t``: before the end, the path tolerance (a violation aborts with
        PATH_TOLERANCE_VIOLATED and holds where the joints are); after it, success once every joint is within its
        goal tolerance, or GOAL_TOLERANCE_VIOLATED once ``goal_time`` (the goal's, else the controller's) has
        passed with some joint outside (0: wait for ever, as Jazzy does). The result strings and log lines are
        Jazzy's (``update()``; the per-joint lines are tolerances.hpp's ``check_state_tolerance_per_joint``)."""
        goal = traj.goal
        assert goal is not None
        end = traj.times[-1]
        if t < end:
            left = [k for k, tol in enumerate(traj.path_tolerance or ()) if violates(tol, err_p[k], err_v[k])]
            if left:
                assert traj.path_tolerance is not None
                self._log_tolerance_failures(left, traj.path_tolerance, err_p, err_v)
                self.log.warning("Aborted due to state tolerance violation")
                self._hold_here(actual)
                goal.finish(
                    GoalState.ABORTED,
                    TrajectoryResult.PATH_TOLERANCE_VIOLATED,
                    "Aborted due to path tolerance violation",
                )
            return
        tolerances = [goal.goal_tolerance.get(j, self.goal_tol[j]) for j in self.joints]
        outside = [k for k, tol in enumerate(tolerances) if violates(tol, err_p[k], err_v[k])]
        if not outside:
            self._hold_last(traj, t)
            self.log.info("Goal reached, success!")
            goal.finish(GoalState.SUCCEEDED, TrajectoryResult.SUCCESSFUL, "Goal successfully reached!")
            return
        allowed = self.goal_time if goal.goal_time_tolerance is None else goal.goal_time_tolerance
        if allowed > 0 and t - end > allowed:
            self._log_tolerance_failures(outside, tolerances, err_p, err_v)
            # std::to_string(double): six decimals
            text = f"Aborted due to goal_time_tolerance exceeding by {t - end:f} seconds"
            self.log.warning(text)
            self._hold_here(actual)
            goal.finish(GoalState.ABORTED, TrajectoryResult.GOAL_TOLERANCE_VIOLATED, text)

    def _log_tolerance_failures(
        self, joints: list[int], tolerances: Sequence[Tolerance], err_p: list[float], err_v: list[float]
    ) -> None:
        """check_state_tolerance_per_joint's lines (show_errors): the joint's index, then each error over its
        tolerance; gazelle adds the joint's name, which upstream's index leaves to the reader."""
        for k in joints:
            tol = tolerances[k]
            self.log.error(f"State tolerances failed for joint {k} ({self.joints[k]}):")
            if tol.position > 0 and abs(err_p[k]) > tol.position:
                self.log.error(f"Position Error: {err_p[k]:f}, Position Tolerance: {tol.position:f}")
            if tol.velocity > 0 and abs(err_v[k]) > tol.velocity:
                self.log.error(f"Velocity Error: {err_v[k]:f}, Velocity Tolerance: {tol.velocity:f}")


def _size_mismatch(joints: int, field: str, size: int, i: int) -> str:
    """validate_trajectory_point_field's text (Jazzy joint_trajectory_controller.cpp) for a point whose
    ``field`` has ``size`` values where the trajectory names ``joints`` joints."""
    return f"Mismatch between joint_names size ({joints}) and {field} ({size}) at point #{i}."


def _preempted_by(goal: TrajectoryGoal | None) -> str:
    """Why a goal ended when a newer trajectory replaced it. A new goal aborts it as jazzy's
    ``preempt_active_goal`` does (ABORTED, INVALID_GOAL, its text); a trajectory on ``~/joint_trajectory``
    replaces the motion too, and here ends the goal the same way (upstream leaves the goal open, to be judged
    against a trajectory it never sent)."""
    if goal is not None:
        return "Current goal preempted by new incoming action."
    return "Current goal preempted by a trajectory on ~/joint_trajectory."
