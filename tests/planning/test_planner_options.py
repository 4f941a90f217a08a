"""An ArmPlanner hands its keyword arguments on to the RobotScene it owns, whose signature alone holds them and their
defaults (gazelle/planning/_robot_options.py names them for the planner): the seed, the SRDF's source name, the
joint limits and the mesh resolver reach the scene as given, and the scene's defaults hold when they are not."""

from __future__ import annotations

import pytest

URDF = """<robot name="arm">
  <link name="base"/>
  <link name="l1">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.3"/><geometry><box size="0.05 0.05 0.5"/></geometry></collision>
  </link>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" velocity="1.5" effort="10"/>
  </joint>
</robot>"""
SRDF = '<robot name="arm"><group name="arm"><chain base_link="base" tip_link="l1"/></group></robot>'


@pytest.fixture(autouse=True)
def _roboplan() -> None:
    pytest.importorskip("roboplan")


def test_the_options_reach_the_scene_as_given() -> None:
    from gazelle.planning import ArmPlanner

    asked: list[str] = []
    planner = ArmPlanner(
        URDF,
        SRDF,
        srdf_source="arm.srdf",
        joint_limits={"j1": {"max_velocity": 0.5}},
        seed=7,
        resolve_mesh=lambda uri: asked.append(uri),
    )
    assert planner.robot.seed == 7
    assert planner.velocity_limits["j1"] == 0.5
    assert planner.groups == ["arm"]


def test_the_scenes_defaults_hold_when_none_is_given() -> None:
    from gazelle.planning import ArmPlanner

    planner = ArmPlanner(URDF, SRDF)
    assert planner.robot.seed == 0
    assert planner.velocity_limits["j1"] == 1.5  # the URDF's


def test_the_srdf_source_names_a_bad_srdf() -> None:
    from gazelle.planning import ArmPlanner, PlanningError

    with pytest.raises(PlanningError) as err:
        ArmPlanner(URDF, "<robot", srdf_source="arm.srdf")
    assert "arm.srdf" in str(err.value)
