"""gazelle.planning on the Panda of moveit_resources_panda_moveit_config (its URDF, SRDF and
joint_limits.yaml unchanged): MoveIt's error names, IK, collision checking and timing."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import yaml
from _paths import REAL, REPO

PANDA = REAL / "moveit_panda"
CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"
ARM = [f"panda_joint{i}" for i in range(1, 8)]
READY = dict(zip(ARM, [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]))
IN_SELF_COLLISION = dict(zip(ARM, [0.0, 1.0, 0.0, -3.0, 0.0, 1.571, 0.785]))  # the hand inside the base
TIPS = ["left_panda_hand", "right_panda_hand"]
"""The chess robot's tools: below each arm's joint 7, link8 and the hand, fixed (the fingers slide)."""


@pytest.fixture(scope="module")
def planner():
    pytest.importorskip("roboplan")
    return panda_planner()


def panda_planner():
    """An ArmPlanner of MoveIt's Panda config (URDF, SRDF, joint_limits.yaml), its meshes from the resource roots."""
    import os

    from gazelle.description import read_description_file as _read_description
    from gazelle.planning import ArmPlanner, moveit_joint_limits

    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)  # the meshes are read from the resource roots only
    try:
        urdf = _read_description(str(CONFIG / "panda.urdf.xacro"))
        limits = moveit_joint_limits(yaml.safe_load((CONFIG / "joint_limits.yaml").read_text()))
        return ArmPlanner(urdf, (CONFIG / "panda.srdf").read_text(), joint_limits=limits, seed=1)
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH")


def _panda_with(srdf: str):
    """An ArmPlanner of MoveIt's Panda URDF with the SRDF text given (its meshes from the resource roots)."""
    import os

    from gazelle.description import read_description_file as _read_description
    from gazelle.planning import ArmPlanner

    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    try:
        urdf = _read_description(str(CONFIG / "panda.urdf.xacro"))
        return ArmPlanner(urdf, srdf, srdf_source="panda.srdf", seed=1)
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH")


def test_the_srdf_groups_named_states_and_tip_come_from_the_file(planner):
    assert planner.groups == ["panda_arm", "hand", "panda_arm_hand"]
    assert planner.group_joints("panda_arm") == ARM
    assert planner.tip_link("panda_arm") == "panda_link8"
    assert planner.named_state("panda_arm", "ready") == pytest.approx(READY)
    assert planner.root_link == "panda_link0"
    assert planner.warnings == []


def test_srdf_groups_and_end_effectors_naming_what_the_urdf_lacks_are_warnings_at_their_lines():
    """A config written for another robot (or a misspelled link): the group is left out, with a warning
    naming the file, the group's line and the missing link and joint; the other groups stay."""
    pytest.importorskip("roboplan")

    srdf = (CONFIG / "panda.srdf").read_text()
    extra = '<group name="gripper2"><link name="no_such_finger"/><joint name="no_such_joint"/></group>'
    # a group of groups that needs it: left out too
    both = '<group name="both"><group name="panda_arm"/><group name="gripper2"/></group>'
    # an end effector naming a group that does not exist (YuMi's and R2's SRDFs have one)
    ee = '<end_effector name="ghost_hand" parent_link="panda_link8" group="ghost"/>'
    srdf = srdf.replace("</robot>", f"\n{extra}\n{both}\n{ee}\n</robot>")
    line = srdf.splitlines().index(extra) + 1
    planner = _panda_with(srdf)
    assert planner.groups == ["panda_arm", "hand", "panda_arm_hand"]
    warning = next(w for w in planner.warnings if "gripper2" in w)
    assert warning.startswith(f"panda.srdf:{line}: "), warning
    assert "link 'no_such_finger'" in warning and "joint 'no_such_joint'" in warning, warning
    warning = next(w for w in planner.warnings if "'both'" in w)
    assert warning.startswith(f"panda.srdf:{line + 1}: ") and "group 'gripper2'" in warning, warning
    warning = next(w for w in planner.warnings if "ghost_hand" in w)
    assert warning.startswith(f"panda.srdf:{line + 2}: ") and "group 'ghost'" in warning, warning


def test_unknown_groups_and_named_states_are_moveit_errors_that_name_what_exists(planner):
    from gazelle.planning import PlanningError

    with pytest.raises(PlanningError) as err:
        planner.group_joints("left_arm")
    assert err.value.code == "INVALID_GROUP_NAME"
    assert "panda_arm" in err.value.message
    with pytest.raises(PlanningError) as err:
        planner.named_state("panda_arm", "r2home")
    assert err.value.code == "INVALID_GOAL_CONSTRAINTS"
    assert "'r2home'" in err.value.message and "ready" in err.value.message


def test_ik_reaches_a_pose_that_fk_gives_and_refuses_one_out_of_reach(planner):
    from gazelle.planning import PlanningError

    ready = planner.state(READY)
    target = planner.fk(planner.state({**READY, "panda_joint1": 0.6, "panda_joint4": -1.9}), "panda_link8")
    q = planner.ik("panda_arm", "panda_link8", target, ready)
    reached = planner.fk(q, "panda_link8")
    assert np.linalg.norm(reached[:3, 3] - target[:3, 3]) < 1e-4
    assert np.allclose(reached[:3, :3], target[:3, :3], atol=2e-3)
    assert not planner.in_collision(q)
    far = target.copy()
    far[:3, 3] = [2.0, 0.0, 0.5]
    with pytest.raises(PlanningError) as err:
        planner.ik("panda_arm", "panda_link8", far, ready, timeout=0.1)
    assert err.value.code == "NO_IK_SOLUTION"


def test_self_collision_honours_the_srdfs_disabled_pairs(planner):
    # at 'ready' adjacent links touch; the SRDF disables those pairs, so the state is free
    assert not planner.in_collision(planner.state(READY))
    assert planner.in_collision(planner.state(IN_SELF_COLLISION))


def test_a_plan_starts_and_ends_where_asked_and_keeps_to_the_scaled_velocity_limits(planner):
    from gazelle.planning import PlanningError

    start = planner.state(READY)
    goal = planner.state({**READY, "panda_joint1": 1.2, "panda_joint2": 0.3})
    vmax = np.array([2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61])  # joint_limits.yaml
    full = planner.plan("panda_arm", goal, start)
    half = planner.plan("panda_arm", goal, start, velocity_scaling=0.5, acceleration_scaling=0.5)
    for traj in (full, half):
        assert traj.joint_names == tuple(ARM)
        assert traj.positions[0] == pytest.approx(start[:7], abs=1e-6)
        assert traj.positions[-1] == pytest.approx(goal[:7], abs=1e-6)
    assert np.all(np.abs(full.velocities) <= vmax * 1.01)
    assert np.all(np.abs(half.velocities) <= 0.5 * vmax * 1.01)
    assert half.duration > full.duration * 1.3
    with pytest.raises(PlanningError) as err:
        planner.plan("panda_arm", planner.state(IN_SELF_COLLISION), start)
    assert err.value.code == "GOAL_IN_COLLISION"


def test_a_box_in_the_world_is_planned_around_and_goals_inside_it_refused(planner):
    from gazelle.planning import PlanningError

    start = planner.state({**READY, "panda_joint1": -1.2})
    goal = planner.state({**READY, "panda_joint1": 1.2})
    wall = np.eye(4)
    wall[:3, 3] = planner.fk(planner.state(READY), "panda_link8")[:3, 3]  # where the hand passes at 'ready'
    planner.add_box("wall", [0.1, 0.05, 0.3], wall)
    assert planner.in_collision(planner.state(READY))
    try:
        traj = planner.plan("panda_arm", goal, start)
        for q in traj.positions:
            full = planner.state(dict(zip(ARM, q)))
            assert not planner.in_collision(full)
        at_wall = planner.state({**READY})
        with pytest.raises(PlanningError) as err:
            planner.plan("panda_arm", at_wall, start)
        assert err.value.code == "GOAL_IN_COLLISION"
    finally:
        planner.remove_object("wall")
    assert not planner.in_collision(planner.state(READY))


def test_an_attached_object_moves_with_its_link_and_touches_only_its_touch_links(planner):
    from gazelle.planning import SceneObject, Shape

    ready = planner.state(READY)
    tool = np.eye(4)
    tool[2, 3] = 0.2  # a rod from 10 to 30 cm out of the flange: between the fingertips and beyond
    shapes = (Shape("cylinder", (0.2, 0.01), np.eye(4)),)
    hand = ("panda_hand", "panda_leftfinger", "panda_rightfinger")
    bent = planner.state({**READY, "panda_joint6": 0.2})  # the hand turned back: the rod points at the arm
    assert not planner.in_collision(bent)
    try:
        planner.add_object(SceneObject("rod", shapes, tool, link="panda_link8"))
        assert planner.in_collision(ready)  # with the hand it is held in
        planner.add_object(SceneObject("rod", shapes, tool, link="panda_link8", touch_links=hand))
        assert not planner.in_collision(ready)
        assert planner.in_collision(bent)  # it went with the hand
        assert [o.name for o in planner.objects()] == ["rod"]
    finally:
        assert planner.remove_object("rod")
    assert planner.objects() == []
    assert not planner.in_collision(bent)


def test_an_attached_object_is_kept_clear_of_world_objects(planner):
    """A box held 30 cm under the flange, where a world box is: the state is in collision and a plan to it
    is GOAL_IN_COLLISION; detached, the same state is free. (Before, an attached object was checked
    against the robot only.)"""
    from gazelle.planning import PlanningError, SceneObject, Shape

    ready = planner.state(READY)
    flange = planner.fk(ready, "panda_link8")
    below = flange.copy()
    below[2, 3] -= 0.3
    cube = (Shape("box", (0.05, 0.05, 0.05), np.eye(4)),)
    try:
        planner.add_object(SceneObject("block", cube, below))
        assert not planner.in_collision(ready)
        planner.add_object(SceneObject("held", cube, np.linalg.inv(flange) @ below, link="panda_link8"))
        assert planner.in_collision(ready)
        start = planner.state({**READY, "panda_joint1": 0.8})
        assert not planner.in_collision(start)  # the held box swung away from the block
        with pytest.raises(PlanningError) as err:
            planner.plan("panda_arm", ready, start)
        assert err.value.code == "GOAL_IN_COLLISION"
        assert planner.remove_object("held")
        assert not planner.in_collision(ready)
        assert [o.name for o in planner.objects()] == ["block"]  # the world object stayed through the rebuilds
    finally:
        planner.remove_object("held")
        planner.remove_object("block")


HAND = ("panda_hand", "panda_leftfinger", "panda_rightfinger")
PIECE = (0.02, 0.02, 0.04)
"""The seed's chess piece, held between the fingers 10.4 cm out of panda_hand."""


def _held_piece(at: np.ndarray):
    from gazelle.planning import SceneObject, Shape

    return SceneObject("piece", (Shape("box", PIECE, np.eye(4)),), at, "panda_hand", HAND)


def test_an_object_held_in_the_hand_is_where_the_hand_is_for_the_arms_own_links(planner):
    """panda_hand is welded 10.7 cm out of link7's joint. The copy of a held object that the arm's own
    links are checked against was placed in that joint's frame without the hand's offset: a piece held
    between the fingers sat at link7, and every plan with a grasped piece failed ("left_panda_link7 with
    piece_r1_c3::link", the chess robot's pick-and-place)."""
    ready = planner.state(READY)
    between_fingers = np.eye(4)
    between_fingers[2, 3] = 0.104
    try:
        planner.add_object(_held_piece(between_fingers))
        assert planner.colliding_pairs(ready) == []
        # held where link5 is, it does touch link5: the check is live
        planner.add_object(
            _held_piece(np.linalg.inv(planner.fk(ready, "panda_hand")) @ planner.fk(ready, "panda_link5"))
        )
        assert {frozenset(p) for p in planner.colliding_pairs(ready)} >= {frozenset(("panda_link5", "piece"))}
    finally:
        planner.remove_object("piece")


def test_a_cartesian_retreat_starts_from_a_state_that_touches(planner):
    """MoveIt's compute_cartesian_path checks the state of each pose along the line, not the start
    (moveit_ros/move_group cartesian_path_service_capability.cpp, isStateValid on every IK solution):
    a grasped piece standing on the board is lifted straight up. gazelle checked the way from the start
    too, so a lift after a grasp reached 0 % of its path."""
    from gazelle.planning import SceneObject, Shape

    ready = planner.state(READY)
    between_fingers = np.eye(4)
    between_fingers[2, 3] = 0.104
    piece = planner.fk(ready, "panda_hand") @ between_fingers
    board = np.eye(4)
    board[:3, 3] = piece[:3, 3] - [0.0, 0.0, PIECE[2] / 2 + 0.01 - 0.0005]  # its top 0.5 mm into the piece
    flange = planner.fk(ready, "panda_link8")
    up, down = flange.copy(), flange.copy()
    up[2, 3] += 0.05
    down[2, 3] -= 0.05
    try:
        planner.add_object(SceneObject("board", (Shape("box", (0.3, 0.3, 0.02), np.eye(4)),), board))
        planner.add_object(_held_piece(between_fingers))
        assert planner.in_collision(ready)  # the piece stands on the board
        traj, fraction = planner.cartesian_path("panda_arm", "panda_link8", [up], ready, max_step=0.005)
        assert fraction == pytest.approx(1.0) and traj is not None
        _, fraction = planner.cartesian_path("panda_arm", "panda_link8", [down], ready, max_step=0.005)
        assert fraction == 0.0  # into the board: the first pose is in collision
    finally:
        planner.remove_object("piece")
        planner.remove_object("board")


def test_a_cartesian_path_follows_a_straight_line_and_reports_the_fraction_it_reached(planner):
    start = planner.state(READY)
    begin = planner.fk(start, "panda_link8")
    end = begin.copy()
    end[:3, 3] += [0.0, 0.2, 0.0]  # 20 cm sideways
    traj, fraction = planner.cartesian_path("panda_arm", "panda_link8", [end], start, max_step=0.01)
    assert fraction == pytest.approx(1.0)
    assert traj is not None and traj.duration > 0
    for positions in traj.positions:  # TOPP-RA's samples between the IK poses stay on the line too
        at = planner.fk(planner.state(dict(zip(ARM, positions))), "panda_link8")[:3, 3]
        off_line = np.linalg.norm(np.cross(at - begin[:3, 3], [0.0, 1.0, 0.0]))
        assert off_line < 2e-3
    assert planner.fk(planner.state(dict(zip(ARM, traj.positions[-1]))), "panda_link8")[:3, 3] == pytest.approx(
        end[:3, 3], abs=1e-3
    )
    too_far = begin.copy()
    too_far[:3, 3] += [1.5, 0.0, 0.0]  # out of reach after some 0.5 m
    traj, fraction = planner.cartesian_path("panda_arm", "panda_link8", [too_far], start, max_step=0.01)
    assert 0.0 < fraction < 0.6


def test_what_the_arm_stands_on_may_touch_its_base_but_not_the_links_that_move(planner):
    assert planner.root_link == "panda_link0" and planner.fixed_links == {"panda_link0"}
    table = np.eye(4)
    table[2, 3] = -0.02  # its top 3 cm into the base's mesh
    planner.add_box("table", [1.0, 1.0, 0.1], table)
    try:
        assert not planner.in_collision(planner.state(READY))
        reaching_down = planner.state({**READY, "panda_joint2": 1.3, "panda_joint4": -1.5})
        assert planner.fk(reaching_down, "panda_link8")[2, 3] < 0.0  # the hand through the table
        assert planner.in_collision(reaching_down)
    finally:
        planner.remove_object("table")


def test_the_ground_is_a_slab_under_the_plane_in_the_simulations_planning_scene(make_sim):
    """The sim's geometry for planners has the ground plane as a slab whose top face is the plane: an arm
    bolted to the ground plans around the floor the simulation stops it at (before, planes were left out
    and a plan could sweep the hand through the floor: the arm jammed against it, pushed past its limits)."""
    from gazelle.sim import SceneGeometry

    sim = make_sim()
    links = {link.name: link for link in SceneGeometry().links(sim.world)}
    (slab,) = links["ground_plane::link"].shapes
    assert slab.kind == "box" and slab.dimensions[0] >= 10 and slab.dimensions[1] >= 10
    X = links["ground_plane::link"].pose * slab.pose
    assert X.position[2] + slab.dimensions[2] / 2 == pytest.approx(0.0, abs=1e-9)  # the top face is z = 0
    assert slab.dimensions[2] >= 0.1  # thick: no planned step jumps it


def test_links_that_only_joints_outside_every_group_move_may_touch_the_world():
    """A mobile manipulator's wheels stand on the ground: no plan moves them, so touching the ground (or
    the table under a fixed arm) is not a collision a plan must avoid; the arm's links are checked."""
    from lxml import etree

    from gazelle.planning._robot_scene import _tree

    robot = etree.fromstring(
        b"""<robot name="r"><link name="base"/><link name="wheel"/><link name="l1"/><link name="l2"/>
        <joint name="w" type="continuous"><parent link="base"/><child link="wheel"/></joint>
        <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/></joint>
        <joint name="j2" type="fixed"><parent link="l1"/><child link="l2"/></joint></robot>"""
    )
    assert _tree(robot).moved_by({"j1"}) == {"l1", "l2"}
    assert _tree(robot).moved_by({"w", "j1"}) == {"wheel", "l1", "l2"}


def test_objects_of_the_world_may_touch_each_other(planner):
    ready = planner.state(READY)
    under, over = np.eye(4), np.eye(4)
    under[:3, 3] = [0.6, 0.0, 0.2]
    over[:3, 3] = [0.6, 0.0, 0.45]  # resting on the first one
    planner.add_box("table", [0.4, 0.4, 0.4], under)
    planner.add_box("board", [0.3, 0.3, 0.1], over)
    try:
        assert not planner.in_collision(ready)
    finally:
        planner.remove_object("table")
        planner.remove_object("board")


def test_a_moveit_configs_kinematics_yaml_becomes_moveits_parameters():
    """kinematics.yaml, read by --config, as MoveIt's robot_description_kinematics.<group>.* parameters."""
    pytest.importorskip("rclpy")
    from gazelle.ros._move_group_config import config_parameters as _config_parameters

    params = {p.name: p.value for p in _config_parameters(CONFIG)}
    assert params["robot_description_kinematics.panda_arm.kinematics_solver_timeout"] == 0.05
    assert (
        params["robot_description_kinematics.panda_arm.kinematics_solver"]
        == "kdl_kinematics_plugin/KDLKinematicsPlugin"
    )
    assert params["robot_description_planning.joint_limits.panda_joint1.max_velocity"] == pytest.approx(2.175)


def test_a_moveit_configs_ompl_planning_yaml_becomes_ompl_parameters_that_move_group_names():
    """ompl_planning.yaml, read by --config, as MoveItConfigsBuilder lays it out (``ompl.*``), so that
    move_group can say at start that it plans with its own pipeline; keys no parameter can be named after
    are left out rather than failing the node."""
    pytest.importorskip("rclpy")
    from gazelle.ros._move_group_config import PIPELINE_PARAMETERS, _flat
    from gazelle.ros._move_group_config import config_parameters as _config_parameters

    params = {p.name: p.value for p in _config_parameters(CONFIG)}
    assert params["ompl.planner_configs.RRTConnectkConfigDefault.type"] == "geometric::RRTConnect"
    adapters, configs = params["ompl.response_adapters"], params["ompl.panda_arm.planner_configs"]
    assert isinstance(adapters, list) and isinstance(configs, list)
    assert "default_planning_response_adapters/AddTimeOptimalParameterization" in adapters
    assert "RRTConnectkConfigDefault" in configs
    assert {n.split(".", 1)[0] for n in params if n.startswith("ompl.")} <= PIPELINE_PARAMETERS
    flat = {p.name for p in _flat("ompl", {"good": 1, "bad key": 2, "mixed": [1, "a"], "nested": {"9x": 3}})}
    assert flat == {"ompl.good"}


def test_a_config_file_that_is_not_yaml_is_an_error_naming_its_file_and_line(tmp_path):
    """move_group --config: a malformed ompl_planning.yaml (or any of the files it reads) is a one-line
    error with its file and line, which the command prints and exits 2 on, never a traceback."""
    pytest.importorskip("rclpy")
    from gazelle.ros._move_group_config import config_parameters as _config_parameters

    (tmp_path / "ompl_planning.yaml").write_text("planner_configs:\n  RRT: [unclosed\n")
    with pytest.raises(ValueError) as err:
        _config_parameters(tmp_path)
    assert str(err.value).startswith(f"{tmp_path / 'ompl_planning.yaml'}:3: not valid YAML"), str(err.value)


def test_a_group_of_groups_plans_both_arms_at_once_and_the_viewer_draws_both_tools():
    """R2's `arms` kind of group: a group made of the dual-arm SRDF's two arm groups moves all 14 joints in
    one collision-free plan, and the viewer's planned path has a tool per arm."""
    pytest.importorskip("roboplan")
    import os

    from _paths import REPO

    from gazelle.description import load_string
    from gazelle.description import read_description_file as _read_description
    from gazelle.planning import ArmPlanner
    from gazelle.viewer._overlays import plan_tips

    srdf = (PANDA / "dual_arm_panda_moveit_config" / "config" / "panda.srdf").read_text()
    both = '<group name="arms"><group name="left_panda_arm"/><group name="right_panda_arm"/></group>'
    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    try:
        urdf = _read_description(str(REPO / "examples" / "chessbot" / "chessbot.urdf.xacro"))
        planner = ArmPlanner(urdf, srdf.replace("</robot>", f"{both}</robot>"), seed=3)
        model = load_string(urdf).model
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH")
    assert "arms" in planner.groups, planner.warnings
    joints = planner.group_joints("arms")
    assert len(joints) == 14 and {j.split("_")[0] for j in joints} == {"left", "right"}
    home = {j: v for arm in ("left", "right") for j, v in planner.named_state(f"{arm}_panda_arm", "ready").items()}
    start = planner.state(home)
    goal = start.copy()
    index = {n: i for i, n in enumerate(planner.joint_names)}
    goal[index["left_panda_joint1"]] += 0.6
    goal[index["right_panda_joint1"]] -= 0.6
    trajectory = planner.plan("arms", goal, start)
    assert set(trajectory.joint_names) == set(joints)
    end = dict(zip(trajectory.joint_names, trajectory.positions[-1]))
    assert end["left_panda_joint1"] == pytest.approx(home["left_panda_joint1"] + 0.6, abs=1e-6)
    assert end["right_panda_joint1"] == pytest.approx(home["right_panda_joint1"] - 0.6, abs=1e-6)
    assert sorted(plan_tips(model, set(trajectory.joint_names))) == TIPS


def test_a_small_box_attached_to_the_hand_plans_and_checks_every_time(planner):
    """Issue 25: any attached object could make every collision check raise inside coal (roboplan's
    setCollisions changed the pairs, then raised for a link without geometry before rebuilding the
    collision data), so plan_kinematic_path answered error code 0. Which pair comes last depends on a
    set's order: several touch-link sets, one of them with panda_link8 (no geometry), cover it."""
    from gazelle.planning import SceneObject, Shape

    held = np.eye(4)
    held[2, 3] = 0.2  # 2 cm box 20 cm out of the hand's frame, past the fingertips
    fingers = ("panda_leftfinger", "panda_rightfinger")
    ready = planner.state(READY)
    try:
        for touch in [(), ("panda_link8",), ("panda_link7", "panda_link8"), ("panda_link8", "panda_link7")]:
            for name in ("piece", "pawn", "rook"):
                box = (Shape("box", (0.02, 0.02, 0.02), np.eye(4)),)
                planner.add_object(SceneObject(name, box, held, "panda_hand", ("panda_hand", *fingers, *touch)))
                for _ in range(3):
                    assert not planner.in_collision(ready)
                planner.remove_object(name)
        planner.add_object(SceneObject("piece", box, held, "panda_hand", ("panda_hand", *fingers)))
        traj = planner.plan("panda_arm", planner.state({**READY, "panda_joint1": 0.5}), ready, timeout=5.0)
        assert len(traj.times) >= 2
    finally:
        planner.remove_object("piece")


def test_a_finger_a_hair_past_its_limit_does_not_refuse_an_arm_plan_and_a_bad_goal_names_its_joint(planner):
    """Issue 27: a pymoveit2 client sent /joint_states' finger at -6.6e-12 m (limit 0) as its start state;
    6 of 8 joint goals failed with GOAL_STATE_INVALID, naming nothing."""
    from gazelle.planning import PlanningError

    start = planner.onto_limits(planner.state({**READY, "panda_finger_joint1": -6.6e-12}))
    finger = planner.joint_names.index("panda_finger_joint1")
    assert start[finger] == 0.0
    raw = planner.state({**READY, "panda_finger_joint1": -6.6e-12})
    goal = raw.copy()
    goal[planner.joint_names.index("panda_joint1")] = 0.4
    traj = planner.plan("panda_arm", goal, raw, timeout=5.0)  # the finger is not the arm's business
    assert len(traj.times) >= 2
    goal[planner.joint_names.index("panda_joint4")] = 0.5  # above its upper limit, -0.0698
    with pytest.raises(PlanningError) as info:
        planner.plan("panda_arm", goal, start, timeout=5.0)
    assert info.value.code == "GOAL_STATE_INVALID" and "joint 'panda_joint4' at 0.5" in info.value.message


def test_one_bad_tip_link_leaves_out_its_group_only():
    """Issue 27: a chain tip the URDF lacks (panda_link9) made roboplan refuse the whole SRDF, and the
    untouched hand group was reported as naming missing links."""
    pytest.importorskip("roboplan")

    srdf = (CONFIG / "panda.srdf").read_text().replace('tip_link="panda_link8"', 'tip_link="panda_link9"')
    planner = _panda_with(srdf)
    assert "hand" in planner.groups and "panda_arm" not in planner.groups
    warnings = " ".join(planner.warnings)
    assert "SRDF group 'panda_arm' names link 'panda_link9'" in warnings
    assert "'hand' names" not in warnings


def test_a_state_in_collision_names_the_bodies_that_collide(planner):
    """Issue 27: check_state_validity's contacts were empty and START/GOAL_IN_COLLISION named no pair."""
    from gazelle.planning import PlanningError, SceneObject, Shape

    inside = planner.state(IN_SELF_COLLISION)
    pairs = planner.colliding_pairs(inside)
    assert ("panda_link1", "panda_hand") in pairs or ("panda_hand", "panda_link1") in pairs, pairs
    assert planner.colliding_pairs(planner.state(READY)) == []
    ready = planner.state(READY)
    hand = planner.fk(ready, "panda_hand")
    try:
        planner.add_object(SceneObject("crate", (Shape("box", (0.3, 0.3, 0.3), np.eye(4)),), hand))
        with pytest.raises(PlanningError) as info:
            planner.plan("panda_arm", ready, planner.state({**READY, "panda_joint1": 0.5}), timeout=2.0)
        assert info.value.code in ("START_STATE_IN_COLLISION", "GOAL_IN_COLLISION")
        assert "with crate" in info.value.message, info.value.message
    finally:
        planner.remove_object("crate")


def test_velocity_limits_come_from_the_urdf_and_joint_limits_yaml_on_a_robot_with_two_mimic_joints():
    """Issue 27 item 1: roboplan 0.7's Scene.getVelocityLimitVectors("") writes past its vector on a robot with
    two mimic joints (YuMi's grippers): move_group's execute_trajectory check called it and the process died
    of "double free or corruption". The planner keeps the limits itself: the URDF's, then joint_limits.yaml's."""
    from gazelle.planning import ArmPlanner

    yumi = REPO / "tests" / "data" / "yumi_like"
    planner = ArmPlanner(
        (yumi / "yumi.urdf").read_text(),
        (yumi / "yumi.srdf").read_text(),
        joint_limits={"yumi_joint_1_l": {"max_velocity": 1.5}},
    )
    assert len(planner.joint_names) == 16  # 14 arm joints and 2 grippers; their 2 mimic joints are not listed
    assert planner.velocity_limits["yumi_joint_1_l"] == 1.5  # joint_limits.yaml wins
    assert planner.velocity_limits["yumi_joint_1_r"] == pytest.approx(3.14159265359)  # the URDF's
    assert planner.velocity_limits["gripper_l_joint"] == pytest.approx(2.0)


def test_a_failed_ik_says_whether_the_pose_is_out_of_reach_or_in_collision(planner):
    """Issue 27 item 8: a pose inside the table and a pose 2 m away both gave the same NO_IK_SOLUTION. The code
    stays MoveIt's; the message says which, and names what collides."""
    from gazelle.planning import PlanningError

    ready = planner.state(READY)
    target = planner.fk(planner.state({**READY, "panda_joint1": 0.6, "panda_joint4": -1.9}), "panda_link8")
    far = target.copy()
    far[:3, 3] = [2.0, 0.0, 0.5]
    with pytest.raises(PlanningError) as err:
        planner.ik("panda_arm", "panda_link8", far, ready, timeout=0.1)
    assert err.value.code == "NO_IK_SOLUTION" and "out of reach" in err.value.message
    block = np.eye(4)
    block[:3, 3] = target[:3, 3]  # a block where the flange would be
    planner.add_box("block", [0.3, 0.3, 0.3], block)
    try:
        with pytest.raises(PlanningError) as err:
            planner.ik("panda_arm", "panda_link8", target, ready, timeout=0.2)
        assert err.value.code == "NO_IK_SOLUTION"
        assert "reachable, but in collision" in err.value.message and "block" in err.value.message, err.value.message
    finally:
        planner.remove_object("block")


def test_the_collision_matrix_round_trips_moveits_message_layout():
    """The matrix as MoveIt's AllowedCollisionMatrix message lays it out (entry_names, entry_values rows);
    a malformed one is refused with why."""
    from gazelle.planning import CollisionMatrix

    acm = CollisionMatrix.initial(["a", "b", "c"], [("a", "b"), ("a", "zz")])
    assert acm.rows() == [[False, True, False], [True, False, False], [False, False, False]]
    again = CollisionMatrix.from_rows(acm.names + ["box"], [r + [True] for r in acm.rows()] + [[True] * 4])
    assert again.is_allowed("a", "b") and again.is_allowed("box", "c") and not again.is_allowed("b", "c")
    assert dict(again.pairs_with("box")) == {"a": True, "b": True, "c": True}
    for names, rows, why in (
        (["a", "b"], [[False, True]], "2 entry_names but 1 entry_values"),
        (["a", "b"], [[False], [True, False]], "entry_values[0] has 1 values for 2 entry_names"),
    ):
        with pytest.raises(ValueError, match=re.escape(why)):
            CollisionMatrix.from_rows(names, rows)


def test_a_replaced_collision_matrix_allows_and_forbids_pairs_and_outlives_an_attach(planner):
    """MoveIt's semantics (planning_scene.cpp setPlanningSceneDiffMsg): a new matrix replaces the old, its
    allowed pairs are not checked, the rest among its names are, the SRDF's pairs included; a rebuild of the
    scene (an attach) keeps it."""
    from gazelle.planning import CollisionMatrix, SceneObject, Shape

    q = planner.state(READY)
    flange = planner.fk(q, "panda_link8")
    block = np.eye(4)
    block[:3, 3] = flange[:3, 3]
    initial = planner.acm
    planner.add_box("acm_block", [0.2, 0.2, 0.2], block)
    try:
        assert planner.in_collision(q)

        def with_block(allow: bool, srdf: bool = True) -> CollisionMatrix:
            names = [*initial.names, "acm_block"]
            rows = [[*r, allow] for r in initial.rows()] + [[allow] * len(initial.names) + [False]]
            if not srdf:  # every robot pair checked: the links that touch by design now collide
                rows = [[False] * len(names) for _ in names]
            return CollisionMatrix.from_rows(names, rows)

        planner.set_allowed_collision_matrix(with_block(True))
        assert not planner.in_collision(q)
        held = SceneObject("acm_held", (Shape("box", (0.02, 0.02, 0.02), np.eye(4)),), np.eye(4), link="panda_hand")
        planner.add_object(held)  # rebuilds the robot model: the matrix is applied again
        pairs = planner.colliding_pairs(q)  # the held piece is in the block: not in the matrix, so checked
        assert pairs and all("acm_held" in pair for pair in pairs), pairs
        planner.remove_object("acm_held")
        planner.set_allowed_collision_matrix(with_block(False))
        assert planner.in_collision(q) and "acm_block" in planner.named_pairs(q)
        planner.remove_object("acm_block")
        planner.set_allowed_collision_matrix(with_block(False, srdf=False))
        assert planner.in_collision(q)  # panda_link0 touches panda_link1: the SRDF's pair is checked again
    finally:
        planner.remove_object("acm_block")
        planner.set_allowed_collision_matrix(initial)
    assert not planner.in_collision(q)


STOPPED_CARTESIAN = """
import os, sys, json
import numpy as np
import yaml
sys.path.insert(0, {tests!r})
from planning.test_planning import CONFIG, PANDA, READY
from gazelle.description import read_description_file
from gazelle.planning import ArmPlanner, moveit_joint_limits
os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
urdf = read_description_file(str(CONFIG / "panda.urdf.xacro"))
limits = moveit_joint_limits(yaml.safe_load((CONFIG / "joint_limits.yaml").read_text()))
planner = ArmPlanner(urdf, (CONFIG / "panda.srdf").read_text(), joint_limits=limits, seed=1)
start = planner.state(READY)
end = planner.fk(start, "panda_link8")
end[:3, 3] += [0.0, 0.2, 0.0]
print("ready", flush=True)
sys.stdin.readline()
out = []
for _ in range(6):
    traj, fraction = planner.cartesian_path("panda_arm", "panda_link8", [end], start, max_step=0.002)
    out.append([fraction, [round(float(v), 9) for v in traj.positions[-1]] if traj is not None else None])
print(json.dumps(out), flush=True)
"""


def test_a_cartesian_path_is_the_same_on_a_machine_that_stalls_the_planner():
    """Each pose of a Cartesian path is solved from the last in a bounded number of IK iterations, not
    in a wall-clock budget: the chess robot's lift once answered 0 % beside a CPU hog (each pose had
    50 ms of wall time, and a loaded machine took that from the solver). Here the planner's process is
    stopped for 60 ms after every 5 ms of running while it computes the same 20 cm line six times (100
    poses in 2 mm steps each): every run reaches all of it, and ends in the same joint positions (before:
    fractions of 0 to 5 %)."""
    import json
    import os
    import signal
    import subprocess
    import sys
    import threading

    script = STOPPED_CARTESIAN.format(tests=str(REPO / "tests"))
    proc = subprocess.Popen(
        [sys.executable, "-c", script], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    assert proc.stdin is not None and proc.stdout is not None
    try:
        assert proc.stdout.readline().strip() == "ready", proc.stderr.read() if proc.stderr else ""
        done = threading.Event()

        def stall() -> None:
            while not done.wait(0.005):
                os.kill(proc.pid, signal.SIGSTOP)
                done.wait(0.06)
                os.kill(proc.pid, signal.SIGCONT)

        staller = threading.Thread(target=stall, daemon=True)
        staller.start()
        proc.stdin.write("go\n")
        proc.stdin.flush()
        line = proc.stdout.readline()
        done.set()
        staller.join(2)
        os.kill(proc.pid, signal.SIGCONT)
        runs = json.loads(line)
    finally:
        proc.kill()
        proc.wait(10)
    assert [fraction for fraction, _ in runs] == [1.0] * 6, runs
    assert all(end == runs[0][1] for _, end in runs), runs


def _box_at_flange(planner, name: str):
    """A 20 cm box where the flange is at READY: (that state, the matrix before)."""
    q = planner.state(READY)
    block = np.eye(4)
    block[:3, 3] = planner.fk(q, "panda_link8")[:3, 3]
    initial = planner.acm
    planner.add_box(name, [0.2, 0.2, 0.2], block)
    return q, initial


def test_a_matrix_that_no_longer_names_an_object_has_its_collisions_checked_again(planner):
    """MoveIt replaces the whole matrix (planning_scene.cpp setPlanningSceneDiffMsg): an object the new
    matrix does not name has no entry, so its pairs are not allowed (collision_matrix.cpp
    getAllowedCollision: no entry and no default); gazelle kept the old matrix's allowance for it. And
    MoveIt reads a message's pairs from the upper triangle only (the AllowedCollisionMatrix constructor
    reads entry_values[i].enabled[j] for j > i)."""
    from gazelle.planning import CollisionMatrix

    q, initial = _box_at_flange(planner, "acm_gone")
    try:
        names = [*initial.names, "acm_gone"]
        rows = [[*r, True] for r in initial.rows()] + [[True] * len(initial.names) + [False]]
        planner.set_allowed_collision_matrix(CollisionMatrix.from_rows(names, rows))
        assert not planner.in_collision(q)
        planner.set_allowed_collision_matrix(CollisionMatrix.from_rows(initial.names, initial.rows()))
        assert planner.in_collision(q) and "acm_gone" in planner.named_pairs(q)
    finally:
        planner.remove_object("acm_gone")
        planner.set_allowed_collision_matrix(initial)
    lower_only = CollisionMatrix.from_rows(["a", "b"], [[False, False], [True, False]])
    assert not lower_only.is_allowed("a", "b")
    upper_only = CollisionMatrix.from_rows(["a", "b"], [[False, True], [False, False]])
    assert upper_only.is_allowed("a", "b")


def test_default_entries_decide_the_pairs_the_entries_do_not(planner):
    """MoveIt's default entries (collision_matrix.cpp ``getAllowedCollision``/``getDefaultEntry``): a pair
    with no entry takes its names' defaults (one default decides; with two, allowed only when both say
    ALWAYS; none: not allowed). An object with a default ALWAYS and no entries may touch everything; the
    message written back lists it and its default, as MoveIt's ``getMessage`` does."""
    from gazelle.planning import CollisionMatrix

    m = CollisionMatrix.from_rows(
        ["a", "b"], [[False, False], [False, False]], ["box", "a", "wall"], [True, False, False]
    )
    assert not m.is_allowed("a", "b")  # an entry decides, whatever the defaults
    assert not m.is_allowed("box", "a") and not m.is_allowed("box", "wall")  # both defaults: NEVER wins
    assert m.is_allowed("box", "b") and m.is_allowed("box", "anything")  # one default: ALWAYS
    assert not m.is_allowed("b", "anything")  # no entry, no default
    assert m.message_names() == ["a", "b", "box", "wall"] and m.rows()[2] == [False, True, True, False]
    with pytest.raises(ValueError, match="2 default_entry_names but 1 default_entry_values"):
        CollisionMatrix.from_rows([], [], ["x", "y"], [True])

    q, initial = _box_at_flange(planner, "acm_default")
    try:
        assert planner.in_collision(q)
        rows = initial.rows()
        planner.set_allowed_collision_matrix(CollisionMatrix.from_rows(initial.names, rows, ["acm_default"], [True]))
        assert not planner.in_collision(q)
        assert planner.acm.defaults == {"acm_default": True} and "acm_default" in planner.acm.message_names()
        planner.set_allowed_collision_matrix(CollisionMatrix.from_rows(initial.names, rows, ["acm_default"], [False]))
        assert planner.in_collision(q) and "acm_default" in planner.named_pairs(q)
    finally:
        planner.remove_object("acm_default")
        planner.set_allowed_collision_matrix(initial)
    assert not planner.in_collision(q)


def test_a_groups_urdf_is_built_as_moveits_get_urdf_builds_it(planner):
    """get_group_urdf_capability.cpp: the group's links sorted, then its joints sorted, each followed by an
    empty parent link when that link is not in yet; the group's joints as MoveIt's JointModelGroup has them
    (a chain's joints, fixed ones too; a named link's parent joint; a subgroup's joints)."""
    from lxml import etree

    from gazelle.planning import GroupUrdfError, group_urdf

    urdf = planner.robot._urdf
    arm = etree.fromstring(group_urdf(urdf, planner.semantics, "panda_arm").encode())
    assert arm.tag == "robot" and arm.get("name") == "panda_arm"
    order = [(e.tag, e.get("name")) for e in arm]
    links = [("link", f"panda_link{i}") for i in range(1, 9)]
    joints = [("joint", f"panda_joint{i}") for i in range(1, 9)]
    assert order == [*links, joints[0], ("link", "panda_link0"), *joints[1:]]
    stub, link1, joint8 = (
        arm.find(path)
        for path in ("link[@name='panda_link0']", "link[@name='panda_link1']", "joint[@name='panda_joint8']")
    )
    assert stub is not None and len(stub) == 0  # the stub
    assert link1 is not None and link1.find("collision") is not None  # copied whole
    assert joint8 is not None and joint8.get("type") == "fixed"

    hand = etree.fromstring(group_urdf(urdf, planner.semantics, "hand").encode())
    assert [(e.tag, e.get("name")) for e in hand] == [
        ("link", "panda_hand"),
        ("link", "panda_leftfinger"),
        ("link", "panda_rightfinger"),
        ("joint", "panda_finger_joint1"),
        ("joint", "panda_finger_joint2"),
        ("joint", "panda_hand_joint"),
        ("link", "panda_link8"),
    ]
    both = etree.fromstring(group_urdf(urdf, planner.semantics, "panda_arm_hand").encode())
    assert {e.get("name") for e in both.iter("joint")} == {f"panda_joint{i}" for i in range(1, 9)} | {
        "panda_finger_joint1",
        "panda_finger_joint2",
        "panda_hand_joint",
    }
    with pytest.raises(GroupUrdfError, match="Cannot create URDF because planning group 'legs' does not exist"):
        group_urdf(urdf, planner.semantics, "legs")


def test_servo_turns_commands_into_joint_steps_as_moveit_servo_does(planner):
    """moveit_servo's command.cpp and servo.cpp on MoveIt's Panda: speed_units capped at scale.linear, a jog of
    a joint outside the group or with a velocity short is INVALID, a step past a joint limit less its margin
    halts every joint (JOINT_BOUND), and a twist at the stretched-out singularity is an emergency stop."""
    from gazelle.planning import ServoCore, ServoKinematics, ServoSettings
    from gazelle.planning import servo as sv

    k = ServoKinematics(planner, "panda_arm")
    assert (k.planning_frame, k.ee_frame) == ("panda_link0", "panda_link8")
    assert np.allclose(
        k.jacobian(np.array(list(READY.values()))), k.numeric_jacobian(np.array(list(READY.values()))), atol=1e-6
    )
    core = ServoCore(k, ServoSettings(command_in_type="speed_units", scale_linear=0.2))
    q = np.array(list(READY.values()))
    status, delta, _ = core.twist(q, np.array([0.0, 0.0, 1.0, 0.0, 0.0, 0.0]))  # 1 m/s asked, 0.2 allowed
    assert status == sv.NO_WARNING
    dx = k.jacobian(q) @ delta
    assert dx[2] == pytest.approx(0.2 * 0.01, rel=1e-3) and np.abs(dx[[0, 1, 3, 4, 5]]).max() < 1e-6
    # about the end effector's own axes: its z is the base's -z at READY (pointing down)
    moved = core.twist_in_planning_frame(q, "panda_link8", [0.0, 0.0, 0.1, 0.0, 0.0, 0.0])
    assert moved is not None and moved[2] == pytest.approx(-0.1, abs=1e-3)
    assert core.twist_in_planning_frame(q, "nowhere", [0.0] * 6) is None

    assert core.joint_jog(["panda_finger_joint1"], [0.1])[0] == sv.INVALID
    assert core.joint_jog(["panda_joint1"], [float("nan")])[0] == sv.INVALID  # a value off the wire
    assert core.twist(q, np.array([float("inf"), 0.0, 0.0, 0.0, 0.0, 0.0]))[0] == sv.INVALID
    assert "Received 2 joints with 1 commands" in core.joint_jog(["panda_joint1", "panda_joint2"], [0.1])[2]
    near = q.copy()
    near[0] = k.upper[0] - 0.05  # within the 0.1 margin of joint 1's upper limit
    status, delta, _ = core.joint_jog(["panda_joint1"], [1.0])
    step = core.next_state(near, status, delta, sv.JOINT_JOG)
    assert step.status == sv.JOINT_BOUND and np.array_equal(step.positions, near) and not step.velocities.any()
    assert "panda_joint1" in step.warning

    stretched = np.array([0.0, 0.0, 0.0, -0.07, 0.0, 0.0, 0.0])  # the arm straight up: elbow almost straight
    status, delta, _ = core.twist(stretched, np.array([0.0, 0.0, 0.05, 0.0, 0.0, 0.0]))
    assert status == sv.HALT_FOR_SINGULARITY and not delta.any()


def test_servo_approaches_a_pose_target_at_the_capped_speeds(planner):
    """command.cpp jointDeltaFromPose: the error to the target, capped at scale.linear and scale.rotational
    per second; a target within reach of one cycle is reached in it."""
    from gazelle.planning import ServoCore, ServoKinematics, ServoSettings
    from gazelle.planning import servo as sv

    k = ServoKinematics(planner, "panda_arm")
    core = ServoCore(k, ServoSettings(scale_linear=0.2, scale_rotational=0.8))
    q = np.array(list(READY.values()))
    here = k.pose(q, k.ee_frame)
    far = here.copy()
    far[0, 3] += 0.10  # 10 cm ahead: 0.2 m/s allows 2 mm in a 10 ms cycle
    status, delta, _ = core.pose(q, far)
    step = k.pose(q + delta, k.ee_frame)[:3, 3] - here[:3, 3]
    assert status == sv.NO_WARNING and step[0] == pytest.approx(0.002, rel=0.02) and abs(step[1]) < 1e-4
    near = here.copy()
    near[1, 3] += 0.001  # 1 mm: within one cycle's reach
    status, delta, _ = core.pose(q, near)
    assert np.linalg.norm(k.pose(q + delta, k.ee_frame)[:3, 3] - near[:3, 3]) < 1e-5


def test_servo_commands_of_1e308_are_capped_or_invalid_never_nan(planner):
    """gazelle issue 48: a unitless twist of 1.7e308 overflowed into NaN joint positions (the next cycle's SVD
    then did not converge and servo_node died). A unitless twist outside [-1, 1] is INVALID (Humble's rule,
    the range servo_parameters.yaml gives), a speed_units twist of 1.7e308 is capped at scale.linear along
    its direction (its norm overflowed to inf and zeroed it), a pose target of 1e308 is approached at the
    capped speed, and any step that is not finite is INVALID with no motion."""
    from gazelle.planning import ServoCore, ServoKinematics, ServoSettings
    from gazelle.planning import servo as sv

    k = ServoKinematics(planner, "panda_arm")
    q = np.array(list(READY.values()))
    unitless = ServoCore(k, ServoSettings())
    assert unitless.out_of_range([1.7e308, 0, 0, 0, 0, 0]) and unitless.out_of_range([0, 0, 0, 0, 0, -1.01])
    assert not unitless.out_of_range([1.0, -1.0, 0.5, 0, 0, 1.0])
    speed = ServoCore(k, ServoSettings(command_in_type="speed_units", scale_linear=0.2))
    assert not speed.out_of_range([1.7e308, 0, 0, 0, 0, 0])
    status, delta, _ = speed.twist(q, np.array([1.7e308, 1.7e308, 0.0, 0.0, 0.0, 0.0]))
    dx = k.jacobian(q) @ delta
    assert status == sv.NO_WARNING and np.all(np.isfinite(delta))
    assert dx[0] == pytest.approx(0.2 * 0.01 / math.sqrt(2), rel=1e-3) and dx[1] == pytest.approx(dx[0], rel=1e-3)
    target = k.pose(q, k.ee_frame)
    target[0, 3] = 1e308
    status, delta, _ = speed.pose(q, target)
    step = k.pose(q + delta, k.ee_frame)[:3, 3] - k.pose(q, k.ee_frame)[:3, 3]
    assert status == sv.NO_WARNING and step[0] == pytest.approx(0.002, rel=0.02)
    with np.errstate(over="ignore"):
        huge = np.full(7, 1e307) * 10.0  # a delta the arithmetic cannot hold: inf
    step = unitless.next_state(q, sv.NO_WARNING, huge, sv.TWIST)
    assert step.status == sv.INVALID and step.warning == sv.TOO_LARGE
    assert np.array_equal(step.positions, q) and not step.velocities.any()
    step = unitless.next_state(q, sv.NO_WARNING, np.full(7, 1e307), sv.TWIST)  # finite, but /period overflows
    assert step.status == sv.INVALID and np.all(np.isfinite(step.positions))
