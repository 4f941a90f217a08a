"""SDF loader: real public files, the chess seed, quirks, frame semantics and invalid inputs."""

from __future__ import annotations

import math
import random
import time
from pathlib import Path

import pytest
from _paths import REAL, TEST_DATA

from gazelle.description import (
    Box,
    Capsule,
    ConfigElement,
    Cylinder,
    Inertial,
    Joint,
    JointAxis,
    JointType,
    Link,
    Mesh,
    Model,
    ModelLoadError,
    Plane,
    ResourceResolver,
    World,
    load,
    load_string,
)

DATA = TEST_DATA / "sdf"

TB3 = REAL / "turtlebot3" / "turtlebot3_gazebo"
GZM = REAL / "gazebo_models" / "models"
needs_real = pytest.mark.skipif(not REAL.is_dir(), reason="shared real fixtures not available")


def inertial_of(link: Link) -> Inertial:
    """The link's mass properties (every loaded link has them: SDF's default when none are written)."""
    assert link.inertial is not None
    return link.inertial


def axis_of(joint: Joint) -> JointAxis:
    """The joint's axis (a joint type that has one)."""
    assert joint.axis is not None
    return joint.axis


def child(config: ConfigElement, tag: str) -> ConfigElement:
    """The first ``<tag>`` child of a plugin's or sensor's block, which the test knows is there."""
    found = config.find(tag)
    assert found is not None, f"no <{tag}> in <{config.tag}>"
    return found


def resolver(*paths: Path) -> ResourceResolver:
    """A resolver that only sees ``paths`` (the environment is ignored)."""
    return ResourceResolver(extra_paths=list(paths), env={})


def codes(result) -> set[str]:
    return {d.code.value for d in result.diagnostics}


def close(a, b, tol=1e-6) -> bool:
    return all(abs(x - y) <= tol for x, y in zip(a, b, strict=True))


def load_error(name: str, **kw) -> ModelLoadError:
    with pytest.raises(ModelLoadError) as info:
        load(DATA / name, resolver=kw.pop("res", resolver()), **kw)
    return info.value


# --------------------------------------------------------------------------- real files
REAL_CASES = [
    # (file, model path, expected kind, expected warning codes)
    ("turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model.sdf", TB3 / "models", Model, set()),
    ("turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model-1_4.sdf", TB3 / "models", Model, set()),
    ("turtlebot3/turtlebot3_gazebo/models/turtlebot3_world/model.sdf", TB3 / "models", Model, set()),
    ("turtlebot3/turtlebot3_gazebo/models/turtlebot3_world/model-1_4.sdf", TB3 / "models", Model, set()),
    # Fuel's Ground Plane and Sun are built in (nothing is fetched)
    ("turtlebot3/turtlebot3_gazebo/worlds/turtlebot3_world.world", TB3 / "models", World, set()),
    ("turtlebot3/turtlebot3_gazebo/worlds/empty_world.world", TB3 / "models", World, {"ELEMENT_UNSUPPORTED"}),
] + [
    (f"gazebo_models/models/{m}/{f}", GZM, World if m == "sun" else Model, set())
    for m in ("ground_plane", "sun", "table", "coke_can")
    for f in ("model.sdf", "model-1_2.sdf", "model-1_3.sdf", "model-1_4.sdf")
]


@needs_real
@pytest.mark.parametrize(("rel", "model_path", "kind", "warnings"), REAL_CASES, ids=[c[0] for c in REAL_CASES])
def test_real_sdf_loads_with_exact_warnings(rel, model_path, kind, warnings):
    result = load(REAL / rel, resolver=resolver(model_path))
    assert isinstance(result.value, kind)
    assert codes(result) == warnings
    assert all(d.severity.value == "warning" for d in result.diagnostics)


@needs_real
def test_turtlebot3_burger_structure():
    model = load(TB3 / "models/turtlebot3_burger/model.sdf", resolver=resolver(TB3 / "models")).value
    assert isinstance(model, Model)
    assert [lk.name for lk in model.links] == [
        "base_footprint",
        "base_link",
        "imu_link",
        "base_scan",
        "wheel_left_link",
        "wheel_right_link",
        "caster_back_link",
    ]
    assert len(model.joints) == 6
    assert model.root_link == "base_footprint"
    assert model.joint("caster_back_joint").type is JointType.BALL
    wheel = model.joint("wheel_left_joint")
    assert wheel.type is JointType.REVOLUTE and wheel.axis is not None
    assert (
        close(axis_of(wheel).xyz, (0, 0, 1))
        and axis_of(wheel).limit.effort == 20
        and axis_of(wheel).limit.lower is None
    )
    # joint pose is relative to the child link (at the model origin): X_PC = origin * child_offset
    x_pc = wheel.origin * wheel.child_offset
    assert close(x_pc.position, (0, 0, 0)) and close(x_pc.orientation, (1, 0, 0, 0))
    assert close(wheel.origin.position, (0, 0.08, 0.023))
    base = model.link("base_link")
    assert base.inertial is not None and math.isclose(inertial_of(base).mass, 0.82573504)
    geometry = base.visuals[0].geometry
    assert isinstance(geometry, Mesh) and geometry.path is not None
    assert geometry.scale == (0.001, 0.001, 0.001)
    # no <inertial>: SDF's default (1 kg, unit inertia), as in Gazebo
    assert inertial_of(model.link("base_footprint")).mass == 1.0
    imu = model.link("imu_link").sensors[0]
    assert (imu.type, imu.update_rate_hz, imu.topic, imu.always_on) == ("imu", 200.0, "imu", True)
    lidar = model.link("base_scan").sensors[0]
    assert lidar.type == "gpu_lidar" and close(lidar.pose.position, (-0.032, 0, 0.171))
    assert lidar.config is not None and lidar.config.find("lidar") is not None
    surface = model.link("wheel_left_link").collisions[0].surface
    assert (surface.mu, surface.mu2, surface.kp, surface.kd, surface.soft_erp) == (1e5, 1e5, 1e5, 1.0, 0.2)
    assert surface.fdir1 == (0.0, 0.0, 0.0) and surface.min_depth == 0.001
    caster = model.link("caster_back_link")
    assert caster.pose is not None and close(caster.pose.position, (-0.081, 0, -0.004))
    drive = model.plugins[0]
    assert drive.name == "gz::sim::systems::DiffDrive" and drive.filename == "gz-sim-diff-drive-system"
    assert child(drive.config, "wheel_radius").text == "0.033"
    assert [c.text for c in model.plugins[1].config.findall("joint_name")] == ["wheel_left_joint", "wheel_right_joint"]


@needs_real
def test_turtlebot3_burger_sdf14_counts_and_sensor_plugins():
    model = load(TB3 / "models/turtlebot3_burger/model-1_4.sdf", resolver=resolver(TB3 / "models")).model
    assert (len(model.links), len(model.joints)) == (7, 6)
    assert [p.filename for p in model.link("base_scan").sensors[0].plugins] == ["libgazebo_ros_ray_sensor.so"]
    # SDF 1.4: the axis is in the model frame (libsdformat adds use_parent_model_frame);
    # the joint frame is rolled by -1.57 rad, so model z is joint -y.
    axis = axis_of(model.joint("wheel_left_joint"))
    assert close(axis.xyz, (0, -math.sin(1.57), math.cos(1.57)))


@needs_real
def test_turtlebot3_world_includes_nested_model():
    res = resolver(TB3 / "models")
    result = load(TB3 / "worlds/turtlebot3_world.world", resolver=res)
    world = result.value
    assert isinstance(world, World) and world.name == "default"
    assert [m.name for m in world.models] == ["ground_plane", "turtlebot3_world"]  # Fuel's Ground Plane, built in
    assert [lt.name for lt in world.lights] == ["sun"]
    model = world.models[1]
    assert model.static and [lk.name for lk in model.links] == ["ros_symbol::symbol"]
    assert len(model.links[0].collisions) == 15
    assert world.physics.max_step_size_sec == 0.001 and world.physics.real_time_update_rate_hz == 1000
    assert len(world.plugins) == 5 and child(world.plugins[3].config, "render_engine").text == "ogre2"
    assert [d for d in result.diagnostics if d.code.value == "URI_UNRESOLVED"] == []


@needs_real
def test_gazebo_models_contents():
    res = resolver(GZM)
    ground = load(GZM / "ground_plane/model.sdf", resolver=res).model
    assert ground.static and isinstance(ground.links[0].collisions[0].geometry, Plane)
    assert ground.links[0].collisions[0].surface.mu == 100 and ground.links[0].collisions[0].surface.mu2 == 50
    material = ground.links[0].visuals[0].material
    assert material is not None and material.name == "Gazebo/Grey"
    # the script's colour, as Classic's gazebo.material draws it (the visual gives no <diffuse> of its own)
    assert material.diffuse == (0.7, 0.7, 0.7, 1.0)
    table = load(GZM / "table/model.sdf", resolver=res).model
    assert len(table.links[0].collisions) == 5
    can = load(GZM / "coke_can/model.sdf", resolver=res).model
    mesh = can.links[0].collisions[0].geometry
    assert isinstance(mesh, Mesh) and mesh.path is not None and mesh.path.endswith("coke_can.dae")
    assert math.isclose(inertial_of(can.links[0]).mass, 0.39) and close(
        inertial_of(can.links[0]).pose.position, (0, 0, 0.06)
    )
    sun = load(GZM / "sun/model-1_2.sdf", resolver=res).world  # <gazebo version="1.2"> root
    assert isinstance(sun, World) and sun.lights[0].type == "directional" and sun.lights[0].cast_shadows


def test_model_config_picks_highest_supported_version(tmp_path):
    folder = tmp_path / "widget"
    folder.mkdir()
    (folder / "model.config").write_text(
        '<?xml version="1.0"?><model><name>w</name>'
        '<sdf version="1.4">old.sdf</sdf><sdf version="1.5">model.sdf</sdf><sdf version="1.12">future.sdf</sdf></model>'
    )
    body = '<model name="{0}"><link name="l"/></model>'
    (folder / "old.sdf").write_text(f'<sdf version="1.4">{body.format("old")}</sdf>')
    # quirk: model.config says 1.5, the file declares 1.8 — accepted, read as 1.8
    (folder / "model.sdf").write_text(f'<sdf version="1.8">{body.format("current")}</sdf>')
    (folder / "future.sdf").write_text(f'<sdf version="1.12">{body.format("future")}</sdf>')
    world = '<sdf version="1.9"><world name="w"><include><uri>model://widget</uri></include></world></sdf>'
    result = load_string(world, format="sdf", resolver=resolver(tmp_path))
    assert [m.name for m in result.world.models] == ["current"]
    # sdformat's getBestSupportedModelVersion warns about the entry it is too old to read
    assert [d.message for d in result.diagnostics] == [
        f"{folder / 'model.config'}: ignoring version 1.12 of model 'widget' because it is newer than the "
        "SDFormat gazelle reads (1.11)"
    ]


def test_a_model_config_without_versions_uses_its_first_sdf_entry_and_manifest_xml_still_works(tmp_path):
    """sdformat 14 parser.cc: with no readable version, the first <sdf> entry is the model's file, whatever
    its name; without model.config, the deprecated manifest.xml is read, with a warning."""
    body = '<sdf version="1.6"><model name="{0}"><link name="l"/></model></sdf>'
    for name, config in (("plain", "model.config"), ("old", "manifest.xml")):
        folder = tmp_path / name
        folder.mkdir()
        (folder / config).write_text(f"<model><name>{name}</name><sdf>{name}.sdf</sdf><sdf>other.sdf</sdf></model>")
        (folder / f"{name}.sdf").write_text(body.format(name))
        (folder / "other.sdf").write_text(body.format("other"))
    world = (
        '<sdf version="1.9"><world name="w"><include><uri>model://plain</uri></include>'
        "<include><uri>model://old</uri></include></world></sdf>"
    )
    result = load_string(world, format="sdf", resolver=resolver(tmp_path))
    assert [m.name for m in result.world.models] == ["plain", "old"]
    assert ["manifest.xml for a model is deprecated" in d.message for d in result.diagnostics] == [True]


@needs_real
def test_world_include_overrides():
    result = load(DATA / "world_include.sdf", resolver=resolver(GZM))
    world = result.world
    assert world.name == "kitchen" and world.gravity == (0, 0, -9.81)
    assert (
        world.physics.max_step_size_sec,
        world.physics.real_time_factor,
        world.physics.real_time_update_rate_hz,
    ) == (
        0.002,
        2.0,
        500.0,
    )
    assert world.scene.ambient == (0.1, 0.2, 0.3, 1.0) and world.scene.shadows is False
    assert [m.name for m in world.models] == ["table_1", "coke_can"]
    table, can = world.models
    assert close(table.pose.position, (1, 2, 0)) and table.static  # the table model is static
    assert close(can.pose.position, (1, 2, 1.02)) and can.static  # relative_to the table, static override
    assert [lt.name for lt in world.lights] == ["sun", "lamp"]
    lamp = world.lights[1]
    assert (lamp.type, lamp.attenuation_range, lamp.cast_shadows, lamp.diffuse) == (
        "spot",
        20.0,
        True,
        (1, 0.5, 0.5, 1),
    )
    assert close(world.lights[0].direction, (-0.5, 0.1, -0.9))
    [diag] = result.diagnostics
    # a model found nowhere is an error the load goes on past (issue 49), saying how to get it
    assert diag.format().startswith(
        f"{DATA / 'world_include.sdf'}:27: error: [URI_UNRESOLVED] model 'QQQmissing' is not on the model paths"
    )
    assert diag.format().endswith("include skipped, the world loads without it")


# --------------------------------------------------------------------------- chess seed
def test_chess_board():
    result = load(DATA / "chess_board.sdf", resolver=resolver())
    board = result.model
    assert not result.diagnostics and board.static and board.name == "box"
    collision = board.links[0].collisions[0]
    assert isinstance(collision.geometry, Box) and collision.geometry.size == (0.5, 0.5, 0.02)
    assert (collision.surface.mu, collision.surface.max_vel, collision.surface.min_depth) == (0.1, 0.1, 0.001)


def test_chess_piece_nested_inertial_uses_intended_values():
    result = load(DATA / "chess_piece.sdf", resolver=resolver())
    [diag] = result.diagnostics
    assert diag.format() == (
        f"{DATA / 'chess_piece.sdf'}:7: warning: [INERTIAL_NESTED] link 'link': <inertial> nested inside "
        "<inertial>; using its values as the outer inertial's"
    )
    inertial = inertial_of(result.model.links[0])
    assert inertial.mass == 0.001 and not inertial.derived
    assert (inertial.ixx, inertial.iyy, inertial.izz, inertial.iyz) == (1.667e-7, 1.667e-8, 1.667e-7, 0.0)
    assert result.model.links[0].collisions[0].surface.mu == 0.4


# --------------------------------------------------------------------------- quirks and semantics
def test_comment_before_xml_declaration_keeps_line_numbers():
    err = load_error("comment_before_declaration.sdf")
    [diag] = err.diagnostics
    assert diag.format() == (
        f"{DATA / 'comment_before_declaration.sdf'}:8: error: [VALUE_INVALID] <size> must be 3 numbers, got '1 1 QQQ'"
    )


def test_comment_before_xml_declaration_loads():
    text = "<!-- c -->\n\n<?xml version='1.0' encoding='UTF-8'?>\n<sdf version='1.7'><model name='m'><link name='l'/></model></sdf>"
    assert load_string(text, format="sdf", resolver=resolver()).model.name == "m"


def test_namespaced_tags_are_kept_in_plugin_config():
    result = load(DATA / "gz_namespaced.sdf", resolver=resolver())
    assert not result.diagnostics
    config = result.model.plugins[0].config
    assert child(config, "gz::system_priority").text == "-10"
    legacy = child(config, "ignition:legacy")
    assert legacy.attr("ignition:flag") == "1" and legacy.location is not None and legacy.location.line == 7


def test_sdf14_axis_is_in_model_frame():
    # child link yawed by 90°; the joint frame is the child frame; axis 1 0 0 is in the
    # model frame in SDF 1.4, i.e. -y of the joint frame
    joint = load(DATA / "axis_sdf14.sdf", resolver=resolver()).model.joint("j")
    assert close(axis_of(joint).xyz, (0, -1, 0))
    assert close(joint.origin.position, (0, 0, 1)) and close(joint.child_offset.position, (0, 0, 0))


def test_sdf16_axis_is_in_joint_frame():
    joint = load(DATA / "axis_sdf16.sdf", resolver=resolver()).model.joint("j")
    assert close(axis_of(joint).xyz, (1, 0, 0))


def test_relative_to_degrees_quaternion_and_expressed_in():
    model = load(DATA / "relative_to_degrees.sdf", resolver=resolver()).model
    arm = model.link("arm")
    # mount: x=1 yawed 90°; arm 0.5 above the mount
    assert arm.pose is not None and close(arm.pose.position, (1, 0, 0.5)) and close(arm.pose.rpy, (0, 0, math.pi / 2))
    joint = model.joint("j")
    assert close(joint.origin.position, (1, 0, 0)) and close(joint.origin.rpy, (0, 0, 0))
    assert close((joint.origin * joint.child_offset).position, (1, 0, 0.5))
    assert close(axis_of(joint).xyz, (0, 1, 0))  # joint frame is aligned with the model frame
    assert (
        axis_of(joint).limit.lower,
        axis_of(joint).limit.upper,
        axis_of(joint).limit.effort,
        axis_of(joint).limit.velocity,
    ) == (
        -1,
        1,
        5,
        2,
    )
    assert (axis_of(joint).dynamics.damping, axis_of(joint).dynamics.friction) == (0.1, 0.2)
    frames = {f.name: f for f in model.frames}
    assert frames["mount"].attached_to == "base" and close(frames["mount"].pose.rpy, (0, 0, math.pi / 2))
    # no attached_to: attached to the model frame, i.e. the canonical link; pose given relative_to arm
    assert frames["tool"].attached_to == "base" and close(frames["tool"].pose.position, (1, 0, 0.6))
    assert close(frames["tool"].pose.orientation, (0, 0, 0, 1))  # yaw 90° + 90°


def test_nested_model_is_flattened_with_scoped_names():
    model = load(DATA / "nested_model.sdf", resolver=resolver()).model
    assert [lk.name for lk in model.links] == ["base", "gripper::palm", "gripper::finger"]
    assert close(model.pose.position, (0, 0, 0.1))
    palm, finger = model.link("gripper::palm").pose, model.link("gripper::finger").pose
    assert palm is not None and close(palm.position, (1, 0, 0.5))
    assert finger is not None and close(finger.position, (1, 0, 0))
    slide = model.joint("gripper::slide")
    assert (slide.parent, slide.child, slide.type) == ("gripper::palm", "gripper::finger", JointType.PRISMATIC)
    assert close((slide.origin * slide.child_offset).position, (0, 0, -0.5))
    mount = model.joint("mount")
    assert (mount.parent, mount.child) == ("base", "gripper::palm")
    assert close((mount.origin * mount.child_offset).position, (1, 0, 0.5))
    [tcp] = model.frames
    assert (tcp.name, tcp.attached_to) == ("gripper::tcp", "gripper::palm") and close(tcp.pose.position, (0, 0, 0.2))


def test_world_parent_and_shapes():
    text = """<sdf version="1.11"><model name="m"><pose>0 0 2 0 0 0</pose>
      <link name="l"><collision name="c"><geometry><capsule><radius>0.1</radius><length>0.3</length></capsule></geometry>
        <surface><friction><torsional><coefficient>0.5</coefficient></torsional>
          <bullet><friction>0.7</friction><friction2>0.6</friction2></bullet></friction>
          <contact><collide_bitmask>0x01</collide_bitmask></contact>
          <bounce><restitution_coefficient>0.3</restitution_coefficient></bounce></surface></collision>
        <visual name="v"><geometry><cylinder><radius>1</radius><length>2</length></cylinder></geometry>
          <material><diffuse>1 0 0</diffuse><pbr><metal><albedo_map>tex.png</albedo_map></metal></pbr></material></visual>
      </link>
      <joint name="pin" type="fixed"><parent>world</parent><child>l</child></joint>
      <link name="nut"/>
      <joint name="s" type="screw"><parent>l</parent><child>nut</child><axis><xyz>0 0 1</xyz></axis>
        <screw_thread_pitch>0.01</screw_thread_pitch></joint></model></sdf>"""
    model = load_string(text, format="sdf", resolver=resolver()).model
    pin = model.joint("pin")
    assert pin.parent == "world" and close(pin.origin.position, (0, 0, 2))
    col = model.link("l").collisions[0]
    assert isinstance(col.geometry, Capsule)
    assert (col.surface.mu, col.surface.mu2, col.surface.torsional, col.surface.restitution) == (0.7, 0.6, 0.5, 0.3)
    assert col.surface.collide_bitmask == 1
    vis = model.link("l").visuals[0]
    assert (
        isinstance(vis.geometry, Cylinder)
        and vis.material is not None
        and vis.material.diffuse == (1, 0, 0, 1)
        and vis.material.texture == "tex.png"
    )
    assert model.joint("s").screw_thread_pitch == 0.01


def test_inertia_problems_are_warned_and_derived():
    result = load(DATA / "inertia_problems.sdf", resolver=resolver())
    assert [(d.code.value, d.location and d.location.line) for d in result.diagnostics] == [
        ("INERTIA_INVALID", 7),
        ("MASS_INVALID", 13),
        ("INERTIA_MISSING", 18),
        ("INERTIA_INVALID", 26),
    ]
    model = result.model
    box = inertial_of(model.link("not_pd"))
    assert box.derived and box.mass == 2 and math.isclose(box.ixx, 2 * (0.04 + 0.09) / 12)
    sphere = inertial_of(model.link("zero_mass"))
    assert sphere.derived and math.isclose(sphere.mass, 1000 * 4 / 3 * math.pi * 0.001)
    cyl = inertial_of(model.link("no_inertia"))
    assert cyl.derived and math.isclose(cyl.izz, 3 * 0.01 / 2)
    assert inertial_of(model.link("malformed")).derived  # no collision: a water-density sphere


def test_mesh_not_found_warns_with_line():
    result = load(DATA / "mesh_missing.sdf", resolver=resolver())
    [diag] = result.diagnostics
    assert (
        diag.format()
        == f"{DATA / 'mesh_missing.sdf'}:7: warning: [MESH_NOT_FOUND] mesh 'meshes/QQQmissing.stl' not found"
    )
    mesh = result.model.links[0].visuals[0].geometry
    assert isinstance(mesh, Mesh) and mesh.path is None and mesh.scale == (2, 2, 2)


def test_unsupported_elements_warn():
    result = load(DATA / "unsupported_elements.sdf", resolver=resolver())
    assert [(d.code.value, d.location and d.location.line) for d in result.diagnostics] == [
        ("ELEMENT_UNSUPPORTED", line)
        for line in (4, 5, 7, 8, 9)  # line 6's <spherical_coordinates> is read
    ]
    assert "<gui> in <world>" in result.diagnostics[0].message
    assert result.world.spherical_coordinates is not None


def test_spherical_coordinates_are_read_for_gps_sensors():
    world = load_string(
        """<sdf version="1.9"><world name="w"><spherical_coordinates>
        <surface_model>EARTH_WGS84</surface_model><world_frame_orientation>ENU</world_frame_orientation>
        <latitude_deg>-22.986687</latitude_deg><longitude_deg>-43.202501</longitude_deg>
        <elevation>12.5</elevation><heading_deg>15</heading_deg></spherical_coordinates></world></sdf>""",
        format="sdf",
        resolver=resolver(),
    ).world
    sc = world.spherical_coordinates
    assert sc is not None
    assert (sc.latitude_deg, sc.longitude_deg, sc.elevation, sc.heading_deg) == (-22.986687, -43.202501, 12.5, 15.0)
    assert load_string('<sdf version="1.9"><world name="w"/></sdf>', format="sdf").world.spherical_coordinates is None


def test_lone_light_is_a_world():
    world = load_string(
        '<sdf version="1.6"><light type="point" name="bulb"><pose>0 0 1 0 0 0</pose></light></sdf>',
        format="sdf",
        resolver=resolver(),
    ).value
    assert isinstance(world, World) and world.name == "default" and world.lights[0].name == "bulb"
    # the colours it leaves out are sdf/1.11/light.sdf's defaults, as sdformat's Light reads them
    assert (world.lights[0].diffuse, world.lights[0].specular) == ((1, 1, 1, 1), (0.1, 0.1, 0.1, 1))


# --------------------------------------------------------------------------- invalid files
INVALID = [
    (
        "malformed_xml.sdf",
        5,
        "XML_PARSE_ERROR",
        "malformed XML: Opening and ending tag mismatch: link line 4 and model, line 5, column 11",
    ),
    ("model_missing_name.sdf", 3, "ATTRIBUTE_MISSING", "<model> is missing the required 'name' attribute"),
    (
        "joint_unknown_type.sdf",
        6,
        "JOINT_TYPE_INVALID",
        "joint 'j' has unknown type 'QQQhinge' (expected one of ball, continuous, fixed, prismatic, revolute, revolute2, screw, universal)",
    ),
    ("joint_unknown_parent.sdf", 7, "JOINT_PARENT_INVALID", "joint 'j' has unknown parent 'QQQa'"),
    ("joint_unknown_child.sdf", 8, "JOINT_CHILD_INVALID", "joint 'j' has unknown child 'QQQb'"),
    ("duplicate_link.sdf", 5, "DUPLICATE_NAME", "link name 'a' is already used by a link in model 'm'"),
    ("bad_number.sdf", 6, "VALUE_INVALID", "<radius> must be a number, got 'QQQ'"),
    (
        "version_unsupported.sdf",
        2,
        "SDF_VERSION_UNSUPPORTED",
        "SDF version '1.12' is not supported (supported: 1.2 to 1.11)",
    ),
    ("version_missing.sdf", 2, "ATTRIBUTE_MISSING", "<sdf> has no 'version' attribute"),
    ("frame_cycle.sdf", 5, "FRAME_CYCLE", "cycle in pose relative_to: f1 -> f2 -> f1"),
    ("relative_to_unknown.sdf", 4, "FRAME_INVALID", "unknown frame 'QQQframe'"),
    ("joint_axis_zero.sdf", 10, "JOINT_AXIS_INVALID", "joint 'j': axis xyz has zero length"),
    ("root_invalid.sdf", 2, "ROOT_ELEMENT_INVALID", "root element must be <sdf>, got <robot>"),
    ("geometry_negative.sdf", 7, "GEOMETRY_INVALID", "<box> dimensions must be positive, got (1.0, -1.0, 1.0)"),
]


@pytest.mark.parametrize(("name", "line", "code", "message"), INVALID, ids=[c[0] for c in INVALID])
def test_invalid_sdf(name, line, code, message):
    err = load_error(name)
    assert [d.format() for d in err.diagnostics] == [f"{DATA / name}:{line}: error: [{code}] {message}"]
    assert err.first is not None and err.first.code.value == code


# --------------------------------------------------------------------------- robustness
def _mutate(text: str, rng: random.Random) -> str:
    ops = rng.randrange(6)
    i = rng.randrange(len(text))
    j = min(len(text), i + rng.randrange(1, 40))
    if ops == 0:
        return text[:i] + text[j:]
    if ops == 1:
        return (
            text[:i]
            + rng.choice(["<", ">", "</link>", "&", "'", '"', "::", "nan", "-1e999", "<model name='x'>"])
            + text[i:]
        )
    if ops == 2:
        lines = text.splitlines(keepends=True)
        k = rng.randrange(len(lines))
        lines.insert(rng.randrange(len(lines)), lines[k])
        return "".join(lines)
    if ops == 3:
        return text.replace(
            rng.choice(["link", "joint", "pose", "mass", "inertia", "box", "parent", "child"]),
            rng.choice(["frame", "QQQ", "model", "include", "link"]),
            1,
        )
    if ops == 4:
        return text[:i] + rng.choice(["0", "-3", "abc", "1 2", "1e308", "", "world", "__model__"]) + text[j:]
    return text[:i] + text[j:] + text[i:j]


FUZZ_SOURCES = [DATA / "chess_piece.sdf", DATA / "nested_model.sdf", DATA / "relative_to_degrees.sdf"]
if REAL.is_dir():
    FUZZ_SOURCES.append(TB3 / "models/turtlebot3_burger/model.sdf")


def test_fuzz_only_model_load_error_escapes():
    rng = random.Random(20240607)
    res = resolver(TB3 / "models")
    deadline = time.monotonic() + 6.0
    runs = 0
    for source in FUZZ_SOURCES:
        base = source.read_text()
        for _ in range(150):
            if time.monotonic() > deadline:
                break
            text = base
            for _ in range(rng.randrange(1, 4)):
                text = _mutate(text, rng)
            runs += 1
            try:
                load_string(text, format="sdf", source=str(source), resolver=res)
            except ModelLoadError:
                pass
    assert runs > 100


def test_collide_without_contact_false_is_read_silently_and_true_collides_with_nothing():
    """Issue 26: a house world of gz-sim's printed 54 `<collide_without_contact>` warnings for its default
    (false), one a model file. False is what gazelle does: silent. True (a contact-only shape in gz-sim)
    has no MuJoCo equivalent: the collision takes part in no contact, said once where it is."""

    def model(flag: str):
        text = f"""<sdf version="1.9"><model name="m"><link name="l"><collision name="c">
          <geometry><box><size>1 1 1</size></box></geometry>
          <surface><contact><collide_without_contact>{flag}</collide_without_contact></contact></surface>
        </collision></link></model></sdf>"""
        result = load_string(text, format="sdf", resolver=resolver())
        return result.model, [d for d in result.diagnostics if "collide_without_contact" in d.message]

    quiet, said = model("false")
    assert said == [] and quiet.link("l").collisions[0].surface.collide_bitmask is None
    ghost, said = model("true")
    assert len(said) == 1 and said[0].location is not None and said[0].location.line == 3
    assert ghost.link("l").collisions[0].surface.collide_bitmask == 0


def _placed(frame: str) -> str:
    return f"""<sdf version="1.8"><world name="w">
  <model name="m" placement_frame="{frame}"><pose>1 0 0 0 0 0</pose>
    <link name="base"><pose>0 0 0.5 0 0 0</pose><inertial><mass>1</mass></inertial></link>
    <frame name="f" attached_to="base"><pose>0 0 0.2 0 0 0</pose></frame>
  </model>
  <model name="outer"><pose>0 2 0 0 0 0</pose><link name="l"><inertial><mass>1</mass></inertial></link>
    <model name="inner" placement_frame="{frame}"><pose>0 0 1 0 0 0</pose>
      <link name="base"><pose>0 0 0.5 0 0 0</pose><inertial><mass>1</mass></inertial></link>
      <frame name="f" attached_to="base"><pose>0 0 0.2 0 0 0</pose></frame>
    </model></model></world></sdf>"""


def test_placement_frame_puts_the_named_frame_at_the_pose_and_a_frame_the_model_lacks_is_an_error() -> None:
    """sdformat's placement_frame: the model's <pose> is where that frame goes, for a model in a world and
    for a nested one (the world's, the nested and the top-level model's code share one reading of it)."""
    world = load_string(_placed("f"), source="w.sdf").value
    assert isinstance(world, World)
    m, outer = world.models
    assert close(m.pose.position, (1.0, 0.0, -0.7))  # f = base (0.5) + 0.2 lands at z = 0
    inner_base = next(lk for lk in outer.links if lk.name == "inner::base")
    assert inner_base.pose is not None and close(
        inner_base.pose.position, (0.0, 0.0, 0.8)
    )  # inner's f at z = 1 in outer's frame
    with pytest.raises(ModelLoadError) as info:
        load_string(_placed("nope"), source="w.sdf")
    text = str(info.value)
    assert "w.sdf:2: error: [FRAME_INVALID] placement_frame 'nope' is not a frame of model 'm'" in text
    assert "w.sdf:7: error: [FRAME_INVALID] placement_frame 'nope' is not a frame of model 'inner'" in text

    # a file whose root is the model: the same reading
    root = _placed("f").split("\n")
    model_only = '<sdf version="1.8">' + "\n".join(root[1:5]).replace("</model>", "") + "</model></sdf>"
    assert close(load_string(model_only, source="m.sdf").model.pose.position, (1.0, 0.0, -0.7))
    with pytest.raises(ModelLoadError, match=r"m.sdf:1: error: \[FRAME_INVALID\] placement_frame 'nope'"):
        load_string(model_only.replace('placement_frame="f"', 'placement_frame="nope"'), source="m.sdf")


MERGED_ROBOT = """<sdf version="1.8"><model name="diff_drive">
  <link name="chassis"><pose>-0.15 0 0.4 0 0 0</pose></link>
  <link name="left_wheel"><pose>0.55 0.6 0.4 -1.5707 0 0</pose></link>
  <link name="right_wheel"><pose>0.55 -0.6 0.4 -1.5707 0 0</pose></link>
  <frame name="lidar_frame" attached_to="chassis"><pose>0.8 0 0.5 0 0 0</pose></frame>
  <joint name="left_wheel_joint" type="revolute"><parent>chassis</parent><child>left_wheel</child>
    <axis><xyz expressed_in="__model__">0 1 0</xyz></axis></joint>
  <joint name="right_wheel_joint" type="revolute"><parent>chassis</parent><child>right_wheel</child>
    <axis><xyz expressed_in="__model__">0 1 0</xyz></axis></joint>
  <plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
    <left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>
  </plugin>
</model></sdf>"""


def test_a_merged_include_gives_the_parent_model_its_content_under_their_own_names(tmp_path):
    """ros_gz_project_template's world: `<model name="diff_drive"><include merge="true">` of a model whose DiffDrive
    names `left_wheel_joint`. gazelle scoped the merged content (`diff_drive::left_wheel_joint`), so the DiffDrive
    found no joints. SDF 1.9's merge-include (sdf/1.9/model.sdf, libsdformat's merge) puts the links, joints, frames
    and plugins in the parent under their own names, placed through a proxy frame at the include's pose; the
    parent's own elements may name them."""
    folder = tmp_path / "diff_drive"
    folder.mkdir()
    (folder / "model.config").write_text("<model><name>diff_drive</name><sdf>model.sdf</sdf></model>")
    (folder / "model.sdf").write_text(MERGED_ROBOT)
    world = """<sdf version="1.9"><world name="w">
      <model name="diff_drive"><pose>0 0 0.35 0 0 0</pose>
        <include merge="true"><uri>model://diff_drive</uri><pose>0.1 0 0 0 0 0</pose></include>
        <link name="mast"><pose relative_to="lidar_frame">0 0 0.1 0 0 0</pose></link>
        <joint name="mast_joint" type="fixed"><parent>chassis</parent><child>mast</child></joint>
        <plugin filename="gz-sim-joint-state-publisher-system" name="gz::sim::systems::JointStatePublisher"/>
      </model></world></sdf>"""
    result = load_string(world, format="sdf", resolver=resolver(tmp_path))
    assert [d for d in result.diagnostics if d.severity.value == "error"] == []
    model = result.world.models[0]
    assert sorted(j.name for j in model.joints) == ["left_wheel_joint", "mast_joint", "right_wheel_joint"]
    assert sorted(link.name for link in model.links) == ["chassis", "left_wheel", "mast", "right_wheel"]
    assert model.canonical_link == "chassis"
    chassis, mast = model.link("chassis").pose, model.link("mast").pose
    assert chassis is not None and mast is not None
    assert close(chassis.position, (-0.05, 0, 0.4))  # the include's pose carried in
    # lidar_frame is 0.8 0 0.5 from the chassis (its attached_to), so the mast stands at 0.75 0 1.0
    assert close(mast.position, (0.75, 0, 1.0))
    assert [p.name for p in model.plugins] == ["gz::sim::systems::JointStatePublisher", "gz::sim::systems::DiffDrive"]
    assert [f.name for f in model.frames] == ["lidar_frame"]


def test_a_merged_include_in_a_world_is_refused_as_sdformat_refuses_it(tmp_path):
    folder = tmp_path / "diff_drive"
    folder.mkdir()
    (folder / "model.config").write_text("<model><name>diff_drive</name><sdf>model.sdf</sdf></model>")
    (folder / "model.sdf").write_text(MERGED_ROBOT)
    world = (
        '<sdf version="1.9"><world name="w"><include merge="true"><uri>model://diff_drive</uri></include></world></sdf>'
    )
    with pytest.raises(ModelLoadError) as info:
        load_string(world, format="sdf", resolver=resolver(tmp_path))
    assert "merge-include does not support a parent element of type world" in str(info.value)


def test_a_classic_worlds_state_places_its_models_where_they_were_saved():
    """Husky's playpen (a world saved from Gazebo Classic) turns its barriers in `<state>`: yaw 2.36 there, 0 in the
    model. Classic's World::Load applies the first `<state>` (World::SetState); gazelle ignored it with a warning,
    and a barrier stood across the robot's spawn point. The save's time stamps are not warned about; a link moved
    apart from its model, and a model the world lacks, are named."""
    world = """<sdf version="1.6"><world name="playpen">
      <model name="barrier"><static>true</static><pose>1 0 0 0 0 0</pose><link name="link"/></model>
      <model name="robot_stand"><pose>0 1 0 0 0 0</pose><link name="base"><pose>0 0 0.5 0 0 0</pose></link></model>
      <state world_name="playpen"><sim_time>412 5000</sim_time><real_time>420 1</real_time><iterations>412005</iterations>
        <model name="barrier"><pose>-2 3 0 0 0 2.36</pose><scale>1 1 1</scale>
          <link name="link"><pose>-2 3 0 0 0 2.36</pose><velocity>0 0 0 0 0 0</velocity></link></model>
        <model name="robot_stand"><pose>0 1 0 0 0 0</pose><link name="base"><pose>0 1 0.9 0 0 0</pose></link></model>
        <model name="gone"><pose>5 5 0 0 0 0</pose></model>
      </state></world></sdf>"""
    result = load_string(world, format="sdf")
    barrier = result.world.models[0]
    assert close(barrier.pose.position, (-2, 3, 0))
    assert abs(2 * math.atan2(barrier.pose.orientation[3], barrier.pose.orientation[0]) - 2.36) < 1e-9
    messages = [d.message for d in result.diagnostics]
    assert len(messages) == 2, messages
    assert "<state> moves link 'robot_stand::base' apart from its model" in messages[0]
    assert "<state> names model 'gone', which the world does not have" in messages[1]
