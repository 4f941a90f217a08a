"""gazebo_ros plugins are ROS nodes of their own, as in Gazebo Classic: the runtime stamps a plugin's
topics with its node and announces the node with its configuration as parameters (no ROS here: what
the bridge is given; the ROS side is tested in tests/integration/test_ros2cli.py and test_turtlebot3.py)."""

from __future__ import annotations

from _paths import SEED_XACRO

from gazelle.description import load
from gazelle.sim import Simulation
from gazelle.systems import PluginNode
from systems.test_sensors import _lidar, _lidar_model, _record, _spawn


def _nodes(sim: Simulation) -> dict[str, PluginNode]:
    return {c.fully_qualified_name: c for _o, c in sim.bus._components if isinstance(c, PluginNode)}


def test_the_diff_drive_is_its_node_with_its_configuration_read_only(make_sim):
    sim = make_sim()
    model = load(SEED_XACRO).model
    sim.spawn(model, name="bot")
    sim.spawn(model, name="bot2", namespace="r2")
    nodes = _nodes(sim)
    assert set(nodes) == {"/differential_drive", "/r2/differential_drive"}
    drive = nodes["/differential_drive"]
    assert drive.plugin == "libgazebo_ros_diff_drive.so"
    assert drive.parameters["wheel_separation"] == 0.34  # xacro wrote 0.33999999999999997
    assert drive.parameters["publish_odom_tf"] is True and drive.parameters["odometry_frame"] == "odom"
    assert drive.settable == {}  # gazebo_ros reads the SDF once: all read-only
    owners = {(e.topic, e.node) for e in sim.bus.endpoints()}
    assert {("/cmd_vel", "/differential_drive"), ("/odom", "/differential_drive")} <= owners
    assert ("/r2/odom", "/r2/differential_drive") in owners
    assert ("/robot_description", "") in owners  # the built-in robot_state_publisher is the server's


def test_a_sensor_node_s_update_rate_is_set_at_run_time_and_checked(make_sim):
    sim = make_sim()
    scanner = _spawn(sim, _lidar_model(), "scanner")
    node = _nodes(sim)["/my_laser"]
    assert node.parameters["update_rate"] == 10.0 and node.parameters["output_type"] == "sensor_msgs/LaserScan"
    assert set(node.settable) == {"update_rate"}
    scans = _record(sim, "/scan")
    sim.step(1000)
    gaps = {round(b.stamp_sec - a.stamp_sec, 6) for a, b in zip(scans[1:], scans[2:], strict=False)}
    assert gaps == {0.1}  # 10 Hz
    assert sim.call(lambda: node.settable["update_rate"](2.0)) is None
    assert _lidar(scanner).rate_hz == 2.0
    before = len(scans)
    sim.step(2000)
    after = scans[before + 1 :]
    assert len(after) >= 3 and {round(b.stamp_sec - a.stamp_sec, 6) for a, b in zip(after, after[1:])} == {0.5}
    assert "must be a number >= 0" in (node.settable["update_rate"]("fast") or "")
    assert "must be a number >= 0" in (node.settable["update_rate"](-1.0) or "")
    assert _lidar(scanner).rate_hz == 2.0
