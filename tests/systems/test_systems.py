"""Systems in-process (no ROS): the phase and priority contract, and each system configured from a plugin block."""

from __future__ import annotations

import logging
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest
from _paths import BOX, REAL, REPO, SEED_XACRO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.physics import EntityState
from gazelle.systems import System, UpdateInfo
from gazelle.systems._bus import MsgType
from gazelle.systems._payloads import Twist
from gazelle.systems.diff_drive import ODOM_WORLD, DiffDrive
from gazelle.systems.gz_diff_drive import GzDiffDrive, SpeedLimiter, SpeedLimits
from gazelle.systems.joint_controllers import JointCommands, JointController, JointPositionController
from gazelle.systems.pose_publisher import P3D

TB3 = REAL / "turtlebot3"


def seed_urdf(plugin_xml: str) -> str:
    """The seed robot's URDF with its classic diff drive replaced by ``plugin_xml`` (in a ``<gazebo>`` block)."""
    urdf = load(SEED_XACRO).model.urdf
    assert urdf
    out, n = re.subn(
        r"<gazebo>\s*<plugin[^>]*libgazebo_ros_diff_drive.*?</gazebo>",
        f"<gazebo>{plugin_xml}</gazebo>",
        urdf,
        flags=re.S,
    )
    assert n == 1
    return out


def seed_geometry() -> tuple[float, float]:
    """(wheel separation, wheel radius) of the seed robot, from its classic plugin block."""
    urdf = load(SEED_XACRO).model.urdf
    sep_match = re.search(r"<wheel_separation>([^<]+)<", urdf)
    diam_match = re.search(r"<wheel_diameter>([^<]+)<", urdf)
    assert sep_match is not None and diam_match is not None
    sep, diam = float(sep_match.group(1)), float(diam_match.group(1))
    return sep, diam / 2.0


def spawn(text: str, *, name: str = "robot", namespace: str = "", z: float = 0.05, source: str | None = None):
    sim = new_simulation()
    model = load_string(text, source=source).model
    entity = sim.spawn(model, name=name, pose=Pose((0.0, 0.0, z)), namespace=namespace)
    return sim, entity


def system(entity, cls):
    return next(s for s in entity.systems if isinstance(s, cls))


# --------------------------------------------------------------------------- phases and priorities
class Recorder(System):
    def __init__(self, tag: str, log: list, priority: int = 0) -> None:
        self.tag, self.log, self.priority = tag, log, priority

    def pre_update(self, info: UpdateInfo, world) -> None:
        self.log.append(("pre", self.tag))

    def post_update(self, info: UpdateInfo, world) -> None:
        self.log.append(("post", self.tag))


def test_priorities_order_systems_in_every_phase(make_sim) -> None:
    sim = make_sim()
    log: list = []
    for tag, prio in (("c", 10), ("a", -10), ("b", 0), ("b2", 0)):
        sim.systems.add("x", Recorder(tag, log, prio))
    sim.step()
    assert log == [("pre", t) for t in ("a", "b", "b2", "c")] + [("post", t) for t in ("a", "b", "b2", "c")]


class Kick(System):
    """Pushes a free box up with a large force on one chosen step only, and records what post_update sees."""

    def __init__(self, entity: str, step: int) -> None:
        self.entity, self.step = entity, step
        self.seen: list[tuple[int, float, float, float]] = []  # iteration, sim time, vz, z

    def pre_update(self, info: UpdateInfo, world) -> None:
        bid = world.body_id(self.entity)
        world.data.xfrc_applied[bid, 2] = 1000.0 if info.iterations == self.step else 0.0

    def post_update(self, info: UpdateInfo, world) -> None:
        st = world.entity_state(self.entity)
        self.seen.append((info.iterations, info.sim_time_sec, st.linear_velocity[2], st.pose.position[2]))


def test_pre_update_acts_in_the_same_step_and_post_update_sees_the_post_step_state(make_sim) -> None:
    sim = make_sim()
    sim.spawn(load_string(BOX).model, name="box", pose=Pose((0.0, 0.0, 2.0)))
    kick = Kick("box", step=5)
    sim.systems.add("box", kick)
    sim.step(10)
    dt = sim.world.timestep
    by_iter = {it: (t, vz, z) for it, t, vz, z in kick.seen}
    # post_update of step k runs after the k-th mj_step: iterations = k + 1, time = (k + 1) dt
    assert by_iter[6][0] == pytest.approx(6 * dt)
    # falling freely until the kick, which shows in the very step it was commanded
    assert by_iter[5][1] < 0
    assert by_iter[6][1] == pytest.approx(by_iter[5][1] + (1000.0 - 9.8) * dt, rel=1e-3)
    # post_update saw exactly the state left after the step (what a caller sees after sim.step)
    assert kick.seen[-1][2] == pytest.approx(sim.world.entity_state("box").linear_velocity[2], abs=0)
    assert kick.seen[-1][3] == pytest.approx(float(sim.world.data.qpos[2]), abs=1e-12)


# --------------------------------------------------------------------------- unknown plugins
def test_unknown_plugin_warns_with_name_file_and_line(tmp_path, caplog, make_sim) -> None:
    urdf = seed_urdf('<plugin name="mystery" filename="libgazebo_ros_mystery.so"><x>1</x></plugin>')
    path = tmp_path / "robot.urdf"
    path.write_text(urdf)
    line = next(i for i, ln in enumerate(urdf.splitlines(), 1) if "libgazebo_ros_mystery" in ln)
    with caplog.at_level(logging.WARNING):
        make_sim().spawn(load(path).model, name="r", pose=Pose((0, 0, 0.05)))
    msgs = [r.getMessage() for r in caplog.records if "mystery" in r.getMessage()]
    assert msgs, caplog.text
    assert "libgazebo_ros_mystery.so" in msgs[0] and f"{path}:{line}" in msgs[0]


# --------------------------------------------------------------------------- classic diff drive, ROS 1 names
def test_classic_diff_drive_reads_the_ros1_names_of_turtlebot3(caplog, monkeypatch, make_sim) -> None:
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(TB3))
    model = load(TB3 / "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro").model
    sim = make_sim()
    with caplog.at_level(logging.WARNING):
        entity = sim.spawn(model, name="tb3", pose=Pose((0, 0, 0.01)))
    c = system(entity, DiffDrive).config
    assert (c.left_joints, c.right_joints) == (("wheel_left_joint",), ("wheel_right_joint",))
    assert (c.wheel_separation, c.wheel_diameter) == ((0.16,), (0.066,))
    assert (c.max_wheel_torque, c.max_wheel_acceleration, c.update_rate) == (10.0, 1.0, 30.0)
    assert (c.command_topic, c.odometry_topic, c.odometry_frame, c.robot_base_frame) == (
        "cmd_vel",
        "odom",
        "odom",
        "base_footprint",
    )
    assert c.odometry_source == ODOM_WORLD and c.publish_odom and c.publish_odom_tf and not c.publish_wheel_tf
    assert c.publish_wheel_joint_state and not c.legacy_mode
    assert "is not a parameter" not in caplog.text
    topics = {(e.topic, e.msg_type) for e in sim.bus.endpoints()}
    assert {("/cmd_vel", MsgType.TWIST), ("/odom", MsgType.ODOMETRY), ("/joint_states", MsgType.JOINT_STATE)} <= topics
    drive = system(entity, DiffDrive)
    sim.step(300)
    x0 = sim.world.entity_state("tb3").pose.position[0]
    drive.command(0.2, 0.0)
    sim.step(2000)
    assert sim.world.entity_state("tb3").pose.position[0] - x0 == pytest.approx(0.4 - 0.2 * 0.2 / 2, rel=0.1)


def test_classic_diff_drive_warns_about_unknown_parameters_by_name(caplog) -> None:
    urdf = seed_urdf(
        '<plugin name="dd" filename="libgazebo_ros_diff_drive.so"><leftJoint>base_left_wheel_joint</leftJoint>'
        "<rightJoint>base_right_wheel_joint</rightJoint><legacyMode>false</legacyMode><wheelBogus>3</wheelBogus></plugin>"
    )
    with caplog.at_level(logging.WARNING):
        _, entity = spawn(urdf)
    assert "<wheelBogus> is not read by libgazebo_ros_diff_drive.so; it is ignored" in caplog.text
    assert system(entity, DiffDrive).config.left_joints == ("base_left_wheel_joint",)


# --------------------------------------------------------------------------- gz-sim DiffDrive
def gz_plugin(extra: str = "") -> str:
    sep, r = seed_geometry()
    return (
        '<plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">'
        "<left_joint>base_left_wheel_joint</left_joint><right_joint>base_right_wheel_joint</right_joint>"
        f"<wheel_separation>{sep}</wheel_separation><wheel_radius>{r}</wheel_radius>{extra}</plugin>"
    )


def test_gz_diff_drive_moves_the_seed_robot_with_gz_defaults() -> None:
    sim, entity = spawn(seed_urdf(gz_plugin()))
    drive = system(entity, GzDiffDrive)
    assert drive.cmd_topic == "/model/robot/cmd_vel"
    assert (drive.frame_id, drive.child_frame_id) == ("robot/odom", "robot/base_link")
    topics = {e.topic for e in sim.bus.endpoints()}
    assert {"/model/robot/cmd_vel", "/model/robot/odometry", "/tf"} <= topics
    sim.step(300)
    p0 = sim.world.entity_state("robot").pose
    drive.command(0.3, 0.0)
    sim.step(2000)
    p1 = sim.world.entity_state("robot").pose
    assert p1.position[0] - p0.position[0] == pytest.approx(0.6, rel=0.05)
    assert abs(p1.position[1] - p0.position[1]) < 0.01
    # encoder odometry follows ground truth while the wheels roll without slipping
    odom = drive._odom
    assert odom is not None and odom.x == pytest.approx(p1.position[0] - p0.position[0], rel=0.03)
    assert odom.linear == pytest.approx(0.3, rel=0.03)
    drive.command(0.0, 1.0)
    sim.step(1000)
    yaw = sim.world.entity_state("robot").pose.rpy[2] - p1.rpy[2]
    assert yaw == pytest.approx(1.0, rel=0.1)
    assert odom.heading == pytest.approx(yaw, rel=0.08)  # turning in place scrubs: encoders overestimate


def test_gz_diff_drive_limiters() -> None:
    extra = "<max_linear_acceleration>0.5</max_linear_acceleration><max_velocity>0.2</max_velocity>"
    sim, entity = spawn(seed_urdf(gz_plugin(extra)))
    drive = system(entity, GzDiffDrive)
    assert drive.config.linear.max_acceleration == 0.5 and math.isinf(drive.config.angular.max_acceleration)
    assert drive.config.linear.max_velocity == drive.config.angular.max_velocity == 0.2
    drive.command(1.0, 1.0)
    steps = round(0.1 / sim.world.timestep)
    sim.step(steps)
    lin, ang = drive.limited_command
    assert lin == pytest.approx(0.05, rel=1e-6)  # 0.5 m/s² for 0.1 s
    assert ang == pytest.approx(0.2)  # no angular acceleration limit, velocity capped
    sim.step(steps * 10)
    assert drive.limited_command[0] == pytest.approx(0.2)
    # jerk, as gz::math::SpeedLimiter
    jerk = SpeedLimiter(SpeedLimits(max_jerk=10.0))
    assert jerk.limit(1.0, 0.0, 0.0, 0.1) == pytest.approx(0.1)  # da <= 10 * 0.1²


def test_gz_diff_drive_relative_topic_and_frames_go_under_the_namespace() -> None:
    extra = "<topic>cmd_vel</topic><odom_topic>odom</odom_topic><frame_id>odom</frame_id><child_frame_id>base_link</child_frame_id>"
    sim, entity = spawn(seed_urdf(gz_plugin(extra)), name="r1", namespace="r1")
    drive = system(entity, GzDiffDrive)
    assert drive.cmd_topic == "/r1/cmd_vel"
    assert (drive.frame_id, drive.child_frame_id) == ("r1/odom", "r1/base_link")
    assert "/r1/odom" in {e.topic for e in sim.bus.endpoints()}


# --------------------------------------------------------------------------- joint controllers
ARM = """<?xml version="1.0"?><sdf version="1.9"><model name="arm">
<link name="base"><inertial><mass>5</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial></link>
<joint name="fix" type="fixed"><parent>world</parent><child>base</child></joint>
<link name="upper"><pose>0.25 0 0.5 0 0 0</pose>
  <inertial><mass>1</mass><inertia><ixx>0.001</ixx><iyy>0.02</iyy><izz>0.02</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.5 0.05 0.05</size></box></geometry></collision></link>
<joint name="shoulder" type="revolute"><parent>base</parent><child>upper</child><pose>-0.25 0 0 0 0 0</pose>
  <axis><xyz>0 1 0</xyz><limit><lower>-3</lower><upper>3</upper><effort>50</effort><velocity>3</velocity></limit></axis></joint>
<link name="wheel"><pose>0 0 0.1 0 0 0</pose>
  <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial></link>
<joint name="spin" type="continuous"><parent>base</parent><child>wheel</child><axis><xyz>0 0 1</xyz><limit><effort>5</effort></limit></axis></joint>
%s
</model></sdf>"""


def test_gz_joint_position_controller_reaches_a_target_against_gravity() -> None:
    plugin = (
        '<plugin filename="gz-sim-joint-position-controller-system" name="gz::sim::systems::JointPositionController">'
        "<joint_name>shoulder</joint_name><p_gain>200</p_gain><i_gain>50</i_gain><d_gain>10</d_gain>"
        "<i_max>10</i_max><i_min>-10</i_min></plugin>"
    )
    sim, entity = spawn(ARM % plugin, name="arm", z=0.0)
    ctl = system(entity, JointPositionController)
    assert ctl.topic == "/model/arm/joint/shoulder/0/cmd_pos"
    ctl.command(-0.8)
    sim.step(4000)
    qadr, _ = sim.world.joint_address("arm", "shoulder")
    assert float(sim.world.data.qpos[qadr]) == pytest.approx(-0.8, abs=2e-3)


@pytest.mark.parametrize("cmd_max", [None, 0.5])
def test_gz_joint_position_controllers_velocity_mode_caps_its_speed_at_cmd_max_only(cmd_max) -> None:
    """gz-sim 8 JointPositionController.cc (PreUpdate, OperationMode::ABS): the joint's velocity command is
    (target - q)/dt, capped at <cmd_max> when the file writes one (isMaxSet): gazelle ignored it and capped
    only at the joint's <limit><velocity> (3 rad/s here), which it still does."""
    extra = f"<cmd_max>{cmd_max}</cmd_max>" if cmd_max is not None else ""
    plugin = (
        '<plugin filename="gz-sim-joint-position-controller-system" name="gz::sim::systems::JointPositionController">'
        f"<joint_name>shoulder</joint_name><use_velocity_commands>true</use_velocity_commands>{extra}</plugin>"
    )
    sim, entity = spawn(ARM % plugin, name="arm", z=0.0)
    system(entity, JointPositionController).command(-0.8)
    sim.step(round(0.1 / sim.world.timestep))
    qadr, _ = sim.world.joint_address("arm", "shoulder")
    turned = float(sim.world.data.qpos[qadr])
    if cmd_max is None:
        assert turned == pytest.approx(-0.3, abs=0.02)  # the joint's 3 rad/s for 0.1 s
    else:
        assert turned == pytest.approx(-0.05, abs=0.01)  # 0.5 rad/s for 0.1 s


def test_gz_joint_velocity_controller_and_classic_command_topics() -> None:
    plugins = (
        '<plugin filename="gz-sim-joint-controller-system" name="gz::sim::systems::JointController">'
        "<joint_name>spin</joint_name></plugin>"
        '<plugin filename="gazelle_joint_commands" name="cmds"><joint_name>shoulder</joint_name>'
        "<ros><namespace>arm1</namespace></ros></plugin>"
    )
    sim, entity = spawn(ARM % plugins, name="arm", z=0.0)
    vel = system(entity, JointController)
    cmds = system(entity, JointCommands)
    assert vel.topic == "/model/arm/joint/spin/cmd_vel"
    assert cmds.topics == {"shoulder": "/arm1/shoulder/cmd_pos"}
    vel.command(2.0)
    cmds.command("shoulder", 0.5)
    sim.step(2000)
    _, dspin = sim.world.joint_address("arm", "spin")
    qsh, _ = sim.world.joint_address("arm", "shoulder")
    assert float(sim.world.data.qvel[dspin]) == pytest.approx(2.0, rel=1e-3)
    assert float(sim.world.data.qpos[qsh]) == pytest.approx(0.5, abs=0.05)  # P-D servo, no integral: a small sag


# --------------------------------------------------------------------------- p3d
def test_p3d_publishes_ground_truth_with_offsets() -> None:
    plugin = (
        '<plugin name="truth" filename="libgazebo_ros_p3d.so"><ros><namespace>gt</namespace></ros>'
        "<body_name>base_link</body_name><frame_name>world</frame_name><update_rate>50</update_rate>"
        "<xyz_offsets>1 2 3</xyz_offsets></plugin>"
    )
    urdf = load(SEED_XACRO).model.urdf.replace("</robot>", f"<gazebo>{plugin}</gazebo></robot>")
    sim, entity = spawn(urdf)
    p3d = system(entity, P3D)
    assert p3d.topic == "/gt/odom" and (p3d.frame_id, p3d.child_frame_id) == ("world", "base_link")
    got = []
    ep = next(e for e in sim.bus.endpoints() if e.topic == "/gt/odom")
    ep.add_sink(got.append)
    system(entity, DiffDrive).command(0.2, 0.0)
    sim.step(1000)
    assert len(got) == pytest.approx(50, abs=1)
    truth = sim.world.entity_state("robot", "base_link")
    last = got[-1]
    assert last.stamp_sec == pytest.approx(sim.world.time, abs=0.021)
    sim.step(0)
    pose, twist = p3d.measure(sim.world)
    assert [a - b for a, b in zip(pose.position, truth.pose.position)] == pytest.approx([1, 2, 3], abs=1e-9)
    assert twist.linear[0] == pytest.approx(0.2, rel=0.05)


def _p3d_odometry(caplog, inner: str) -> tuple[list, EntityState, P3D]:
    """The Odometry a gazebo_ros_p3d with ``inner`` parameters sends over 0.1 s, the robot's truth, the system."""
    plugin = (
        '<plugin name="truth" filename="libgazebo_ros_p3d.so"><ros><remapping>odom:=truth</remapping></ros>'
        f"<body_name>base_link</body_name>{inner}</plugin>"
    )
    urdf = load(SEED_XACRO).model.urdf.replace("</robot>", f"<gazebo>{plugin}</gazebo></robot>")
    with caplog.at_level(logging.WARNING):
        sim, entity = spawn(urdf)
    got = []
    next(e for e in sim.bus.endpoints() if e.topic == "/truth").add_sink(got.append)
    sim.step(100)
    return got, sim.world.entity_state("robot", "base_link"), system(entity, P3D)


def test_p3d_reads_xyz_offset_and_warns_about_the_deprecated_plural_as_gazebo_ros_p3d(caplog) -> None:
    """gazebo_ros_p3d.cpp (ros2): <xyz_offset>/<rpy_offset>; <xyz_offsets> works with a deprecation warning, and
    the singular wins when both are there."""
    got, truth, _ = _p3d_odometry(caplog, "<xyz_offset>1 2 3</xyz_offset>")
    assert [a - b for a, b in zip(got[-1].pose.position, truth.pose.position)] == pytest.approx([1, 2, 3], abs=1e-9)
    assert not [r for r in caplog.records if "offset" in r.getMessage()]
    caplog.clear()
    got, truth, _ = _p3d_odometry(caplog, "<xyz_offsets>5 5 5</xyz_offsets><xyz_offset>1 2 3</xyz_offset>")
    assert [a - b for a, b in zip(got[-1].pose.position, truth.pose.position)] == pytest.approx([1, 2, 3], abs=1e-9)
    assert any("<xyz_offsets> is deprecated, use <xyz_offset> instead." in r.getMessage() for r in caplog.records)


def test_p3d_noise_is_on_the_velocities_only_and_both_covariances_carry_it(caplog) -> None:
    """gazebo_ros_p3d.cpp (ros2) draws <gaussian_noise> for the six twist values; the pose is exact."""
    got, truth, _ = _p3d_odometry(caplog, "<gaussian_noise>0.5</gaussian_noise>")
    odom = got[-1]
    assert odom.pose.position == pytest.approx(truth.pose.position, abs=1e-12)
    assert max(abs(v) for v in odom.twist.linear + odom.twist.angular) > 0.01  # at rest: all noise
    assert odom.pose_covariance[0] == odom.twist_covariance[35] == pytest.approx(0.25)


# --------------------------------------------------------------------------- plugin declarations
# the 28 names the hand-kept table held before the systems declared them (issue 32)
KNOWN_PLUGIN_NAMES = {
    "gazebo_ros_diff_drive": "DiffDrive",
    "gazebo_ros_joint_state_publisher": "JointStatePublisher",
    **dict.fromkeys(
        (
            "gz-sim-joint-state-publisher-system",
            "gz::sim::systems::JointStatePublisher",
            "ignition-gazebo-joint-state-publisher-system",
            "ignition::gazebo::systems::JointStatePublisher",
        ),
        "GzJointStatePublisher",
    ),
    **dict.fromkeys(
        (
            "gz-sim-diff-drive-system",
            "gz::sim::systems::DiffDrive",
            "ignition-gazebo-diff-drive-system",
            "ignition::gazebo::systems::DiffDrive",
        ),
        "GzDiffDrive",
    ),
    **dict.fromkeys(
        (
            "gz-sim-joint-position-controller-system",
            "gz::sim::systems::JointPositionController",
            "ignition-gazebo-joint-position-controller-system",
            "ignition::gazebo::systems::JointPositionController",
        ),
        "JointPositionController",
    ),
    **dict.fromkeys(
        (
            "gz-sim-joint-controller-system",
            "gz::sim::systems::JointController",
            "ignition-gazebo-joint-controller-system",
            "ignition::gazebo::systems::JointController",
        ),
        "JointController",
    ),
    "gazelle_joint_commands": "JointCommands",
    "gazebo_ros_p3d": "P3D",
    **dict.fromkeys(
        (
            "gz-sim-odometry-publisher-system",
            "gz::sim::systems::OdometryPublisher",
            "ignition-gazebo-odometry-publisher-system",
            "ignition::gazebo::systems::OdometryPublisher",
        ),
        "OdometryPublisher",
    ),
    "gazebo_ros_ft_sensor": "ForceTorqueSensor",
    "gazebo_ros_imu": "ImuSensor",
    **dict.fromkeys(
        (
            "gazebo_ros2_control",
            "gz_ros2_control-system",
            "gz_ros2_control::GazeboSimROS2ControlPlugin",
            "ign_ros2_control-system",
            "ign_ros2_control::IgnitionROS2ControlPlugin",
        ),
        "ControllerManager",
    ),
}


def test_the_plugin_table_is_derived_from_the_systems_declarations() -> None:
    """Every name of the old hand-kept table still runs its system, and every name in the table is one a registered
    class declares (a new plugin adds its own names, tested with it, without editing this list)."""
    from gazelle.systems._registration import registered
    from gazelle.systems._registry import plugin_names, plugin_table

    table = plugin_table()
    assert {name: table[name].__name__ for name in KNOWN_PLUGIN_NAMES if name in table} == KNOWN_PLUGIN_NAMES
    assert table == {name: cls for cls in registered() for name in plugin_names(cls)}


def test_a_gz_system_declared_by_its_class_name_answers_to_every_gz_and_ignition_spelling() -> None:
    from gazelle.systems._registry import plugin_names

    class LiftDrag(System):
        gz_plugin = "LiftDrag"

    class Classic(System):
        plugin_files = ("gazebo_ros_thing",)
        gz_plugin = "NavSat"
        gz_plugin_file = "navsat"

    assert plugin_names(LiftDrag) == (
        "gz-sim-lift-drag-system",
        "gz::sim::systems::LiftDrag",
        "ignition-gazebo-lift-drag-system",
        "ignition::gazebo::systems::LiftDrag",
    )
    assert plugin_names(Classic)[:2] == ("gazebo_ros_thing", "gz-sim-navsat-system")


def test_a_plugin_declared_twice_or_a_registered_system_without_a_name_is_refused() -> None:
    from gazelle.systems._registry import plugin_table
    from gazelle.systems.diff_drive import DiffDrive
    from gazelle.systems.robot_state import RobotStatePublisher

    with pytest.raises(ValueError, match="'gazebo_ros_diff_drive' is declared by DiffDrive and DiffDrive"):
        plugin_table((DiffDrive, DiffDrive))
    with pytest.raises(ValueError, match="robot_state.RobotStatePublisher declares no plugin name"):
        plugin_table((RobotStatePublisher,))


def test_every_system_registers_itself_at_the_bottom_of_its_own_module() -> None:
    """Issue 53: one way to extend. A plugin or a sensor kind registers itself in its own module (gz-sim's
    ``GZ_ADD_PLUGIN``), found by the registry without a list kept elsewhere; ``add_plugin`` takes systems only."""
    from gazelle.systems._registration import add_plugin, registered
    from gazelle.systems.odometry_publisher import OdometryPublisher
    from gazelle.systems.sensors.air_pressure import AirPressureSensor

    classes = registered()
    assert OdometryPublisher in classes and AirPressureSensor in classes
    for cls in classes:
        module = Path(sys.modules[cls.__module__].__file__ or "").read_text()
        assert module.rstrip().splitlines()[-1].startswith("add_plugin("), cls
    with pytest.raises(TypeError, match="add_plugin takes a System class"):
        add_plugin(int)  # type: ignore[type-var]


# --------------------------------------------------------------------------- docs
def test_plugin_docs_are_up_to_date() -> None:
    out = subprocess.run(
        [sys.executable, str(REPO / "scripts" / "gen_plugin_docs.py"), "--check"],
        capture_output=True,
        text=True,
        cwd=REPO,
    )
    assert out.returncode == 0, out.stdout + out.stderr


def test_a_system_that_raises_is_disabled_and_the_world_goes_on(caplog, make_sim):
    from gazelle.description import Pose, load
    from gazelle.systems import System

    class Broken(System):
        calls = 0

        def pre_update(self, info, world):
            Broken.calls += 1
            raise RuntimeError("plugin bug")

    sim = make_sim()
    robot = load("examples/simple_robot/simple_robot/robot.urdf.xacro").model
    e = sim.spawn(robot, pose=Pose((0.0, 0.0, 0.08)))
    sim.systems.add(e.name, Broken())
    e.systems[0].command(0.2, 0.0)
    with caplog.at_level("ERROR"):
        sim.step(500)
    assert Broken.calls == 1
    assert "system Broken of entity 'simple_robot' raised in pre_update: RuntimeError: plugin bug" in caplog.text
    assert sim.world.entity_state("simple_robot").pose.position[0] > 0.05  # the diff drive still drives


def test_the_bus_fans_out_and_takes_injection() -> None:
    """Any number of listeners per publisher (a recorder and an echo beside the bridge), and anything
    can publish into the simulation as the ROS bridge does (the viewer's drive buttons, bag playback)."""
    sim, entity = spawn(load(SEED_XACRO).model.urdf)
    odom = next(e for e in sim.bus.endpoints() if e.topic == "/odom" and e.is_publisher)
    first, second = [], []
    odom.add_sink(first.append)
    odom.add_sink(second.append)
    delivered = sim.bus.inject("/cmd_vel", MsgType.TWIST, Twist((0.2, 0.0, 0.0), (0.0, 0.0, 0.0)))
    assert delivered == 1
    sim.step(1000)
    assert len(first) == len(second) > 0 and first[-1] is second[-1]
    assert first[-1].pose.position[0] > 0.15  # the injected command drove it
    odom.remove_sink(second.append)
    n = len(second)
    sim.step(100)
    assert len(second) == n and len(first) > n
    assert sim.bus.inject("/nobody", MsgType.TWIST, Twist((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))) == 0


def test_one_rate_gate_for_every_periodic_publisher() -> None:
    from gazelle.systems import RateGate

    gate = RateGate()
    due = [k for k in range(1000) if gate.due(k * 0.001, 50.0)]
    assert len(due) == 50 and due[:3] == [0, 20, 40]  # 50 Hz of sim time, first at the first step
    assert all(gate.due(1.0 + k * 0.001, 0.0) for k in range(5))  # rate 0: every step
    gate.reset()
    assert gate.due(0.0, 50.0)  # after a reset of sim time, at once


def test_did_you_mean_offers_a_typo_its_plugin_and_another_plugin_nothing():
    """Issue 26: `gazelle check` suggested 'gz-sim-diff-drive-system' for gz-sim's LiftDrag (the gz-sim
    names share most of their characters); a typo still gets its plugin."""
    from gazelle.description import ConfigElement, Plugin
    from gazelle.systems._registry import plugin_problem

    def problem(filename: str, name: str = "p") -> str:
        text = plugin_problem(Plugin(name=name, filename=filename, config=ConfigElement("plugin")))
        assert text is not None
        return text

    assert "did you mean" not in problem("gz-sim-lift-drag-system", "gz::sim::systems::LiftDrag")
    assert "did you mean" not in problem("gz-sim-buoyancy-system", "gz::sim::systems::Buoyancy")
    assert "did you mean 'gz-sim-diff-drive-system'?" in problem("gz-sim-diff-drive-sytem")
    assert "did you mean 'libgazebo_ros_diff_drive.so'?" in problem("libgazebo_ros_diff_drve.so")
    assert "did you mean 'libgazebo_ros_imu_sensor.so'?" in problem("libgazebo_ros_imu_sensr.so")


def test_every_sensor_kind_declares_what_runs_it_and_the_registry_is_derived_from_that() -> None:
    """Issue 32: a sensor's SDF types, its gazebo_ros plugins and its gz-sim world system are declared on
    its class (one place); the registry's tables come from those declarations. Before, they were spelled
    in three tables, and a sensor without an entry in a fourth was silently a lidar."""
    from gazelle.systems import _registry
    from gazelle.systems.sensors import OUTPUT_MESSAGES, Camera, GpsSensor, ImuSensor, Lidar

    assert len(_registry.sensor_classes()) == 9
    for cls in _registry.sensor_classes():
        assert cls.sdf_types and cls.sdf_types <= _registry.SDF_SENSOR_TYPES, cls
        assert cls.gz_system, cls
        kind = getattr(cls, "output_kind", None)
        # every output is a message sensor_output knows, or one the sensor's own module declares
        assert kind is None or kind in OUTPUT_MESSAGES or getattr(cls, "output_message", None) is not None, cls
    plugins, world = _registry._sensor_tables()
    assert plugins["gazebo_ros_ray_sensor"] == (Lidar, Lidar.sdf_types)
    assert plugins["gazebo_ros_depth_camera"][0] is Camera and "camera" not in plugins["gazebo_ros_depth_camera"][1]
    for spelling in ("gz-sim-imu-system", "gz::sim::systems::Imu", "ignition::gazebo::systems::Imu"):
        assert world[spelling] == {"imu": ImuSensor}
    assert world["gz-sim-navsat-system"] == {"gps": GpsSensor, "navsat": GpsSensor}
    assert set(world["gz-sim-air-pressure-system"]) == {"air_pressure"}  # its file's spelling, declared
    assert world["gz-sim-sensors-system"]["gpu_lidar"] is Lidar and world["gz-sim-sensors-system"]["rgbd"] is Camera


# --------------------------------------------------------------------------- built-in robot_state_publisher
_TURNTABLE = """<robot name="turntable">
  <link name="world"/>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="plate"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="to_world" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0.5 0 0.1"/></joint>
  <joint name="spin" type="continuous"><parent link="world"/><child link="plate"/><origin xyz="0 1 0"/>
    <axis xyz="0 0 1"/></joint>
</robot>"""


def test_the_built_in_robot_state_publisher_publishes_the_joints_of_a_world_link_as_robot_state_publisher_does() -> (
    None
):
    """robot_state_publisher 3.3.3 (addChildren) publishes every joint of the URDF's tree, a ``world`` link's
    too, in the URDF's frame: world -> base at the joint's origin (not where the robot was spawned), and a
    moving joint from world at its position."""
    sim = new_simulation()
    entity = sim.spawn(load_string(_TURNTABLE).model, name="tt", pose=Pose((3.0, 0.0, 0.0)))
    static = next(e for e in sim.bus.endpoints() if e.topic == "/tf_static" and e.owner == "tt")
    fixed = {t.child: t for t in static.last.transforms}
    assert set(fixed) == {"base"} and fixed["base"].parent == "world"
    assert fixed["base"].pose.position == pytest.approx((0.5, 0.0, 0.1))
    sim.world.set_joint_state("tt", "spin", position=0.4)
    tf = next(e for e in sim.bus.endpoints() if e.topic == "/tf" and e.owner == "tt")
    got = []
    tf.add_sink(got.append)
    sim.step(100)
    (plate,) = [t for t in got[-1].transforms if t.child == "plate"]
    assert plate.parent == "world" and plate.pose.position == pytest.approx((0.0, 1.0, 0.0), abs=1e-6)
    w, _x, _y, z = plate.pose.orientation
    assert 2 * math.atan2(z, w) == pytest.approx(sim.world.joint("tt", "spin").position, abs=1e-6)
    assert sim.world.joint("tt", "spin").position == pytest.approx(0.4, abs=1e-3)
    assert entity.X_WM.position == pytest.approx((3.0, 0.0, 0.0))


def test_a_plugin_parameter_no_system_reads_is_named_with_its_line(caplog) -> None:
    """Nothing a user gave is dropped silently: every child of a ``<plugin>`` its system's configure never
    looked up is a warning naming it and its file:line (a typo, a parameter gazelle does not simulate such
    as gz_ros2_control's position_proportional_gain); ROS 1 names a system maps count as read."""
    diffbot = (REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf").read_text()
    urdf = diffbot.replace(
        "</robot>",
        '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
        "<position_proportional_gain>0.5</position_proportional_gain><hold_joint>false</hold_joint>"
        "<hold_joints>true</hold_joints></plugin>"
        '<plugin filename="libgazebo_ros_p3d.so" name="truth"><bodyName>base_link</bodyName>'
        "<topicName>truth</topicName><updateRate>10</updateRate></plugin></gazebo></robot>",
    )
    with caplog.at_level(logging.WARNING):
        spawn(urdf, source="/robots/diffbot.urdf")
    unread = sorted(r.getMessage() for r in caplog.records if "is not read by" in r.getMessage())
    line = diffbot.rstrip("\n").count("\n") + 1  # the plugins are on the file's last line
    assert unread == [
        f"/robots/diffbot.urdf:{line}: <hold_joint> is not read by gz_ros2_control-system; it is ignored",
        f"/robots/diffbot.urdf:{line}: <position_proportional_gain> is not read by gz_ros2_control-system; "
        "it is ignored",
    ]


def test_gz_sims_joint_state_publisher_publishes_every_joint_as_ros_gz_bridge_delivers_it(caplog) -> None:
    """gz-sim8's JointStatePublisher through ros_gz_bridge: without <joint_name> every joint of the model
    (the fixed one too, at zero), each with an effort of 0 (gz-sim's physics never fills JointForce), on
    /world/<world>/model/<model>/joint_state; a named joint the model lacks is an error and left out."""
    plugin = '<plugin filename="gz-sim-joint-state-publisher-system" name="gz::sim::systems::JointStatePublisher">'
    urdf = _TURNTABLE.replace("</robot>", f"<gazebo>{plugin}</plugin></gazebo></robot>")
    sim = new_simulation()
    sim.spawn(load_string(urdf).model, name="tt", pose=Pose((0.0, 0.0, 0.0)))
    sim.world.set_joint_state("tt", "spin", position=0.4)
    (ep,) = [e for e in sim.bus.endpoints() if e.topic == "/world/default/model/tt/joint_state"]
    got = []
    ep.add_sink(got.append)
    sim.step(20)
    last = got[-1]
    assert last.names == ("to_world", "spin")
    assert last.positions[0] == 0.0 and last.positions[1] == pytest.approx(0.4, abs=1e-3)
    assert last.efforts == (0.0, 0.0)
    named = urdf.replace(
        f"{plugin}</plugin>", f"{plugin}<joint_name>nope</joint_name><joint_name>spin</joint_name></plugin>"
    )
    with caplog.at_level(logging.ERROR):
        sim2 = new_simulation()
        sim2.spawn(load_string(named).model, name="tt", pose=Pose((0.0, 0.0, 0.0)))
    assert "Joint with name[nope] not found." in caplog.text
    (ep2,) = [e for e in sim2.bus.endpoints() if e.topic == "/world/default/model/tt/joint_state"]
    got2 = []
    ep2.add_sink(got2.append)
    sim2.step(20)
    assert got2[-1].names == ("spin",)
