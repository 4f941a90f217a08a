"""Issue 26: what real repositories hit, each against Gazebo's own behaviour."""

from __future__ import annotations

from pathlib import Path

import pytest
from _paths import REAL

from gazelle.description import Pose, ResourceResolver, load, load_string

CLASSIC_WORLD = """<?xml version="1.0"?>
<sdf version="1.6"><world name="default">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>
</world></sdf>"""

BALL = """<sdf version="1.6"><model name="ball"><link name="l">
  <inertial><mass>1</mass><inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.004</izz></inertia></inertial>
  <collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
</link></model></sdf>"""


def test_classic_stock_ground_plane_and_sun_are_built_in(monkeypatch, tmp_path: Path, make_sim) -> None:
    """Gazebo Classic installs model://ground_plane and model://sun with itself: a Classic world (TurtleBot3's,
    empty.world) that includes them has a floor in gazelle too (it fell to z = -245 m in 7 s)."""
    for var in ("GAZELLE_RESOURCE_PATH", "GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "AMENT_PREFIX_PATH"):
        monkeypatch.delenv(var, raising=False)
    world_file = tmp_path / "empty.world"
    world_file.write_text(CLASSIC_WORLD)
    result = load(world_file)
    world = result.world
    assert [m.name for m in world.models] == ["ground_plane"]
    assert [light.name for light in world.lights] == ["sun"]
    assert not [d for d in result.diagnostics if "ground_plane" in d.message or "sun" in d.message]
    sim = make_sim(world)
    try:
        sim.spawn(load_string(BALL).model, name="ball", pose=Pose((0.0, 0.0, 0.5)))
        sim.step(2000)
        z = sim.world.entity_state("ball").pose.position[2]
        assert z == pytest.approx(0.1, abs=0.01)
    finally:
        sim.stop()


def test_an_installed_ground_plane_model_is_used_before_the_built_in_one() -> None:
    resolver = ResourceResolver(extra_paths=[REAL / "gazebo_models" / "models"], env={})
    world = load_string(CLASSIC_WORLD, resolver=resolver).world
    (ground,) = world.models
    assert "gazebo_models" in ground.source_file


def test_a_missing_or_broken_collision_mesh_is_left_out_and_the_world_loads(tmp_path: Path, caplog, make_sim) -> None:
    """turtlebot3_house, articubot's obstacles.world and the Husky playpen died with a 70-line traceback
    on one missing mesh; Gazebo loads them without that geometry and says so."""
    broken = tmp_path / "broken.stl"
    broken.write_bytes(b"not a mesh at all")
    model = f"""<model name="barrel"><static>true</static><link name="l">
      <collision name="gone"><geometry><mesh><uri>model://no_such_model/meshes/barrel.dae</uri></mesh></geometry>
      </collision>
      <collision name="bad"><geometry><mesh><uri>{broken}</uri></mesh></geometry></collision>
      <collision name="kept"><geometry><box><size>1 1 1</size></box></geometry></collision>
    </link></model>"""
    world = tmp_path / "w.world"
    world.write_text(
        f'<sdf version="1.6"><world name="w"><include><uri>model://ground_plane</uri></include>{model}</world></sdf>'
    )
    sim = make_sim(load(world).world)
    try:
        assert set(sim.world.entities) == {"ground_plane", "barrel"}
        geoms = [sim.world.model.geom(i).name for i in range(sim.world.model.ngeom)]
        assert any("kept" in g for g in geoms) and not any("gone" in g or "::bad" in g for g in geoms)
        text = caplog.text
        assert "collision 'gone'" in text and "it is left out" in text and "collision 'bad'" in text
    finally:
        sim.stop()


@pytest.mark.parametrize("enforce", [False, True])
def test_command_interface_min_max_clamp_only_where_the_manager_enforces_command_limits(
    enforce: bool, tmp_path, make_sim
) -> None:
    """Husky declares min -1 / max 1 on its wheel velocity interfaces and drives at 1 m/s in Gazebo:
    gz_ros2_control (gz_system.cpp, write()) and gazebo_ros2_control pass commands on unclamped;
    ros2_control Jazzy clamps only with the manager's enforce_command_limits (default false)."""
    from gazelle.systems import Float64Array, MsgType
    from gazelle.systems.ros2_control import ControllerManager

    urdf = (REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf").read_text()
    urdf = urdf.replace(
        '<command_interface name="velocity"/>',
        '<command_interface name="velocity"><param name="min">-1</param><param name="max">1</param></command_interface>',
    )
    params = tmp_path / "cm.yaml"
    params.write_text(
        f"controller_manager:\n  ros__parameters:\n    enforce_command_limits: {str(enforce).lower()}\n"
        "wheels:\n  ros__parameters:\n    type: velocity_controllers/JointGroupVelocityController\n"
        "    joints: [left_wheel_joint, right_wheel_joint]\n"
    )
    urdf = urdf.replace(
        "</robot>",
        '<gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">'
        f"<parameters>{params}</parameters></plugin></gazebo></robot>",
    )
    source = tmp_path / "diffbot.urdf"
    source.write_text(urdf)
    sim = make_sim()
    try:
        entity = sim.spawn(load(source).model, name="diffbot", pose=Pose((0.0, 0.0, 0.05)))
        (cm,) = [s for s in entity.systems if isinstance(s, ControllerManager)]
        cm.load_controller("wheels")
        cm.configure_controller("wheels")
        cm.switch_controller(["wheels"], [])
        sim.bus.inject("/wheels/commands", MsgType.FLOAT64_ARRAY, Float64Array((3.0, 3.0)))
        sim.step(1000)
        speed = sim.world.joint("diffbot", "left_wheel_joint").velocity
        assert speed == pytest.approx(1.0 if enforce else 3.0, rel=0.03)
    finally:
        sim.stop()


def test_models_a_package_exports_for_gazebo_are_found(tmp_path: Path) -> None:
    """turtlebot3_gazebo's package.xml exports ``gazebo_model_path="${prefix}/models"``; gazebo_ros adds
    it to GAZEBO_MODEL_PATH, so TurtleBot3's world finds model://turtlebot3_world (issue 26)."""
    prefix = tmp_path / "install"
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    for name, export in (("my_gazebo", "${prefix}/models"), ("sneaky", "/etc")):
        (index / name).write_text("")
        share = prefix / "share" / name
        (share / "models" / f"{name}_world").mkdir(parents=True)
        (share / "models" / f"{name}_world" / "model.sdf").write_text(BALL.replace("ball", f"{name}_world"))
        (share / "package.xml").write_text(
            f'<package format="3"><name>{name}</name><export><build_type>ament_cmake</build_type>'
            f'<gazebo_ros gazebo_model_path="{export}"/></export></package>'
        )
    resolver = ResourceResolver(env={"AMENT_PREFIX_PATH": str(prefix)})
    world = '<sdf version="1.6"><world name="w"><include><uri>model://my_gazebo_world</uri></include></world></sdf>'
    assert [m.name for m in load_string(world, resolver=resolver).world.models] == ["my_gazebo_world"]
    assert resolver.find_package("passwd") is None  # an export outside its package is not followed
    assert prefix / "share" / "my_gazebo" / "models" in [p for p in resolver.search_paths()]


def test_a_package_is_found_by_the_name_in_its_package_xml(tmp_path: Path) -> None:
    """Issue 27: GAZELLE_RESOURCE_PATH=<a moveit_resources clone> did not find
    moveit_resources_panda_moveit_config, whose folder is panda_moveit_config."""
    clone = tmp_path / "moveit_resources"
    pkg = clone / "panda_moveit_config"
    (pkg / "config").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        "<package format='3'>\\n  <name>moveit_resources_panda_moveit_config</name>\\n</package>"
    )
    (pkg / "config" / "panda.srdf").write_text("<robot name='panda'/>")
    (clone / ".git" / "deep").mkdir(parents=True)
    (clone / ".git" / "deep" / "package.xml").write_text("<package><name>hidden</name></package>")
    resolver = ResourceResolver(extra_paths=[clone], env={})
    assert resolver.find_package("moveit_resources_panda_moveit_config") == pkg.resolve()
    uri = "package://moveit_resources_panda_moveit_config/config/panda.srdf"
    assert resolver.resolve_uri(uri) == (pkg / "config" / "panda.srdf").resolve()
    assert resolver.find_package("hidden") is None


def test_a_joint_whose_limits_are_equal_is_held_there_not_refused(make_sim) -> None:
    """gz-sim's nested_model_joint_positions and tracked_vehicle_simple have joints with lower == upper;
    Gazebo loads them (the joint cannot move), MuJoCo's compiler refused them."""
    inertial = (
        '<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
    )
    urdf = (
        f'<robot name="r"><link name="a">{inertial}</link><link name="b">{inertial}'
        '<collision><origin xyz="0.2 0 0"/><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>'
        '<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
        '<limit lower="0.3" upper="0.3" effort="1" velocity="1"/></joint></robot>'
    )

    sim = make_sim()
    try:
        sim.spawn(load_string(urdf).model, name="r", pose=Pose((0.0, 0.0, 2.0)))
        sim.step(300)
        assert sim.world.joint("r", "j").position == pytest.approx(0.3, abs=1e-3)
    finally:
        sim.stop()
