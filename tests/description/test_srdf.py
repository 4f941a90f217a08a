"""SRDF loader: MoveIt's real SRDFs, the nested passive_joint quirk and invalid inputs."""

from __future__ import annotations

import pytest
from _paths import REAL, TEST_DATA

from gazelle.description import Chain, ModelLoadError, Semantics, load, load_string

DATA = TEST_DATA / "srdf"

needs_real = pytest.mark.skipif(not REAL.is_dir(), reason="shared real fixtures not available")

# file, groups, group_states, end_effectors, disable_collisions, warning codes
REAL_CASES = [
    ("moveit_panda/_xacro_expanded/panda_arm_hand.srdf", ["panda_arm", "hand", "panda_arm_hand"], 5, 1, 34, set()),
    ("moveit_panda/_xacro_expanded/panda_arm.srdf", ["panda_arm"], 3, 0, 19, set()),
    (
        "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf",
        ["panda_arm", "hand", "panda_arm_hand"],
        5,
        1,
        34,
        set(),
    ),
    # MoveIt's dual-arm SRDF names end-effector groups it never defines
    (
        "moveit_panda/dual_arm_panda_moveit_config/config/panda.srdf",
        ["left_panda_arm", "right_panda_arm"],
        2,
        2,
        68,
        {"SRDF_REFERENCE_INVALID"},
    ),
    ("ros2_control_r6bot/ros2_control_demo_description/r6bot/srdf/r6bot.srdf", None, 1, 0, 5, set()),
]


@needs_real
@pytest.mark.parametrize(
    ("rel", "groups", "states", "effectors", "disabled", "warnings"), REAL_CASES, ids=[c[0] for c in REAL_CASES]
)
def test_real_srdf(rel, groups, states, effectors, disabled, warnings):
    result = load(REAL / rel)
    sem = result.value
    assert isinstance(sem, Semantics)
    if groups is not None:
        assert [g.name for g in sem.groups] == groups
    assert (len(sem.group_states), len(sem.end_effectors), len(sem.disabled_collisions)) == (
        states,
        effectors,
        disabled,
    )
    assert {d.code.value for d in result.diagnostics} == warnings


@needs_real
def test_panda_details_and_nested_passive_joint():
    sem = load(REAL / "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf").semantics
    assert sem.robot_name == "panda"
    arm, hand, both = sem.groups
    assert arm.chains == (Chain("panda_link0", "panda_link8"),)
    assert hand.links == ("panda_hand", "panda_leftfinger", "panda_rightfinger") and hand.joints == (
        "panda_finger_joint1",
    )
    assert both.subgroups == ("panda_arm", "hand")
    assert sem.passive_joints == ("panda_finger_joint2",)  # nested in <group name="hand">: kept, no warning
    ready = sem.group_states[0]
    assert (ready.name, ready.group) == ("ready", "panda_arm") and ready.joint_values[1] == ("panda_joint2", (-0.785,))
    [vj] = sem.virtual_joints
    assert (vj.type, vj.parent_frame, vj.child_link) == ("floating", "world", "panda_link0")
    [ee] = sem.end_effectors
    assert (ee.name, ee.parent_link, ee.group) == ("hand", "panda_link8", "hand")
    assert sem.disabled_collisions[0].reason in ("Adjacent", "Never", "Default")


def test_references_unknown_elements_and_multi_dof_values():
    result = load(DATA / "references_and_unknown.srdf")
    assert [d.format() for d in result.diagnostics] == [
        f"{DATA / 'references_and_unknown.srdf'}:14: warning: [ELEMENT_UNSUPPORTED] <QQQfancy> in <robot> is not supported and is ignored",
        f"{DATA / 'references_and_unknown.srdf'}:5: warning: [SRDF_REFERENCE_INVALID] subgroup 'QQQhand' is not a defined group",
        f"{DATA / 'references_and_unknown.srdf'}:8: warning: [SRDF_REFERENCE_INVALID] group_state 'home' refers to unknown group 'QQQleg'",
        f"{DATA / 'references_and_unknown.srdf'}:11: warning: [SRDF_REFERENCE_INVALID] end_effector 'ee' group 'QQQgripper' is not a defined group",
    ]
    assert result.semantics.passive_joints == ("finger_mimic", "caster")
    text = '<robot name="r"><group name="g"><joint name="base"/></group><group_state name="s" group="g"><joint name="base" value="1 2 0.5"/></group_state></robot>'
    assert load_string(text, format="srdf").semantics.group_states[0].joint_values == (("base", (1.0, 2.0, 0.5)),)


INVALID = [
    (
        "group_state_bad_value.srdf",
        7,
        "VALUE_INVALID",
        "group_state 'home': joint 'j1' value must be numbers, got 'QQQ'",
    ),
    (
        "virtual_joint_bad_type.srdf",
        3,
        "JOINT_TYPE_INVALID",
        "virtual_joint 'vj' has unknown type 'QQQwelded' (expected fixed, floating or planar)",
    ),
    ("duplicate_group.srdf", 6, "DUPLICATE_NAME", "group 'arm' is defined twice"),
    (
        "disable_collisions_missing_link2.srdf",
        3,
        "ATTRIBUTE_MISSING",
        "<disable_collisions> is missing the required 'link2' attribute",
    ),
    ("root_invalid.srdf", 2, "ROOT_ELEMENT_INVALID", "SRDF root element must be <robot>, got <QQQrobot>"),
    (
        "malformed_xml.srdf",
        5,
        "XML_PARSE_ERROR",
        "malformed XML: Opening and ending tag mismatch: joint line 4 and group, line 5, column 11",
    ),
]


@pytest.mark.parametrize(("name", "line", "code", "message"), INVALID, ids=[c[0] for c in INVALID])
def test_invalid_srdf(name, line, code, message):
    with pytest.raises(ModelLoadError) as info:
        load(DATA / name)
    assert [d.format() for d in info.value.diagnostics] == [f"{DATA / name}:{line}: error: [{code}] {message}"]
