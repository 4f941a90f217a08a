"""Issue 51 items 4, 5 and 7: motion plan requests and the planning scene as MoveIt's move_group answers them,
on the simulated Panda of test_move_group.py (its module fixture, a simulation and move_group of this module's
own): the start state checked before the goal is looked for, a whole scene that keeps the simulation's
objects, /monitored_planning_scene, planner_id, and path constraints."""

from __future__ import annotations

import threading
import time
from typing import Any

import numpy as np
import pytest
from _harness import wait_for
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (
    CollisionObject,
    Constraints,
    MoveItErrorCodes,
    PlanningScene,
    PositionConstraint,
)
from moveit_msgs.srv import ApplyPlanningScene, GetMotionPlan, GetPlanningScene
from shape_msgs.msg import SolidPrimitive

from integration.test_move_group import (  # noqa: F401 - panda: the module's fixture
    ARM,
    IN_SELF_COLLISION,
    Panda,
    _group_states,
    panda,
)

pytestmark = pytest.mark.slow


def _plan(panda: Panda, request: Any, timeout: float = 60.0) -> tuple[Any, float]:
    """plan_kinematic_path: (its MoveItErrorCodes, how long the answer took, the service's discovery not
    counted)."""
    panda.ros.client(GetMotionPlan, "/plan_kinematic_path")
    panda.joints()  # and the arm's /joint_states are there (move_group waits for its current state)
    t0 = time.monotonic()
    reply = panda.ros.call(
        GetMotionPlan, "/plan_kinematic_path", GetMotionPlan.Request(motion_plan_request=request), timeout
    )
    return reply.motion_plan_response, time.monotonic() - t0


def _request(start: dict[str, float] | None = None, goal: Constraints | None = None) -> Any:
    request = GetMotionPlan.Request().motion_plan_request
    request.group_name = "panda_arm"
    request.allowed_planning_time = 5.0
    if start is not None:
        request.start_state.joint_state.name = list(start)
        request.start_state.joint_state.position = [float(v) for v in start.values()]
    if goal is not None:
        request.goal_constraints = [goal]
    return request


def _position_goal(x: float, y: float, z: float, link: str = "panda_link8") -> Constraints:
    """A position-only goal for ``link``: a 1 mm sphere at (x, y, z) in the planning frame."""
    pc = PositionConstraint(link_name=link, weight=1.0)
    pc.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001])]
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = x, y, z
    pose.orientation.w = 1.0
    pc.constraint_region.primitive_poses = [pose]
    return Constraints(position_constraints=[pc])


def test_a_start_state_in_collision_is_answered_at_once_before_the_goal_is_looked_for(panda):
    """Issue 51 item 7: a start state in collision spent the goal's whole search (here 21 orientations of an
    unreachable position goal, ~6 s) before failing; MoveIt's CheckStartStateCollision adapter runs before the
    planner and answers START_STATE_IN_COLLISION naming the contacts."""
    start = dict(zip(ARM, IN_SELF_COLLISION))
    response, took = _plan(panda, _request(start, _position_goal(3.0, 0.0, 0.5)))  # 3 m away: out of reach
    assert response.error_code.val == MoveItErrorCodes.START_STATE_IN_COLLISION, response.error_code.message
    assert "contact(s) detected : " in response.error_code.message
    assert took < 2.0, took


def test_a_start_state_outside_the_joint_limits_is_start_state_invalid(panda):
    """Issue 51 item 7: a start state past a limit reached roboplan, which answered PLANNING_FAILED ("Invalid start
    configuration requested"). MoveIt Jazzy's CheckStartStateBounds answers START_STATE_INVALID "Start state out
    of bounds." and logs the joint (check_start_state_bounds.cpp; it clamps nothing)."""
    ready = _group_states("panda_arm")["ready"]
    start = {**ready, "panda_joint4": 0.5}  # panda_joint4's upper limit is -0.0698 rad
    goal = panda.joint_goal(ready).request.goal_constraints[0]
    response, took = _plan(panda, _request(start, goal))
    assert response.error_code.val == MoveItErrorCodes.START_STATE_INVALID, response.error_code.message
    assert response.error_code.message == "Start state out of bounds."
    panda.move_group.wait_line("Joint 'panda_joint4' from the starting state is outside bounds by: [0.5 ]", 5)
    assert took < 2.0, took


def test_a_whole_planning_scene_keeps_the_simulations_objects(panda):
    """Issue 51 item 7: a full (non-diff) apply_planning_scene removed the simulation's ground, which came back
    only when something in the simulation moved. A whole scene replaces the objects clients applied; the
    simulation's own stay, as a sensed world does in MoveIt."""
    crate = CollisionObject(id="crate", operation=CollisionObject.ADD)
    crate.header.frame_id = "panda_link0"
    crate.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=[0.1, 0.1, 0.1])]
    at = Pose()
    at.position.x, at.position.z, at.orientation.w = 0.6, 0.05, 1.0
    crate.primitive_poses = [at]
    whole = PlanningScene(is_diff=False)
    whole.world.collision_objects = [crate]
    assert panda.ros.call(ApplyPlanningScene, "/apply_planning_scene", ApplyPlanningScene.Request(scene=whole)).success
    listed = panda.ros.call(GetPlanningScene, "/get_planning_scene", GetPlanningScene.Request())
    assert sorted(o.id for o in listed.scene.world.collision_objects) == ["crate", "ground_plane::link"]
    empty = PlanningScene(is_diff=False)
    assert panda.ros.call(ApplyPlanningScene, "/apply_planning_scene", ApplyPlanningScene.Request(scene=empty)).success
    listed = panda.ros.call(GetPlanningScene, "/get_planning_scene", GetPlanningScene.Request())
    assert [o.id for o in listed.scene.world.collision_objects] == ["ground_plane::link"]


def test_the_scene_is_published_on_monitored_planning_scene(panda):
    """Issue 51 item 7: there was no /monitored_planning_scene (RViz's MotionPlanning display follows the scene
    there). As MoveIt's PlanningSceneMonitor: the whole scene, then its changes (a new object as a whole scene,
    the robot's motion as robot-state diffs)."""
    heard: list[PlanningScene] = []
    lock = threading.Lock()

    def on_scene(msg: PlanningScene) -> None:
        with lock:
            heard.append(msg)

    panda.ros.node.create_subscription(PlanningScene, "/monitored_planning_scene", on_scene, 100)

    def whole_with(name: str) -> bool:
        with lock:
            return any(not m.is_diff and name in {o.id for o in m.world.collision_objects} for m in heard)

    wait_for(lambda: whole_with("ground_plane::link"), 15, "a whole scene with the ground on /monitored_planning_scene")
    marker = CollisionObject(id="marker", operation=CollisionObject.ADD)
    marker.header.frame_id = "panda_link0"
    marker.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.02])]
    at = Pose()
    at.position.x, at.position.y, at.position.z, at.orientation.w = 0.5, 0.5, 0.02, 1.0
    marker.primitive_poses = [at]
    diff = PlanningScene(is_diff=True)
    diff.world.collision_objects = [marker]
    assert panda.ros.call(ApplyPlanningScene, "/apply_planning_scene", ApplyPlanningScene.Request(scene=diff)).success
    try:
        wait_for(lambda: whole_with("marker"), 10, "the marker on /monitored_planning_scene")
    finally:
        diff.world.collision_objects = [CollisionObject(id="marker", operation=CollisionObject.REMOVE)]
        panda.ros.call(ApplyPlanningScene, "/apply_planning_scene", ApplyPlanningScene.Request(scene=diff))
    with lock:
        scene = next(m for m in heard if not m.is_diff)
    assert scene.robot_model_name == "panda" and set(ARM) <= set(scene.robot_state.joint_state.name)
    assert np.all(np.isfinite(scene.robot_state.joint_state.position))


def test_a_planner_id_of_a_planner_gazelle_has_is_honoured_and_another_is_said(panda):
    """Issue 51 item 4: planner_id was ignored. An OMPL configuration of RRTConnect, RRTstar or RRT
    (ompl_planning.yaml's ``type``, as MoveIt's OMPL interface reads it) is planned with that planner; another
    is planned with RRTConnect and said once."""
    ready = _group_states("panda_arm")["ready"]
    goal = panda.joint_goal({**ready, "panda_joint1": 0.4}).request.goal_constraints[0]
    request = _request(ready, goal)
    request.planner_id = "RRTstarkConfigDefault"
    request.allowed_planning_time = 1.0
    response, _ = _plan(panda, request)
    assert response.error_code.val == MoveItErrorCodes.SUCCESS, response.error_code.message
    panda.move_group.wait_line("planner_id 'RRTstarkConfigDefault': planned with RRTstar", 5)
    request.planner_id = "ESTkConfigDefault"
    response, _ = _plan(panda, request)
    assert response.error_code.val == MoveItErrorCodes.SUCCESS, response.error_code.message
    panda.move_group.wait_line("planner_id 'ESTkConfigDefault' is not simulated", 5)
    assert not [line for line in panda.move_group.lines if "'RRTstarkConfigDefault' is not simulated" in line]


def _tilt(panda: Panda, joints: list[str], positions: Any, up: np.ndarray) -> float:
    """The angle (rad) between panda_link8's z axis at ``positions`` and ``up``, by /compute_fk."""
    from moveit_msgs.srv import GetPositionFK

    req = GetPositionFK.Request(fk_link_names=["panda_link8"])
    req.header.frame_id = "panda_link0"
    req.robot_state.joint_state.name = list(joints)
    req.robot_state.joint_state.position = [float(v) for v in positions]
    q = panda.ros.call(GetPositionFK, "/compute_fk", req).pose_stamped[0].pose.orientation
    x, y, z, w = q.x, q.y, q.z, q.w
    axis = np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])
    return float(np.arccos(np.clip(axis @ up, -1.0, 1.0)))


def test_an_orientation_path_constraint_is_kept_along_the_whole_path(panda):
    """Issue 51 item 5: path constraints were ignored (pymoveit2's orientation path constraint example moved the
    hand as it liked). panda_link8 kept within 0.05 rad of its 'ready' orientation in roll, pitch and yaw, from
    'ready' to a pose 0.5 m away: every point of the plan tilts the hand by at most √2 · 0.05 rad (the
    unconstrained plan tilts it by some 0.18 rad)."""
    from moveit_msgs.msg import OrientationConstraint
    from moveit_msgs.srv import GetPositionFK

    ready = _group_states("panda_arm")["ready"]
    fk = GetPositionFK.Request(fk_link_names=["panda_link8"])
    fk.header.frame_id = "panda_link0"
    fk.robot_state.joint_state.name = list(ready)
    fk.robot_state.joint_state.position = list(ready.values())
    hand = panda.ros.call(GetPositionFK, "/compute_fk", fk).pose_stamped[0].pose
    goal = _position_goal(hand.position.x + 0.1, hand.position.y + 0.4, hand.position.z - 0.3)
    keep = OrientationConstraint(link_name="panda_link8", orientation=hand.orientation, weight=1.0)
    keep.header.frame_id = "panda_link0"
    keep.absolute_x_axis_tolerance = keep.absolute_y_axis_tolerance = keep.absolute_z_axis_tolerance = 0.05
    goal.orientation_constraints = [keep]
    request = _request(ready, goal)
    request.path_constraints.orientation_constraints = [keep]
    response, _ = _plan(panda, request)
    assert response.error_code.val == MoveItErrorCodes.SUCCESS, response.error_code.message
    trajectory = response.trajectory.joint_trajectory
    up = np.array([0.0, 0.0, -1.0])  # 'ready' points panda_link8's z axis down
    assert _tilt(panda, list(ready), list(ready.values()), up) < 1e-3
    points = trajectory.points[:: max(1, len(trajectory.points) // 30)] + [trajectory.points[-1]]
    worst = max(_tilt(panda, list(trajectory.joint_names), p.positions, up) for p in points)
    assert worst <= 0.05 * np.sqrt(2) + 0.005, worst
