"""URDF loader: features, structural errors with file:line, inertia derivation, robustness."""

from __future__ import annotations

import math
import random
import re

import pytest
from _paths import REAL, TEST_DATA
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from gazelle.description import (
    Box,
    Capsule,
    JointType,
    LoadResult,
    Mesh,
    Model,
    ModelLoadError,
    ResourceResolver,
    load,
    load_string,
)
from gazelle.description._inertia import inertia_from_geometry, inertia_problem

DATA = TEST_DATA / "urdf"

SEED_URDF = DATA / "mybot2.urdf"


def formatted(diagnostics: object) -> str:
    """All diagnostics, one formatted line each."""
    return "\n".join(d.format() for d in diagnostics)  # type: ignore[attr-defined]


def load_error(name: str) -> str:
    """Load a data file that must fail; return its formatted diagnostics."""
    with pytest.raises(ModelLoadError) as info:
        load(DATA / name)
    return formatted(info.value.diagnostics)


def codes(result: LoadResult) -> list[str]:
    return [d.code.value for d in result.diagnostics]


# --------------------------------------------------------------------------- seed examples
def test_seed_single_link_loads_without_diagnostics() -> None:
    result = load(DATA / "mybot.urdf")
    model = result.value
    assert isinstance(model, Model)
    assert [lk.name for lk in model.links] == ["base_link"]
    assert model.links[0].inertial is None  # visual only: a pure frame, no warning
    assert result.diagnostics == ()


def test_seed_two_links_revolute_gets_placeholder_inertia() -> None:
    result = load(SEED_URDF)
    model = result.value
    assert isinstance(model, Model)
    joint = model.joint("joint_0")
    assert joint.type is JointType.REVOLUTE
    assert joint.axis is not None and joint.axis.xyz == (0.0, 0.0, 1.0)
    assert (joint.axis.limit.lower, joint.axis.limit.upper, joint.axis.limit.effort) == (0.0, 0.5, 100.0)
    assert joint.origin.position == (0.0, 0.0, 0.3)
    inertial = model.link("link_1").inertial
    assert inertial is not None and inertial.derived and inertial.mass == pytest.approx(1e-3)
    assert model.link("link_0").inertial is None
    assert (
        "mybot2.urdf:11: warning: [INERTIA_MISSING] link 'link_1': has no <inertial> but moves with joint 'joint_0'"
        in formatted(result.diagnostics)
    )


# --------------------------------------------------------------------------- features
@pytest.fixture(scope="module")
def features() -> LoadResult:
    return load(DATA / "features.urdf")


def test_every_joint_type_and_joint_details(features: LoadResult) -> None:
    model = features.value
    assert isinstance(model, Model)
    types = {j.name: j.type for j in model.joints}
    assert types["rev"] is JointType.REVOLUTE and types["planar"] is JointType.PLANAR
    assert {t.value for t in types.values()} == {"revolute", "continuous", "prismatic", "fixed", "floating", "planar"}
    rev = model.joint("rev")
    assert rev.axis is not None and rev.axis.xyz == (0.0, 0.0, 1.0)  # normalised
    assert rev.axis.dynamics.damping == 0.1 and rev.axis.dynamics.friction == 0.2
    assert rev.safety_controller is not None and rev.safety_controller.k_position == 100
    assert rev.calibration is not None and rev.calibration.rising == 0.5 and rev.calibration.falling is None
    cont = model.joint("cont")
    assert cont.axis is not None and cont.axis.xyz == (1.0, 0.0, 0.0)  # default axis
    assert cont.axis.limit.lower is None and cont.axis.limit.effort == 5
    assert cont.mimic is not None and (cont.mimic.joint, cont.mimic.multiplier, cont.mimic.offset) == ("rev", -2, 0.1)
    assert model.joint("fixed").axis is None and model.joint("float").axis is None
    assert len(model.links) == 8  # fixed joints are not lumped


def test_visuals_collisions_and_materials(features: LoadResult) -> None:
    model = features.value
    assert isinstance(model, Model)
    base = model.link("base")
    assert [v.name for v in base.visuals] == ["body", "base_visual_1", "base_visual_2"]
    assert [c.name for c in base.collisions] == ["c0", "c1"]
    assert base.visuals[0].geometry == Box((0.4, 0.2, 0.1))
    assert base.visuals[0].pose.rpy[2] == pytest.approx(math.pi / 2)
    # (base's own colours are overridden by its <gazebo> material; see the gazebo test)
    mesh = base.visuals[2].geometry
    assert isinstance(mesh, Mesh) and mesh.scale == (2, 2, 2) and mesh.path == str(DATA / "meshes" / "cube.stl")
    assert base.visuals[2].material is not None and base.visuals[2].material.texture == "textures/wood.png"
    # a material defined inline in one visual is usable by name in another link
    rev_material = model.link("l_rev").visuals[0].material
    assert rev_material is not None and rev_material.diffuse == (0, 1, 0, 1)
    assert base.location is not None and base.location.line == 5 and base.visuals[0].location.line == 6  # type: ignore[union-attr]


def test_gazebo_extension_applied_to_link(features: LoadResult) -> None:
    model = features.value
    assert isinstance(model, Model)
    base = model.link("base")
    surface = base.collisions[1].surface
    assert (surface.mu, surface.mu2, surface.kp, surface.kd) == (0.8, 0.7, 1e6, 100)
    assert (surface.max_vel, surface.min_depth, surface.fdir1) == (0.5, 0.001, (1.0, 0.0, 0.0))
    assert base.self_collide is True and base.gravity is False and base.kinematic is False
    assert base.visuals[0].material is not None and base.visuals[0].material.name == "Gazebo/Orange"
    (sensor,) = base.sensors
    assert (sensor.name, sensor.type, sensor.update_rate_hz, sensor.always_on, sensor.topic) == (
        "cam",
        "camera",
        30,
        True,
        "image",
    )
    assert sensor.pose.position == (0.1, 0.0, 0.2)
    assert sensor.config is not None and sensor.config.find("camera") is not None
    assert [p.filename for p in sensor.plugins] == ["libgazebo_ros_camera.so"]
    assert [p.name for p in model.plugins] == ["jsp"]
    assert model.plugins[0].config.find("joint_name").text == "rev"  # type: ignore[union-attr]
    assert len(model.gazebo) == 3 and model.gazebo[0].reference == "base"
    assert "features.urdf:81: warning: [ELEMENT_UNSUPPORTED] <provideFeedback>" in formatted(features.diagnostics)


def test_mesh_inertia_is_derived_from_an_stl(features: LoadResult) -> None:
    # in a robot with some mass, a massless link fixed to another merges into it (sdformat's reduction)
    assert features.model.link("l_mesh").inertial is None
    # in a robot with no mass at all (Gazebo would model none of it), inertia comes from the collisions
    urdf = (DATA / "features.urdf").read_text()
    alone = '<robot name="m"><link name="l_mesh"><collision><geometry><mesh filename="file://meshes/cube.stl"/></geometry></collision></link></robot>'
    model = load_string(alone, source=str(DATA / "alone.urdf")).value
    assert "l_mesh" in urdf
    assert isinstance(model, Model)
    inertial = model.link("l_mesh").inertial
    assert inertial is not None and inertial.derived
    assert inertial.mass == pytest.approx(1.0)  # 0.1 m cube at 1000 kg/m^3
    assert inertial.pose.position == pytest.approx((0.0, 0.0, 0.05))
    assert inertial.ixx == pytest.approx(1.0 * 0.02 / 12) and inertial.ixy == pytest.approx(0.0, abs=1e-12)


def test_features_warning_codes(features: LoadResult) -> None:
    # its massless links are all fixed to massive ones: merged, as sdformat reduces fixed joints, no warning
    assert sorted(set(codes(features))) == ["ELEMENT_UNSUPPORTED"]


def test_massless_links_follow_sdformat(make_sim) -> None:
    """Merged through fixed joints, else left out with their joint and what hangs below, with a warning."""
    inertial = '<inertial><mass value="2"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>'
    urdf = (
        '<robot name="r"><link name="base_footprint"/>'  # massless root: carried by base_link fixed to it
        f'<link name="base_link">{inertial}<collision><geometry><box size="1 1 1"/></geometry></collision></link>'
        '<link name="arm"><collision><geometry><box size="1 1 1"/></geometry></collision></link>'  # massless, moves
        f'<link name="hand">{inertial}</link>'  # below the massless arm: left out with it
        '<link name="laser_frame"/>'  # massless sensor frame, fixed: merged
        '<joint name="fp" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>'
        '<joint name="shoulder" type="revolute"><parent link="base_link"/><child link="arm"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<joint name="wrist" type="continuous"><parent link="arm"/><child link="hand"/></joint>'
        '<joint name="laser" type="fixed"><parent link="base_link"/><child link="laser_frame"/></joint></robot>'
    )
    result = load_string(urdf)
    model = result.model
    assert sorted(lk.name for lk in model.links) == ["base_footprint", "base_link", "laser_frame"]
    assert sorted(j.name for j in model.joints) == ["fp", "laser"]
    inertial = model.link("base_link").inertial
    assert inertial is not None and inertial.mass == 2.0  # never made up from the collision volume
    [warning] = [d for d in result.diagnostics if d.code.value == "INERTIA_MISSING"]
    assert "link 'arm'" in warning.message and "'shoulder'" in warning.message and "hand" in warning.message
    # and it simulates: the merged root carries the mass
    from gazelle.description import Pose

    sim = make_sim()
    sim.spawn(model, name="r", pose=Pose((0.0, 0.0, 1.0)))
    sim.step(2000)
    assert sim.world.entity_state("r").pose.position[2] == pytest.approx(0.5, abs=0.01)


# --------------------------------------------------------------------------- structural errors
@pytest.mark.parametrize(
    ("name", "expected"),
    [
        (
            "joint_missing_parent.urdf",
            "joint_missing_parent.urdf:5: error: [JOINT_PARENT_INVALID] joint 'shoulder' has unknown parent link 'base_QQQ'",
        ),
        (
            "joint_missing_child.urdf",
            "joint_missing_child.urdf:4: error: [JOINT_CHILD_INVALID] joint 'shoulder' has unknown child link 'arm_QQQ'",
        ),
        ("malformed.urdf", "malformed.urdf:5: error: [XML_PARSE_ERROR] malformed XML: Opening and ending tag mismatch"),
        (
            "duplicate_link.urdf",
            "duplicate_link.urdf:5: error: [DUPLICATE_NAME] link 'arm' is defined more than once (first at ",
        ),
        ("duplicate_joint.urdf", "duplicate_joint.urdf:7: error: [DUPLICATE_NAME] joint 'j' is defined more than once"),
        (
            "unknown_joint_type.urdf",
            "unknown_joint_type.urdf:5: error: [JOINT_TYPE_INVALID] joint 'hinge' has unknown type 'QQQ'",
        ),
        ("bad_number.urdf", 'bad_number.urdf:8: error: [VALUE_INVALID] <origin xyz="0 a 0">: not a number'),
        (
            "wrong_vector_length.urdf",
            'wrong_vector_length.urdf:8: error: [VALUE_INVALID] <origin xyz="0 0">: expected 3 numbers, got 2',
        ),
        ("zero_axis.urdf", "zero_axis.urdf:8: error: [JOINT_AXIS_INVALID] joint 'wheel' has a zero axis"),
        ("loop.urdf", "loop.urdf:8: error: [KINEMATIC_LOOP] kinematic loop: 'a' -> 'b' -> 'base' -> 'a'"),
        (
            "two_roots.urdf",
            "two_roots.urdf:5: error: [MULTIPLE_ROOTS] robot 'r' has 2 root links ('base_link', 'floating_QQQ')",
        ),
        ("two_parents.urdf", "two_parents.urdf:7: error: [JOINT_CHILD_INVALID] link 'c' has two parents: joint 'a_c'"),
        ("missing_name.urdf", "missing_name.urdf:4: error: [ATTRIBUTE_MISSING] <link> has no 'name' attribute"),
        (
            "negative_radius.urdf",
            "negative_radius.urdf:6: error: [GEOMETRY_INVALID] <cylinder> of collision 'a_collision_0' of link 'a' radius must be > 0, got -0.1",
        ),
        (
            "zero_box.urdf",
            "zero_box.urdf:6: error: [GEOMETRY_INVALID] <box> of visual 'a_visual_0' of link 'a' size must be > 0",
        ),
        (
            "bad_root.urdf",
            "bad_root.urdf:2: error: [ROOT_ELEMENT_INVALID] root element is <sdf>; a URDF must have <robot>",
        ),
    ],
)
def test_invalid_file_reports_code_message_and_line(name: str, expected: str) -> None:
    text = load_error(name)
    assert expected in text
    assert text.count("error:") == 1, text  # one failure mode, one error


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        (
            "bad_mass.urdf",
            "bad_mass.urdf:8: warning: [MASS_INVALID] link 'a': mass must be > 0, got '-1'; inertia derived from 1 collision shape(s), mass 6 kg from volume 0.006 m^3 at 1000 kg/m^3",
        ),
        (
            "bad_inertia.urdf",
            "bad_inertia.urdf:9: warning: [INERTIA_INVALID] link 'a': principal moments 1, 1, 5 violate the triangle inequality",
        ),
        (
            "no_inertial.urdf",
            "no_inertial.urdf:4: warning: [INERTIA_MISSING] link 'body': has collision geometry but no <inertial>",
        ),
        (
            "gazebo_bad_reference.urdf",
            'gazebo_bad_reference.urdf:4: warning: [GAZEBO_REFERENCE_INVALID] <gazebo reference="a_QQQ"> names no link or joint',
        ),
        (
            "gazebo_bad_reference.urdf",
            'gazebo_bad_reference.urdf:8: warning: [ELEMENT_UNSUPPORTED] <laserRetro> in <gazebo reference="a">',
        ),
        (
            "undefined_material.urdf",
            "undefined_material.urdf:6: warning: [MATERIAL_UNDEFINED] material 'blue_QQQ' is not defined",
        ),
        (
            "missing_mesh.urdf",
            "missing_mesh.urdf:5: warning: [URI_UNRESOLVED] cannot resolve mesh URI 'package://no_such_package_QQQ/meshes/a.stl'",
        ),
        ("missing_mesh.urdf", "missing_mesh.urdf:8: warning: [MESH_NOT_FOUND] mesh file "),
        (
            "unsupported.urdf",
            "unsupported.urdf:4: warning: [ELEMENT_UNSUPPORTED] <velocity_decay> in link 'a' is not supported",
        ),
        (
            "unsupported.urdf",
            "unsupported.urdf:11: warning: [ELEMENT_UNSUPPORTED] transmission 't1' is kept but not simulated",
        ),
        ("unsupported.urdf", "unsupported.urdf:14: warning: [ELEMENT_MISSING] ros2_control 'sys' has no <hardware>"),
        (
            "unsupported.urdf",
            "unsupported.urdf:15: warning: [ELEMENT_UNSUPPORTED] <sensor> in <robot> is not supported",
        ),
    ],
)
def test_warning_reports_code_message_and_line(name: str, expected: str) -> None:
    result = load(DATA / name)
    assert expected in formatted(result.diagnostics)


def test_strict_mode_turns_warnings_into_errors() -> None:
    with pytest.raises(ModelLoadError, match=r"MATERIAL_UNDEFINED"):
        load(DATA / "undefined_material.urdf", strict=True)


def test_strict_mode_still_reports_structure_errors() -> None:
    """Promoted warnings do not hide the structure errors behind them."""
    relaxed = load_error("strict_structure.urdf")
    with pytest.raises(ModelLoadError) as info:
        load(DATA / "strict_structure.urdf", strict=True)
    strict = formatted(info.value.diagnostics)
    expected = [
        'strict_structure.urdf:3: error: [ATTRIBUTE_UNSUPPORTED] attribute foo="1" of <link>',
        "strict_structure.urdf:4: error: [MATERIAL_UNDEFINED] material 'blue_QQQ' is not defined",
        "strict_structure.urdf:7: error: [JOINT_PARENT_INVALID] joint 'j' has unknown parent link 'a_QQQ'",
    ]
    for line in expected:
        assert line in strict, strict
    assert [d.code for d in info.value.diagnostics] == [d.code for d in load_error_diagnostics("strict_structure.urdf")]
    assert "JOINT_PARENT_INVALID" in relaxed


def test_strict_mode_reports_inertia_warnings_after_the_structure_checks() -> None:
    with pytest.raises(ModelLoadError) as info:
        load(DATA / "unsupported_attributes.urdf", strict=True)
    assert sorted({d.code.value for d in info.value.diagnostics}) == ["ATTRIBUTE_UNSUPPORTED", "INERTIA_MISSING"]
    assert all(d.severity.value == "error" for d in info.value.diagnostics)


def load_error_diagnostics(name: str) -> tuple:
    with pytest.raises(ModelLoadError) as info:
        load(DATA / name)
    return info.value.diagnostics


def test_unsupported_attributes_warn_with_line() -> None:
    result = load(DATA / "unsupported_attributes.urdf")
    text = formatted(result.diagnostics)
    assert codes(result) == ["ATTRIBUTE_UNSUPPORTED"] * 3 + ["INERTIA_MISSING"], text
    assert (
        'unsupported_attributes.urdf:4: warning: [ATTRIBUTE_UNSUPPORTED] attribute foo="1" of <link> '
        "is not supported and is ignored" in text
    )
    assert 'unsupported_attributes.urdf:5: warning: [ATTRIBUTE_UNSUPPORTED] attribute colour="red" of <box>' in text
    assert (
        'unsupported_attributes.urdf:9: warning: [ATTRIBUTE_UNSUPPORTED] attribute degrees="true" of <origin>' in text
    )
    # robot version, xmlns declarations, xsi:schemaLocation and plugin attributes (raw config) do not warn
    assert "version" not in text and "xsi" not in text and "any_attribute_here" not in text


def test_repeated_unsupported_attribute_warns_once() -> None:
    joints = "".join(
        f'<link name="l{i}"/><joint name="j{i}" type="fixed"><parent link="l{i - 1}"/><child link="l{i}"/>'
        f'<dynamics damping="1" D="1"/></joint>'
        for i in range(1, 4)
    )
    result = load_string(f'<robot name="r"><link name="l0"/>{joints}</robot>')
    (warning,) = result.diagnostics
    assert warning.message == 'attribute D="1" of <dynamics> is not supported and is ignored (and on 2 more <dynamics>)'
    assert warning.location is not None and warning.location.line == 1


def test_joints_without_links_is_an_error() -> None:
    diagnostics = load_error_diagnostics("joints_without_links.urdf")
    text = formatted(diagnostics)
    assert "joints_without_links.urdf:3: error: [LINK_MISSING] robot 'r' has 1 joint(s) but no links" in text
    assert "FRAGMENT" not in text


def test_empty_nameless_robot_is_a_fragment() -> None:
    result = load_string("<robot>\n  <material name='m'><color rgba='1 0 0 1'/></material>\n</robot>")
    model = result.value
    assert isinstance(model, Model) and model.links == () and model.name == ""
    assert formatted(result.diagnostics) == (
        "<string>.urdf:1: warning: [FRAGMENT] <robot> defines no links (an include fragment?): "
        "it holds 1 material(s); it cannot be simulated on its own"
    )


def test_nameless_robot_with_links_is_still_an_error() -> None:
    with pytest.raises(ModelLoadError, match=r"<string>.urdf:1: error: \[ATTRIBUTE_MISSING\] <robot> has no 'name'"):
        load_string('<robot><link name="a"/></robot>')


def test_derived_inertia_keeps_given_mass_and_missing_mesh_path_is_none() -> None:
    model = load(DATA / "bad_inertia.urdf").value
    assert isinstance(model, Model)
    inertial = model.link("a").inertial
    assert inertial is not None and inertial.derived and inertial.mass == 2.0
    assert inertial.ixx == pytest.approx(0.4 * 2.0 * 0.01)
    mesh_model = load(DATA / "missing_mesh.urdf").value
    assert isinstance(mesh_model, Model)
    assert [v.geometry.path for v in mesh_model.link("a").visuals] == [None, None]  # type: ignore[union-attr]


def test_transmissions_are_kept() -> None:
    model = load(DATA / "unsupported.urdf").value
    assert isinstance(model, Model)
    assert [t.attr("name") for t in model.transmissions] == ["t1"]


def test_root_link_with_inertia_is_accepted() -> None:
    text = (
        '<robot name="r"><link name="a"><inertial><mass value="1"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link></robot>'
    )
    result = load_string(text, format="urdf")
    assert result.diagnostics == ()
    assert result.value.links[0].inertial is not None  # type: ignore[union-attr]


def test_string_source_uses_synthetic_name() -> None:
    with pytest.raises(ModelLoadError) as info:
        load_string('<robot name="r"><link name="a"/>\n<link name="a"/></robot>', format="urdf")
    assert "<string>.urdf:2: error: [DUPLICATE_NAME]" in formatted(info.value.diagnostics)


# --------------------------------------------------------------------------- inertia helpers
def test_inertia_validation() -> None:
    assert inertia_problem(1, 0, 0, 1, 0, 1) is None
    assert inertia_problem(0, 0, 0, 0, 0, 0) == "inertia is zero"
    assert "positive-definite" in (inertia_problem(1, 0, 0, -1, 0, 1) or "")
    assert "triangle" in (inertia_problem(1, 0, 0, 1, 0, 3) or "")


def test_capsule_inertia_mass_from_volume() -> None:
    inertial = inertia_from_geometry(Capsule(0.1, 0.2), None)
    assert inertial is not None
    volume = math.pi * 0.01 * 0.2 + 4 / 3 * math.pi * 0.001
    assert inertial.mass == pytest.approx(volume * 1000)


# --------------------------------------------------------------------------- real robots
def test_panda_urdf_derives_mesh_inertia(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REAL / "moveit_panda"))
    result = load(REAL / "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf")
    model = result.value
    assert isinstance(model, Model)
    assert (len(model.links), len(model.joints)) == (12, 11)
    assert set(codes(result)) == {"INERTIA_MISSING"} and len(result.diagnostics) == 11
    meshes = [g.geometry for lk in model.links for g in (*lk.visuals, *lk.collisions)]
    assert len(meshes) == 22 and all(isinstance(m, Mesh) and m.path for m in meshes)
    link1 = model.link("panda_link1").inertial
    assert link1 is not None and link1.derived and 1.0 < link1.mass < 5.0


# --------------------------------------------------------------------------- robustness
_JUNK = ["", "-1", "nan", "0 0 0", "a b c", "1e999", "${x}", "$(find q)", "&amp;", "world", "base_link", "0 0 0 0"]


def _mutate(text: str, rng: random.Random) -> str:
    """Delete, duplicate or alter a span of characters, or replace an attribute value."""
    kind = rng.choice((0, 1, 2, 3, 3, 3))
    i = rng.randrange(len(text))
    j = min(len(text), i + rng.randint(1, 40))
    if kind == 0:
        return text[:i] + text[j:]
    if kind == 1:
        return text[:j] + text[i:j] + text[j:]
    if kind == 2:
        return text[:i] + rng.choice('<>/"=${}()0a- \n') + text[i + 1 :]
    values = list(re.finditer(r'"([^"]*)"', text))
    m = rng.choice(values)
    return text[: m.start(1)] + rng.choice(_JUNK) + text[m.end(1) :]


def _fuzz(text: str, fmt: str, seed: int, rounds: int) -> None:
    rng = random.Random(seed)
    for _ in range(rounds):
        mutated = text
        for _ in range(rng.randint(1, 3)):
            mutated = _mutate(mutated, rng)
        try:
            result = load_string(mutated, format=fmt, resolver=ResourceResolver(env={}))
        except ModelLoadError as err:
            assert err.diagnostics
            continue
        assert isinstance(result.value, Model)


def test_fuzzed_urdf_only_raises_model_load_error() -> None:
    _fuzz((DATA / "features.urdf").read_text(), "urdf", seed=1, rounds=400)
    _fuzz(
        (REAL / "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro").read_text(),
        "urdf",
        seed=2,
        rounds=300,
    )


# --------------------------------------------------------------------------- property-based fuzzing
_VALUES = st.one_of(
    st.sampled_from(_JUNK + ["inf", "-0", "1e-320", "1 2 3", "package://nope/a.stl", "model://x/y.dae", "__model__"]),
    st.text(alphabet=st.characters(blacklist_categories=("Cs", "Cc")), max_size=12),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
)
_TAGS = st.sampled_from(
    [
        "link",
        "joint",
        "origin",
        "inertial",
        "inertia",
        "mass",
        "geometry",
        "box",
        "mesh",
        "pose",
        "frame",
        "model",
        "include",
        "collision",
        "visual",
        "plugin",
        "gazebo",
        "axis",
        "limit",
        "QQQ",
        "xacro:macro",
    ]
)
_OPS = st.lists(
    st.tuples(
        st.sampled_from(["set_attr", "del_attr", "set_text", "drop", "duplicate", "add_child", "rename", "move"]),
        st.integers(min_value=0, max_value=10_000),
        st.integers(min_value=0, max_value=10_000),
        _VALUES,
        _TAGS,
    ),
    min_size=1,
    max_size=4,
)


def _apply_ops(text: str, ops: list) -> str:
    """Structured mutations of an XML document (elements, attributes, values), serialized back."""
    from lxml import etree

    root = etree.fromstring(text.encode())
    for op, i, j, value, tag in ops:
        elements = [e for e in root.iter() if isinstance(e.tag, str)]
        el = elements[i % len(elements)]
        other = elements[j % len(elements)]
        names = sorted(el.attrib) or ["name"]
        if op == "set_attr":
            el.set(names[j % len(names)] if j % 3 else tag.replace(":", "_"), value)
        elif op == "del_attr" and el.attrib:
            del el.attrib[names[j % len(names)]]
        elif op == "set_text":
            el.text = value
        elif op == "drop" and el is not root:
            el.getparent().remove(el)
        elif op == "duplicate" and el is not root:
            from copy import deepcopy

            el.addnext(deepcopy(el))
        elif op == "add_child":
            etree.SubElement(el, tag.replace(":", "_"), {"name": value} if j % 2 else {}).text = value
        elif op == "rename" and el is not root:
            el.tag = tag.replace(":", "_")
        elif op == "move" and el is not root and other is not el and el not in other.iterancestors():
            other.append(el)
    return etree.tostring(root, encoding="unicode")


_FUZZ_SEEDS = {
    "urdf": (DATA / "features.urdf").read_text(),
    "urdf-seed": SEED_URDF.read_text(),
    "sdf": (TEST_DATA / "sdf" / "chess_piece.sdf").read_text(),
}


@pytest.mark.parametrize("seed", sorted(_FUZZ_SEEDS))
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow], database=None)
@given(ops=_OPS)
def test_hypothesis_mutations_only_raise_model_load_error(seed: str, ops: list) -> None:
    """Structured mutations of the seed robot(s) and the chess piece: the loaders either load or
    raise their own error; nothing else escapes."""
    text = _apply_ops(re.sub(r"<\?xml[^>]*\?>", "", _FUZZ_SEEDS[seed]), ops)
    fmt = seed.split("-")[0]
    try:
        result = load_string(text, format=fmt, resolver=ResourceResolver(env={}))
    except ModelLoadError as err:
        assert err.diagnostics
        event(f"error {err.first.code.value if err.first else None}")
        return
    event("loaded")
    assert isinstance(result, LoadResult)
    try:  # strict mode walks the same paths further (structure checks after promoted warnings)
        load_string(text, format=fmt, strict=True, resolver=ResourceResolver(env={}))
    except ModelLoadError as err:
        assert err.diagnostics


def test_a_load_result_gives_its_value_typed_or_says_what_it_holds() -> None:
    """Issue 32 (types fixed at the root): ``LoadResult.value`` is a union, and code that knows what it
    loaded passed it on untyped (pyright: 160 such arguments in the tests); ``.model``, ``.world`` and
    ``.semantics`` give it typed, and the wrong one says what the description is."""
    from gazelle.description import Model, World, load_string

    robot = load_string('<robot name="r"><link name="base"/></robot>', format="urdf")
    assert isinstance(robot.model, Model) and robot.model.name == "r"
    with pytest.raises(TypeError, match="expected an SDF world, but the description is a Model"):
        _ = robot.world
    world = load_string('<sdf version="1.9"><world name="w"/></sdf>', format="sdf")
    assert isinstance(world.world, World) and world.world.name == "w"
    with pytest.raises(TypeError, match="expected an SRDF, but the description is a World"):
        _ = world.semantics


def test_a_geometry_with_two_shapes_uses_the_first_as_urdfdom_and_names_the_second() -> None:
    """urdfdom's parseGeometry (link.cpp) reads the first child element of <geometry> and passes over the rest:
    robot_state_publisher and Gazebo load such a file, so gazelle does too, and says what it left out."""
    urdf = """<robot name="r"><link name="a">
  <visual><geometry><box size="1 2 3"/><sphere radius="1"/></geometry></visual>
  <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
</link></robot>"""
    result = load_string(urdf)
    assert result.model is not None and result.model.links[0].visuals[0].geometry == Box((1.0, 2.0, 3.0))
    assert [d.format() for d in result.diagnostics] == [
        "<string>.urdf:2: warning: [GEOMETRY_INVALID] <geometry> of visual 'a_visual_0' of link 'a' holds a second "
        "shape <sphere>; only the first, <box>, is used (as urdfdom reads it)"
    ]
