"""A planning error quotes a name a request gave at most 40 characters long (issue 48). On MoveIt's Panda."""

from __future__ import annotations

import pytest
import yaml

from planning.test_planning import CONFIG, PANDA, READY


def _make_planner():
    import os

    from gazelle.description import read_description_file
    from gazelle.planning import ArmPlanner, moveit_joint_limits

    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)  # the meshes are read from the resource roots only
    try:
        urdf = read_description_file(str(CONFIG / "panda.urdf.xacro"))
        limits = moveit_joint_limits(yaml.safe_load((CONFIG / "joint_limits.yaml").read_text()))
        return ArmPlanner(urdf, (CONFIG / "panda.srdf").read_text(), joint_limits=limits, seed=1)
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH")


@pytest.fixture(scope="module")
def planner():
    pytest.importorskip("roboplan")
    return _make_planner()


def test_a_huge_name_is_quoted_at_most_40_characters(planner):
    """A 1 MB group or link name was echoed whole into the reply and the log; now 40 characters of it."""
    from gazelle.planning import GroupUrdfError, PlanningError, group_urdf

    name = "g" * 1_000_000
    with pytest.raises(PlanningError) as err:
        planner.group_joints(name)
    assert len(err.value.message) < 200 and f"'{'g' * 40}'… (1000000 characters)" in err.value.message
    with pytest.raises(PlanningError) as err:
        planner.fk(planner.state(READY), name)
    assert len(err.value.message) < 200
    with pytest.raises(GroupUrdfError) as urdf_err:
        group_urdf("<robot name='panda'/>", planner.semantics, name)
    assert len(str(urdf_err.value)) < 200
    with pytest.raises(PlanningError) as err:
        planner.group_joints("left_arm")
    assert "no planning group 'left_arm'" in err.value.message  # a short name as before
