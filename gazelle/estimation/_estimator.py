"""robot_localization's state estimation node without ROS (``RosFilter``, ros2 branch, read for its behaviour):
readings in, one cycle at a time out.

* Each input part (``odom0_pose``, ``odom0_twist``, ``imu0_pose``...) takes readings in stamp order: one older
  than the part's last is ignored, and so is one stamped at or before the last ``set_pose`` (at start, 0:
  a reading stamped 0 is never used). A reading becomes a measurement (:class:`MeasurementBuilder`) queued by
  its stamp.
* Each cycle (``frequency`` Hz of the node's clock) fuses the queued measurements stamped up to now, in
  stamp order. When none was queued and the last is ``sensor_timeout`` old (or always, with
  ``predict_to_current_time``), the state is predicted to now.
* The cycle's output is the state at the last measurement's time; it is published only when that time moved
  on since the last publication (unless ``permit_corrected_publication``). The transform is
  ``odom_frame`` -> body when ``world_frame`` is ``odom_frame``; when it is ``map_frame``, ``map`` -> ``odom``
  from the state and the body's heard ``odom`` pose.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Callable

import numpy as np

from ._config import EkfConfig
from ._ekf import Ekf
from ._frames import FrameTree
from ._inputs import MeasurementBuilder
from ._measurement import STATE_SIZE, Measurement
from ._readings import FilterOutput, ImuReading, PoseReading, TwistReading, measured
from ._rigid import Rigid, rotation_from_rpy
from ._sensor_config import SensorConfig

MAX_QUEUED = 10_000
"""Measurements waiting for the clock at most (stamped ahead of it): a reading beyond is dropped."""
MAX_AHEAD_NS = 3600 * 1_000_000_000
"""A reading stamped further than this (an hour) ahead of the node's clock is ignored, and does not become its
input's last: gazelle's guard (upstream would take its stamp as the input's last, and ignore every later
reading of that input as older, however right its clock)."""


class StateEstimator:
    """The filter, its inputs' bookkeeping and one cycle's output (see the module docstring)."""

    def __init__(
        self, cfg: EkfConfig, frames: FrameTree, now_ns: int = 0, clock: Callable[[], int] | None = None
    ) -> None:
        """``now_ns``: the node's time at start; ``clock``: the node's time when a reading arrives (for
        :data:`MAX_AHEAD_NS`; None: no such check)."""
        self.cfg = cfg
        self.clock = clock
        self.frames = frames
        self.ekf = Ekf()
        self.ekf.dynamic_process_noise = cfg.dynamic_process_noise
        self.ekf.control = cfg.control
        self.notes: dict[str, str] = {}
        """Diagnostics by key (the latest text of each), for the node to say."""
        self.builder = MeasurementBuilder(cfg, frames, self.ekf, self.notes.__setitem__)
        self.enabled = not cfg.disabled_at_startup
        """False until the ``enable`` service, with ``disabled_at_startup``: cycles do nothing."""
        self._queue: list[tuple[int, int, Measurement]] = []
        """Measurements waiting for their turn: a heap by (stamp, arrival), so equal stamps keep their order."""
        self._order = itertools.count()
        self._last_message_ns: dict[str, int] = {}
        """Input part -> its last reading's stamp: an older reading is ignored, and the interval of a
        differential input is measured from it."""
        self._last_set_pose_ns = 0
        """Readings stamped at or before this are ignored (the last set_pose; 0 at start)."""
        self._last_published_ns = 0
        """The stamp of the last output: an output is published once per stamp."""
        self._last_diff_ns = 0
        self._last_rates = np.zeros(3)
        self._angular_acceleration_cov = np.zeros((3, 3))
        self._restore()
        if cfg.initial_state is not None:
            # the state before the first measurement; that one sets only the variables it measures
            self.ekf.state = np.array(cfg.initial_state, dtype=float)
        # upstream starts the filter's clock at the node's start, so a timeout prediction has a sane interval
        self.ekf.last_measurement_ns = now_ns

    def _restore(self) -> None:
        """The filter's parameters as configured (after a reset too): the process noise and the initial
        covariance. The initial state is not restored by a reset, as upstream's is not (it sets it once, at
        start); a reset filter is at rest at the origin."""
        if self.cfg.process_noise is not None:
            self.ekf.process_noise = self.cfg.process_noise.copy()
        if self.cfg.initial_covariance is not None:
            self.ekf.covariance = self.cfg.initial_covariance.copy()

    # ------------------------------------------------------------------ inputs
    def _too_early(self, topic: str, stamp_ns: int) -> bool:
        """True (and said) for a reading stamped at or before the last set_pose (0 at start)."""
        if stamp_ns > self._last_set_pose_ns:
            return False
        self.notes[f"{topic}_timestamp"] = (
            f"The {topic} message has a timestamp equal to or before the last filter reset, this message will "
            f"be ignored. This may indicate an empty or bad timestamp. (message time: {stamp_ns * 1e-9:.9f})"
        )
        return True

    def _take(self, topic: str, stamp_ns: int, prepare: Callable[[int], Measurement | None]) -> None:
        """A reading of input part ``topic``: refused when stamped at or before the last set_pose or before the
        part's last reading; else ``prepare(previous stamp)`` makes its measurement, which is queued. A reading
        that gives no measurement (its frame unknown, a differential input's first) still counts as the
        part's last."""
        if self._too_early(topic, stamp_ns):
            return
        if self.clock is not None and stamp_ns > self.clock() + MAX_AHEAD_NS:
            self.notes[f"{topic}_future"] = (
                f"The {topic} message is stamped {stamp_ns * 1e-9:.9f}, more than an hour ahead of the node's "
                "clock: it is ignored"
            )
            return
        last = self._last_message_ns.setdefault(topic, stamp_ns)
        if last > stamp_ns:
            self.notes[f"{topic}_timestamp"] = (
                f"The {topic} message has a timestamp before that of the previous message received, this message "
                f"will be ignored. This may indicate a bad timestamp. (message time: {stamp_ns * 1e-9:.9f})"
            )
            return
        m = prepare(last)
        if m is not None:
            if len(self._queue) >= MAX_QUEUED:
                self.notes["queue"] = f"{MAX_QUEUED} measurements are waiting for the clock; {topic}'s is dropped"
            else:
                heapq.heappush(self._queue, (m.time_ns, next(self._order), m))
        self._last_message_ns[topic] = stamp_ns

    def _pose(self, s: SensorConfig, topic: str, r: PoseReading, target: str, update: np.ndarray, imu: bool) -> None:
        """A pose part (an odometry's, a pose's, an IMU's orientation) through :meth:`_take`, into ``target``."""
        self._take(
            topic,
            r.stamp_ns,
            lambda last: self.builder.pose(
                r,
                topic,
                update,
                s.pose_threshold,
                target=target,
                differential=s.differential,
                relative=s.relative,
                imu=imu,
                last_ns=last,
            ),
        )

    def _twist(self, s: SensorConfig, topic: str, r: TwistReading, update: np.ndarray) -> None:
        """A twist part (an odometry's, a twist's, an IMU's angular velocity) into the body frame."""
        base = self.cfg.base_link_frame
        self._take(topic, r.stamp_ns, lambda _: self.builder.twist(r, topic, update, s.twist_threshold, target=base))

    def odometry(self, s: SensorConfig, pose: PoseReading, twist: TwistReading) -> None:
        """nav_msgs/Odometry: the pose (in its header's frame, taken into the world frame) and the twist (in its
        child frame, taken into the body's), two parts with their own update vectors and thresholds."""
        if self._too_early(s.name, pose.stamp_ns):
            return
        if s.pose_update().any():
            self._pose(s, f"{s.name}_pose", pose, self.cfg.world_frame, s.pose_update(), imu=False)
        if s.twist_update().any():
            self._twist(s, f"{s.name}_twist", twist, s.twist_update())

    def pose(self, s: SensorConfig, reading: PoseReading) -> None:
        """geometry_msgs/PoseWithCovarianceStamped."""
        self._pose(s, s.name, reading, self.cfg.world_frame, s.pose_update(), imu=False)

    def twist(self, s: SensorConfig, reading: TwistReading) -> None:
        """geometry_msgs/TwistWithCovarianceStamped."""
        self._twist(s, s.name, reading, s.twist_update())

    def imu(self, s: SensorConfig, r: ImuReading) -> None:
        """sensor_msgs/Imu: orientation, angular velocity and linear acceleration, each when configured and
        measured (a first covariance element of -1 says it is not). The three are separate parts, each with its
        own order of stamps and its own rejection threshold, as upstream splits the message: the orientation
        is a pose in the body frame (corrected for the mount), the angular velocity a twist, the acceleration
        its own measurement."""
        if self._too_early(s.name, r.stamp_ns):
            return
        if s.pose_update().any() and measured(r.orientation_covariance):
            self._pose(s, f"{s.name}_pose", r.pose(), self.cfg.base_link_frame, s.pose_update(), imu=True)
        if s.twist_update().any() and measured(r.angular_velocity_covariance):
            self._twist(s, f"{s.name}_twist", r.twist(), s.twist_update())
        if s.acceleration_update().any() and measured(r.linear_acceleration_covariance):
            topic = f"{s.name}_acceleration"
            update, threshold = s.acceleration_update(), s.acceleration_threshold
            self._take(
                topic,
                r.stamp_ns,
                lambda _: self.builder.acceleration(
                    r, topic, update, threshold, relative=s.relative, gravity=s.remove_gravity
                ),
            )

    def command(self, twist: tuple[float, ...], now_ns: int) -> None:
        """A ``cmd_vel`` (body twist: vx, vy, vz, wx, wy, wz), stamped now (``use_control``)."""
        if self.ekf.control is not None:
            # upstream stamps a cmd_vel with the node's time on arrival: the control timeout counts from it
            self.ekf.control.latest = np.array(twist, dtype=float)
            self.ekf.control.latest_ns = now_ns

    # ------------------------------------------------------------------ services
    def reset(self) -> None:
        """robot_localization's ``reset`` service: every measurement and memory forgotten, the filter
        uninitialized at the origin with its configured covariances."""
        self._queue.clear()
        self._last_message_ns.clear()
        self.builder.reset()
        self._last_set_pose_ns = self._last_published_ns = self._last_diff_ns = 0
        self.ekf.reset()
        self._restore()

    def set_pose(self, reading: PoseReading, now_ns: int) -> None:
        """The ``set_pose`` topic: the state becomes the pose (in the world frame; velocities and accelerations
        0), its covariance the reading's (1e-6 elsewhere); readings stamped up to the pose's stamp are ignored."""
        self._queue.clear()
        self.builder.reset()
        self._last_set_pose_ns = reading.stamp_ns
        everything = np.ones(STATE_SIZE, dtype=bool)
        m = self.builder.pose(reading, "set_pose", everything, np.inf, target=self.cfg.world_frame)
        state = np.zeros(STATE_SIZE)
        covariance = np.eye(STATE_SIZE) * 1e-6
        if m is not None:
            state = m.values.copy()
            covariance[0:6, 0:6] = m.covariance[0:6, 0:6]
        # as upstream: the filter keeps its initialized flag (an uninitialized one is still set wholly by its
        # first measurement) and its time is now, so the next prediction starts from the pose
        self.ekf.state = state
        self.ekf.covariance = covariance
        self.ekf.last_measurement_ns = now_ns

    # ------------------------------------------------------------------ the cycle
    def _integrate(self, now_ns: int) -> None:
        """Fuse what is due by ``now_ns``; predict to now after a sensor timeout (``integrateMeasurements``)."""
        ekf = self.ekf
        predict_now = self.cfg.predict_to_current_time
        if self._queue:
            # measurements stamped later than now wait for a later cycle (a sensor whose clock runs ahead)
            while self._queue and self._queue[0][0] <= now_ns:
                ekf.process(heapq.heappop(self._queue)[2])
        elif ekf.initialized and now_ns - ekf.last_measurement_ns >= self.cfg.sensor_timeout_ns:
            predict_now = True
        if ekf.initialized and predict_now:
            delta_ns = now_ns - ekf.last_measurement_ns
            if delta_ns > 0:  # never backwards (a clock that went back: upstream would predict back in time)
                ekf.predict(now_ns, delta_ns * 1e-9)
                ekf.last_measurement_ns = now_ns

    def _differentiate(self, now_ns: int) -> None:
        """The angular acceleration from the rates' change since the last cycle (``differentiateMeasurements``):
        the state has no angular acceleration, but an IMU mounted off the body's origin feels it, and
        ``accel/filtered`` reports it; its covariance is the rates' times 2 / dt^2."""
        if not self.ekf.initialized or now_ns <= self._last_diff_ns:
            return
        dt = (now_ns - self._last_diff_ns) * 1e-9
        rates = self.ekf.state[9:12].copy()
        self.builder.angular_acceleration = (rates - self._last_rates) / dt
        self._angular_acceleration_cov = self.ekf.covariance[9:12, 9:12] * 2.0 / (dt * dt)
        self._last_rates = rates
        self._last_diff_ns = now_ns

    def cycle(self, now_ns: int) -> FilterOutput | None:
        """One periodic update at ``now_ns``: what to publish, or None (disabled, not initialized, or nothing new).

        The output's stamp is the filter's time (its last measurement's, or now after a timeout prediction),
        not ``now_ns``: the state is what it was then, and the transform says so."""
        if not self.enabled:
            return None
        self._integrate(now_ns)
        self._differentiate(now_ns)
        ekf = self.ekf
        if not ekf.initialized:
            return None
        stamp = ekf.last_measurement_ns
        # upstream's rule against publishing a state twice at one stamp (tf2 warns of repeated transforms):
        # a cycle with nothing new publishes nothing
        corrected = not self.cfg.permit_corrected_publication and self._last_published_ns >= stamp
        self._last_published_ns = stamp
        if corrected:
            return None
        if not (np.isfinite(ekf.state).all() and np.isfinite(ekf.covariance).all()):
            self.notes["nan"] = (
                "Critical Error, NaNs were detected in the output state of the filter. This was likely due to "
                "poorly coniditioned process, noise, or sensor covariances."
            )
        acceleration = None
        if self.cfg.publish_acceleration:
            # the body's linear acceleration is the state's; the angular, the rates' change (above)
            values = np.concatenate([ekf.state[12:15], self.builder.angular_acceleration])
            cov = np.zeros((6, 6))
            cov[0:3, 0:3] = ekf.covariance[12:15, 12:15]
            cov[3:6, 3:6] = self._angular_acceleration_cov
            acceleration = (values, cov)
        return FilterOutput(
            stamp,
            self.cfg.world_frame,
            self.cfg.base_link_output_frame,
            ekf.state.copy(),
            ekf.covariance.copy(),
            self._transform() if self.cfg.publish_tf else None,
            acceleration,
        )

    def _transform(self) -> tuple[str, str, Rigid] | None:
        """The transform to broadcast with the state (see the module docstring)."""
        cfg, s = self.cfg, self.ekf.state
        body = Rigid(rotation_from_rpy(float(s[3]), float(s[4]), float(s[5])), s[0:3].copy())
        if cfg.world_frame == cfg.odom_frame:
            return cfg.world_frame, cfg.base_link_output_frame, body
        if cfg.world_frame == cfg.map_frame:
            # tf allows one parent per frame and odom -> base_link is someone else's (an odometry EKF):
            # the map's correction is broadcast as map -> odom = (map -> base_link) (base_link -> odom)
            odom_in_body = self.frames.lookup(cfg.base_link_frame, cfg.odom_frame)
            if odom_in_body is None:
                self.notes["map_odom"] = f"Could not obtain transform from {cfg.odom_frame}->{cfg.base_link_frame}"
                return None
            return cfg.map_frame, cfg.odom_frame, body * odom_in_body
        self.notes["world_frame"] = (
            f"Odometry message frame_id was {cfg.world_frame}, expected {cfg.map_frame} or {cfg.odom_frame}"
        )
        return None
