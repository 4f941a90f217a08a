"""Real Gazebo files load as Gazebo loads them (issue 10): what sdformat and TinyXML accept, we accept.

Each case is the shape found in public files: Husky's and articubot_one's `<mu1 value="1.0"/>`,
comments with `--` in 19 of gz-sim's example worlds, "Construction Cone" names from GUI-saved
worlds, `r2.urdf.xml`, SDF 1.11's `<cone>`.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from gazelle.description import Cone, ErrorCode, ModelLoadError, Pose, load, load_string


def test_gazebo_extension_values_may_be_attributes() -> None:
    urdf = (
        '<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/>'
        '</inertial><collision><geometry><box size="1 1 1"/></geometry></collision></link>'
        '<gazebo reference="a"><mu1 value="0.3"/><mu2 value="0.2"/><kp value="1e6"/><selfCollide value="true"/></gazebo>'
        "</robot>"
    )
    result = load_string(urdf)
    surface = result.model.links[0].collisions[0].surface
    assert (surface.mu, surface.mu2, surface.kp) == (0.3, 0.2, 1e6)
    assert result.diagnostics == ()


def test_a_bad_value_in_a_xacro_included_file_points_at_that_file(tmp_path: Path) -> None:
    (tmp_path / "wheel.urdf.xacro").write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="wheel" params="name">\n    <link name="${name}"/>\n'
        '    <gazebo reference="${name}">\n      <mu1 value="slippery"/>\n    </gazebo>\n'
        "  </xacro:macro>\n</robot>\n"
    )
    top = tmp_path / "robot.urdf.xacro"
    top.write_text(
        '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:include filename="wheel.urdf.xacro"/>\n  <link name="base"/>\n  <xacro:wheel name="w"/>\n'
        '  <joint name="j" type="fixed"><parent link="base"/><child link="w"/></joint>\n</robot>\n'
    )
    with pytest.raises(Exception) as info:
        load(top)
    assert f"{tmp_path / 'wheel.urdf.xacro'}:6: error: [VALUE_INVALID] <mu1>" in str(info.value)


@pytest.mark.parametrize("suffix", [".sdf", ".urdf", ".urdf.xacro"])
def test_comments_with_double_hyphens_are_accepted_with_a_warning(tmp_path: Path, suffix: str) -> None:
    if suffix == ".sdf":
        text = (
            '<?xml version="1.0"?>\n<sdf version="1.9">\n<!-- --- a ruler -- and more --->\n<world name="w"/>\n</sdf>\n'
        )
    else:
        text = (
            '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
            '<!-- -- old -- notes -->\n<link name="a"/>\n</robot>\n'
        )
    f = tmp_path / f"doc{suffix}"
    f.write_text(text)
    result = load(f)
    if suffix == ".sdf":
        warnings = [d for d in result.diagnostics if "'--'" in d.message]
        assert [d.location and d.location.line for d in warnings] == [3]
    else:
        assert result.model.links[0].name == "a"


def test_the_root_element_tells_the_format_when_the_suffix_does_not(tmp_path: Path) -> None:
    f = tmp_path / "r2.urdf.xml"
    f.write_text('<robot name="r2"><link name="body"/></robot>')
    assert load(f).model.name == "r2"
    g = tmp_path / "world.xml"
    g.write_text('<sdf version="1.9"><world name="w"/></sdf>')
    assert load(g).world.name == "w"


def test_names_with_spaces_load_and_simulate(make_sim) -> None:
    world = (
        '<sdf version="1.9"><world name="playpen"><model name="Construction Cone"><pose>1 0 0.5 0 0 0</pose>'
        '<link name="link"><inertial><mass>1</mass></inertial><collision name="c"><geometry><box><size>0.2 0.2 0.2</size>'
        "</box></geometry></collision></link></model></world></sdf>"
    )
    sim = make_sim(load_string(world).world)
    sim.step(10)
    assert "Construction Cone" in sim.world.entities
    sim.spawn(sim.world.entities["Construction Cone"].model, name="Construction Cone_0", pose=Pose((3.0, 0.0, 0.5)))
    assert sim.world.entity_state("Construction Cone_0").pose.position[0] == pytest.approx(
        4.0, abs=1e-3
    )  # + its file pose


def test_a_cone_collides_and_rests_on_its_base(make_sim) -> None:
    model = load_string(
        '<sdf version="1.11"><model name="cone"><link name="l"><inertial><mass>1</mass><inertia><ixx>0.01</ixx>'
        '<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial><collision name="c"><geometry><cone><radius>0.2</radius>'
        "<length>0.4</length></cone></geometry></collision></link></model></sdf>"
    ).model
    assert model.links[0].collisions[0].geometry == Cone(0.2, 0.4)
    sim = make_sim()
    sim.spawn(model, name="cone", pose=Pose((0.0, 0.0, 1.0)))
    sim.step(3000)
    z = sim.world.entity_state("cone").pose.position[2]
    assert z == pytest.approx(0.2, abs=0.005)  # the base on the ground, the origin half a length up (it fell before)


def test_an_unsupported_geometry_says_the_link_collides_with_nothing() -> None:
    result = load_string(
        '<sdf version="1.11"><model name="m"><link name="l"><collision name="c"><geometry><heightmap/></geometry>'
        "</collision></link></model></sdf>"
    )
    [d] = [d for d in result.diagnostics if "heightmap" in d.message]
    assert d.code is ErrorCode.ELEMENT_UNSUPPORTED and "collides with nothing" in d.message


def _fuel_world(*names: str) -> str:
    incs = "".join(f"<include><uri>https://fuel.gazebosim.org/1.0/{n}</uri></include>" for n in names)
    return f'<sdf version="1.8"><world name="w">{incs}</world></sdf>'


def test_fuel_ground_plane_and_sun_are_built_in(monkeypatch, tmp_path: Path, make_sim) -> None:
    monkeypatch.setenv("HOME", str(tmp_path))  # no local Fuel cache
    monkeypatch.delenv("GZ_FUEL_CACHE_PATH", raising=False)
    world = load_string(_fuel_world("OpenRobotics/models/Ground Plane", "OpenRobotics/models/Sun")).world
    assert [m.name for m in world.models] == ["ground_plane"] and [lt.name for lt in world.lights] == ["sun"]
    sim = make_sim(world)
    sim.spawn(
        load_string(
            '<sdf version="1.9"><model name="b"><link name="l"><inertial><mass>1</mass></inertial><collision name="c">'
            "<geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link></model></sdf>"
        ).value,
        name="b",
        pose=Pose((0.0, 0.0, 0.5)),
    )
    sim.step(1500)
    assert sim.world.entity_state("b").pose.position[2] == pytest.approx(0.1, abs=0.005)  # rests on Fuel's plane


def test_other_fuel_models_come_from_the_local_cache_or_are_named_in_an_error_line(monkeypatch, tmp_path: Path) -> None:
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.delenv("GZ_FUEL_CACHE_PATH", raising=False)
    result = load_string(_fuel_world("OpenRobotics/models/Construction Cone"))
    [d] = result.diagnostics
    assert "Fuel model 'OpenRobotics/Construction Cone'" in d.message and "nothing was fetched" in d.message
    assert "get it with `gz fuel download -u" in d.message  # what the user can do, in the same line
    # gz-sim's cache layout: <cache>/<host>/<owner>/models/<name>/<version>/model.sdf
    cache = tmp_path / "cache"
    model_dir = cache / "fuel.gazebosim.org" / "openrobotics" / "models" / "construction cone" / "2"
    model_dir.mkdir(parents=True)
    (model_dir / "model.sdf").write_text(
        '<sdf version="1.6"><model name="Construction Cone"><static>true</static><link name="link"/></model></sdf>'
    )
    monkeypatch.setenv("GZ_FUEL_CACHE_PATH", str(cache))
    world = load_string(_fuel_world("OpenRobotics/models/Construction Cone")).world
    assert [m.name for m in world.models] == ["Construction Cone"]


def test_the_bridge_converts_between_a_stamped_and_an_unstamped_type():
    """Issue 26 (TurtleBot3's jazzy bridge YAML has cmd_vel as TwistStamped; gazelle's DiffDrive takes Twist):
    the parameter_bridge stand-in converts between a type and the one that holds it."""
    from geometry_msgs.msg import Twist, TwistStamped
    from sensor_msgs.msg import Imu

    from gazelle.ros._gz_compat import converter

    stamped = TwistStamped()
    stamped.twist.linear.x = 0.2
    assert converter(TwistStamped, Twist)(stamped).linear.x == 0.2
    plain = Twist()
    plain.angular.z = 0.5
    assert converter(Twist, TwistStamped)(plain).twist.angular.z == 0.5
    assert converter(Twist, Imu) is None


def test_a_cached_fuel_model_without_a_model_is_a_clear_error(monkeypatch, tmp_path: Path) -> None:
    """A Fuel cache entry whose model.sdf holds no <model> is named in an error; it raised NameError ('path'
    is only set for file includes) from inside the loader."""
    from gazelle.description import ModelLoadError

    cache = tmp_path / "cache"
    model_dir = cache / "fuel.gazebosim.org" / "someone" / "models" / "empty thing" / "1"
    model_dir.mkdir(parents=True)
    (model_dir / "model.sdf").write_text('<sdf version="1.6"><world name="not_a_model"/></sdf>')
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.setenv("GZ_FUEL_CACHE_PATH", str(cache))
    with pytest.raises(ModelLoadError, match=r"holds no <model>"):
        load_string(_fuel_world("someone/models/Empty Thing"))


def test_a_collision_block_is_applied_to_every_collision_of_its_link_then_the_short_forms_over_it():
    """sdformat's parser_urdf.cc: a <gazebo reference> block's <collision> children go into each collision of the
    link (a <surface> replacing what earlier blocks gave), then that block's short forms are written over them."""
    urdf = """<?xml version="1.0"?><robot name="r">
  <link name="w"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><cylinder radius="0.1" length="0.05"/></geometry></collision>
    <collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <gazebo reference="w"><kp>1e5</kp></gazebo>
  <gazebo reference="w">
    <mu2>0.25</mu2>
    <collision>
      <laser_retro>100</laser_retro>
      <surface><friction><ode><mu>0.8</mu><mu2>0.5</mu2><fdir1>0 0 1</fdir1></ode></friction>
        <contact><collide_bitmask>0x03</collide_bitmask></contact></surface>
      <geometry><box><size>1 1 1</size></box></geometry>
    </collision>
  </gazebo>
</robot>"""
    result = load_string(urdf)
    surfaces = [c.surface for c in result.model.links[0].collisions]
    assert len(surfaces) == 2 and surfaces[0] == surfaces[1]
    s = surfaces[0]
    # the block's <surface> replaced the first block's kp; its own <mu2> short form went over the surface's
    assert (s.mu, s.mu2, s.fdir1, s.collide_bitmask, s.kp) == (0.8, 0.25, (0.0, 0.0, 1.0), 3, None)
    assert [d.format() for d in result.diagnostics] == [
        '<string>.urdf:12: warning: [ELEMENT_UNSUPPORTED] <geometry> in <gazebo reference="w"><collision> is not '
        "supported and is ignored"
    ]


def test_a_bad_value_in_a_collision_block_is_an_error_at_its_line():
    urdf = """<?xml version="1.0"?><robot name="r">
  <link name="w"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <gazebo reference="w"><collision><surface><friction><ode>
    <mu>QQQ</mu></ode></friction></surface></collision></gazebo>
</robot>"""
    with pytest.raises(ModelLoadError) as err:
        load_string(urdf)
    assert "<string>.urdf:4: error: [VALUE_INVALID] <mu> must be a number, got 'QQQ'" in str(err.value)
