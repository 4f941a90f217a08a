"""Sensors against geometry and physics with known answers (issue 12): lidar ranges, angles and noise,
the IMU at rest and spinning, and which sensors of real robots run and where they publish.

Noise is off unless a test is about noise.
"""

from __future__ import annotations

import dataclasses
import logging
import math

import numpy as np
import pytest
from _paths import REAL, REPO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.sim import Simulation
from gazelle.systems import Imu, LaserScan, MsgType, PointCloud, Range, plan_sensors
from gazelle.systems.sensors import ImuSensor, Lidar
from gazelle.worlds import default_world

TB3 = REAL / "turtlebot3"
BOX_2KG = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="box"><link name="link">'
    "<inertial><mass>2.0</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>"
    '<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>'
)


def _lidar_model(
    *,
    samples: int = 181,
    min_angle: float = -math.pi / 2,
    max_angle: float = math.pi / 2,
    rmin: float = 0.1,
    rmax: float = 10.0,
    noise: str = "",
    output: str = "sensor_msgs/LaserScan",
    vertical: str = "",
    z: float = 0.5,
    ros: str = "<ros><remapping>~/out:=scan</remapping></ros>",
) -> str:
    """A static post carrying a lidar at height ``z`` with a gazebo_ros ray sensor plugin (``~/out:=scan``,
    or the plugin's ``ros`` block)."""
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="scanner"><static>true</static>
  <link name="base">
    <collision name="post"><pose>0 0 {z / 2} 0 0 0</pose><geometry><box><size>0.05 0.05 {z}</size></box></geometry></collision>
    <sensor name="laser" type="ray">
      <pose>0 0 {z} 0 0 0</pose>
      <update_rate>10</update_rate>
      <ray>
        <scan><horizontal><samples>{samples}</samples><resolution>1</resolution>
          <min_angle>{min_angle!r}</min_angle><max_angle>{max_angle!r}</max_angle></horizontal>{vertical}</scan>
        <range><min>{rmin}</min><max>{rmax}</max></range>
        {noise}
      </ray>
      <plugin name="my_laser" filename="libgazebo_ros_ray_sensor.so">
        {ros}
        <output_type>{output}</output_type>
      </plugin>
    </sensor>
  </link>
</model></sdf>"""


def _wall(name: str, x: float, y: float, sx: float, sy: float) -> str:
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="{name}"><static>true</static><pose>{x} {y} 1 0 0 0</pose>
  <link name="l"><collision name="c"><geometry><box><size>{sx} {sy} 2</size></box></geometry></collision></link>
</model></sdf>"""


def _spawn(sim: Simulation, xml: str, name: str, pose: Pose = Pose()):
    result = load_string(xml)
    assert not [d for d in result.diagnostics if d.severity.name == "ERROR"], [d.format() for d in result.diagnostics]
    return sim.spawn(result.model, name=name, pose=pose)


def _lidar(entity) -> Lidar:
    return next(s for s in entity.systems if isinstance(s, Lidar))


def _record(sim: Simulation, topic: str) -> list:
    got: list = []
    ep = next(e for e in sim.bus.endpoints() if e.topic == topic and e.is_publisher)
    ep.add_sink(got.append)
    return got


def test_a_lidar_facing_a_wall_reads_the_geometry_to_1_mm_with_exact_first_and_last_angles(make_sim):
    sim = make_sim()
    d = 2.0  # the wall's near face is 2 m in front of the sensor
    _spawn(sim, _wall("wall", d + 0.1, 0.0, 0.2, 20.0), "wall")
    scanner = _spawn(sim, _lidar_model(), "scanner")
    lidar = _lidar(scanner)
    assert lidar.output is not None and lidar.output.topic == "/scan"  # ~/out:=scan
    assert lidar.output.frame_id == "base"  # no <frame_name>: the sensor's link
    scans = _record(sim, "/scan")
    sim.step(150)  # 10 Hz: scans at t = 0, 0.1
    assert len(scans) == 2
    scan: LaserScan = scans[-1]
    assert isinstance(scan, LaserScan)
    assert scan.stamp_sec == pytest.approx(0.1, abs=1e-9)  # stamped with the sim time of the scan
    assert (scan.angle_min, scan.angle_max) == (-math.pi / 2, math.pi / 2)
    assert scan.angle_increment == pytest.approx(math.pi / 180, rel=1e-12)
    # one instant of sim time: gazebo_ros and ros_gz_bridge both send 0 for these two
    assert (scan.scan_time, scan.time_increment) == (0.0, 0.0)
    ranges = np.frombuffer(scan.ranges, np.float32)
    assert len(ranges) == 181
    angles = scan.angle_min + scan.angle_increment * np.arange(181)
    expect = d / np.cos(angles)
    hits = np.abs(angles) < math.radians(75)  # the wall is 20 m long: it fills ±84° within 10 m
    assert np.all(np.abs(ranges[hits] - expect[hits]) < 1e-3)
    # the two end rays run parallel to the wall: nothing within range is +inf (REP 117)
    assert math.isinf(ranges[0]) and ranges[0] > 0 and math.isinf(ranges[-1]) and ranges[-1] > 0


def test_a_lidar_in_a_closed_square_room_matches_the_analytic_ranges(make_sim):
    sim = make_sim()
    a, t = 1.5, 0.2  # half the room's inner width; wall thickness
    for name, x, y, sx, sy in (
        ("north", 0, a + t / 2, 2 * a + 2 * t, t),
        ("south", 0, -a - t / 2, 2 * a + 2 * t, t),
        ("east", a + t / 2, 0, t, 2 * a),
        ("west", -a - t / 2, 0, t, 2 * a),
    ):
        _spawn(sim, _wall(name, x, y, sx, sy), name)
    scanner = _spawn(sim, _lidar_model(samples=360, min_angle=0.0, max_angle=2 * math.pi * 359 / 360), "scanner")
    lidar = _lidar(scanner)
    sim.step(1)
    ranges = lidar.scan(sim.world)[0]
    angles = np.arange(360) * 2 * math.pi / 360
    expect = a / np.maximum(np.abs(np.cos(angles)), np.abs(np.sin(angles)))
    assert np.max(np.abs(ranges - expect)) < 1e-3


def _lidar_facing_a_wall(make_sim, noise: str, samples: int, half_angle: float):
    """A world with a long wall whose near face is 2 m ahead of a lidar of ``samples`` rays over ±``half_angle``
    with ``noise``, stepped once."""
    sim = make_sim()
    _spawn(sim, _wall("wall", 2.1, 0.0, 0.2, 20.0), "wall")
    model = _lidar_model(samples=samples, min_angle=-half_angle, max_angle=half_angle, noise=noise)
    lidar = _lidar(_spawn(sim, model, "scanner"))
    sim.step(1)
    return sim, lidar


def test_gaussian_noise_has_the_configured_stddev_over_10000_samples(make_sim):
    noise = "<noise><type>gaussian</type><mean>0.0</mean><stddev>0.01</stddev></noise>"
    sim, lidar = _lidar_facing_a_wall(make_sim, noise, 100, 0.5)
    angles = np.linspace(-0.5, 0.5, 100)
    errors = np.concatenate([lidar.scan(sim.world)[0] - 2.0 / np.cos(angles) for _ in range(100)])
    assert errors.size == 10_000
    assert abs(errors.std() - 0.01) < 0.001
    assert abs(errors.mean()) < 0.001


@pytest.mark.parametrize(("face", "mean", "expect"), [(9.9, 0.3, 10.0), (0.35, -0.2, 0.3)])
def test_noise_never_turns_a_hit_into_inf_it_is_clamped_into_the_range_as_gz_sensors_does(make_sim, face, mean, expect):
    # gz-sensors 8 Lidar::ApplyNoise: noise on the readings in range, then Clamp into [min, max]; ±inf untouched
    sim = make_sim()
    _spawn(sim, _wall("wall", face + 0.1, 0.0, 0.2, 0.02), "wall")  # 2 cm wide: only the straight ray hits it
    noise = f"<noise><type>gaussian</type><mean>{mean}</mean><stddev>0.0</stddev></noise>"
    model = _lidar_model(samples=3, min_angle=-0.5, max_angle=0.5, rmin=0.3, noise=noise)
    lidar = _lidar(_spawn(sim, model, "scanner"))
    sim.step(1)
    ranges = lidar.scan(sim.world)[0]
    assert ranges[1] == pytest.approx(expect, abs=1e-9)
    assert np.all(np.isposinf(ranges[[0, 2]]))  # the misses stay +inf however large the noise
    # a wall past range_max is no hit, noise or not (MuJoCo's ray cutoff does not filter it by distance)
    far = make_sim()
    _spawn(far, _wall("wall", 10.6, 0.0, 0.2, 40.0), "wall")
    lidar = _lidar(_spawn(far, model, "scanner"))
    far.step(1)
    assert np.all(np.isposinf(lidar.scan(far.world)[0]))


def test_a_lidar_noise_bias_is_drawn_once_and_adds_to_every_scan(make_sim):
    # gz-sensors GaussianNoiseModel: a bias of magnitude bias_mean and random sign, drawn when loaded
    sim, lidar = _lidar_facing_a_wall(
        make_sim, "<noise><type>gaussian</type><bias_mean>0.05</bias_mean></noise>", 3, 0.1
    )
    scans = np.array([lidar.scan(sim.world)[0][1] for _ in range(5)])
    assert np.all(scans == scans[0]) and abs(scans[0] - 2.0) == pytest.approx(0.05, abs=1e-9)


def test_rays_nearer_than_the_minimum_are_minus_inf_and_the_own_link_is_not_seen(make_sim):
    sim = make_sim()
    _spawn(sim, _wall("wall", 0.35, 0.0, 0.2, 20.0), "wall")  # near face at 0.25 m
    lidar = _lidar(_spawn(sim, _lidar_model(samples=3, min_angle=-0.1, max_angle=0.1, rmin=0.3), "scanner"))
    sim.step(1)
    ranges = lidar.scan(sim.world)[0]
    assert np.all(np.isneginf(ranges))  # REP 117: detected, but too close to quantify


def test_pointcloud2_and_range_outputs(make_sim):
    sim = make_sim()
    _spawn(sim, _wall("wall", 2.1, 0.0, 0.2, 20.0), "wall")
    vertical = "<vertical><samples>3</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical>"
    cloud_model = _lidar_model(
        samples=11, min_angle=-0.2, max_angle=0.2, output="sensor_msgs/PointCloud2", vertical=vertical
    )
    _spawn(sim, cloud_model, "cloud")
    range_model = _lidar_model(samples=5, min_angle=-0.2, max_angle=0.2, output="sensor_msgs/Range").replace(
        "~/out:=scan", "~/out:=range"
    )
    _spawn(sim, range_model, "ranger", Pose((0.0, 5.0, 0.0)))
    clouds, ranges = _record(sim, "/scan"), _record(sim, "/range")
    sim.step(1)
    cloud: PointCloud = clouds[-1]
    assert (cloud.width, cloud.height) == (33, 1)
    pts = np.frombuffer(cloud.data, "<f4").reshape(-1, 4)
    assert np.allclose(pts[:, 0], 2.0, atol=1e-3)  # every point on the wall's face, in the sensor frame
    rng: Range = ranges[-1]
    assert rng.radiation_type == 1 and rng.field_of_view == pytest.approx(0.4)
    # the ranger stands 5 m to the side, facing the same wall: its nearest ray is the straight one
    assert rng.range == pytest.approx(2.0 / math.cos(0.0), abs=1e-3)


def test_a_range_is_the_least_of_its_rays_so_one_too_near_reads_minus_inf_as_in_gazebo_ros(make_sim):
    # gazebo_ros conversions/sensor_msgs.hpp Convert<Range>: the minimum over every ray of the cone
    sim = make_sim()
    _spawn(sim, _wall("wall", 2.1, 0.0, 0.2, 20.0), "wall")  # straight ahead: 2 m, in range
    _spawn(sim, _wall("post", 0.2, 0.3, 0.1, 0.1), "post")  # the leftmost ray's way: 0.3 m, under range_min
    model = _lidar_model(samples=5, min_angle=-1.0, max_angle=1.0, output="sensor_msgs/Range", rmin=0.5)
    ranger = _spawn(sim, model.replace("~/out:=scan", "~/out:=range"), "ranger")
    got = _record(sim, "/range")
    sim.step(1)
    rays = _lidar(ranger).scan(sim.world, noise=False)[0]
    assert np.isneginf(rays[-1]) and np.all(np.isfinite(rays[1:4]))  # the set-up: one ray too near, others hit
    assert got[-1].range == -math.inf
    # and a cone that sees nothing reads +inf (REP 117; gazebo_ros sends FLT_MAX there)
    sim.delete("wall")
    sim.delete("post")
    sim.step(100)
    assert got[-1].range == math.inf


def _ros1_sonar(plugin_extra: str = "") -> str:
    """A post with a ROS 1-era sonar: a 5-ray cone and libgazebo_ros_range.so, as ROS 1 robot descriptions wrote it."""
    plugin = f"""<plugin name="sonar" filename="libgazebo_ros_range.so">
        <robotNamespace>/bot</robotNamespace><topicName>sonar</topicName><frameName>sonar_link</frameName>
        <updateRate>5</updateRate>{plugin_extra}</plugin>"""
    xml = _lidar_model(samples=5, min_angle=-0.1, max_angle=0.1, rmin=0.1, rmax=4.0)
    return xml[: xml.index("<plugin")] + plugin + xml[xml.index("</plugin>") + len("</plugin>") :]


def test_ros1_gazebo_ros_range_publishes_the_nearest_ray_as_its_plugin_did(make_sim, caplog):
    """ROS 1's gazebo_ros_range.cpp (PutRangeData): sensor_msgs/Range on <topicName> under <robotNamespace>, the
    least raw ray (a miss reads range_max, not +inf), <radiation> ultrasound by default, the plugin's <fov> (0.05
    by default), throttled to <updateRate>; it was a warning ('not simulated yet') before."""
    sim = make_sim()
    _spawn(sim, _wall("wall", 2.1, 0.0, 0.2, 20.0), "wall")
    with caplog.at_level(logging.WARNING):
        _spawn(sim, _ros1_sonar(), "bot")
    assert not caplog.records, [r.getMessage() for r in caplog.records]  # every parameter read
    got = _record(sim, "/bot/sonar")
    sim.step(1000)  # 1 s: the 10 Hz sensor throttled to 5 Hz
    stamps = [m.stamp_sec for m in got]
    assert len(stamps) == 6 and all(b - a == pytest.approx(0.2, abs=1e-9) for a, b in zip(stamps[1:], stamps[2:]))
    r: Range = got[-1]
    assert (r.radiation_type, r.field_of_view, r.min_range, r.max_range) == (0, 0.05, 0.1, 4.0)
    assert r.frame_id == "sonar_link" and r.range == pytest.approx(2.0, abs=1e-3)
    sim.delete("wall")
    sim.step(200)
    assert got[-1].range == 4.0  # nothing in range: Classic's raw rays report range_max


def _imu_box(extra: str = "", offset: str = "0.3 0 0 0 0 0", plugin: bool = True) -> str:
    ros = """<plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so">
        <ros><namespace>/demo</namespace><remapping>~/out:=imu</remapping></ros>
        <frame_name>imu_link</frame_name>
      </plugin>"""
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="imu_box">
  <link name="body">
    <inertial><mass>1.0</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.02</izz></inertia></inertial>
    <collision name="c"><geometry><box><size>0.4 0.4 0.1</size></box></geometry></collision>
    <sensor name="imu" type="imu">
      <pose>{offset}</pose>
      <update_rate>100</update_rate>
      {extra}
      {ros if plugin else ""}
    </sensor>
  </link>
</model></sdf>"""


def test_an_imu_at_rest_reads_plus_g_and_no_rotation(make_sim):
    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, -9.81))
    sim = make_sim(world)
    entity = _spawn(sim, _imu_box(), "imu_box", Pose((0.0, 0.0, 0.05)))
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    assert imu.output is not None and (imu.output.topic, imu.output.frame_id) == ("/demo/imu", "imu_link")
    got = _record(sim, "/demo/imu")
    sim.step(1000)  # settle on the ground
    msg: Imu = got[-1]
    assert msg.stamp_sec == pytest.approx(1.0, abs=1e-9)  # after the 1000th step
    assert np.allclose(msg.linear_acceleration, (0.0, 0.0, 9.81), atol=0.01)
    assert np.allclose(msg.angular_velocity, (0.0, 0.0, 0.0), atol=1e-3)
    assert np.allclose(msg.orientation, (1.0, 0.0, 0.0, 0.0), atol=1e-3)


def test_an_imu_spinning_about_z_reads_omega_and_the_centripetal_acceleration(make_sim):
    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, 0.0))
    sim = make_sim(world)
    entity = _spawn(sim, _imu_box(), "imu_box", Pose((0.0, 0.0, 1.0)))
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    omega = 2.0
    sim.world.set_entity_state("imu_box", Pose((0.0, 0.0, 1.0)), angular=(0.0, 0.0, omega))
    sim.step(100)
    _q, w, a = imu.read()
    assert w[2] == pytest.approx(omega, rel=0.01)
    assert abs(w[0]) < 1e-3 and abs(w[1]) < 1e-3
    # 0.3 m from the axis: a centripetal omega^2 r towards the axis, i.e. along the sensor's -x
    assert a[0] == pytest.approx(-(omega**2) * 0.3, rel=0.01)
    assert abs(a[1]) < 0.01 and abs(a[2]) < 0.01


def test_a_yawed_imu_off_the_axis_reads_in_its_own_frame_and_its_orientation_includes_the_yaw(make_sim):
    """The sensor 0.3 m along the body's x and yawed +90° on it: its x axis is the body's y. Spinning at
    omega about z, it reads omega about its z, the centripetal omega^2 r towards the axis (the body's -x,
    the sensor's +y), and its orientation is the body's yaw plus 90°."""
    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, 0.0))
    sim = make_sim(world)
    entity = _spawn(sim, _imu_box(offset=f"0.3 0 0 0 0 {math.pi / 2!r}"), "imu_box", Pose((0.0, 0.0, 1.0)))
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    omega = 2.0
    sim.world.set_entity_state("imu_box", Pose((0.0, 0.0, 1.0)), angular=(0.0, 0.0, omega))
    sim.step(100)
    q, w, a = imu.read()
    assert w[2] == pytest.approx(omega, rel=0.01) and abs(w[0]) < 1e-3 and abs(w[1]) < 1e-3
    assert a[1] == pytest.approx(omega**2 * 0.3, rel=0.01)
    assert abs(a[0]) < 0.01 and abs(a[2]) < 0.01
    body = sim.world.entity_state("imu_box").pose.orientation
    body_yaw = 2.0 * math.atan2(body[3], body[0])
    yaw = 2.0 * math.atan2(q[3], q[0])
    assert abs(q[1]) < 1e-6 and abs(q[2]) < 1e-6
    assert math.remainder(yaw - body_yaw - math.pi / 2, 2 * math.pi) == pytest.approx(0.0, abs=1e-6)


def test_a_yawed_lidar_on_its_link_scans_in_its_own_frame(make_sim):
    """A lidar turned +90° on its post faces the world's +y: a wall 2 m along +y is straight ahead of it."""
    sim = make_sim()
    d = 2.0
    _spawn(sim, _wall("wall", 0.0, d + 0.1, 20.0, 0.2), "wall")
    xml = _lidar_model().replace("<pose>0 0 0.5 0 0 0</pose>", f"<pose>0 0 0.5 0 0 {math.pi / 2!r}</pose>")
    scanner = _spawn(sim, xml, "scanner")
    scans = _record(sim, "/scan")
    sim.step(2)
    ranges = np.frombuffer(scans[-1].ranges, np.float32)
    angles = -math.pi / 2 + (math.pi / 180) * np.arange(181)
    hits = np.abs(angles) < math.radians(75)
    assert np.all(np.abs(ranges[hits] - d / np.cos(angles[hits])) < 1e-3)
    assert _lidar(scanner).world_points(sim.world)[:, 1].max() == pytest.approx(d, abs=1e-3)


def test_imu_noise_per_axis_as_configured(make_sim):
    noise = (
        "<imu><angular_velocity>"
        + "".join(f"<{ax}><noise type='gaussian'><mean>0</mean><stddev>0.02</stddev></noise></{ax}>" for ax in "xyz")
        + "</angular_velocity></imu>"
    )
    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, -9.81))
    sim = make_sim(world)
    entity = _spawn(sim, _imu_box(noise), "imu_box", Pose((0.0, 0.0, 0.05)))
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    sim.step(500)
    samples = np.array([imu.read()[1] for _ in range(3000)])
    assert np.allclose(samples.std(axis=0), 0.02, rtol=0.1)
    accel = np.array([imu.read()[2] for _ in range(10)])
    assert np.allclose(accel, (0.0, 0.0, 9.81), atol=0.01)  # no noise configured there: exact


def test_unsimulated_noise_and_bad_lidar_configuration_are_named_with_file_and_line(caplog, make_sim):
    sim = make_sim()
    bad_noise = "<noise><type>custom</type><stddev>0.1</stddev></noise>"
    with caplog.at_level(logging.WARNING):
        _spawn(sim, _lidar_model(noise=bad_noise), "a")
    assert any(
        "<string>.sdf:12: sensor 'laser': noise type 'custom' is not simulated" in r.getMessage()
        for r in caplog.records
    )
    caplog.clear()
    with caplog.at_level(logging.ERROR):
        entity = _spawn(sim, _lidar_model(samples=0), "b")
    msgs = [r.getMessage() for r in caplog.records]
    assert any("<string>.sdf:5: sensor 'laser': <samples> must be at least 1" in m for m in msgs), msgs
    assert _lidar(entity).next_update(0.0) == math.inf  # it does nothing, and says so; the world goes on


def test_turtlebot3_burger_sensors_run_from_all_three_of_its_files(make_sim):
    # ROS 2 Classic SDF (gazebo_ros plugins with ~/out remappings)
    classic = load(TB3 / "turtlebot3_gazebo/models/turtlebot3_burger/model-1_4.sdf").model
    plans, problems = plan_sensors(classic, ())
    assert sorted((p.sensor.name, p.plugin.filename if p.plugin else None) for p in plans) == [
        ("hls_lfcd_lds", "libgazebo_ros_ray_sensor.so"),
        ("tb3_imu", "libgazebo_ros_imu_sensor.so"),
    ]
    assert problems == []
    # gz-sim SDF: sensors run by the world's gz-sim systems (present in the default world)
    gz = load(TB3 / "turtlebot3_gazebo/models/turtlebot3_burger/model.sdf").model
    plans, problems = plan_sensors(gz, default_world().plugins)
    assert sorted(p.sensor.name for p in plans) == ["hls_lfcd_lds", "tb3_imu"] and problems == []
    plans, problems = plan_sensors(gz, ())  # a world file without them: named, as gz-sim would not run them
    assert plans == [] and len(problems) == 2
    assert all("gz-sim-" in p.message for p in problems)

    for path, scan_frame, imu_topic in (
        ("turtlebot3_gazebo/models/turtlebot3_burger/model-1_4.sdf", "base_scan", "/imu"),
        ("turtlebot3_gazebo/models/turtlebot3_burger/model.sdf", "base_scan", "/imu"),
    ):
        sim = make_sim()
        entity = sim.spawn(load(TB3 / path).model, name="burger", pose=Pose((0.0, 0.0, 0.01)))
        lidar = _lidar(entity)
        imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
        assert lidar.output is not None and imu.output is not None
        assert (lidar.output.topic, lidar.output.frame_id, lidar.output.msg_type) == (
            "/scan",
            scan_frame,
            MsgType.LASER_SCAN,
        )
        assert imu.output.topic == imu_topic
        assert (lidar.rate_hz, imu.rate_hz) == (5.0, 200.0)
        scans = _record(sim, "/scan")
        sim.step(201)
        assert len(scans) == 2 and len(np.frombuffer(scans[-1].ranges, np.float32)) == 360


def _ray_circle(origin: np.ndarray, dirs: np.ndarray, centre: tuple[float, float], r: float) -> np.ndarray:
    """Distance along each 2-D unit direction from origin to a circle (inf where it misses)."""
    oc = origin - np.asarray(centre)
    b = dirs @ oc
    c = oc @ oc - r * r
    disc = b * b - c
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return np.where((disc >= 0) & (t > 0), t, np.inf)


def test_turtlebot3_in_its_world_sees_the_pillars_at_the_distances_the_geometry_gives(resource_path, make_sim):
    resource_path("turtlebot3/turtlebot3_gazebo/models")
    world = load(TB3 / "turtlebot3_gazebo/worlds/turtlebot3_world.world").world
    sim = make_sim(world)
    burger = load(TB3 / "turtlebot3_gazebo/models/turtlebot3_burger/model.sdf").model
    entity = sim.spawn(burger, name="burger", pose=Pose((-2.0, -0.5, 0.01)))  # turtlebot3_world.launch.py's pose
    lidar = _lidar(entity)
    lidar.spec = dataclasses.replace(lidar.spec, noise=dataclasses.replace(lidar.spec.noise, type="none"))
    sim.step(2000)
    ranges = lidar.scan(sim.world)[0]
    X = lidar.sensor_pose()
    q = X.orientation
    yaw = math.atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2))
    angles = yaw + lidar.spec.horizontal.angles()
    dirs = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    origin = np.array(X.position[:2])
    pillars = [(x, y) for x in (-1.1, 0.0, 1.1) for y in (-1.1, 0.0, 1.1)]  # radius 0.15, from its model.sdf
    expect = np.min([_ray_circle(origin, dirs, c, 0.15) for c in pillars], axis=0)
    seen = expect < 3.5
    assert seen.sum() >= 20, "the burger at its launch pose should see several pillars"
    assert np.max(np.abs(ranges[seen] - expect[seen])) < 1e-3


def _camera_model(sensor_type: str = "camera", hfov: float = 1.2, width: int = 320, height: int = 240) -> str:
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="cam"><static>true</static>
  <link name="camera_link">
    <sensor name="front" type="{sensor_type}">
      <pose>0 0 0.5 0 0 0</pose>
      <update_rate>10</update_rate>
      <camera><horizontal_fov>{hfov!r}</horizontal_fov>
        <image><width>{width}</width><height>{height}</height><format>R8G8B8</format></image>
        <clip><near>0.05</near><far>50</far></clip></camera>
      <plugin name="front_camera" filename="libgazebo_ros_camera.so"><ros><namespace>/bot</namespace></ros></plugin>
    </sensor>
  </link>
</model></sdf>"""


def _box(name: str, pos: tuple[float, float, float], size: tuple[float, float, float], rgba: str) -> str:
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="{name}"><static>true</static><pose>{pos[0]} {pos[1]} {pos[2]} 0 0 0</pose>
  <link name="l">
    <collision name="c"><geometry><box><size>{size[0]} {size[1]} {size[2]}</size></box></geometry></collision>
    <visual name="v"><geometry><box><size>{size[0]} {size[1]} {size[2]}</size></box></geometry>
      <material><diffuse>{rgba}</diffuse></material></visual>
  </link>
</model></sdf>"""


def test_a_camera_sees_a_red_plate_where_its_pose_and_camera_info_project_it_and_depth_to_1_mm(make_sim):
    from gazelle.systems.sensors import Camera

    sim = make_sim()
    _spawn(sim, _box("plate", (3.0, 0.4, 0.6), (0.02, 0.4, 0.4), "1 0 0 1"), "plate")  # face at x = 2.99
    _spawn(sim, _box("wall", (6.0, 0.0, 1.0), (0.2, 20.0, 2.0), "0.5 0.5 0.5 1"), "wall")  # face at x = 5.9
    cam = next(s for s in _spawn(sim, _camera_model(), "cam").systems if isinstance(s, Camera))
    assert (cam.topics.image, cam.topics.info) == ("/bot/front/image_raw", "/bot/front/camera_info")
    sim.step(1)
    assert cam._renderer is None  # nobody subscribed: nothing was rendered
    images, infos = _record(sim, "/bot/front/image_raw"), _record(sim, "/bot/front/camera_info")
    sim.step(100)
    image, info = images[-1], infos[-1]
    assert (image.width, image.height, image.encoding, image.frame_id) == (320, 240, "rgb8", "camera_link")
    f = 160 / math.tan(0.6)
    # gazebo_ros_camera's CameraInfo: the principal point at ((w + 1) / 2, (h + 1) / 2) (see the next test)
    assert info.k == pytest.approx((f, 0, 160.5, 0, f, 120.5, 0, 0, 1)) and info.p[0] == pytest.approx(f)
    rgb = np.frombuffer(image.data, np.uint8).reshape(240, 320, 3)
    red = (rgb[..., 0] > 100) & (rgb[..., 1] < 60) & (rgb[..., 2] < 60)
    assert red.sum() > 100
    ys, xs = np.nonzero(red)
    # the plate's centre (2.99 m ahead, 0.4 m left, 0.1 m up from the camera) through K
    u, v = 160 - f * 0.4 / 2.99, 120 - f * 0.1 / 2.99
    assert abs(xs.mean() + 0.5 - u) <= 1.0 and abs(ys.mean() + 0.5 - v) <= 1.0
    frame = cam.render(sim.world, depth=True)
    assert frame is not None
    _rgb, depth = frame
    assert depth is not None
    assert abs(depth[120, 160] - 5.9) < 1e-3  # the wall straight ahead
    assert abs(depth[int(v), int(u)] - 2.99) < 1e-3  # the plate, perpendicular to the axis
    assert math.isinf(depth[0, 160]) and depth[0, 160] > 0  # the sky: nothing within 50 m


def test_camera_info_is_what_each_gazebo_publishes_and_classics_plugin_parameters_set_it(caplog, make_sim):
    """gazebo_ros_camera.cpp (ros2 branch): cx, cy default to (w + 1) / 2, (h + 1) / 2; <focal_length> (warned
    when it disagrees with the field of view), <cx>, <cy>, <hack_baseline> (P's Tx = -f · baseline),
    <rectification_matrix>, <P_fx>.. <Ty> set the message. gz-sensors (no <lens><intrinsics>): the centre at
    (w / 2, h / 2) from the projection, and <camera_info_topic> names its topic."""
    from gazelle.systems.sensors import Camera

    f = 160 / math.tan(0.6)
    sim = make_sim()
    params = (
        "<cx>150</cx><cy>100</cy><focal_length>250</focal_length><hack_baseline>0.07</hack_baseline>"
        "<rectification_matrix>0 1 0 1 0 0 0 0 1</rectification_matrix><P_cy>90</P_cy><Ty>0.5</Ty>"
    )
    xml = _camera_model().replace("</ros></plugin>", f"</ros>{params}</plugin>")
    with caplog.at_level(logging.WARNING):
        cam = next(s for s in _spawn(sim, xml, "cam").systems if isinstance(s, Camera))
    info = cam.info(0.0)
    assert info.k == pytest.approx((250, 0, 150, 0, 250, 100, 0, 0, 1))
    assert info.r == pytest.approx((0, 1, 0, 1, 0, 0, 0, 0, 1))
    assert info.p == pytest.approx((250, 0, 150, -250 * 0.07, 0, 250, 90, 0.5, 0, 0, 1, 0))
    assert any("<focal_length> [250" in r.getMessage() and f"[{f:f}]" in r.getMessage() for r in caplog.records)
    gz = (
        _camera_model()
        .replace(
            '<plugin name="front_camera" filename="libgazebo_ros_camera.so"><ros><namespace>/bot</namespace></ros></plugin>',
            "<topic>cam/image</topic>",
        )
        .replace("<horizontal_fov>", "<camera_info_topic>/cam/info</camera_info_topic><horizontal_fov>")
    )
    cam = next(s for s in _spawn(sim, gz, "gzcam").systems if isinstance(s, Camera))
    assert (cam.topics.image, cam.topics.info) == ("/cam/image", "/cam/info")
    assert cam.info(0.0).k == pytest.approx((f, 0, 160, 0, f, 120, 0, 0, 1))


def test_camera_elements_gazelle_does_not_render_are_named(caplog, make_sim):
    """What would change the image in Gazebo but not here is warned about, not dropped: <lens><intrinsics>
    (gz renders with them), a triggered camera (it publishes at its rate here), and the like."""
    sim = make_sim()
    extra = "<lens><intrinsics><fx>300</fx><fy>300</fy><cx>160</cx><cy>120</cy></intrinsics></lens>"
    extra += "<triggered>true</triggered><visibility_mask>3</visibility_mask>"
    gz = _camera_model().replace("<horizontal_fov>", extra + "<horizontal_fov>")
    with caplog.at_level(logging.WARNING):
        _spawn(sim, gz, "cam")
    said = " ".join(r.getMessage() for r in caplog.records)
    for name in ("<lens>", "<triggered>", "<visibility_mask>"):
        assert f"{name}" in said and "not simulated" in said, (name, said)
    classic = _camera_model().replace("</ros></plugin>", "</ros><triggered>true</triggered></plugin>")
    caplog.clear()
    with caplog.at_level(logging.WARNING):
        _spawn(sim, classic, "cam2")
    assert any("<triggered>" in r.getMessage() and "image_trigger" in r.getMessage() for r in caplog.records)


def test_a_gazebo_ros_depth_camera_reads_minus_inf_nearer_than_its_min_depth(make_sim):
    """gazebo_ros_camera.cpp OnNewDepthFrame: depth <= <min_depth> (0.4 m by default) is -inf, >= <max_depth>
    (+inf by default) +inf, in the depth image and the points."""
    from gazelle.systems.sensors import Camera

    sim = make_sim()
    _spawn(sim, _box("wall", (0.4, 0.0, 1.0), (0.2, 20.0, 4.0), "0.5 0.5 0.5 1"), "wall")  # face at x = 0.3
    for params, expected in (
        ("", -math.inf),
        ("<min_depth>0.1</min_depth>", 0.3),
        ("<max_depth>0.25</max_depth><min_depth>0.1</min_depth>", math.inf),
    ):
        xml = _camera_model("depth", width=64, height=48).replace("</ros></plugin>", f"</ros>{params}</plugin>")
        name = f"cam{len(params)}"
        cam = next(s for s in _spawn(sim, xml, name).systems if isinstance(s, Camera))
        depths = _record(sim, cam.topics.depth)
        sim.step(1)
        d = np.frombuffer(depths[-1].data, "<f4").reshape(48, 64)
        assert d[24, 32] == pytest.approx(expected, abs=1e-3), params
        sim.delete(name)


def test_a_depth_camera_publishes_32fc1_and_an_organised_cloud_as_gazebo_ros_camera_does(make_sim):
    """gazebo_ros_camera.cpp OnNewDepthFrame: an organised cloud (one point per pixel, row by row) in the optical
    frame (x right, y down, z the depth), fields x, y, z and rgb at byte 16 of 32 (PCL's PointXYZRGB, the
    image's r, g, b bytes copied there as Classic copies them), ±inf outside the valid depths, not dense."""
    from gazelle.systems.sensors import Camera

    sim = make_sim()
    _spawn(sim, _box("wall", (3.1, 0.0, 0.5), (0.2, 20.0, 1.0), "1 0 0 1"), "wall")  # face at x = 3, red, 1 m tall
    cam = next(
        s for s in _spawn(sim, _camera_model("depth", width=64, height=48), "cam").systems if isinstance(s, Camera)
    )
    assert (cam.topics.depth, cam.topics.points) == ("/bot/front/depth/image_raw", "/bot/front/points")
    depths, clouds = _record(sim, "/bot/front/depth/image_raw"), _record(sim, "/bot/front/points")
    sim.step(1)
    d = np.frombuffer(depths[-1].data, "<f4").reshape(48, 64)
    assert depths[-1].encoding == "32FC1"
    assert np.nanmax(np.abs(d[20:28, :] - 3.0)) < 1e-3  # the wall fills the middle rows, 3 m along the axis
    cloud = clouds[-1]
    assert (cloud.width, cloud.height, cloud.layout.point_step, cloud.is_dense) == (64, 48, 32, False)
    assert dict(cloud.layout.fields) == {"x": 0, "y": 4, "z": 8, "rgb": 16}
    raw = np.frombuffer(cloud.data, np.uint8).reshape(48, 64, 32)
    xyz = raw[..., :12].copy().view("<f4").reshape(48, 64, 3)
    assert np.allclose(xyz[20:28, :, 2], d[20:28, :], atol=1e-6)  # z is the depth
    fl = 64 / (2 * math.tan(0.6))
    i = np.arange(64)
    assert np.allclose(xyz[24, :, 0], d[24, :] * np.tan(np.arctan2(i - 31.5, fl)), atol=1e-4)  # x right
    assert xyz[20, 32, 1] < 0 < xyz[27, 32, 1]  # y down
    assert np.all(np.isinf(xyz[0, :, :])) and xyz[0, 0, 2] > 0  # the sky above the wall: +inf points
    assert raw[24, 32, 16] > 100 and raw[24, 32, 17] < 60 and raw[24, 32, 18] < 60  # r, g, b bytes


def test_a_gz_depth_camera_cloud_is_organised_in_its_x_forward_frame(make_sim):
    """gz-sensors PointCloudUtil::FillMsg (DepthCameraSensor): organised, x the depth, y to the left and z up
    (the sensor frame, not the optical one), fields x, y, z, rgb at 0, 4, 8, 12 in 16 bytes (gz-msgs
    InitPointCloudPacked, not memory-aligned), the colour's bytes b, g, r."""
    from gazelle.systems.sensors import Camera

    sim = make_sim()
    _spawn(sim, _box("wall", (3.1, 0.0, 1.0), (0.2, 20.0, 4.0), "0 0 1 1"), "wall")  # blue
    gz = _camera_model("depth_camera", width=64, height=48).replace(
        '<plugin name="front_camera" filename="libgazebo_ros_camera.so"><ros><namespace>/bot</namespace></ros></plugin>',
        "<topic>depth</topic>",
    )
    cam = next(s for s in _spawn(sim, gz, "cam").systems if isinstance(s, Camera))
    assert cam.topics.points == "/depth/points"
    clouds = _record(sim, "/depth/points")
    sim.step(1)
    cloud = clouds[-1]
    assert (cloud.width, cloud.height, cloud.layout.point_step) == (64, 48, 16)
    assert dict(cloud.layout.fields) == {"x": 0, "y": 4, "z": 8, "rgb": 12}
    raw = np.frombuffer(cloud.data, np.uint8).reshape(48, 64, 16)
    xyz = raw[..., :12].copy().view("<f4").reshape(48, 64, 3)
    assert np.allclose(xyz[20:28, :, 0], 3.0, atol=1e-3)  # x forward: the depth
    assert xyz[24, 0, 1] > 1.0 and xyz[24, 63, 1] < -1.0  # the image's left is +y
    assert xyz[20, 32, 2] > 0 > xyz[27, 32, 2]  # up is +z
    assert raw[24, 32, 12] > 100 and raw[24, 32, 13] < 60 and raw[24, 32, 14] < 60  # b, g, r bytes


def test_a_camera_names_the_topics_it_publishes_images_on(caplog, make_sim):
    """Issue 55 item 9: a gz depth camera (its <topic> is the depth image, no colour image) logged
    `on [] and [/depth]`; each camera names the topics it really publishes images and clouds on."""
    sim = make_sim()
    gz = _camera_model("depth_camera", width=64, height=48).replace(
        '<plugin name="front_camera" filename="libgazebo_ros_camera.so"><ros><namespace>/bot</namespace></ros></plugin>',
        "<topic>depth</topic>",
    )
    rgbd = gz.replace('type="depth_camera"', 'type="rgbd_camera"').replace(
        "<topic>depth</topic>", "<topic>rgbd</topic>"
    )
    with caplog.at_level(logging.INFO):
        _spawn(sim, gz, "depth")
        _spawn(sim, rgbd, "rgbd")
        _spawn(sim, _camera_model(), "plain")
    said = [r.getMessage() for r in caplog.records if "' at " in r.getMessage() or ": 64x48 at" in r.getMessage()]
    said += [r.getMessage() for r in caplog.records if ": 320x240 at" in r.getMessage()]
    assert any("depth_camera 'front': 64x48 at 10 Hz on [/depth] and [/depth/points] in frame" in m for m in said), said
    assert any(
        "rgbd_camera 'front': 64x48 at 10 Hz on [/rgbd/image] and [/rgbd/depth_image] and [/rgbd/points]" in m
        for m in said
    ), said
    assert any("camera 'front': 320x240 at 10 Hz on [/bot/front/image_raw] in frame" in m for m in said), said
    assert not any("[]" in m for m in said), said


def test_a_camera_of_zero_pixels_is_an_error_naming_file_and_line(caplog, make_sim):
    sim = make_sim()
    with caplog.at_level(logging.ERROR):
        _spawn(sim, _camera_model(width=0), "cam")
    assert any(
        "<string>.sdf:4: sensor 'front': a camera of 0x240 pixels cannot render" in r.getMessage()
        for r in caplog.records
    )


def _bumper_plate(plugin: bool = True) -> str:
    plug = (
        '<plugin name="bumper" filename="libgazebo_ros_bumper.so"><ros><namespace>/plate</namespace></ros></plugin>'
        if plugin
        else ""
    )
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="plate"><static>true</static>
  <link name="base">
    <collision name="plate_collision"><geometry><box><size>1 1 0.02</size></box></geometry></collision>
    <sensor name="bumper" type="contact">
      <update_rate>50</update_rate>
      <contact><collision>plate_collision</collision><topic>bumps</topic></contact>
      {plug}
    </sensor>
  </link>
</model></sdf>"""


def test_a_box_dropped_on_a_bumper_plate_gives_contacts_naming_both_collisions_and_its_weight(make_sim):
    from gazelle.systems import Contacts
    from gazelle.systems.sensors import ContactSensor

    sim = make_sim()
    plate = _spawn(sim, _bumper_plate(), "plate", Pose((0.0, 0.0, 0.01)))
    sensor = next(s for s in plate.systems if isinstance(s, ContactSensor))
    assert sensor.output is not None and (sensor.output.topic, sensor.output.frame_id) == (
        "/plate/bumper_states",
        "world",
    )
    got = _record(sim, "/plate/bumper_states")
    sim.step(100)
    assert got and all(msg.states == () for msg in got)  # nothing on it yet
    box = load_string(BOX_2KG).model
    sim.spawn(box, name="box", pose=Pose((0.0, 0.0, 0.3)))
    sim.step(1500)  # falls and comes to rest
    msg: Contacts = got[-1]
    assert msg.stamp_sec == pytest.approx(1.6, abs=1e-9)
    assert [(s.collision1, s.collision2) for s in msg.states] == [("plate::base::plate_collision", "box::link::c")]
    pair = msg.states[0]
    total = np.sum(pair.forces, axis=0)
    assert total == pytest.approx((0.0, 0.0, -2.0 * 9.8), abs=0.05)  # the box's weight, on the plate
    assert all(n == pytest.approx((0.0, 0.0, -1.0), abs=1e-6) for n in pair.normals)  # from the box into the plate
    assert all(abs(p[2] - 0.02) < 0.002 for p in pair.positions) and all(0 <= d < 1e-3 for d in pair.depths)


def test_contacts_of_a_few_geoms_among_many_are_exactly_those_involving_them(make_sim):
    """contacts_of finds a link's contacts among all of the world's in numpy (a chess set at rest has ~130 and a
    bumper on every arm link asks for each): the same contacts as MuJoCo's list read one by one, in its order,
    each seen from the asked geom's side."""
    sim = make_sim()
    for k in range(12):
        sim.spawn(load_string(BOX_2KG).model, name=f"box{k}", pose=Pose(((k % 4) * 0.3, (k // 4) * 0.3, 0.2)))
    sim.step(600)
    world = sim.world
    mine = world.collision_geoms("box5", "link") | world.collision_geoms("box7", "link")
    d = world.data
    expected = []
    for i in range(int(d.ncon)):  # MuJoCo's list, read one by one
        g1, g2 = int(d.contact[i].geom1), int(d.contact[i].geom2)
        if g1 in mine or g2 in mine:
            expected.append(g1 if g1 in mine else g2)
    assert int(d.ncon) > 4 * len(expected) > 0  # most contacts are other boxes'
    got = world.contacts_of(mine)
    assert [p.collision1 for p in got] == [
        "box5::link::c" if world.collision_geoms("box5", "link") >= {g} else "box7::link::c" for g in expected
    ]
    assert all(p.normal[2] == pytest.approx(1.0, abs=1e-6) for p in got)  # from the ground into the box
    assert world.contacts_of(frozenset()) == []


def test_a_gz_contact_sensor_publishes_ros_gz_contacts_on_its_contact_topic_only_while_touched(make_sim):
    """gz-sim's Contact system (gz-sim8 src/systems/contact/Contact.cc): <contact><topic>, every step that has
    contacts and none without; ros_gz_bridge makes ros_gz_interfaces/Contacts of it (one Contact per pair,
    named, each point's wrench pair: the force on collision1 and its opposite)."""
    from gazelle.ros._convert import to_ros
    from gazelle.systems import MsgType
    from gazelle.systems.sensors import ContactSensor

    sim = make_sim()  # the default world runs gz-sim's contact system
    plate = _spawn(sim, _bumper_plate(plugin=False), "plate", Pose((0.0, 0.0, 0.01)))
    sensor = next(s for s in plate.systems if isinstance(s, ContactSensor))
    assert sensor.output is not None
    assert (sensor.output.topic, sensor.output.frame_id, sensor.output.msg_type) == ("/bumps", "", MsgType.GZ_CONTACTS)
    got = _record(sim, "/bumps")
    sim.step(100)
    assert got == []  # nothing touches it: nothing is sent
    sim.spawn(load_string(BOX_2KG).model, name="box", pose=Pose((0.0, 0.0, 0.3)))
    sim.step(1500)
    first = got[0].stamp_sec
    assert len(got) == round((1.6 - first) / 0.001) + 1  # every step since the box landed (the rate is not read)
    msg = to_ros(MsgType.GZ_CONTACTS)(got[-1])
    assert type(msg).__name__ == "Contacts" and type(msg).__module__.startswith("ros_gz_interfaces")
    assert [(c.collision1.name, c.collision2.name) for c in msg.contacts] == [
        ("plate::base::plate_collision", "box::link::c")
    ]
    contact = msg.contacts[0]
    assert len(contact.positions) == len(contact.normals) == len(contact.depths) == len(contact.wrenches) > 0
    total = [sum(getattr(w.body_1_wrench.force, a) for w in contact.wrenches) for a in "xyz"]
    assert total == pytest.approx([0.0, 0.0, -2.0 * 9.8], abs=0.05)
    assert all(w.body_2_wrench.force.z == -w.body_1_wrench.force.z for w in contact.wrenches)


def test_a_gz_contact_sensor_names_the_topic_and_rate_gz_sim_does_not_read(caplog, make_sim):
    from gazelle.systems.sensors import ContactSensor

    xml = (
        _bumper_plate(plugin=False)
        .replace("<topic>bumps</topic>", "")
        .replace("<update_rate>50</update_rate>", "<update_rate>50</update_rate><topic>mine</topic>")
    )
    with caplog.at_level(logging.WARNING):
        plate = _spawn(make_sim(), xml, "plate", Pose((0.0, 0.0, 0.01)))
    sensor = next(s for s in plate.systems if isinstance(s, ContactSensor))
    assert sensor.output is not None
    assert sensor.output.topic == "/world/default/model/plate/link/base/sensor/bumper/contact"
    said = " ".join(r.getMessage() for r in caplog.records)
    assert "not the sensor's <topic> 'mine'" in said and "does not read <update_rate> (50 Hz)" in said


def test_a_contact_sensor_naming_a_collision_its_link_lacks_is_an_error_with_file_and_line(caplog, make_sim):
    sim = make_sim()
    with caplog.at_level(logging.ERROR):
        _spawn(
            sim, _bumper_plate().replace("<collision>plate_collision</collision>", "<collision>nope</collision>"), "p"
        )
    assert any(
        "<string>.sdf:5: contact sensor 'bumper': its <collision> nope is not a collision of link 'base'"
        in r.getMessage()
        for r in caplog.records
    ), [r.getMessage() for r in caplog.records]


def _gps_box() -> str:
    return """<?xml version="1.0"?>
<sdf version="1.9"><model name="rover"><static>true</static>
  <link name="base">
    <sensor name="gps" type="gps">
      <update_rate>10</update_rate>
      <plugin name="gps" filename="libgazebo_ros_gps_sensor.so"><ros><remapping>~/out:=fix</remapping></ros></plugin>
    </sensor>
  </link>
</model></sdf>"""


def test_a_gps_moved_100_m_north_changes_latitude_by_100_m_over_the_earth_radius(make_sim):
    from gazelle.description import SphericalCoordinates
    from gazelle.systems import NavSatFix
    from gazelle.systems.sensors import GpsSensor

    origin = SphericalCoordinates(latitude_deg=47.0, longitude_deg=8.0, elevation=400.0)
    sim = make_sim(dataclasses.replace(default_world(), spherical_coordinates=origin))
    entity = _spawn(sim, _gps_box(), "rover")
    gps = next(s for s in entity.systems if isinstance(s, GpsSensor))
    fixes, vels = _record(sim, "/fix"), _record(sim, "/gps/vel")
    sim.step(1)
    home: NavSatFix = fixes[-1]
    assert (home.latitude, home.longitude, home.altitude) == pytest.approx((47.0, 8.0, 400.0), abs=1e-9)
    sim.world.set_entity_state("rover", Pose((0.0, 100.0, 0.0)))  # ENU, heading 0: +y is north
    sim.step(100)
    north: NavSatFix = fixes[-1]
    earth = 6_371_000.0
    assert math.radians(north.latitude - 47.0) == pytest.approx(100.0 / earth, rel=0.01)
    assert north.longitude == pytest.approx(8.0, abs=1e-9)
    sim.world.set_entity_state("rover", Pose((100.0, 0.0, 10.0)))  # +x is east
    sim.step(100)
    east: NavSatFix = fixes[-1]
    assert math.radians(east.longitude - 8.0) * math.cos(math.radians(47.0)) == pytest.approx(100.0 / earth, rel=0.01)
    assert east.altitude == pytest.approx(410.0, abs=1e-6)
    assert vels and vels[-1].vector == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    assert gps.output is not None and gps.output.frame_id == "base"


def _gps_fix_with_noise(make_sim, inner: str, horizontal: str, vertical: str = ""):
    """The first fix of a GPS at the origin (47° N, 8° E, 400 m) run by ``inner`` (a plugin or a <topic>)."""
    from gazelle.description import SphericalCoordinates

    origin = SphericalCoordinates(latitude_deg=47.0, longitude_deg=8.0, elevation=400.0)
    sim = make_sim(dataclasses.replace(default_world(), spherical_coordinates=origin))
    noise = f"""<gps><position_sensing><horizontal><noise type="gaussian">{horizontal}</noise></horizontal>
      <vertical><noise type="gaussian">{vertical}</noise></vertical></position_sensing></gps>"""
    plugin = '<plugin name="gps" filename="libgazebo_ros_gps_sensor.so"><ros><remapping>~/out:=fix</remapping></ros></plugin>'
    _spawn(sim, _gps_box().replace(plugin, inner + noise), "rover")
    fixes = _record(sim, "/fix")
    sim.step(1)
    return fixes[-1]


def test_gps_position_noise_is_metres_with_gazebo_ros_and_degrees_with_gz_sim(make_sim):
    """Classic GpsSensor::UpdateImpl adds position noise in metres to the Gazebo frame's x, y, z before turning
    them into latitude and longitude; gz-sensors' NavSatSensor::Update adds it to the latitude and longitude in
    degrees (one model, so one bias, for both) and to the altitude in metres."""
    plugin = '<plugin name="gps" filename="libgazebo_ros_gps_sensor.so"><ros><remapping>~/out:=fix</remapping></ros></plugin>'
    earth = 6_371_000.0
    fix = _gps_fix_with_noise(make_sim, plugin, "<mean>1.0</mean>", "<mean>2.0</mean>")
    assert math.radians(fix.latitude - 47.0) == pytest.approx(1.0 / earth, rel=0.01)  # 1 m north
    assert math.radians(fix.longitude - 8.0) * math.cos(math.radians(47.0)) == pytest.approx(1.0 / earth, rel=0.01)
    assert fix.altitude == pytest.approx(402.0, abs=1e-9)
    fix = _gps_fix_with_noise(make_sim, "<topic>fix</topic>", "<mean>0.001</mean>", "<mean>2.0</mean>")
    assert (fix.latitude, fix.longitude, fix.altitude) == pytest.approx((47.001, 8.001, 402.0), abs=1e-12)
    fix = _gps_fix_with_noise(make_sim, "<topic>fix</topic>", "<bias_mean>0.01</bias_mean>")
    assert abs(fix.latitude - 47.0) == pytest.approx(0.01, abs=1e-12)
    assert fix.longitude - 8.0 == pytest.approx(fix.latitude - 47.0, abs=1e-12)  # the one bias on both


def _arm(sensor: str = "", plugin: str = "") -> str:
    return f"""<?xml version="1.0"?>
<sdf version="1.9"><model name="arm">
  <link name="base"><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
  <joint name="mount" type="fixed"><parent>world</parent><child>base</child></joint>
  <link name="bob"><pose>0.5 0 1 0 0 0</pose>
    <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
  <joint name="wrist" type="fixed"><pose relative_to="base">0 0 1 0 0 0</pose><parent>base</parent><child>bob</child>
    {sensor}
  </joint>
  {plugin}
</model></sdf>"""


def test_a_force_torque_sensor_reads_the_weight_and_moment_a_joint_carries(make_sim):
    from gazelle.systems.sensors import ForceTorqueSensor

    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, -9.81))
    gz = """<sensor name="ft" type="force_torque"><update_rate>100</update_rate>
      <force_torque><frame>child</frame><measure_direction>parent_to_child</measure_direction></force_torque></sensor>"""
    ros = """<plugin name="ft" filename="libgazebo_ros_ft_sensor.so">
      <ros><namespace>/arm</namespace></ros><joint_name>wrist</joint_name><update_rate>100</update_rate></plugin>"""
    for sensor, plugin, topic in (
        (gz, "", "/world/default/model/arm/joint/wrist/sensor/ft/forcetorque"),
        ("", ros, "/arm/wrench"),
    ):
        sim = make_sim(world)
        entity = _spawn(sim, _arm(sensor, plugin), "arm")
        ft = next(s for s in entity.systems if isinstance(s, ForceTorqueSensor))
        assert ft.topic == topic and ft.frame_id == "bob"
        got = _record(sim, topic)
        sim.step(20)
        w = got[-1]
        # the 2 kg bob hangs 0.5 m out from the wrist: the parent holds up 19.62 N and -9.81 N m about y
        assert w.force == pytest.approx((0.0, 0.0, 2 * 9.81), abs=1e-6)
        assert w.torque == pytest.approx((0.0, -0.5 * 2 * 9.81, 0.0), abs=1e-6)
    # gz's default direction: what the child exerts on the parent
    sim = make_sim(world)
    entity = _spawn(sim, _arm(gz.replace("parent_to_child", "child_to_parent")), "arm")
    ft = next(s for s in entity.systems if isinstance(s, ForceTorqueSensor))
    sim.step(2)
    f, _t = ft.read(sim.world)
    assert f == pytest.approx((0.0, 0.0, -2 * 9.81), abs=1e-6)


def test_a_gz_force_torque_sensor_adds_each_channels_noise(make_sim):
    """gz-sensors 8 ForceTorqueSensor: <force>/<torque> <x|y|z><noise> are six Gaussian models, one per channel,
    added to the wrench in its output frame (gazelle read none of them before)."""
    from gazelle.systems.sensors import ForceTorqueSensor

    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, -9.81))
    noise = "<force><z><noise type='gaussian'><mean>1.5</mean></noise></z></force>"
    noise += "<torque><x><noise type='gaussian'><stddev>0.2</stddev></noise></x></torque>"
    gz = f"""<sensor name="ft" type="force_torque"><update_rate>100</update_rate>
      <force_torque><measure_direction>parent_to_child</measure_direction>{noise}</force_torque></sensor>"""
    sim = make_sim(world)
    ft = next(s for s in _spawn(sim, _arm(gz), "arm").systems if isinstance(s, ForceTorqueSensor))
    sim.step(2)
    readings = [ft.read(sim.world) for _ in range(2000)]
    fz = {float(f[2]) for f, _ in readings}
    tx = np.array([float(t[0]) for _, t in readings])
    assert len(fz) == 1 and fz.pop() == pytest.approx(2 * 9.81 + 1.5, abs=1e-6)  # the mean alone: the same each time
    assert tx.std() == pytest.approx(0.2, rel=0.1) and abs(tx.mean()) < 0.03
    assert all(float(f[0]) == pytest.approx(0.0, abs=1e-6) for f, _ in readings)  # no noise on force x


def test_namespaced_robots_get_namespaced_sensor_topics_and_prefixed_frames(make_sim):
    """Two sensor_bots spawned with namespaces (as `gazelle spawn -robot_namespace r1`): each sensor's
    topics and frames are its own (gz-sensors #359 is about sensors that ignored the namespace)."""
    from gazelle.systems.sensors import Camera, ImuSensor

    sim = make_sim()
    bot = load(REPO / "examples/sensor_bot/sensor_bot.urdf").model
    for i, ns in enumerate(("r1", "r2")):
        entity = sim.spawn(bot, name=f"bot_{ns}", pose=Pose((0.0, 2.0 * i, 0.07)), namespace=ns)
        lidar = _lidar(entity)
        cam = next(s for s in entity.systems if isinstance(s, Camera))
        imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
        assert lidar.output is not None and imu.output is not None and cam.output is not None
        assert (lidar.output.topic, lidar.output.frame_id) == (f"/{ns}/scan", f"{ns}/base_scan")
        assert (imu.output.topic, imu.output.frame_id) == (f"/{ns}/imu", f"{ns}/imu_link")
        assert (cam.topics.image, cam.topics.info, cam.output.frame_id) == (
            f"/{ns}/camera/image_raw",
            f"/{ns}/camera/camera_info",
            f"{ns}/camera_link",
        )


def test_an_unknown_sensor_type_is_named_with_a_did_you_mean_and_an_unsimulated_one_as_not_yet():
    xml = _lidar_model().replace('type="ray"', 'type="lidarr"')
    _plans, problems = plan_sensors(load_string(xml).model, default_world().plugins)
    assert [(p.message, p.location.line if p.location else None) for p in problems] == [
        (
            "sensor 'laser' (lidarr) on link 'base': 'lidarr' is not an SDF sensor type, so nothing runs it; "
            "did you mean 'lidar'?",
            5,
        )
    ]
    gz = """<?xml version="1.0"?><sdf version="1.9"><model name="m"><link name="l">
      <sensor name="baro" type="air_speed"><update_rate>10</update_rate></sensor></link></model></sdf>"""
    plans, problems = plan_sensors(load_string(gz).model, default_world().plugins)
    assert plans == [] and [p.message for p in problems] == [
        "sensor 'baro' (air_speed) on link 'l' is not simulated yet"
    ]


def test_a_camera_keeps_rendering_across_recompiles_and_a_deleted_one_frees_its_gl_context(make_sim):
    from gazelle.systems.sensors import Camera

    sim = make_sim()
    bot = load(REPO / "examples/sensor_bot/sensor_bot.urdf").model
    cam = next(s for s in sim.spawn(bot, name="bot", pose=Pose((0.0, 0.0, 0.07))).systems if isinstance(s, Camera))
    first = cam.render(sim.world, depth=True)
    assert first is not None and first[1] is not None and np.isinf(first[1][0, 160])  # the sky
    # a wall spawned in front recompiles the model: the renderer follows the new model
    _spawn(sim, _box("wall", (2.1, 0.0, 1.0), (0.2, 6.0, 2.0), "1 0 0 1"), "wall")
    again = cam.render(sim.world, depth=True)
    assert (
        again is not None and again[1] is not None and abs(again[1][120, 160] - (2.0 - 0.17)) < 0.01
    )  # the wall, from the camera at x 0.17
    renderer = cam._renderer
    assert renderer is not None and renderer._gl is not None
    sim.delete("bot")
    assert cam._renderer is None and renderer._gl is None  # shut down with its entity
    cam2 = next(s for s in sim.spawn(bot, name="bot", pose=Pose((0.0, 0.0, 0.07))).systems if isinstance(s, Camera))
    third = cam2.render(sim.world, depth=False)
    assert third is not None and (third[0][100:120, 150:170, 0] > 100).mean() > 0.9  # the red wall again


def test_a_lidar_or_camera_too_large_to_simulate_is_refused_with_file_and_line_and_the_world_goes_on(make_sim):
    # issue 25: past a bound, the spawn is refused with the reason (it was accepted with the sensor off)
    sim = make_sim()
    vertical = "<vertical><samples>2000</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical>"
    with pytest.raises(Exception) as lidar:
        _spawn(sim, _lidar_model(samples=10_000, vertical=vertical), "huge_lidar")
    assert "<string>.sdf:5: sensor 'laser': 2000 x 10000 rays is more than the 1,048,576" in str(lidar.value)
    with pytest.raises(Exception) as cam:
        _spawn(sim, _camera_model(width=100_000, height=100_000), "huge_cam")
    assert "<string>.sdf:4: sensor 'front': a camera of 100000x100000 pixels is larger than" in str(cam.value)
    assert "huge_lidar" not in sim.world.entities and "huge_cam" not in sim.world.entities
    sim.step(10)  # the world steps on


@pytest.mark.parametrize("frame", ["base", "nope"])
def test_a_bumper_frame_name_only_labels_the_header_the_contacts_stay_in_the_world_frame(caplog, make_sim, frame):
    """ROS 2's gazebo_ros_bumper.cpp writes <frame_name> into the header and nothing else (its
    Convert<ContactsState> keeps the frame rotation at identity); ROS 1's turned the contacts into that frame."""
    from gazelle.systems import Contacts

    sim = make_sim()
    xml = _bumper_plate().replace("</ros></plugin>", f"</ros><frame_name>{frame}</frame_name></plugin>")
    with caplog.at_level(logging.WARNING):
        _spawn(sim, xml, "plate", Pose((0.0, 0.0, 0.5)))
    assert any(f"<frame_name> '{frame}': as gazebo_ros_bumper in ROS 2" in r.getMessage() for r in caplog.records)
    got = _record(sim, "/plate/bumper_states")
    sim.spawn(load_string(BOX_2KG).model, name="box", pose=Pose((0.0, 0.0, 0.8)))
    sim.step(800)
    msg: Contacts = got[-1]
    assert msg.frame_id == frame and msg.states
    assert all(abs(p[2] - 0.51) < 0.002 for p in msg.states[0].positions)  # the plate's top face, in the world


MAG_BOT = """<?xml version="1.0"?>
<sdf version="1.9"><model name="mag"><static>true</static><pose>0 0 0.5 0 0 {yaw}</pose>
<link name="base">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <sensor name="mag" type="magnetometer"><update_rate>50</update_rate><topic>mag</topic>{noise}</sensor>
</link></model></sdf>"""


def _magnetometer_readings(yaw: float, noise: str = "", steps: int = 400) -> list:
    from gazelle.description import load_string
    from gazelle.systems import MsgType

    sim = new_simulation()
    sim.spawn(load_string(MAG_BOT.format(yaw=yaw, noise=noise)).model, name="mag")
    got: list = []
    (ep,) = [e for e in sim.bus.endpoints() if e.msg_type is MsgType.MAGNETIC_FIELD]
    assert ep.topic == "/mag"
    ep.add_sink(got.append)
    sim.step(steps)
    return got


def test_a_magnetometer_reads_the_world_field_in_its_own_frame():
    from gazelle.description import DEFAULT_MAGNETIC_FIELD

    bx, by, bz = DEFAULT_MAGNETIC_FIELD
    (level,) = {r.field for r in _magnetometer_readings(0.0)}
    assert level == pytest.approx((bx, by, bz), abs=1e-12)
    turned = _magnetometer_readings(math.pi / 2)[-1].field  # turned 90 deg left: world +y is its +x
    assert turned == pytest.approx((by, -bx, bz), abs=1e-12)


def test_magnetometer_noise_has_the_configured_stddev():
    noise = "".join(f"<{ax}><noise type='gaussian'><mean>0</mean><stddev>1e-6</stddev></noise></{ax}>" for ax in "xyz")
    readings = _magnetometer_readings(0.0, f"<magnetometer>{noise}</magnetometer>", steps=200_000)
    xs = np.array([r.field[0] for r in readings])
    assert len(xs) >= 9_000
    assert xs.std() == pytest.approx(1e-6, rel=0.1)
    # gz's Magnetometer message has no covariance: ros_gz_bridge leaves the ROS one zeros
    assert readings[-1].covariance == (0.0,) * 9


def test_a_world_magnetic_field_is_read_and_reaches_the_magnetometer(make_sim):
    from gazelle.description import load_string
    from gazelle.systems import MsgType

    world = load_string(
        '<sdf version="1.9"><world name="w"><magnetic_field>2e-5 0 -3e-5</magnetic_field>'
        '<plugin filename="gz-sim-magnetometer-system" name="gz::sim::systems::Magnetometer"/></world></sdf>'
    ).world
    assert world.magnetic_field == (2e-5, 0.0, -3e-5)
    sim = make_sim(world)
    sim.spawn(load_string(MAG_BOT.format(yaw=0.0, noise="")).model, name="mag")
    got: list = []
    next(e for e in sim.bus.endpoints() if e.msg_type is MsgType.MAGNETIC_FIELD).add_sink(got.append)
    sim.step(100)
    assert got[-1].field == pytest.approx((2e-5, 0.0, -3e-5), abs=1e-12)


ALT_BOX = """<?xml version="1.0"?>
<sdf version="1.9"><model name="alt"><pose>0 0 2 0 0 0</pose>
<link name="base">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>
  <sensor name="alt" type="altimeter"><update_rate>100</update_rate><topic>altimeter</topic></sensor>
</link></model></sdf>"""


def test_an_altimeter_reads_height_above_where_it_started_and_vertical_velocity(make_sim):
    from gazelle.description import load_string
    from gazelle.systems import MsgType

    sim = make_sim()
    sim.spawn(load_string(ALT_BOX).model, name="alt")
    got: list = []
    (ep,) = [e for e in sim.bus.endpoints() if e.msg_type is MsgType.ALTIMETER]
    assert ep.topic == "/altimeter"
    ep.add_sink(got.append)
    sim.step(300)  # free fall from 2 m for 0.3 s
    last = got[-1]
    z = sim.world.entity_state("alt").pose.position[2]
    vz = sim.world.entity_state("alt").linear_velocity[2]
    assert last.vertical_reference == pytest.approx(2.0, abs=1e-3)
    assert last.vertical_position == pytest.approx(z - 2.0, abs=1e-3)
    assert last.vertical_position == pytest.approx(-0.5 * 9.8 * 0.3**2, abs=0.01)
    assert last.vertical_velocity == pytest.approx(vz, abs=1e-6) and vz == pytest.approx(-9.8 * 0.3, rel=0.02)


def test_altimeter_and_magnetic_field_convert_to_their_ros_messages():
    from gazelle.ros._convert import ROS_TYPES, to_ros
    from gazelle.systems import Altimeter, MagneticField, MsgType

    alt = to_ros(MsgType.ALTIMETER)(Altimeter(1.5, "alt_frame", -0.25, -1.0, 2.0))
    assert type(alt) is ROS_TYPES[MsgType.ALTIMETER] and type(alt).__module__.startswith("ros_gz_interfaces")
    assert (alt.vertical_position, alt.vertical_velocity, alt.vertical_reference) == (-0.25, -1.0, 2.0)
    assert (alt.header.stamp.sec, alt.header.stamp.nanosec, alt.header.frame_id) == (1, 500_000_000, "alt_frame")
    mag = to_ros(MsgType.MAGNETIC_FIELD)(MagneticField(2.0, "m", (1e-5, 2e-5, -3e-5)))
    assert (mag.magnetic_field.x, mag.magnetic_field.y, mag.magnetic_field.z) == (1e-5, 2e-5, -3e-5)


URDF_BUMPER = """<?xml version="1.0"?>
<robot name="plate">
  <link name="world"/>
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="1 1 0.02"/></geometry></collision>
    <collision><origin xyz="0 0 -0.2"/><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0 0 0.01"/></joint>
  <gazebo reference="base">
    <sensor name="bumper" type="contact">
      <update_rate>50</update_rate>
      <contact><collision>NAME</collision></contact>
      <plugin name="bumper" filename="libgazebo_ros_bumper.so"/>
    </sensor>
  </gazebo>
</robot>"""


@pytest.mark.parametrize("name", ["base_collision", "base_collision_0"])
def test_a_urdf_bumper_names_the_links_first_collision_as_gazebo_does(name, caplog, make_sim):
    """Gazebo names a URDF link's first unnamed collision '<link>_collision' (and the next '<link>_collision_1'):
    a bumper written for Gazebo watches it here too, and gazelle's own name for it works as well."""
    from gazelle.systems.sensors import ContactSensor

    sim = make_sim()
    with caplog.at_level(logging.ERROR):
        plate = _spawn(sim, URDF_BUMPER.replace("NAME", name), "plate")
    assert not [r.getMessage() for r in caplog.records if "contact sensor" in r.getMessage()]
    sensor = next(s for s in plate.systems if isinstance(s, ContactSensor))
    assert sensor.collisions == ("base_collision_0",)
    got = _record(sim, "/bumper_states")
    sim.spawn(load_string(BOX_2KG).model, name="box", pose=Pose((0.0, 0.0, 0.3)))
    sim.step(1500)
    assert [(s.collision1, s.collision2) for s in got[-1].states] == [("plate::base::base_collision_0", "box::link::c")]


def test_a_seeded_simulation_repeats_its_sensor_noise_and_an_unseeded_one_does_not(make_sim):
    """Issue 30: a robot test is deterministic by default. `Simulation(seed=...)` (`gazelle sim --seed`,
    the pytest plugin's --gazelle-seed) gives every noisy system its own stream from the seed and its
    names, so two runs with one seed publish the same noisy scans and IMU readings; without a seed (as
    Gazebo without --seed) the noise differs from run to run."""
    model = load(TB3 / "turtlebot3_gazebo/models/turtlebot3_burger/model.sdf").model

    def run(seed):
        sim = make_sim(seed=seed)
        _spawn(sim, _wall("wall", 1.0, 0.0, 0.2, 20.0), "wall")  # ranges to read (noise is not added to inf)
        sim.spawn(model, name="burger", pose=Pose((0.0, 0.0, 0.01)))
        scans, imus = _record(sim, "/scan"), _record(sim, "/imu")
        sim.step(401)
        assert len(scans) == 3 and len(imus) > 50
        return [bytes(s.ranges) for s in scans], [(m.linear_acceleration, m.angular_velocity) for m in imus]

    first, again, other = run(7), run(7), run(8)
    assert first == again
    assert first[0] != other[0] and first[1] != other[1]
    assert run(None)[0] != run(None)[0]


@pytest.mark.parametrize(
    ("scene", "plugin", "expected"),
    [
        ("", "", (178, 178, 178)),  # SDFormat's default <background>: 0.7 0.7 0.7
        ("<scene><background>0 0 1 1</background></scene>", "", (0, 0, 255)),
        (  # the gz-sim Sensors system's <background_color> wins over the scene's, as in gz-sim
            "<scene><background>0 0 1 1</background></scene>",
            '<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors">'
            "<render_engine>ogre2</render_engine><background_color>0 1 0</background_color></plugin>",
            (0, 255, 0),
        ),
    ],
)
def test_a_camera_sees_the_worlds_background_where_nothing_is_drawn(
    scene: str, plugin: str, expected, make_sim
) -> None:
    """Gazebo's cameras draw the world's <scene><background> behind everything (gz-sim RenderUtil.cc,
    Sensors.cc); gazelle's drew black."""
    from gazelle.systems.sensors import Camera

    world = load_string(f'<?xml version="1.0"?><sdf version="1.9"><world name="w">{plugin}{scene}</world></sdf>').world
    sim = make_sim(world)
    cam = next(s for s in _spawn(sim, _camera_model(), "cam").systems if isinstance(s, Camera))
    sim.step(1)
    frame = cam.render(sim.world, depth=True)
    assert frame is not None
    rgb, depth = frame
    assert tuple(int(c) for c in rgb[5, 160]) == expected
    assert depth is not None and math.isinf(
        depth[5, 160]
    )  # and no depth there: nothing is  # the top of the image: the sky, nothing in it


TEXTURED_QUAD_DAE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_images><image id="img"><init_from>quad.png</init_from></image></library_images>
  <library_effects><effect id="fx"><profile_COMMON>
    <newparam sid="surf"><surface type="2D"><init_from>img</init_from></surface></newparam>
    <newparam sid="samp"><sampler2D><source>surf</source></sampler2D></newparam>
    <technique sid="common"><lambert><diffuse><texture texture="samp" texcoord="UV0"/></diffuse></lambert></technique>
  </profile_COMMON></effect></library_effects>
  <library_materials><material id="mat"><instance_effect url="#fx"/></material></library_materials>
  <library_geometries><geometry id="quad"><mesh>
    <source id="pos"><float_array id="pa" count="12">0 -0.5 -0.5 0 0.5 -0.5 0 0.5 0.5 0 -0.5 0.5</float_array>
      <technique_common><accessor source="#pa" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <source id="uv"><float_array id="ua" count="8">0 0 1 0 1 1 0 1</float_array>
      <technique_common><accessor source="#ua" count="4" stride="2">
        <param name="S" type="float"/><param name="T" type="float"/></accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
    <triangles material="m" count="4">
      <input semantic="VERTEX" source="#v" offset="0"/><input semantic="TEXCOORD" source="#uv" offset="1" set="0"/>
      <p>0 0 1 1 2 2 0 0 2 2 3 3 0 0 2 2 1 1 0 0 3 3 2 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#quad">
    <bind_material><technique_common><instance_material symbol="m" target="#mat">
      <bind_vertex_input semantic="UV0" input_semantic="TEXCOORD" input_set="0"/>
    </instance_material></technique_common></bind_material></instance_geometry></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


@pytest.mark.parametrize("material", ["", "<material><diffuse>0 1 0 1</diffuse></material>"])
def test_a_camera_sees_a_collada_meshs_own_texture_unless_the_visual_gives_a_material(
    tmp_path, material: str, make_sim
):
    """A DAE's texture (here: its u < 0.5 half red, the other blue) is drawn in camera images;
    a visual with a <material> of its own is drawn in that one instead, as gz-sim does (SceneManager.cc)."""
    from PIL import Image

    from gazelle.systems.sensors import Camera

    image = np.zeros((16, 16, 3), np.uint8)
    image[:, :8] = (255, 0, 0)
    image[:, 8:] = (0, 0, 255)
    Image.fromarray(image).save(tmp_path / "quad.png")
    (tmp_path / "quad.dae").write_text(TEXTURED_QUAD_DAE)
    (tmp_path / "model.sdf").write_text(
        f"""<?xml version="1.0"?><sdf version="1.9"><model name="poster"><static>true</static>
        <pose>2 0 0.5 0 0 0</pose><link name="l"><visual name="v">
        <geometry><mesh><uri>{tmp_path / "quad.dae"}</uri></mesh></geometry>{material}</visual></link></model></sdf>"""
    )
    sim = make_sim()
    # the poster comes before the camera: the camera's arrival puts the poster's visuals in the model; the
    # second time round they are in from the start (and its texture's name, freed at delete, is free again)
    for _ in range(2):
        poster = load(tmp_path / "model.sdf")
        said = [d.format() for d in poster.diagnostics]
        assert poster.value is not None, said
        sim.spawn(poster.model, name="poster")
        cam = next(s for s in _spawn(sim, _camera_model(hfov=0.6), "cam").systems if isinstance(s, Camera))
        sim.step(1)
        frame = cam.render(sim.world, depth=False)
        assert frame is not None
        rgb, _ = frame
        # the camera looks along +x: the image's right is the world's -y, the quad's u = 0 side (red)
        left, right = rgb[120, 100].astype(int), rgb[120, 220].astype(int)
        if material:
            assert left[1] > 100 and left[0] < 60 and right[1] > 100 and right[2] < 60, (left, right)
        else:
            assert left[2] > 100 > left[0] and right[0] > 100 > right[2], (left, right)
        sim.delete("poster")
        sim.delete("cam")


AIR_PRESSURE_WORLD = """<?xml version="1.0"?><sdf version="1.9"><world name="w">
  <plugin filename="gz-sim-air-pressure-system" name="gz::sim::systems::AirPressure"/>
  <model name="baro"><static>true</static><pose>0 0 {z} 0 0 0</pose><link name="l">
    <sensor name="p" type="air_pressure"><update_rate>100</update_rate><topic>baro</topic>
      <air_pressure><reference_altitude>{ref}</reference_altitude>
        <pressure><noise type="gaussian"><mean>0</mean><stddev>{sd}</stddev></noise></pressure></air_pressure>
    </sensor></link></model></world></sdf>"""


@pytest.mark.parametrize(("z", "ref"), [(0.5, 0.0), (2.0, 1000.0), (0.0, 8000.0)])
def test_an_air_pressure_sensor_reads_the_standard_atmosphere_at_its_height(z: float, ref: float, make_sim) -> None:
    """Issue 32's new sensor kind (one module and one import line): SDF's air_pressure, as gz-sensors
    computes it (US standard atmosphere's troposphere on the geopotential height of reference_altitude +
    the sensor's z), published as sensor_msgs/FluidPressure on its <topic>."""
    world = load_string(AIR_PRESSURE_WORLD.format(z=z, ref=ref, sd=0)).world
    sim = make_sim(world)
    readings = _record(sim, "/baro")
    sim.step(50)
    assert readings, "nothing published"
    # the barometric formula, written out here: p0 (1 - L h / T0)^(g M / (R L)), h geopotential
    h = ref + z
    h_geo = 6356766.0 * h / (6356766.0 + h)
    expected = 101325.0 * (1 - 0.0065 * h_geo / 288.15) ** (9.80665 * 28.9644 / (8314.32 * 0.0065))
    last = readings[-1]
    assert last.fluid_pressure == pytest.approx(expected, rel=1e-12)
    assert last.variance == 0.0 and last.frame_id == "baro::l::p"
    if ref == 0.0:
        assert last.fluid_pressure == pytest.approx(101319.0, abs=1.0)  # 0.5 m above sea level
    if ref == 1000.0:
        assert last.fluid_pressure == pytest.approx(89851.0, abs=10.0)  # the tables' 89,875 Pa at 1 km, 2 m lower


def test_air_pressure_noise_and_its_variance_as_gz_sensors_reports_it_and_the_ros_message(make_sim) -> None:
    from gazelle.ros._convert import to_ros
    from gazelle.systems.sensors.air_pressure import FLUID_PRESSURE, pressure_at

    world = load_string(AIR_PRESSURE_WORLD.format(z=1.0, ref=0.0, sd=4.0)).world
    sim = make_sim(world, seed=1)
    readings = _record(sim, "/baro")
    sim.step(3000)
    values = np.array([r.fluid_pressure for r in readings])
    assert len(values) >= 290
    assert abs(values.std() - 4.0) < 0.5  # Gaussian, stddev 4 Pa
    assert abs(values.mean() - pressure_at(1.0)) < 2.0  # around the true value (bias 0 here)
    assert readings[-1].variance == pytest.approx(2.0)  # gz-sensors: sqrt(stddev), not stddev squared
    # the message the ROS bridge publishes: a declared message, converted field by field
    msg = to_ros(FLUID_PRESSURE)(readings[-1])
    assert type(msg).__name__ == "FluidPressure" and type(msg).__module__.startswith("sensor_msgs.msg")
    assert msg.fluid_pressure == readings[-1].fluid_pressure and msg.variance == pytest.approx(2.0)
    assert msg.header.frame_id == "baro::l::p"
    assert msg.header.stamp.sec + 1e-9 * msg.header.stamp.nanosec == pytest.approx(readings[-1].stamp_sec)


def _gz_imu_box(imu: str = "", topic: str = "imu") -> str:
    """The IMU box with no gazebo_ros plugin: gz-sim's Imu system runs it (on ``<topic>``)."""
    return _imu_box(f"<topic>{topic}</topic>{imu}", offset="0 0 0 0 0 0", plugin=False)


def _yaw(q) -> float:
    return 2.0 * math.atan2(q[3], q[0])


def _turned_imu(make_sim, xml: str, spawn_yaw: float, turn: float):
    """Spawn ``xml`` floating (no gravity) at ``spawn_yaw``, step, turn it by ``turn`` about z, step again:
    the IMU system and its message after the turn."""
    from gazelle.description import quat_from_rpy

    world = dataclasses.replace(default_world(), gravity=(0.0, 0.0, 0.0))
    sim = make_sim(world)
    pose = Pose((0.0, 0.0, 1.0), quat_from_rpy(0.0, 0.0, spawn_yaw))
    sim.step(10)  # the world runs a while before the spawn: the reference is the spawn pose, not the world's start
    entity = _spawn(sim, xml, "imu_box", pose)
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    got = _record(sim, "/imu")
    sim.step(20)
    first: Imu = got[-1]
    sim.world.set_entity_state("imu_box", Pose((0.0, 0.0, 1.0), quat_from_rpy(0.0, 0.0, spawn_yaw + turn)))
    sim.step(20)
    return imu, first, got[-1]


def test_a_gz_sim_imu_reports_its_orientation_relative_to_where_it_was_spawned(make_sim):
    """gz-sim's Imu system (gz-sim8 src/systems/imu/Imu.cc AddSensor) sets the sensor's orientation reference
    to its world orientation when it is created: without <orientation_reference_frame>, a robot spawned
    facing +y reads the identity, and a turn of 30° reads 30°."""
    _imu, first, turned = _turned_imu(make_sim, _gz_imu_box(), math.pi / 2, math.radians(30))
    assert np.allclose(first.orientation, (1.0, 0.0, 0.0, 0.0), atol=1e-6)
    assert _yaw(turned.orientation) == pytest.approx(math.radians(30), abs=1e-6)


@pytest.mark.parametrize(
    ("frame", "reference_rpy"),
    [
        ("<localization>ENU</localization>", (0.0, 0.0, 0.0)),
        # gz-sensors ImuSensor.cc SetWorldFrameOrientation's table: ENU -> NED is rpy (pi, 0, pi/2), NWU (0, 0, pi/2)
        ("<localization>NED</localization>", (math.pi, 0.0, math.pi / 2)),
        ("<localization>NWU</localization>", (0.0, 0.0, math.pi / 2)),
        (
            "<localization>CUSTOM</localization><custom_rpy parent_frame='world'>0.1 0.2 0.3</custom_rpy>",
            (0.1, 0.2, 0.3),
        ),
    ],
)
def test_a_gz_sim_imu_with_an_orientation_reference_frame_reports_against_it(make_sim, frame, reference_rpy):
    """With <orientation_reference_frame> (and heading 0), the reference is the world's ENU frame turned by the
    named frame's rotation: the orientation is reference⁻¹ · the sensor's world orientation."""
    from gazelle.description import quat_conj, quat_from_rpy, quat_mul

    xml = _gz_imu_box(f"<imu><orientation_reference_frame>{frame}</orientation_reference_frame></imu>")
    spawn_yaw, turn = math.pi / 2, math.radians(30)
    _imu, _first, turned = _turned_imu(make_sim, xml, spawn_yaw, turn)
    expected = quat_mul(quat_conj(quat_from_rpy(*reference_rpy)), quat_from_rpy(0.0, 0.0, spawn_yaw + turn))
    dot = abs(sum(a * b for a, b in zip(turned.orientation, expected)))
    assert dot == pytest.approx(1.0, abs=1e-9), (turned.orientation, expected)


def test_a_gz_sim_imu_reference_gz_does_not_simulate_is_named_and_the_spawn_pose_stays_the_reference(caplog, make_sim):
    """gz-sensors warns about a CUSTOM frame whose parent is not 'world' and takes GRAV_UP/GRAV_DOWN as no
    frame: both keep the spawn pose as the reference; gazelle names them instead of dropping them silently."""
    for frame, said in (
        ("<localization>CUSTOM</localization><custom_rpy parent_frame='base'>0 0 1</custom_rpy>", "parent_frame"),
        ("<localization>GRAV_UP</localization>", "GRAV_UP"),
    ):
        caplog.clear()
        xml = _gz_imu_box(f"<imu><orientation_reference_frame>{frame}</orientation_reference_frame></imu>")
        with caplog.at_level(logging.WARNING):
            _imu, first, turned = _turned_imu(make_sim, xml, math.pi / 2, math.radians(30))
        assert any(
            said in r.getMessage() and "orientation_reference_frame" in r.getMessage() for r in caplog.records
        ), [r.getMessage() for r in caplog.records]
        assert np.allclose(first.orientation, (1.0, 0.0, 0.0, 0.0), atol=1e-6)
        assert _yaw(turned.orientation) == pytest.approx(math.radians(30), abs=1e-6)


def test_a_gz_sim_imu_with_orientation_disabled_sends_no_orientation(make_sim):
    """<enable_orientation>false</enable_orientation>: gz-sensors leaves the message's orientation unset, which
    arrives in ROS as four zeros (ros_gz_bridge copies the unset quaternion's fields)."""
    xml = _gz_imu_box("<imu><enable_orientation>false</enable_orientation></imu>")
    _imu, first, turned = _turned_imu(make_sim, xml, math.pi / 2, math.radians(30))
    assert first.orientation == (0.0, 0.0, 0.0, 0.0) and turned.orientation == (0.0, 0.0, 0.0, 0.0)


def test_a_gazebo_ros_imu_reports_against_the_world_unless_asked_for_its_initial_orientation(caplog, make_sim):
    """gazebo_ros_imu_sensor.cpp (ros2 branch): the world is the reference (REP 145) unless
    <initial_orientation_as_reference> is true (ROS 1's spelling: <initialOrientationAsReference>)."""
    world_ref = _imu_box(offset="0 0 0 0 0 0").replace("<frame_name>", "<topic>unused</topic><frame_name>")
    for option, expected_first in (
        ("", math.pi / 2),
        ("<initial_orientation_as_reference>true</initial_orientation_as_reference>", 0.0),
        ("<initialOrientationAsReference>true</initialOrientationAsReference>", 0.0),
    ):
        xml = world_ref.replace("<frame_name>", option + "<frame_name>").replace("~/out:=imu", "~/out:=/imu")
        xml = xml.replace("<ros><namespace>/demo</namespace>", "<ros>")
        _imu, first, turned = _turned_imu(make_sim, xml, math.pi / 2, math.radians(30))
        assert _yaw(first.orientation) == pytest.approx(expected_first, abs=1e-6), option
        assert _yaw(turned.orientation) == pytest.approx(expected_first + math.radians(30), abs=1e-6), option


def test_a_gazebo_ros_imu_names_the_gz_reference_elements_it_does_not_apply(caplog, make_sim):
    extra = "<imu><enable_orientation>false</enable_orientation><orientation_reference_frame>"
    extra += "<localization>NED</localization></orientation_reference_frame></imu>"
    with caplog.at_level(logging.WARNING):
        entity = _spawn(make_sim(), _imu_box(extra), "imu_box", Pose((0.0, 0.0, 0.05)))
    said = " ".join(r.getMessage() for r in caplog.records)
    assert "<orientation_reference_frame> is not applied" in said and "<enable_orientation> is not applied" in said
    imu = next(s for s in entity.systems if isinstance(s, ImuSensor))
    assert imu.reference.fixed == (1.0, 0.0, 0.0, 0.0) and imu.reference.enabled


def test_a_gps_fix_carries_the_covariance_and_service_each_gazebo_sends(make_sim):
    """gazebo_ros_gps_sensor.cpp: the noise's variances on the diagonal (0 without noise), always
    COVARIANCE_TYPE_DIAGONAL_KNOWN, service GPS. gz-sim's NavSat through ros_gz_bridge (convert/sensor_msgs.cpp):
    gz's NavSat message has no covariance, so COVARIANCE_TYPE_UNKNOWN, zeros, and no service."""
    from gazelle.systems import NavSatFix

    noise = """<gps><position_sensing><horizontal><noise type="gaussian"><stddev>2</stddev></noise></horizontal>
      <vertical><noise type="gaussian"><stddev>3</stddev></noise></vertical></position_sensing></gps>"""
    plugin = '<plugin name="gps" filename="libgazebo_ros_gps_sensor.so"><ros><remapping>~/out:=fix</remapping></ros></plugin>'
    cases = (
        (plugin, "", (0.0,) * 9, 2, 1),
        (plugin, noise, (4.0, 0, 0, 0, 4.0, 0, 0, 0, 9.0), 2, 1),
        ("<topic>fix</topic>", noise, (0.0,) * 9, 0, 0),
    )
    for inner, extra, covariance, kind, service in cases:
        sim = make_sim()
        xml = _gps_box().replace(plugin, inner + extra)
        _spawn(sim, xml, "rover")
        fixes = _record(sim, "/fix")
        sim.step(1)
        fix: NavSatFix = fixes[-1]
        assert (fix.position_covariance, fix.covariance_type, fix.service) == (covariance, kind, service), inner


def test_a_gazebo_ros_ft_sensor_in_link_mode_says_it_is_not_simulated(caplog, make_sim):
    plugin = '<plugin name="ft" filename="libgazebo_ros_ft_sensor.so"><body_name>bob</body_name></plugin>'
    with caplog.at_level(logging.ERROR):
        _spawn(make_sim(), _arm(plugin=plugin), "arm")
    assert any("<body_name>" in r.getMessage() and "not simulated" in r.getMessage() for r in caplog.records)
