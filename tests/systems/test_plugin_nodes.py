"""gazebo_ros plugins are ROS nodes of their own, as in Gazebo Classic: the runtime stamps a plugin's
topics with its node and announces the node with its configuration as parameters (no ROS here: what
the bridge is given; the ROS side is tested in tests/integration/test_ros2cli.py and test_turtlebot3.py)."""

from __future__ import annotations

import pytest
from _paths import SEED_XACRO

from gazelle.description import load, load_string
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


@pytest.mark.parametrize(
    ("ros", "node", "topic"),
    [
        # articubot_one's lidar: the deprecated bare rule, which rcl still applies before --ros-args
        ("<namespace>/x</namespace><argument>~/out:=scan</argument>", "/x/my_laser", "/x/scan"),
        (
            "<namespace>x</namespace><argument>--ros-args</argument><argument>-r</argument><argument>~/out:=scan</argument>",
            "/x/my_laser",
            "/x/scan",
        ),
        # one argv word with spaces is no ROS argument and no rule: rcl leaves ~/out alone
        ("<namespace>/x</namespace><argument>--ros-args -r ~/out:=scan</argument>", "/x/my_laser", "/x/my_laser/out"),
        # after the ROS arguments' explicit end (--) a bare rule is one again; inside them it needs -r
        (
            "<argument>--ros-args</argument><argument>--</argument><argument>-r</argument><argument>~/out:=a</argument>",
            "/my_laser",
            "/a",
        ),
        ("<argument>--ros-args</argument><argument>~/out:=scan</argument>", "/my_laser", "/my_laser/out"),
        # __ns:= moves the node, as rcl's node namespace remapping does
        (
            "<namespace>/x</namespace><argument>__ns:=/y</argument><argument>~/out:=scan</argument>",
            "/y/my_laser",
            "/y/scan",
        ),
        # the <argument>s come before the <remapping>s, and rcl takes the first rule that matches
        (
            "<namespace>/x</namespace><remapping>~/out:=second</remapping><argument>~/out:=first</argument>",
            "/x/my_laser",
            "/x/first",
        ),
    ],
)
def test_a_plugins_ros_arguments_remap_its_node_as_gazebo_ros_hands_them_to_rcl(make_sim, ros, node, topic):
    """gazebo_ros/src/node.cpp gives the plugin's node its ``<argument>`` texts, then ``--ros-args --remap`` for
    each ``<remapping>``; rcl (humble's arguments.c) reads ``from:=to`` before ``--ros-args`` as a rule (its
    deprecated form) and after ``-r`` within them. The ray sensor's ``~/out`` is its node's private topic."""
    sim = make_sim()
    _spawn(sim, _lidar_model(ros=f"<ros>{ros}</ros>"), "scanner")
    assert set(_nodes(sim)) == {node}
    owners = {(e.topic, e.node) for e in sim.bus.endpoints() if e.is_publisher}
    assert (topic, node) in owners, owners
    scans = _record(sim, topic)
    sim.step(150)
    assert len(scans) == 2


def test_every_gazebo_ros_plugin_takes_its_ros_arguments_as_the_diff_drive_demo_world_writes_them(make_sim):
    """gazebo_plugins' Dashing demo world (gazebo_ros_diff_drive_demo.world) renames the drive's topics with
    ``<argument>cmd_vel:=cmd_demo</argument>`` and ``<argument>odom:=odom_demo</argument>``; a p3d beside it
    (``<argument>odom:=p3d_demo</argument>``, its gazebo_ros_p3d_demo.world) under a namespace."""
    ros = "<ros><namespace>/demo</namespace><argument>cmd_vel:=cmd_demo</argument><argument>odom:=odom_demo</argument></ros>"
    p3d = (
        '<plugin name="p3d" filename="libgazebo_ros_p3d.so"><ros><namespace>/demo</namespace>'
        "<argument>odom:=p3d_demo</argument></ros><body_name>base_link</body_name></plugin>"
    )
    urdf = load(SEED_XACRO).model.urdf.replace("<left_joint>", f"{ros}<left_joint>", 1)
    urdf = urdf.replace("</robot>", f"<gazebo>{p3d}</gazebo></robot>")
    sim = make_sim()
    sim.spawn(load_string(urdf).model, name="bot")
    owners = {(e.topic, e.node, e.is_publisher) for e in sim.bus.endpoints()}
    assert {
        ("/demo/cmd_demo", "/demo/differential_drive", False),
        ("/demo/odom_demo", "/demo/differential_drive", True),
        ("/demo/p3d_demo", "/demo/p3d", True),
    } <= owners, owners
    assert not [o for o in owners if o[0] in ("/demo/cmd_vel", "/demo/odom", "/cmd_vel", "/odom")]
