"""`gazelle arm`'s reading of the SRDF: group joints, tips, named states and --joints, and the refusals
(each names what there is), on the Panda's and the dual-arm Panda's files. No ROS needed."""

from __future__ import annotations

import math

import pytest
from _paths import REAL

from gazelle.estimation import quaternion_from_rpy
from gazelle.ros._arm_cli import ArmError, group_joints, joint_values, named_state, semantics, tip_link

PANDA = REAL / "moveit_panda" / "moveit_resources_panda_moveit_config" / "config"
DUAL = REAL / "moveit_panda" / "dual_arm_panda_moveit_config" / "config"
ARM = [f"panda_joint{i}" for i in range(1, 8)]


@pytest.fixture(scope="module")
def panda():
    import os

    from gazelle.description import read_description_file as _read_description

    os.environ["GAZELLE_RESOURCE_PATH"] = str(REAL / "moveit_panda")
    try:
        urdf = _read_description(str(PANDA / "panda.urdf.xacro"))
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH")
    return semantics((PANDA / "panda.srdf").read_text()), urdf


def test_chains_and_subgroups_give_the_joints_in_order_and_the_tip(panda):
    sem, urdf = panda
    assert group_joints(sem, urdf, "panda_arm") == ARM
    assert group_joints(sem, urdf, "panda_arm_hand")[:7] == ARM  # a group of groups
    assert tip_link(sem, "panda_arm") == "panda_link8"


def test_named_states_and_joint_values(panda):
    sem, urdf = panda
    assert named_state(sem, "panda_arm", "extended")["panda_joint4"] == 0.0
    values = [0.1, 0.2, 0.3, -1.0, 0.5, 1.0, 0.7]
    assert joint_values(sem, urdf, "panda_arm", [str(v) for v in values]) == dict(zip(ARM, values))
    assert joint_values(sem, urdf, "panda_arm", ["panda_joint1=0.5"]) == {"panda_joint1": 0.5}


@pytest.mark.parametrize(
    ("call", "says"),
    [
        (lambda sem, urdf: named_state(sem, "panda_arm", "r2home"), ["no named state 'r2home'", "ready", "extended"]),
        (lambda sem, urdf: named_state(sem, "left_arm", "ready"), ["no planning group 'left_arm'", "panda_arm"]),
        (lambda sem, urdf: joint_values(sem, urdf, "panda_arm", ["0.1", "0.2"]), ["has 7 joints", "gave 2"]),
        (lambda sem, urdf: joint_values(sem, urdf, "panda_arm", ["up"]), ["--joints takes numbers"]),
    ],
)
def test_bad_requests_are_refused_naming_what_there_is(panda, call, says):
    sem, urdf = panda
    with pytest.raises(ArmError) as err:
        call(sem, urdf)
    assert all(text in str(err.value) for text in says), str(err.value)


def test_a_broken_srdf_is_one_clear_error():
    with pytest.raises(ArmError) as err:
        semantics("<robot name='x'><group name='a'>")
    assert "SRDF could not be read" in str(err.value)


def test_the_dual_arm_srdf_s_groups(panda):
    sem = semantics((DUAL / "panda.srdf").read_text())
    assert tip_link(sem, "left_panda_arm") == "left_panda_link8"
    assert named_state(sem, "right_panda_arm", "ready")["right_panda_joint4"] == -2.356


def test_roll_pitch_yaw_as_tf_gives_them():
    x, y, z, w = quaternion_from_rpy(math.pi, 0.0, 0.0)
    assert (abs(x), abs(y), abs(z), abs(w)) == pytest.approx((1.0, 0.0, 0.0, 0.0), abs=1e-12)
    x, y, z, w = quaternion_from_rpy(0.0, 0.0, math.pi / 2)
    assert (x, y, z, w) == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))
