"""gazelle.estimation: robot_localization's EKF (ros2 branch, src/ekf.cpp, filter_base.cpp, ros_filter.cpp) on
numpy, without ROS. The common 2-D configuration (odometry's vx and vyaw, an IMU's yaw and vyaw) follows a
robot driving a circle; updates shrink the covariance of what they measure; a variable a sensor's config
leaves off is never fused; and the inputs' frames, 2-D mode, differential and relative inputs, the rejection
threshold, the sensor timeout and the publication rule behave as upstream's."""

from __future__ import annotations

import math

import numpy as np
import pytest

from gazelle.estimation import (
    ConfigError,
    Ekf,
    FrameTree,
    ImuReading,
    Measurement,
    PoseReading,
    Rigid,
    StateEstimator,
    TwistReading,
    motion_model,
    quaternion_from_rpy,
    read_config,
)
from gazelle.estimation._rigid import rotation_from_rpy

X, Y, Z, ROLL, PITCH, YAW, VX, VY, VZ, VROLL, VPITCH, VYAW = range(12)
NS = 1_000_000_000


def config(*on: int) -> list[bool]:
    """A 15-boolean ``<sensor>_config`` with the variables ``on``."""
    return [i in on for i in range(15)]


COMMON_2D = {
    "frequency": 30.0,
    "two_d_mode": True,
    "odom0": "odom",
    "odom0_config": config(VX, VYAW),
    "imu0": "imu",
    "imu0_config": config(YAW, VYAW),
}
"""A vendor's 2-D ekf.yaml: wheel odometry's forward and turning speed, the IMU's heading and turning speed."""


def _estimator(params: dict, frames: FrameTree | None = None) -> StateEstimator:
    return StateEstimator(read_config(params), frames or FrameTree(), 0)


def _drive_circle(
    est: StateEstimator, v: float, w: float, seconds: float, rng: np.random.Generator, imu_frame: str = "base_link"
) -> list[tuple[float, np.ndarray]]:
    """Feed odometry and IMU readings of a robot driving a circle at 50 Hz (noisy as their covariances say),
    cycle the filter at 25 Hz; the outputs (time, state)."""
    odom, imu = est.cfg.sensors
    twist_cov = np.diag([1e-4] * 6)
    mount_yaw = 0.0
    if imu_frame != "base_link":
        mount = est.frames.lookup("base_link", imu_frame)
        assert mount is not None
        mount_yaw = mount.rpy()[2]
    out = []
    for k in range(1, round(seconds * 50) + 1):
        t = k / 50
        ns = round(t * NS)
        twist = (v + rng.normal(0, 0.01), 0.0, 0.0), (0.0, 0.0, w + rng.normal(0, 0.01))
        est.odometry(odom, PoseReading(ns, "odom"), TwistReading(ns, "base_link", *twist, twist_cov))
        q = quaternion_from_rpy(0.0, 0.0, w * t + mount_yaw + rng.normal(0, 0.01))
        cov3 = np.eye(3) * 1e-4
        est.imu(imu, ImuReading(ns, imu_frame, q, cov3, (0.0, 0.0, w), cov3, (0.0, 0.0, 0.0), -np.eye(3)))
        if k % 2 == 0 and (result := est.cycle(ns)) is not None:
            out.append((t, result.state))
    return out


def _circle(v: float, w: float, t: float) -> tuple[float, float, float]:
    r = v / w
    return r * math.sin(w * t), r * (1 - math.cos(w * t)), math.atan2(math.sin(w * t), math.cos(w * t))


def test_the_motion_models_jacobian_is_its_derivative() -> None:
    rng = np.random.default_rng(1)
    for _ in range(5):
        x = rng.normal(size=15)
        x[PITCH] = rng.uniform(-1.2, 1.2)
        _, jac = motion_model(x, 0.07)
        numeric = np.zeros((15, 15))
        for i in range(15):
            e = np.zeros(15)
            e[i] = 1e-6
            numeric[:, i] = (motion_model(x + e, 0.07)[0] - motion_model(x - e, 0.07)[0]) / 2e-6
        assert np.allclose(jac, numeric, atol=1e-7)


def test_a_constant_velocity_circle_is_followed_from_odometry_speeds_and_the_imus_heading() -> None:
    est = _estimator(COMMON_2D)
    outputs = _drive_circle(est, v=0.5, w=0.4, seconds=12.0, rng=np.random.default_rng(7))
    assert len(outputs) > 100
    for t, s in outputs:
        x, y, yaw = _circle(0.5, 0.4, t)
        assert math.hypot(s[X] - x, s[Y] - y) < 0.05, (t, s[:6], (x, y))
        assert abs(math.remainder(s[YAW] - yaw, 2 * math.pi)) < 0.03
        assert s[VX] == pytest.approx(0.5, abs=0.03) and s[VYAW] == pytest.approx(0.4, abs=0.03)
        assert (s[Z], s[ROLL], s[PITCH]) == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)  # 2-D mode


def test_an_imu_mounted_turned_on_the_body_is_corrected_by_its_mount_from_tf() -> None:
    """The IMU sits yawed 90 degrees on the body (base_link -> imu_link on /tf_static): its heading is the
    body's plus 90 degrees, which robot_localization takes off (preparePose's IMU case); without the
    transform its readings are not used, and the filter says which frames it could not relate."""
    frames = FrameTree()
    frames.set("base_link", "imu_link", Rigid(rotation_from_rpy(0.0, 0.0, math.pi / 2), np.array([0.1, 0.0, 0.2])))
    est = _estimator(COMMON_2D, frames)
    outputs = _drive_circle(est, 0.5, 0.4, 6.0, np.random.default_rng(3), imu_frame="imu_link")
    t, s = outputs[-1]
    assert abs(math.remainder(s[YAW] - _circle(0.5, 0.4, t)[2], 2 * math.pi)) < 0.03

    unknown = _estimator(COMMON_2D)
    imu = unknown.cfg.sensors[1]
    unknown.imu(imu, ImuReading(NS, "imu_link", quaternion_from_rpy(0, 0, 1.0), np.eye(3) * 1e-4))
    assert unknown.cycle(NS) is None  # nothing was measured: the filter is not initialized
    assert any("'imu_link' into 'base_link'" in text for text in unknown.notes.values())


def test_updates_shrink_the_covariance_of_what_they_measure_and_predictions_grow_it() -> None:
    ekf = Ekf()
    first = Measurement("odom0_twist", NS, update=np.array(config(VX, VYAW)))
    first.covariance[:] = np.eye(15) * 0.1
    ekf.process(first)
    variances = [np.diag(ekf.covariance).copy()]
    for k in range(2, 12):
        m = Measurement("odom0_twist", k * NS // 10 + NS, update=np.array(config(VX, VYAW)))
        m.values[VX], m.values[VYAW] = 0.3, 0.1
        m.covariance[:] = np.eye(15) * 0.01
        ekf.predict(m.time_ns, 0.1)
        predicted = np.diag(ekf.covariance).copy()
        assert predicted[VX] >= variances[-1][VX] + 0.1 * 0.025 * 0.999  # vx's default process noise, 0.1 s of it
        assert ekf.correct(m)
        ekf.last_measurement_ns = m.time_ns
        corrected = np.diag(ekf.covariance)
        assert corrected[VX] < predicted[VX] and corrected[VYAW] < predicted[VYAW]
        assert corrected[VY] == pytest.approx(predicted[VY])  # not measured: as predicted
        variances.append(corrected.copy())
    assert variances[-1][VX] < 0.01  # converged below one measurement's variance


def test_a_variable_a_sensors_config_leaves_off_is_never_fused() -> None:
    """odom0 measures vx only: the message's vy, vyaw and pose, however confident, change nothing of them."""
    est = _estimator({"odom0": "odom", "odom0_config": config(VX)})
    odom = est.cfg.sensors[0]
    tight = np.eye(6) * 1e-6
    for k in range(1, 40):
        ns = k * NS // 20
        est.odometry(
            odom,
            PoseReading(ns, "odom", (5.0, 6.0, 0.0), quaternion_from_rpy(0, 0, 1.0), tight),
            TwistReading(ns, "base_link", (0.4, 2.0, 0.0), (0.0, 0.0, 3.0), tight),
        )
        est.cycle(ns)
    s = est.ekf.state
    assert s[VX] == pytest.approx(0.4, abs=1e-3)
    assert (s[VY], s[VYAW], s[YAW], s[Y]) == (0.0, 0.0, 0.0, 0.0)
    assert s[X] == pytest.approx(0.4 * (39 - 1) / 20, rel=0.05)  # integrated from vx alone


def test_two_d_mode_keeps_z_roll_and_pitch_at_zero_whatever_the_imu_says() -> None:
    for two_d, expected in ((True, 0.0), (False, 0.2)):
        est = _estimator({"two_d_mode": two_d, "imu0": "imu", "imu0_config": config(ROLL, PITCH, YAW)})
        imu = est.cfg.sensors[0]
        for k in range(1, 20):
            q = quaternion_from_rpy(0.2, 0.2, 0.5)
            est.imu(imu, ImuReading(k * NS // 10, "base_link", q, np.eye(3) * 1e-4))
            est.cycle(k * NS // 10)
        s = est.ekf.state
        assert (s[ROLL], s[PITCH]) == pytest.approx((expected, expected), abs=1e-3)
        assert s[YAW] == pytest.approx(0.5, abs=1e-3)


def test_a_differential_pose_input_becomes_the_velocity_between_its_poses() -> None:
    """odom0_differential: a pose growing 0.05 m and 0.02 rad per 0.1 s measures vx 0.5 m/s, vyaw 0.2 rad/s."""
    est = _estimator({"odom0": "odom", "odom0_config": config(X, Y, YAW), "odom0_differential": True})
    odom = est.cfg.sensors[0]
    cov = np.eye(6) * 1e-4
    x = y = yaw = 0.0
    for k in range(1, 30):
        ns = k * NS // 10
        est.odometry(
            odom, PoseReading(ns, "odom", (x, y, 0.0), quaternion_from_rpy(0, 0, yaw), cov), TwistReading(ns, "")
        )
        x, y, yaw = x + 0.05 * math.cos(yaw), y + 0.05 * math.sin(yaw), yaw + 0.02
        est.cycle(ns)
    s = est.ekf.state
    assert s[VX] == pytest.approx(0.5, abs=0.01) and s[VYAW] == pytest.approx(0.2, abs=0.01)
    assert s[VY] == pytest.approx(0.0, abs=0.01)


def test_a_relative_input_starts_at_zero() -> None:
    est = _estimator({"pose0": "pose", "pose0_config": config(X, Y, YAW), "pose0_relative": True})
    pose0 = est.cfg.sensors[0]
    for k, dx in ((1, 0.0), (2, 1.0)):
        q = quaternion_from_rpy(0, 0, 1.0)
        est.pose(pose0, PoseReading(k * NS, "odom", (3.0 + dx, 4.0, 0.0), q, np.eye(6) * 1e-6))
        est.cycle(k * NS)
    s = est.ekf.state
    # the second pose is 1 m further along world x from the first, which faced 1 rad: in the first's frame
    assert (s[X], s[Y]) == pytest.approx((math.cos(1.0), -math.sin(1.0)), abs=1e-3)
    assert s[YAW] == pytest.approx(0.0, abs=1e-3)


def test_a_measurement_beyond_the_rejection_threshold_is_not_fused() -> None:
    est = _estimator({"pose0": "pose", "pose0_config": config(X), "pose0_rejection_threshold": 3.0})
    pose0 = est.cfg.sensors[0]
    for k, x in ((1, 1.0), (2, 1.01), (3, 50.0), (4, 1.02)):
        est.pose(pose0, PoseReading(k * NS, "odom", (x, 0.0, 0.0), covariance=np.eye(6) * 0.01))
        est.cycle(k * NS)
        assert est.ekf.state[X] < 2.0, f"the outlier at {x} was fused"


def test_readings_out_of_order_or_at_the_reset_time_are_ignored() -> None:
    est = _estimator({"pose0": "pose", "pose0_config": config(X)})
    pose0 = est.cfg.sensors[0]
    est.pose(pose0, PoseReading(0, "odom", (9.0, 0.0, 0.0), covariance=np.eye(6)))  # stamped 0: never used
    est.pose(pose0, PoseReading(2 * NS, "odom", (1.0, 0.0, 0.0), covariance=np.eye(6)))
    est.pose(pose0, PoseReading(1 * NS, "odom", (7.0, 0.0, 0.0), covariance=np.eye(6)))  # older than the last
    out = est.cycle(3 * NS)
    assert out is not None and out.state[X] == pytest.approx(1.0)
    assert {"pose0_timestamp"} == set(est.notes)


def test_the_output_is_published_when_time_moved_on_and_the_state_predicted_after_a_sensor_timeout() -> None:
    """Upstream publishes the state at its last measurement's time, once; with no reading for ``sensor_timeout``
    it predicts to now and publishes that."""
    est = _estimator({"twist0": "twist", "twist0_config": config(VX), "sensor_timeout": 0.5})
    twist0 = est.cfg.sensors[0]
    est.twist(twist0, TwistReading(NS, "base_link", (1.0, 0.0, 0.0), covariance=np.eye(6) * 1e-6))
    first = est.cycle(NS + NS // 10)
    assert first is not None and first.stamp_ns == NS and first.frame == "odom" and first.child == "base_link"
    assert est.cycle(NS + NS // 5) is None  # nothing new, not timed out
    late = est.cycle(2 * NS)
    assert late is not None and late.stamp_ns == 2 * NS and late.state[X] == pytest.approx(1.0, abs=1e-6)
    assert late.transform is not None and late.transform[:2] == ("odom", "base_link")
    assert late.transform[2].translation[0] == pytest.approx(1.0, abs=1e-6)


def test_in_the_map_frame_the_transform_is_map_to_odom() -> None:
    """world_frame: map: the filter gives map -> base_link, and broadcasts map -> odom from the odom -> base_link
    transform someone else publishes."""
    frames = FrameTree()
    frames.set("odom", "base_link", Rigid(rotation_from_rpy(0, 0, 0.5), np.array([1.0, 0.0, 0.0])))
    params = {"world_frame": "map", "pose0": "amcl_pose", "pose0_config": config(X, Y, YAW)}
    est = _estimator(params, frames)
    q = quaternion_from_rpy(0, 0, 0.7)
    est.pose(est.cfg.sensors[0], PoseReading(NS, "map", (3.0, 2.0, 0.0), q, np.eye(6) * 1e-6))
    out = est.cycle(NS)
    assert out is not None and out.transform is not None
    parent, child, map_odom = out.transform
    assert (parent, child) == ("map", "odom")
    body = map_odom * frames.lookup("odom", "base_link")  # type: ignore[operator] - the transform was set above
    assert body.translation[:2] == pytest.approx([3.0, 2.0], abs=1e-6) and body.rpy()[2] == pytest.approx(0.7)


def test_set_pose_and_reset() -> None:
    est = _estimator({"twist0": "twist", "twist0_config": config(VX)})
    twist0 = est.cfg.sensors[0]
    est.twist(twist0, TwistReading(NS, "base_link", (1.0, 0.0, 0.0), covariance=np.eye(6) * 1e-6))
    est.cycle(NS)
    est.set_pose(PoseReading(3 * NS, "odom", (5.0, 1.0, 0.0), quaternion_from_rpy(0, 0, 0.3)), 3 * NS)
    assert est.ekf.state[[X, Y, YAW, VX]] == pytest.approx([5.0, 1.0, 0.3, 0.0])
    est.twist(twist0, TwistReading(2 * NS, "base_link", (1.0, 0.0, 0.0)))  # before the set_pose: ignored
    assert "twist0_timestamp" in est.notes
    est.reset()
    assert not est.ekf.initialized and est.ekf.state[X] == 0.0 and est.cycle(4 * NS) is None


def test_the_configuration_names_what_it_cannot_use() -> None:
    cfg = read_config(
        {
            **COMMON_2D,
            "debug": True,
            "smooth_lagged_data": True,
            "stamped_control": False,
            "use_sim_time": True,
            "process_noise_covariance": [0.1] * 15,
            "initial_estimate_covariance": [1e-3] * 225,
            "odom1": "wheels",
            "odom1_config": config(),
        }
    )
    assert cfg.unread == ["debug", "smooth_lagged_data"]
    assert cfg.process_noise is not None and np.diag(cfg.process_noise) == pytest.approx([0.1] * 15)
    assert cfg.initial_covariance is not None and cfg.initial_covariance.shape == (15, 15)
    assert "Warning: wheels is listed as an input topic, but all its update variables are false" in cfg.notes
    assert [s.name for s in cfg.sensors] == ["odom0", "odom1", "imu0"]
    assert cfg.sensor_timeout_ns == round(NS / 30)  # 1 / frequency
    with pytest.raises(ConfigError, match="'odom0_config' must have 15 booleans, not 6"):
        read_config({"odom0": "odom", "odom0_config": [True] * 6})
    with pytest.raises(ConfigError, match="'process_noise_covariance' must have 15 or 225 values, not 3"):
        read_config({"process_noise_covariance": [1.0, 2.0, 3.0]})
    with pytest.raises(ConfigError, match="'two_d_mode' must be a bool"):
        read_config({"two_d_mode": "yes"})
    with pytest.raises(ConfigError, match="'frequency' must be a positive"):
        read_config({"frequency": 0.0})


def test_a_reading_with_a_nan_or_overflowing_covariance_leaves_the_filter_as_it_was() -> None:
    """Upstream's filter fuses whatever comes and stays NaN for good; gazelle's refuses such a measurement."""
    est = _estimator({"twist0": "twist", "twist0_config": config(VX, VYAW)})
    twist0 = est.cfg.sensors[0]
    est.twist(twist0, TwistReading(NS, "base_link", (1.0, 0.0, 0.0), covariance=np.eye(6) * 1e-3))
    est.cycle(NS)
    before = est.ekf.state.copy()
    bad = np.eye(6) * 1e-3
    bad[0, 0] = math.nan
    est.twist(twist0, TwistReading(2 * NS, "base_link", (5.0, 0.0, 0.0), covariance=bad))
    est.twist(twist0, TwistReading(3 * NS, "base_link", (1e300, 0.0, 1e300), covariance=np.eye(6) * 1e-300))
    est.twist(twist0, TwistReading(4 * NS, "base_link", (math.nan, 0.0, 0.0), covariance=np.eye(6) * 1e-3))
    out = est.cycle(4 * NS)
    assert out is not None and np.isfinite(out.state).all() and np.isfinite(out.covariance).all()
    assert out.state[VX] == pytest.approx(before[VX])


def test_a_reading_stamped_far_ahead_of_the_clock_does_not_make_its_input_deaf() -> None:
    """Upstream takes any stamp as the input's last: one reading stamped in the far future (a wrong clock, or
    anyone on the graph) would make every later reading of that input 'older', for good."""
    now = [NS]
    params = {"twist0": "twist", "twist0_config": config(VX)}
    est = StateEstimator(read_config(params), FrameTree(), 0, clock=lambda: now[0])
    twist0 = est.cfg.sensors[0]
    est.twist(twist0, TwistReading(10**7 * NS, "base_link", (9.0, 0.0, 0.0), covariance=np.eye(6) * 1e-4))
    assert "twist0_future" in est.notes
    for k in range(2, 6):
        now[0] = k * NS
        est.twist(twist0, TwistReading(k * NS, "base_link", (1.0, 0.0, 0.0), covariance=np.eye(6) * 1e-4))
        out = est.cycle(k * NS)
        assert out is not None and out.stamp_ns == k * NS
    assert est.ekf.state[VX] == pytest.approx(1.0, abs=1e-3)


def test_the_frame_tree_relates_frames_through_their_ancestors_and_survives_a_loop() -> None:
    frames = FrameTree()
    turn = Rigid(rotation_from_rpy(0, 0, math.pi / 2), np.array([1.0, 0.0, 0.0]))
    frames.set("odom", "base_link", turn)
    frames.set("base_link", "imu_link", Rigid(translation=np.array([0.0, 0.5, 0.0])))
    frames.set("base_link", "laser", Rigid(translation=np.array([0.2, 0.0, 0.0])))
    imu_in_odom = frames.lookup("odom", "imu_link")
    assert imu_in_odom is not None and imu_in_odom.translation == pytest.approx([0.5, 0.0, 0.0])
    laser_in_imu = frames.lookup("imu_link", "laser")
    assert laser_in_imu is not None and laser_in_imu.translation == pytest.approx([0.2, -0.5, 0.0])
    assert frames.lookup("odom", "map") is None
    frames.set("imu_link", "odom", Rigid())  # a loop heard on /tf: lookups end, unrelated frames stay so
    assert frames.lookup("map", "laser") is None
