"""move_group's kinematics and planning services: compute_fk/ik, check_state_validity,
plan_kinematic_path, compute_cartesian_path, and the goal of a MotionPlanRequest."""

from __future__ import annotations

import time
from typing import Any

import numpy as np
from geometry_msgs.msg import Pose, PoseStamped
from moveit_msgs.msg import (
    ContactInformation,
)
from moveit_msgs.srv import (
    GetCartesianPath,
    GetMotionPlan,
    GetPositionFK,
    GetPositionIK,
    GetStateValidity,
)

from ..planning import MAX_CARTESIAN_STEPS, ArmPlanner, PlanningError, Trajectory, quoted
from ._move_group_base import (
    MAX_FK_LINKS,
    PLANNING_TIME,
    _code,
    _quat,
    _seconds,
)
from ._move_group_scene import _Scene
from ._planning_scene import matrix as _matrix
from ._planning_scene import pose as _pose


class _Planning(_Scene):
    """The kinematics and planning services."""

    # ------------------------------------------------------------------ services
    def _compute_fk(
        self, req: GetPositionFK.Request, res: GetPositionFK.Response, planner: ArmPlanner
    ) -> GetPositionFK.Response:
        """``compute_fk`` (MoveIt's kinematics_service_capability.cpp): each named link's pose at the request's
        robot state (the current state where it gives none), in the request's frame, else the robot's root; at
        most :data:`MAX_FK_LINKS` links a request."""
        if len(req.fk_link_names) > MAX_FK_LINKS:
            raise PlanningError(
                "FAILURE", f"fk_link_names names {len(req.fk_link_names)} links; at most {MAX_FK_LINKS} a request"
            )
        q = self._start_state(req.robot_state, planner)
        base = np.linalg.inv(self._frame(req.header.frame_id, q, planner))
        poses = []
        for link in req.fk_link_names:
            ps = PoseStamped()
            ps.header.frame_id = req.header.frame_id or planner.root_link
            ps.pose = _pose(base @ planner.fk(q, link))
            poses.append(ps)
        res.pose_stamped = poses
        res.fk_link_names = list(req.fk_link_names)
        res.error_code = _code("SUCCESS")
        return res

    def _ik_timeout(self, group: str) -> float:
        """A group's IK time budget: kinematics.yaml's ``kinematics_solver_timeout`` (MoveIt's default for a
        request without a timeout), else 0.5 s."""
        name = f"robot_description_kinematics.{group}.kinematics_solver_timeout"
        if self.has_parameter(name):
            value = self.get_parameter(name).value
            if isinstance(value, (int, float)) and value > 0:
                return float(value)
        return 0.5

    def _compute_ik(
        self, req: GetPositionIK.Request, res: GetPositionIK.Response, planner: ArmPlanner
    ) -> GetPositionIK.Response:
        """``compute_ik`` (kinematics_service_capability.cpp): a joint solution for ``ik_link_name`` (the group's
        tip by default) at the pose, seeded from the request's robot state, within its timeout (kinematics.yaml's
        ``kinematics_solver_timeout`` where it gives none, and at most the planner's ``MAX_IK_SEC``),
        collision-free when ``avoid_collisions``; the full robot state is returned, as MoveIt fills it."""
        ik = req.ik_request
        q = self._start_state(ik.robot_state, planner)
        link = ik.ik_link_name or planner.tip_link(ik.group_name)
        target = self._frame(ik.pose_stamped.header.frame_id, q, planner) @ _matrix(ik.pose_stamped.pose)
        timeout = _seconds(ik.timeout) or self._ik_timeout(ik.group_name)
        solution = planner.ik(ik.group_name, link, target, q, timeout=timeout, avoid_collisions=ik.avoid_collisions)
        res.solution.joint_state.name = list(planner.joint_names)
        res.solution.joint_state.position = [float(v) for v in solution]
        res.error_code = _code("SUCCESS")
        return res

    def _check_state_validity(
        self, req: GetStateValidity.Request, res: GetStateValidity.Response, planner: ArmPlanner
    ) -> Any:
        """``check_state_validity`` (state_validation_service_capability.cpp): valid when within the joint limits
        and free of collisions; the colliding pairs as contacts (their bodies and kinds; gazelle has no contact
        points to give)."""
        q = self._start_state(req.robot_state, planner)
        colliding = planner.in_collision(q)
        res.valid = planner.within_limits(q) and not colliding
        if colliding:  # as MoveIt: the pairs in contact (gazelle knows the bodies, not the points)
            res.contacts = [self._contact(a, b, planner) for a, b in planner.colliding_pairs(q)]
        return res

    def _contact(self, a: str, b: str, planner: ArmPlanner) -> ContactInformation:
        """A ContactInformation for two colliding bodies, typed as MoveIt types them (a robot link, an object
        attached to the robot, a world object)."""
        attached = {o.name for o in planner.objects() if o.link}

        def kind(body: str) -> int:
            if planner.has_link(body):
                return ContactInformation.ROBOT_LINK
            return ContactInformation.ROBOT_ATTACHED if body in attached else ContactInformation.WORLD_OBJECT

        info = ContactInformation(contact_body_1=a, body_type_1=kind(a), contact_body_2=b, body_type_2=kind(b))
        info.header.frame_id = planner.root_link
        return info

    def _plan_kinematic_path(self, req: GetMotionPlan.Request, res: GetMotionPlan.Response, _planner: Any) -> Any:
        """``plan_kinematic_path`` (plan_service_capability.cpp): plan without executing (on the primary planner,
        held by the caller); a failure is the response's error code and message (MoveIt's MoveItErrorCodes),
        never an exception to the client."""
        t0 = time.monotonic()
        try:
            start, traj = self._plan(req.motion_plan_request)
        except PlanningError as err:
            group = req.motion_plan_request.group_name
            self.get_logger().warning(f"plan_kinematic_path for {quoted(group)} failed: {err.code}: {err.message}")
            res.motion_plan_response.error_code = _code(err.code)
            res.motion_plan_response.error_code.message = err.message
            return res
        mpr = res.motion_plan_response
        mpr.group_name = req.motion_plan_request.group_name
        mpr.trajectory_start = self._robot_state(start)
        mpr.trajectory = self._robot_trajectory(traj)
        mpr.planning_time = time.monotonic() - t0
        mpr.error_code = _code("SUCCESS")
        return res

    def _compute_cartesian_path(
        self, req: GetCartesianPath.Request, res: GetCartesianPath.Response, planner: ArmPlanner
    ) -> Any:
        """``compute_cartesian_path`` (cartesian_path_service_capability.cpp): the link's straight-line path
        through the waypoints in ``max_step`` steps, cut where IK fails, a joint jumps (``jump_threshold``) or a
        collision begins; ``fraction`` says how much was achieved, and a partial path still answers SUCCESS, as
        MoveIt does. The planner's bounds refuse more than ``MAX_CARTESIAN_STEPS`` poses (FAILURE, before any IK;
        so are more waypoints, before they are converted) and IK past ``CARTESIAN_TIMEOUT_SEC`` (TIMED_OUT)."""
        if len(req.waypoints) > MAX_CARTESIAN_STEPS:
            raise PlanningError(
                "FAILURE",
                f"{len(req.waypoints)} waypoints; a Cartesian path solves at most {MAX_CARTESIAN_STEPS} poses",
            )
        q = self._start_state(req.start_state, planner)
        link = req.link_name or planner.tip_link(req.group_name)
        frame = self._frame(req.header.frame_id, q, planner)
        traj, fraction = planner.cartesian_path(
            req.group_name,
            link,
            [frame @ _matrix(p) for p in req.waypoints],
            q,
            max_step=req.max_step,
            jump_threshold=req.jump_threshold,
            avoid_collisions=req.avoid_collisions,
            velocity_scaling=req.max_velocity_scaling_factor,
            acceleration_scaling=req.max_acceleration_scaling_factor,
        )
        res.start_state = self._robot_state(q)
        res.fraction = float(fraction)
        if traj is not None:
            res.solution = self._robot_trajectory(traj)
        res.error_code = _code("SUCCESS")  # as MoveIt: a partial path succeeds with its fraction
        return res

    # ------------------------------------------------------------------ planning
    def _plan(self, request: Any) -> tuple[np.ndarray, Trajectory]:
        """A MotionPlanRequest's start state and timed trajectory (raises PlanningError)."""
        planner = self.planner
        assert planner is not None
        group = request.group_name
        joints = planner.group_joints(group)
        start = self._start_state(request.start_state)
        if not request.goal_constraints:
            raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the request has no goal_constraints")
        goal = self._goal(group, joints, request.goal_constraints[0], start)
        self._note_unhonoured(request)
        asked = request.allowed_planning_time
        timeout = asked if asked > 0.0 else PLANNING_TIME  # NaN too; the planner cuts a long one to its bound
        traj = planner.plan(
            group,
            goal,
            start,
            velocity_scaling=request.max_velocity_scaling_factor,
            acceleration_scaling=request.max_acceleration_scaling_factor,
            timeout=timeout,
        )
        return start, traj

    def _note_unhonoured(self, request: Any) -> None:
        """Say what of a MotionPlanRequest gazelle's planner does not honour, once per kind (the request
        is planned all the same, as MoveIt plans with what it has)."""
        notes: list[tuple[str, str]] = []  # (kind, what is said the first time that kind comes)
        if request.pipeline_id and request.pipeline_id != "ompl":
            notes.append(("pipeline", f"pipeline_id {quoted(request.pipeline_id)} is not simulated"))
        if request.planner_id and "rrtconnect" not in request.planner_id.lower():
            notes.append(("planner", f"planner_id {quoted(request.planner_id)} is not simulated"))
        path = request.path_constraints
        if path.joint_constraints or path.position_constraints or path.orientation_constraints:
            notes.append(
                ("path", "path_constraints are not honoured: the path between the start and the goal ignores them")
            )
        if path.visibility_constraints or request.trajectory_constraints.constraints:
            notes.append(("trajectory", "visibility and trajectory constraints are not honoured"))
        if len(request.goal_constraints) > 1:
            notes.append(("goals", f"only the first of {len(request.goal_constraints)} goal_constraints is planned to"))
        for kind, note in notes:  # once per kind: what a client sends never grows this set or floods the log
            if kind not in self._noted:
                self._noted.add(kind)
                self.get_logger().warning(f"motion plan request: {note}; gazelle plans with RRT-Connect")

    def _goal(self, group: str, joints: list[str], constraints: Any, start: np.ndarray) -> np.ndarray:
        """The goal configuration of one Constraints message: joint constraints, or a pose goal."""
        planner = self.planner
        assert planner is not None
        if constraints.joint_constraints:
            values = {}
            for jc in constraints.joint_constraints:
                if jc.joint_name not in planner.joint_names:
                    raise PlanningError(
                        "INVALID_GOAL_CONSTRAINTS", f"unknown joint {quoted(jc.joint_name)} in the goal"
                    )
                values[jc.joint_name] = jc.position
            missing = [j for j in joints if j not in values]
            if missing and len(missing) == len(joints):
                raise PlanningError("INVALID_GOAL_CONSTRAINTS", f"the goal names none of group '{group}'s joints")
            return planner.state({**planner.positions(start), **values})
        if constraints.position_constraints:
            pc = constraints.position_constraints[0]
            link = pc.link_name or planner.tip_link(group)
            region = pc.constraint_region
            if not region.primitive_poses:
                raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the position constraint has no primitive pose")
            frame = self._frame(pc.header.frame_id, start)
            target = frame @ _matrix(region.primitive_poses[0])
            offset = pc.target_point_offset
            if constraints.orientation_constraints:
                oc = constraints.orientation_constraints[0]
                rotation = self._frame(oc.header.frame_id, start) @ _matrix(Pose(orientation=oc.orientation))
                target[:3, :3] = rotation[:3, :3]
                target[:3, 3] -= target[:3, :3] @ np.array([offset.x, offset.y, offset.z])
                return planner.ik(group, link, target, start)
            return self._position_only(group, link, target[:3, 3], start)
        if constraints.orientation_constraints:
            raise PlanningError(
                "INVALID_GOAL_CONSTRAINTS", "an orientation constraint alone is not a goal gazelle can plan to"
            )
        raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the goal has no joint, position or orientation constraint")

    def _position_only(self, group: str, link: str, position: np.ndarray, start: np.ndarray) -> np.ndarray:
        """A position goal: the link's current orientation first, then others, until IK finds one."""
        planner = self.planner
        assert planner is not None
        current = planner.fk(start, link)
        rng = np.random.default_rng(0)
        rotations = [current[:3, :3]]
        for _ in range(20):
            q = rng.normal(size=4)
            q /= np.linalg.norm(q)
            rotations.append(_matrix(Pose(orientation=_quat(q)))[:3, :3])
        for rotation in rotations:
            target = np.eye(4)
            target[:3, :3], target[:3, 3] = rotation, position
            try:
                return planner.ik(group, link, target, start, timeout=0.1)
            except PlanningError:
                continue
        raise PlanningError("NO_IK_SOLUTION", f"no joint values of '{group}' put '{link}' at the goal position")
