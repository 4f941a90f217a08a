"""``move_group``: MoveIt's ROS interfaces served by :class:`gazelle.planning.ArmPlanner`.

A plain rclpy node named ``move_group``, as MoveIt's. It reads ``robot_description`` and
``robot_description_semantic`` (parameters, as MoveIt's launch files pass them, else the latched
topics of the same names), ``robot_description_planning`` (joint_limits.yaml) and
``moveit_simple_controller_manager`` (moveit_controllers.yaml). It serves:

- the ``/move_action`` (MoveGroup) and ``/execute_trajectory`` (ExecuteTrajectory) actions;
- ``/compute_fk``, ``/compute_ik``, ``/plan_kinematic_path`` and ``/check_state_validity``.

Trajectories are executed by the arm's ``FollowJointTrajectory`` controller that
moveit_controllers.yaml names (the simulated joint_trajectory_controller).
"""

from __future__ import annotations

import logging
import math
import os
import re
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import rclpy
from action_msgs.msg import GoalStatus
from builtin_interfaces.msg import Duration as DurationMsg
from control_msgs.action import FollowJointTrajectory
from geometry_msgs.msg import Pose, PoseStamped
from moveit_msgs.action import ExecuteTrajectory, MoveGroup
from moveit_msgs.msg import (
    AttachedCollisionObject,
    CollisionObject,
    ContactInformation,
    DisplayTrajectory,
    MoveItErrorCodes,
    PlanningScene,
    PlanningSceneWorld,
    RobotState,
    RobotTrajectory,
)
from moveit_msgs.srv import (
    ApplyPlanningScene,
    GetCartesianPath,
    GetMotionPlan,
    GetPlanningScene,
    GetPositionFK,
    GetPositionIK,
    GetStateValidity,
)
from rclpy._rclpy_pybind11 import RCLError
from rclpy.action.client import ActionClient
from rclpy.action.server import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, ShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.utilities import try_shutdown
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64, String
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ..description import read_description_file
from ..planning import START_BOUNDS_ERROR, ArmPlanner, PlanningError, SceneObject, Trajectory, moveit_joint_limits
from ._dds import announce_often
from ._planning_scene import attached_message, checked_matrix, padded, shapes_of, to_message
from ._planning_scene import matrix as _matrix
from ._planning_scene import pose as _pose
from ._replies import serve

_log = logging.getLogger("gazelle.move_group")

OBJECT_PADDING_PARAMETER = "robot_description_planning.default_object_padding"
"""MoveIt's parameter (m) by which world objects are grown for collision checking; 0 by default, as MoveIt's
planning_scene_monitor.cpp (configureDefaultPadding). Here it grows the simulation's objects (what
``gazelle sim`` publishes); objects a client applies are kept as given, as ``get_planning_scene`` reports
them. The simulated robot collides with the convex hulls of its meshes, a little fatter than the meshes
the planner checks: a plan that grazes an object may touch it in the simulation (an arm planned 5 mm past
a pillar brushed it); 0.01 keeps a centimetre."""
TWIN_CHECK_SEC = 2.0
"""s after start when move_group looks for another of its name on the domain (discovery has run)."""
SHUTDOWN_DEADLINE_SEC = 3.0
"""s after SIGINT/SIGTERM by which move_group has ended, however busy (its watchdog process kills it)."""
CURRENT_STATE_WAIT = 5.0
"""s a request waits for the first /joint_states (MoveIt's planning-scene monitor waits 1 s)."""
CONTROLLER_WAIT = 5.0
"""s an execution waits for its controller's action server, or its joints' gz command topics, to be
discovered."""
_ENDED = (GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED)
STREAM_RATE_HZ = 100.0
"""Set-points a second streamed to gz JointPositionController topics (wall time)."""
STREAM_GOAL_TOLERANCE = 0.01
"""rad (m): how near each joint must come to the trajectory's end for a streamed execution to succeed."""
GZ_CMD_POS = re.compile(r"/joint/(?P<joint>[^/]+)/n?\d+/cmd_pos$")
"""gz-sim JointPositionController's default command topic, ``/model/<model>/joint/<joint>/<index>/cmd_pos``
(on ROS ``.../n0/cmd_pos``: see ``gazelle.ros._names``)."""
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
MAX_SCENE_OBJECTS = 256
"""The most collision objects one planning-scene request may carry, and a scene may hold besides the
simulation's own. Adding one costs time in all the others (roboplan rebuilds its collision pairs): 200
take ~2 s; 3,000 in one request kept move_group deaf for over 15 minutes."""


def _code(name: str) -> MoveItErrorCodes:
    return MoveItErrorCodes(val=getattr(MoveItErrorCodes, name, MoveItErrorCodes.FAILURE))


def _same_shapes(a: tuple[Any, ...], b: tuple[Any, ...]) -> bool:
    return len(a) == len(b) and all(
        x.kind == y.kind and x.dimensions == y.dimensions and np.allclose(x.pose, y.pose) for x, y in zip(a, b)
    )


def _failed(response: Any, code: str, message: str) -> Any:
    """A service response that says why it failed: its error_code (GetMotionPlan's is in its
    motion_plan_response: an internal error there answered code 0 with no message), or ``success``."""
    if hasattr(response, "motion_plan_response"):
        response.motion_plan_response.error_code = _code(code)
        response.motion_plan_response.error_code.message = message
    elif hasattr(response, "error_code"):
        response.error_code = _code(code)
        response.error_code.message = message
    elif hasattr(response, "success"):
        response.success = False
    return response


def _duration(t: float) -> DurationMsg:
    sec = math.floor(t)
    return DurationMsg(sec=int(sec), nanosec=int(round((t - sec) * 1e9)) % 1_000_000_000)


def _seconds(d: DurationMsg) -> float:
    return d.sec + d.nanosec * 1e-9


@dataclass(frozen=True)
class Controller:
    """A FollowJointTrajectory controller from moveit_controllers.yaml."""

    name: str
    action: str
    joints: tuple[str, ...]


class MoveGroupNode(Node):
    """MoveIt's move_group interfaces for one robot."""

    def __init__(
        self, *, srdf_source: str = "robot_description_semantic", resolve_mesh: Any = None, **kwargs: Any
    ) -> None:
        self._srdf_source = srdf_source  # what SRDF warnings name: the file, when one was given
        self._resolve_mesh = resolve_mesh  # how mesh URIs are found (None: the resource roots)
        super().__init__("move_group", automatically_declare_parameters_from_overrides=True, **kwargs)
        self._lock = threading.Lock()  # one planning request at a time
        self._ready = threading.Event()
        self.planner: ArmPlanner | None = None
        self._latest_joints: dict[str, float] = {}
        self._warned_no_state = False  # from /joint_states; the planner takes it when it plans
        self._noted: set[str] = set()  # the kinds of request parts gazelle does not honour, each said once
        self._texts: dict[str, str] = {}
        self._sim_objects: set[str] = set()  # ids of the objects that came from the simulation
        self._sim_world: Any = None  # the simulation's geometry heard before the robot was known
        self.object_padding = self._object_padding()
        cb = ReentrantCallbackGroup()
        self._cb = cb
        self.create_subscription(JointState, "joint_states", self._on_joint_states, 10, callback_group=cb)
        urdf = self._param("robot_description")
        srdf = self._param("robot_description_semantic")
        if urdf and srdf:
            self._build(urdf, srdf)
        else:
            # as MoveIt's nodes do when the parameters are not given: the latched topics
            for topic in ("robot_description", "robot_description_semantic"):
                self.create_subscription(
                    String,
                    topic,
                    lambda msg, t=topic: self._on_text(t, str(getattr(msg, "data", ""))),
                    LATCHED,
                    callback_group=cb,
                )
            if urdf:
                self._texts["robot_description"] = urdf
            if srdf:
                self._texts["robot_description_semantic"] = srdf
        for srv_type, name, fn in (
            (GetPositionFK, "compute_fk", self._compute_fk),
            (GetPositionIK, "compute_ik", self._compute_ik),
            (GetMotionPlan, "plan_kinematic_path", self._plan_kinematic_path),
            (GetStateValidity, "check_state_validity", self._check_state_validity),
            (GetCartesianPath, "compute_cartesian_path", self._compute_cartesian_path),
            (GetPlanningScene, "get_planning_scene", self._get_planning_scene),
            (ApplyPlanningScene, "apply_planning_scene", self._apply_planning_scene),
        ):
            serve(self, srv_type, name, self._guard(name, fn), cb)
        for msg_type, topic, fn in (
            (PlanningScene, "planning_scene", self._on_scene_diff),
            (CollisionObject, "collision_object", self._on_collision_object),
            (AttachedCollisionObject, "attached_collision_object", self._on_attached_object),
        ):
            self.create_subscription(msg_type, topic, self._scene_topic(topic, fn), 10, callback_group=cb)
        # the simulation's world (gazelle sim publishes its collision geometry): the table, the board,
        # the other robots; this robot itself is left out
        self.create_subscription(
            PlanningSceneWorld, "/gazelle/planning_scene_world", self._on_sim_world, LATCHED, callback_group=cb
        )
        self._display = self.create_publisher(DisplayTrajectory, "display_planned_path", 10)
        # a second move_group on the domain answers every request too: said once, after discovery
        self._twin_check = self.create_timer(TWIN_CHECK_SEC, self._warn_of_twins, callback_group=cb)
        self._move = ActionServer(
            self,
            MoveGroup,
            "move_action",
            execute_callback=self._execute_move_group,
            goal_callback=lambda _g: GoalResponse.ACCEPT,
            cancel_callback=lambda _g: CancelResponse.ACCEPT,
            callback_group=cb,
        )
        self._execute = ActionServer(
            self,
            ExecuteTrajectory,
            "execute_trajectory",
            execute_callback=self._execute_trajectory,
            goal_callback=lambda _g: GoalResponse.ACCEPT,
            cancel_callback=lambda _g: CancelResponse.ACCEPT,
            callback_group=cb,
        )
        self._controllers = self._read_controllers()
        self._trajectory_clients: dict[str, ActionClient] = {}
        self._position_pubs: dict[str, Any] = {}  # gz JointPositionController command topics
        self._controller_lists: dict[str, Any] = {}  # list_controllers clients by service name
        # The controllers' FollowJointTrajectory clients live on their own node and single-threaded
        # executor: on the node's multi-threaded one, busy with /joint_states, their status and result
        # messages came seconds late or not at all (rclpy's executor is slow and its action client
        # racy across threads: ros2/rclpy#1123).
        self._execution_node = rclpy.create_node("move_group_trajectory_execution", context=self.context)
        self._execution_executor = SingleThreadedExecutor(context=self.context)
        self._execution_executor.add_node(self._execution_node)
        self._execution_thread = threading.Thread(target=self._spin_execution, name="move_group execution", daemon=True)
        self._execution_thread.start()

    def _on_execution_thread(self, fn: Any, timeout: float = 10.0) -> Any:
        """``fn()`` run on the thread that spins the execution node, which is where that node's clients and
        publishers are made. Made from an action's worker thread while that executor waited on the node's
        entities, rcl aborted the process: YuMi's move_group died on execute_trajectory ("double free or
        corruption", "Fatal Python error: Aborted" in ``create_client`` under ``PYTHONMALLOC=debug``)."""
        if threading.current_thread() is self._execution_thread:
            return fn()
        done = threading.Event()
        box: dict[str, Any] = {}

        def task() -> None:
            try:
                box["value"] = fn()
            except BaseException as err:  # handed to the caller
                box["error"] = err
            finally:
                done.set()

        self._execution_executor.create_task(task)
        if not done.wait(timeout):
            raise TimeoutError("the execution thread did not run the task")
        if "error" in box:
            raise box["error"]
        return box.get("value")

    def _spin_execution(self) -> None:
        try:
            self._execution_executor.spin()
        except (ExternalShutdownException, ShutdownException):
            pass

    def destroy_node(self) -> None:
        """Destroy the action servers and clients first: one left alive holds its node's handle, and the
        node would stay in the graph with that action's endpoints alone."""
        self._execution_executor.shutdown()
        for client in self._trajectory_clients.values():
            client.destroy()
        self._execution_node.destroy_node()
        self._move.destroy()
        self._execute.destroy()
        super().destroy_node()

    # ------------------------------------------------------------------ set-up
    def _warn_of_twins(self) -> None:
        self._twin_check.cancel()
        me = (self.get_name(), self.get_namespace())
        twins = sum(1 for named in self.get_node_names_and_namespaces() if named == me)
        if twins > 1:
            self.get_logger().warning(
                f"another {self.get_fully_qualified_name()} is running on ROS_DOMAIN_ID "
                f"{os.environ.get('ROS_DOMAIN_ID', '0')}: both answer every planning request and action "
                "(stop one, or run them in other domains or namespaces)"
            )

    def _object_padding(self) -> float:
        """:data:`OBJECT_PADDING_PARAMETER`, 0 when absent; a value that is no finite non-negative number is
        named in a warning and taken as 0."""
        if not self.has_parameter(OBJECT_PADDING_PARAMETER):
            return 0.0
        value = self.get_parameter(OBJECT_PADDING_PARAMETER).value
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
            self._warn(f"{OBJECT_PADDING_PARAMETER} must be a non-negative number of metres, got {value!r}: using 0")
            return 0.0
        if value:
            _log.info(f"world objects are padded by {value:g} m for collision checking ({OBJECT_PADDING_PARAMETER})")
        return float(value)

    def _param(self, name: str) -> str:
        if not self.has_parameter(name):
            return ""
        value = self.get_parameter(name).value
        return value if isinstance(value, str) else ""

    def _on_text(self, topic: str, text: str) -> None:
        if self.planner is not None:
            return
        self._texts[topic] = text
        if "robot_description" in self._texts and "robot_description_semantic" in self._texts:
            self._build(self._texts["robot_description"], self._texts["robot_description_semantic"])

    def _build(self, urdf: str, srdf: str) -> None:
        limits = {}
        prefix = "robot_description_planning.joint_limits."
        grouped: dict[str, dict[str, Any]] = {}
        for name, param in self._parameters.items():
            if name.startswith(prefix):
                joint, _, key = name[len(prefix) :].rpartition(".")
                grouped.setdefault(joint, {})[key] = param.value
        if grouped:
            limits = moveit_joint_limits({"joint_limits": grouped})
        try:
            planner = ArmPlanner(
                urdf, srdf, joint_limits=limits, srdf_source=self._srdf_source, resolve_mesh=self._resolve_mesh
            )
        except PlanningError as err:
            self.get_logger().error(f"cannot plan for this robot: {err.message}")
            return
        except Exception as err:  # a URDF roboplan cannot model: say so once and keep serving errors
            self.get_logger().error(f"cannot plan for this robot: {type(err).__name__}: {err}")
            return
        for warning in planner.warnings:
            self.get_logger().warning(warning)
        solvers = "robot_description_kinematics."
        for name, param in sorted(self._parameters.items()):
            if name.startswith(solvers) and name.endswith(".kinematics_solver"):
                group = name[len(solvers) : -len(".kinematics_solver")]
                self.get_logger().warning(
                    f"kinematics.yaml: {group}'s kinematics_solver {param.value} is MoveIt's plugin and is not "
                    f"loaded; gazelle's IK (roboplan) solves, within kinematics_solver_timeout "
                    f"({self._ik_timeout(group):g} s) when a request gives no timeout"
                )
        pipeline = sorted(n for n in self._parameters if n.split(".", 1)[0] in PIPELINE_PARAMETERS)
        if pipeline:
            shown = ", ".join(pipeline[:3]) + (f" and {len(pipeline) - 3} more" if len(pipeline) > 3 else "")
            self.get_logger().warning(
                f"MoveIt's planning pipeline settings are not used ({shown}: ompl_planning.yaml's planner "
                "configurations and adapters): gazelle plans every request with roboplan's RRT-Connect, "
                "shortcutting and TOPP-RA time parameterization within the joint limits"
            )
        self.planner = planner
        if self._sim_world is not None:
            with self._lock:
                self._take_sim_world(self._sim_world)
        self._ready.set()
        self.get_logger().info(
            f"You can start planning now! (groups: {', '.join(planner.groups)}; planning frame {planner.root_link})"
        )

    def _read_controllers(self) -> list[Controller]:
        prefix = "moveit_simple_controller_manager."
        names = (
            self.get_parameter(prefix + "controller_names").value
            if self.has_parameter(prefix + "controller_names")
            else []
        )
        out = []
        for name in names or []:
            ns = self._param(f"{prefix}{name}.action_ns") or "follow_joint_trajectory"
            joints = (
                self.get_parameter(f"{prefix}{name}.joints").value
                if self.has_parameter(f"{prefix}{name}.joints")
                else []
            )
            out.append(Controller(name, f"/{name}/{ns}".replace("//", "/"), tuple(joints or ())))
        return out

    def _on_joint_states(self, msg: JointState) -> None:
        if self.planner is None or not msg.name:
            return
        # no lock and no planner work here: at 100 Hz that starved planning of the GIL and the lock
        self._latest_joints = {**self._latest_joints, **dict(zip(msg.name, msg.position))}

    # ------------------------------------------------------------------ plumbing
    def _guard(self, name: str, fn: Any) -> Any:
        def wrapper(request: Any, response: Any) -> Any:
            if self.planner is None:
                return _failed(
                    response,
                    "FAILURE",
                    "move_group has no robot yet (robot_description and robot_description_semantic)",
                )
            try:
                with self._lock:
                    return fn(request, response)
            except PlanningError as err:
                self.get_logger().warning(f"{name}: {err.code}: {err.message}")
                return _failed(response, err.code, err.message)
            except Exception as err:
                self.get_logger().error(f"{name}: {type(err).__name__}: {err}")
                return _failed(response, "FAILURE", f"{name}: internal error: {type(err).__name__}: {err}")

        return wrapper

    def _start_state(self, state: RobotState) -> np.ndarray:
        """The request's start state: the current one with what the request gives put in."""
        assert self.planner is not None
        deadline = time.monotonic() + CURRENT_STATE_WAIT
        while not self._latest_joints and time.monotonic() < deadline:
            time.sleep(0.01)  # as MoveIt waits for a current state (the callback takes no lock)
        if self._latest_joints:
            self.planner.set_current(self._latest_joints)
        elif not self._warned_no_state:
            self._warned_no_state = True
            self.get_logger().warning(
                f"no /joint_states within {CURRENT_STATE_WAIT:g} s: planning from the model's zero positions"
            )
        js = state.joint_state
        # a start state read from /joint_states may be a hair past a limit: moved onto it, as the current
        # state is (MoveIt's start_state_max_bounds_error, 0.05)
        return self.planner.onto_limits(self.planner.state(dict(zip(js.name, js.position)) if js.name else None))

    def _frame(self, frame: str, q: np.ndarray) -> np.ndarray:
        """The pose of ``frame`` in the planning frame: the root link, the SRDF's virtual joint parent
        (a fixed virtual joint is the identity, as in MoveIt) or another link of the robot."""
        assert self.planner is not None
        virtual = {v.parent_frame for v in self.planner.semantics.virtual_joints if v.type == "fixed"}
        if not frame or frame == self.planner.root_link or frame in virtual:
            return np.eye(4)
        try:
            return self.planner.fk(q, frame)
        except PlanningError:
            raise PlanningError("FRAME_TRANSFORM_FAILURE", f"unknown frame '{frame}'") from None

    # ------------------------------------------------------------------ services
    def _compute_fk(self, req: GetPositionFK.Request, res: GetPositionFK.Response) -> GetPositionFK.Response:
        assert self.planner is not None
        q = self._start_state(req.robot_state)
        base = np.linalg.inv(self._frame(req.header.frame_id, q))
        poses = []
        for link in req.fk_link_names:
            ps = PoseStamped()
            ps.header.frame_id = req.header.frame_id or self.planner.root_link
            ps.pose = _pose(base @ self.planner.fk(q, link))
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

    def _compute_ik(self, req: GetPositionIK.Request, res: GetPositionIK.Response) -> GetPositionIK.Response:
        assert self.planner is not None
        ik = req.ik_request
        q = self._start_state(ik.robot_state)
        link = ik.ik_link_name or self.planner.tip_link(ik.group_name)
        target = self._frame(ik.pose_stamped.header.frame_id, q) @ _matrix(ik.pose_stamped.pose)
        timeout = _seconds(ik.timeout) or self._ik_timeout(ik.group_name)
        solution = self.planner.ik(
            ik.group_name, link, target, q, timeout=timeout, avoid_collisions=ik.avoid_collisions
        )
        res.solution.joint_state.name = list(self.planner.joint_names)
        res.solution.joint_state.position = [float(v) for v in solution]
        res.error_code = _code("SUCCESS")
        return res

    def _check_state_validity(self, req: GetStateValidity.Request, res: GetStateValidity.Response) -> Any:
        assert self.planner is not None
        q = self._start_state(req.robot_state)
        colliding = self.planner.in_collision(q)
        res.valid = self.planner.within_limits(q) and not colliding
        if colliding:  # as MoveIt: the pairs in contact (gazelle knows the bodies, not the points)
            res.contacts = [self._contact(a, b) for a, b in self.planner.colliding_pairs(q)]
        return res

    def _contact(self, a: str, b: str) -> ContactInformation:
        planner = self.planner
        assert planner is not None
        attached = {o.name for o in planner.objects() if o.link}

        def kind(body: str) -> int:
            if planner.has_link(body):
                return ContactInformation.ROBOT_LINK
            return ContactInformation.ROBOT_ATTACHED if body in attached else ContactInformation.WORLD_OBJECT

        info = ContactInformation(contact_body_1=a, body_type_1=kind(a), contact_body_2=b, body_type_2=kind(b))
        info.header.frame_id = planner.root_link
        return info

    def _plan_kinematic_path(self, req: GetMotionPlan.Request, res: GetMotionPlan.Response) -> Any:
        t0 = time.monotonic()
        try:
            start, traj = self._plan(req.motion_plan_request)
        except PlanningError as err:
            group = req.motion_plan_request.group_name
            self.get_logger().warning(f"plan_kinematic_path for '{group}' failed: {err.code}: {err.message}")
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

    def _compute_cartesian_path(self, req: GetCartesianPath.Request, res: GetCartesianPath.Response) -> Any:
        planner = self.planner
        assert planner is not None
        q = self._start_state(req.start_state)
        link = req.link_name or planner.tip_link(req.group_name)
        frame = self._frame(req.header.frame_id, q)
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

    # ------------------------------------------------------------------ planning scene
    def _get_planning_scene(self, req: GetPlanningScene.Request, res: GetPlanningScene.Response) -> Any:
        planner = self.planner
        assert planner is not None
        scene = res.scene
        scene.name = "gazelle"
        scene.robot_model_name = planner.semantics.robot_name
        scene.robot_state = self._robot_state(planner.state(self._latest_joints or None))
        objects = planner.objects()
        scene.robot_state.attached_collision_objects = [attached_message(o) for o in objects if o.link]
        scene.world.collision_objects = [to_message(o, planner.root_link) for o in objects if not o.link]
        scene.is_diff = False
        return res

    def _apply_planning_scene(self, req: ApplyPlanningScene.Request, res: ApplyPlanningScene.Response) -> Any:
        self._apply_scene(req.scene)
        res.success = True
        return res

    def _scene_topic(self, topic: str, fn: Any) -> Any:
        """A planning-scene topic's callback: under the planning lock, a bad message logged, not raised."""

        def callback(msg: Any) -> None:
            if self.planner is None:
                return
            try:
                with self._lock:
                    fn(msg)
            except PlanningError as err:
                self.get_logger().warning(f"/{topic}: {err.code}: {err.message}")

        return callback

    def _on_scene_diff(self, msg: PlanningScene) -> None:
        self._apply_scene(msg)

    def _on_collision_object(self, msg: CollisionObject) -> None:
        self._apply_world_object(msg)

    def _on_attached_object(self, msg: AttachedCollisionObject) -> None:
        self._apply_attached(msg)

    def _on_sim_world(self, msg: PlanningSceneWorld) -> None:
        """The simulation's collision geometry: every entity link but this robot's, in the planning frame."""
        if self.planner is None:
            self._sim_world = msg  # taken when the robot is known
            return
        with self._lock:
            self._take_sim_world(msg)

    def _take_sim_world(self, msg: PlanningSceneWorld) -> None:
        planner = self.planner
        assert planner is not None
        by_entity: dict[str, list[CollisionObject]] = {}
        for co in msg.collision_objects:
            entity, _, link = co.id.rpartition("::")
            by_entity.setdefault(entity, []).append(co)
        ours = {
            entity
            for entity, objects in by_entity.items()
            if all(planner.has_link(co.id.rpartition("::")[2]) for co in objects)
        }
        root_in_world = self._root_in_world([co for e in ours for co in by_entity[e]])
        world_to_root = np.linalg.inv(root_in_world)
        names = set()
        for entity, objects in by_entity.items():
            if entity in ours:
                continue
            for co in objects:
                at = world_to_root @ _matrix(co.pose)
                names.add(co.id)
                existing = self._find(co.id)
                if existing is not None and existing.link:
                    continue  # attached to the robot (a grasp): MoveIt's scene moves it with its link, not from here
                pad = self.object_padding
                shapes = tuple(padded(sh, pad) if pad else sh for sh in shapes_of(co, self._warn))
                if not shapes:
                    continue
                if existing is not None and not existing.link and _same_shapes(existing.shapes, shapes):
                    planner.move_object(co.id, at)
                else:
                    planner.add_object(SceneObject(co.id, shapes, at))
        for stale in self._sim_objects - names:
            obj = self._find(stale)
            if obj is not None and not obj.link:
                planner.remove_object(stale)
        self._sim_objects = names

    def _root_in_world(self, robot_links: list[CollisionObject]) -> np.ndarray:
        """Where the planning frame (the robot's root link) is in the simulation's world: from a link of
        this robot the simulation reports and the current joint values; the identity if none."""
        planner = self.planner
        assert planner is not None
        q = planner.state(self._latest_joints or None)
        for co in sorted(robot_links, key=lambda c: c.id.rpartition("::")[2] != planner.root_link):
            link = co.id.rpartition("::")[2]
            return _matrix(co.pose) @ np.linalg.inv(planner.fk(q, link))
        return np.eye(4)

    def _apply_scene(self, scene: PlanningScene) -> None:
        planner = self.planner
        assert planner is not None
        given = len(scene.world.collision_objects) + len(scene.robot_state.attached_collision_objects)
        if given > MAX_SCENE_OBJECTS:
            raise PlanningError(
                "FAILURE", f"the scene has {given} collision objects; at most {MAX_SCENE_OBJECTS} are planned with"
            )
        # every object is checked before any is applied: a bad one refuses the request, the scene unchanged
        for co in [
            *scene.world.collision_objects,
            *(aco.object for aco in scene.robot_state.attached_collision_objects),
        ]:
            if co.operation != CollisionObject.REMOVE:
                checked_matrix(co.pose, f"collision object '{co.id[:80]}'")
                shapes_of(co, lambda _text: None)
        if not scene.is_diff:  # a whole scene replaces the objects there are
            for obj in planner.objects():
                planner.remove_object(obj.name)
        for co in scene.world.collision_objects:
            self._apply_world_object(co)
        for aco in scene.robot_state.attached_collision_objects:
            self._apply_attached(aco)

    def _warn(self, text: str) -> None:
        self.get_logger().warning(text)

    def _find(self, name: str) -> SceneObject | None:
        assert self.planner is not None
        return next((o for o in self.planner.objects() if o.name == name), None)

    def _apply_world_object(self, co: CollisionObject) -> None:
        """A CollisionObject's ADD, REMOVE, APPEND or MOVE on the world's objects."""
        planner = self.planner
        assert planner is not None
        existing = self._find(co.id) if co.id else None
        if existing is not None and existing.link:
            existing = None  # an attached object of that name is changed through attached_collision_object
        if co.operation == CollisionObject.REMOVE:
            targets = [existing] if co.id else [o for o in planner.objects() if not o.link]
            for obj in targets:
                if obj is not None:
                    planner.remove_object(obj.name)
            return
        if not co.id:
            raise PlanningError("INVALID_OBJECT_NAME", "a collision object needs an id")
        if existing is None and co.operation == CollisionObject.ADD:
            mine = [o for o in planner.objects() if not o.link and o.name not in self._sim_objects]
            if len(mine) >= MAX_SCENE_OBJECTS:
                raise PlanningError(
                    "FAILURE", f"the scene holds {len(mine)} collision objects already; at most {MAX_SCENE_OBJECTS}"
                )
        pose = checked_matrix(co.pose, f"collision object '{co.id[:80]}'")
        at = self._frame(co.header.frame_id, planner.state(self._latest_joints or None)) @ pose
        if co.operation == CollisionObject.MOVE:
            if existing is None:
                raise PlanningError("INVALID_OBJECT_NAME", f"no collision object '{co.id}' to move")
            planner.add_object(SceneObject(co.id, existing.shapes, at))
            return
        shapes = tuple(shapes_of(co, self._warn))
        if co.operation == CollisionObject.APPEND and existing is not None:
            relative = np.linalg.inv(existing.pose) @ at
            shapes = existing.shapes + tuple(type(sh)(sh.kind, sh.dimensions, relative @ sh.pose) for sh in shapes)
            at = existing.pose
        if not shapes:
            raise PlanningError("INVALID_OBJECT_NAME", f"collision object '{co.id}' has no shape gazelle plans with")
        planner.add_object(SceneObject(co.id, shapes, at))

    def _apply_attached(self, aco: AttachedCollisionObject) -> None:
        """Attach an object to a link (a world object of that id, or the message's shapes) or detach it
        back into the world where it is now."""
        planner = self.planner
        assert planner is not None
        co = aco.object
        q = planner.state(self._latest_joints or None)
        if co.operation == CollisionObject.REMOVE:
            attached = [o for o in planner.objects() if o.link and (o.name == co.id or not co.id)]
            attached = [o for o in attached if not aco.link_name or o.link == aco.link_name]
            for obj in attached:
                world = planner.fk(q, obj.link) @ obj.pose
                planner.add_object(SceneObject(obj.name, obj.shapes, world))
            return
        if not aco.link_name:
            raise PlanningError("INVALID_LINK_NAME", f"attached object '{co.id}' names no link")
        link_pose = planner.fk(q, aco.link_name)
        existing = self._find(co.id)
        if existing is not None and not co.primitives and not co.meshes:
            world = existing.pose if not existing.link else planner.fk(q, existing.link) @ existing.pose
            shapes, at = existing.shapes, np.linalg.inv(link_pose) @ world
        else:
            shapes = tuple(shapes_of(co, self._warn))
            if not shapes:
                raise PlanningError("INVALID_OBJECT_NAME", f"attached object '{co.id}' has no shape gazelle plans with")
            frame = self._frame(co.header.frame_id or aco.link_name, q)
            at = np.linalg.inv(link_pose) @ frame @ checked_matrix(co.pose, f"attached object '{co.id[:80]}'")
        planner.add_object(SceneObject(co.id, shapes, at, aco.link_name, tuple(aco.touch_links)))

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
        timeout = request.allowed_planning_time or 5.0
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
            notes.append(("pipeline", f"pipeline_id '{request.pipeline_id}' is not simulated"))
        if request.planner_id and "rrtconnect" not in request.planner_id.lower():
            notes.append(("planner", f"planner_id '{request.planner_id}' is not simulated"))
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
                    raise PlanningError("INVALID_GOAL_CONSTRAINTS", f"unknown joint '{jc.joint_name}' in the goal")
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

    # ------------------------------------------------------------------ messages
    def _robot_state(self, q: np.ndarray) -> RobotState:
        assert self.planner is not None
        state = RobotState()
        state.joint_state.name = list(self.planner.joint_names)
        state.joint_state.position = [float(v) for v in q]
        return state

    def _robot_trajectory(self, traj: Trajectory) -> RobotTrajectory:
        out = RobotTrajectory()
        jt = out.joint_trajectory
        jt.header.frame_id = self.planner.root_link if self.planner else ""
        jt.joint_names = list(traj.joint_names)
        jt.points = [
            JointTrajectoryPoint(
                positions=[float(v) for v in traj.positions[i]],
                velocities=[float(v) for v in traj.velocities[i]],
                accelerations=[float(v) for v in traj.accelerations[i]],
                time_from_start=_duration(float(t)),
            )
            for i, t in enumerate(traj.times)
        ]
        return out

    # ------------------------------------------------------------------ actions
    def _execute_move_group(self, handle: Any) -> MoveGroup.Result:
        result = MoveGroup.Result()
        if self.planner is None:
            result.error_code = _code("FAILURE")
            result.error_code.message = "move_group has no robot yet (robot_description and robot_description_semantic)"
            handle.abort()
            return result
        goal = handle.request
        t0 = time.monotonic()
        handle.publish_feedback(MoveGroup.Feedback(state="PLANNING"))
        try:
            with self._lock:
                start, traj = self._plan(goal.request)
        except PlanningError as err:
            result.error_code = _code(err.code)
            result.error_code.message = err.message
            self.get_logger().warning(f"planning for '{goal.request.group_name}' failed: {err.code}: {err.message}")
            handle.abort()
            return result
        except Exception as err:
            self.get_logger().error(f"planning failed: {type(err).__name__}: {err}")
            result.error_code = _code("FAILURE")
            result.error_code.message = f"internal error: {type(err).__name__}: {err}"
            handle.abort()
            return result
        result.planning_time = time.monotonic() - t0
        result.trajectory_start = self._robot_state(start)
        result.planned_trajectory = self._robot_trajectory(traj)
        # as MoveIt's move_group: every plan on /display_planned_path (RViz's and Foxglove's trajectory displays)
        self._display.publish(
            DisplayTrajectory(
                model_id=self.planner.semantics.robot_name if self.planner else "",
                trajectory=[result.planned_trajectory],
                trajectory_start=result.trajectory_start,
            )
        )
        if goal.planning_options.plan_only:
            result.error_code = _code("SUCCESS")
            handle.succeed()
            return result
        handle.publish_feedback(MoveGroup.Feedback(state="MONITOR"))
        code, message = self._run(result.planned_trajectory.joint_trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        if code == "SUCCESS":
            result.executed_trajectory = result.planned_trajectory
            handle.succeed()
        elif code == "PREEMPTED":
            handle.canceled()
        else:
            handle.abort()
        return result

    def _execute_trajectory(self, handle: Any) -> ExecuteTrajectory.Result:
        result = ExecuteTrajectory.Result()
        trajectory = handle.request.trajectory.joint_trajectory
        problem = self._check_trajectory(trajectory)
        if problem is not None:
            result.error_code = _code("INVALID_MOTION_PLAN")
            result.error_code.message = problem
            handle.abort()
            return result
        code, message = self._run(trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        if code == "SUCCESS":
            handle.succeed()
        elif code == "PREEMPTED":
            handle.canceled()
        else:
            handle.abort()
        return result

    def _check_trajectory(self, trajectory: JointTrajectory) -> str | None:
        """Why a trajectory sent to execute_trajectory cannot run (positions or speeds beyond the limits).

        Under the planner's lock, as every use of roboplan's scene: the simulation's scene updates (a
        message for every millimetre anything moves, so a stream while an arm executes) add, move and
        rebuild its pinocchio/coal models on another executor thread. Read without the lock, the limits
        came from a model being replaced: pymoveit2's execute_trajectory on a YuMi died of "double free
        or corruption" 4 runs in 4, while the MoveGroup action (which plans under the lock) did not."""
        with self._lock:
            return self._check_trajectory_locked(trajectory)

    def _check_trajectory_locked(self, trajectory: JointTrajectory) -> str | None:
        planner = self.planner
        if planner is None:
            return "move_group has no robot yet"
        if not trajectory.points:
            return "the trajectory has no points"
        unknown = [j for j in trajectory.joint_names if j not in planner.joint_names]
        if unknown:
            return f"unknown joints {unknown}"
        lo, hi = planner.scene.getPositionLimitVectors("")
        speed = planner.velocity_limits  # not roboplan's getVelocityLimitVectors: see ArmPlanner.velocity_limits
        index = {n: i for i, n in enumerate(planner.joint_names)}
        prev = None
        for k, point in enumerate(trajectory.points):
            t = _seconds(point.time_from_start)
            for j, name in enumerate(trajectory.joint_names):
                i = index[name]
                p = point.positions[j]
                # the first point is where the arm is: a reading a little past a limit is allowed there,
                # as MoveIt allows a start state within start_state_max_bounds_error
                slack = START_BOUNDS_ERROR if k == 0 else 1e-4
                if not lo[i] - slack <= p <= hi[i] + slack:
                    return f"point {k}: {name} = {p:.4f} is outside its limits [{lo[i]:.4f}, {hi[i]:.4f}]"
                if prev is not None and t > prev[0]:
                    v = (p - prev[1][j]) / (t - prev[0])
                    if abs(v) > speed[name] * 1.01:
                        return f"point {k}: {name} moves at {v:.3f} rad/s, beyond its velocity limit {speed[name]:.3f}"
            prev = (t, list(point.positions))
        return None

    def _controllers_for(self, joints: list[str]) -> list[Controller]:
        """The controllers that execute a trajectory of ``joints``, as MoveIt's TrajectoryExecutionManager
        picks them: one that has every joint, else the fewest that together have them (a dual arm's group
        of both arms, one joint_trajectory_controller an arm), each then given its own joints' part. From
        moveit_controllers.yaml first, then the controller manager's active ones; [] when none cover them."""
        wanted = set(joints)
        listed: list[Controller] | None = None
        for pool_of in ("yaml", "ros2_control"):
            if pool_of == "yaml":
                pool = list(self._controllers)
            else:
                listed = self._ros2_control_controllers()
                pool = listed
            single = next((c for c in pool if wanted <= set(c.joints)), None)
            if single is not None:
                return [single]
            chosen = _cover(wanted, pool)
            if chosen:
                return chosen
        return _cover(wanted, [*self._controllers, *(listed or [])])

    def _ros2_control_controllers(self) -> list[Controller]:
        """The active joint_trajectory_controllers of the controller manager, as MoveIt's
        Ros2ControlManager finds them (moveit_controllers.yaml names no controllers then)."""
        from controller_manager_msgs.srv import ListControllers

        namespace = (self._param("ros_control_namespace") or "/").rstrip("/")  # MoveIt's parameter
        name = f"{namespace}/controller_manager/list_controllers"
        client = self._controller_lists.get(name)
        if client is None:
            client = self._controller_lists[name] = self._on_execution_thread(
                lambda: self._execution_node.create_client(ListControllers, name)
            )
        listed = any(n == name for n, _ in self._execution_node.get_service_names_and_types())
        if not client.wait_for_service(timeout_sec=2.0 if listed else 0.3):  # none: gz arms, say
            return []
        done = threading.Event()
        box: dict[str, Any] = {}

        def call() -> None:
            future = client.call_async(ListControllers.Request())
            future.add_done_callback(lambda f: (box.__setitem__("result", f.result()), done.set()))

        self._execution_executor.create_task(call)
        if not done.wait(5.0) or box.get("result") is None:
            return []
        out = []
        for c in box["result"].controller:
            if c.state != "active" or not c.type.endswith("JointTrajectoryController"):
                continue
            joints = tuple(dict.fromkeys(i.split("/")[0] for i in c.claimed_interfaces))
            out.append(Controller(c.name, f"{namespace}/{c.name}/follow_joint_trajectory", joints))
        return out

    def _position_topics(self, joints: list[str]) -> dict[str, str] | None:
        """gz-sim JointPositionController command topics (std_msgs/Float64, the default names
        ``/model/<model>/joint/<joint>/n0/cmd_pos`` on ROS, with a subscriber) for every one of ``joints``; None
        unless each joint has exactly one."""
        found: dict[str, list[str]] = {}
        for topic, types in self._execution_node.get_topic_names_and_types():
            m = GZ_CMD_POS.search(topic)
            if m and "std_msgs/msg/Float64" in types and m.group("joint") in joints:
                if self._execution_node.count_subscribers(topic) > 0:
                    found.setdefault(m.group("joint"), []).append(topic)
        if set(found) != set(joints) or any(len(t) != 1 for t in found.values()):
            return None
        return {j: t[0] for j, t in found.items()}

    def _wait_for_execution(self, joints: list[str]) -> tuple[list[Controller], bool, dict[str, str] | None]:
        """(the controllers of ``joints``, whether their actions are served, else the joints' gz command topics),
        waiting up to :data:`CONTROLLER_WAIT` for a served action or the topics to be discovered: right
        after a robot is spawned, a busy machine's graph may not list them, nor the controller manager
        that names the controller, yet (MoveIt's controller managers wait for their action servers
        likewise). Once the wait is over without either: (the controllers or [], False, None)."""
        deadline = time.monotonic() + CONTROLLER_WAIT
        while True:
            controllers = self._controllers_for(joints)
            if controllers and all(self._action_served(c.action) for c in controllers):
                return controllers, True, None
            topics = self._position_topics(joints)
            if topics is not None or time.monotonic() >= deadline:
                return controllers, False, topics
            time.sleep(0.1)  # the graph is kept by the middleware's threads

    def _action_served(self, action: str) -> bool:
        from rclpy.action.graph import get_action_names_and_types

        return any(name == action for name, _ in get_action_names_and_types(self._execution_node))

    def _stream(self, trajectory: JointTrajectory, topics: dict[str, str], handle: Any) -> tuple[str, str]:
        """Execute ``trajectory`` on gz JointPositionController arms: its positions, interpolated, streamed
        to each joint's command topic at :data:`STREAM_RATE_HZ` on the wall clock, then the end held until
        every joint is within :data:`STREAM_GOAL_TOLERANCE` of it (by /joint_states)."""
        joints = list(trajectory.joint_names)
        pubs = []
        for j in joints:
            pub = self._position_pubs.get(topics[j])
            if pub is None:
                pub = self._position_pubs[topics[j]] = self._on_execution_thread(
                    lambda t=topics[j]: self._execution_node.create_publisher(Float64, t, 10)
                )
            pubs.append(pub)
        points = [p for p in trajectory.points if len(p.positions) == len(joints)]
        if not points:
            return "INVALID_MOTION_PLAN", "the trajectory has no positions"
        times = np.array([_seconds(p.time_from_start) for p in points])
        positions = np.array([list(p.positions) for p in points], dtype=float)
        goal = positions[-1]

        def send(q: np.ndarray) -> None:
            for pub, v in zip(pubs, q):
                pub.publish(Float64(data=float(v)))

        def measured() -> np.ndarray | None:
            latest = self._latest_joints
            return np.array([latest[j] for j in joints]) if all(j in latest for j in joints) else None

        started = time.monotonic()
        duration = float(times[-1])
        period = 1.0 / STREAM_RATE_HZ
        while True:
            if handle.is_cancel_requested:
                now = measured()
                if now is not None:
                    send(now)  # stop where the arm is
                return "PREEMPTED", "stopped"
            t = time.monotonic() - started
            send(np.array([np.interp(t, times, positions[:, i]) for i in range(len(joints))]))
            if t >= duration:
                break
            time.sleep(period)
        # MoveIt's allowed_goal_duration_margin and more: the servos settle after the last set-point
        deadline = time.monotonic() + 0.2 * duration + 3.0
        settled = 0
        while True:
            now = measured()
            error = float(np.max(np.abs(now - goal))) if now is not None else math.inf
            # within the tolerance for 0.1 s on end: a servo swinging through the goal is not there yet
            settled = settled + 1 if error <= STREAM_GOAL_TOLERANCE else 0
            if settled >= STREAM_RATE_HZ / 10:
                return "SUCCESS", ""
            if handle.is_cancel_requested:
                if now is not None:
                    send(now)
                return "PREEMPTED", "stopped"
            if time.monotonic() > deadline:
                what = "no /joint_states for them" if now is None else f"{error:.4f} from the end"
                return "TIMED_OUT", f"the joints' command topics were streamed, but the arm is {what}"
            send(goal)
            time.sleep(period)

    def _run(self, trajectory: JointTrajectory, handle: Any) -> tuple[str, str]:
        """Send ``trajectory`` to its FollowJointTrajectory controller and wait; cancel it when ``handle`` is.
        Without a controller serving its joints, gz-sim JointPositionController arms get it streamed."""
        joints = list(trajectory.joint_names)
        controllers, served, topics = self._wait_for_execution(joints)
        if not served and topics is not None:
            return self._stream(trajectory, topics, handle)
        if not controllers:
            return (
                "CONTROL_FAILED",
                f"no controller drives {joints} (moveit_controllers.yaml, an active joint_trajectory_controller "
                "of /controller_manager, or gz JointPositionController topics .../joint/<joint>/n0/cmd_pos)",
            )
        if len(controllers) == 1:
            return self._follow(controllers[0], trajectory, handle, served)
        # each controller its joints' part, all at once (MoveIt's distributeTrajectory), as one execution
        parts, given = [], set()
        for c in controllers:
            mine = [j for j in joints if j in c.joints and j not in given]
            given.update(mine)
            parts.append((c, _part(trajectory, mine)))
        results: list[tuple[str, str]] = [("CONTROL_FAILED", "not run")] * len(parts)

        def follow(i: int, controller: Controller, part: JointTrajectory) -> None:
            results[i] = self._follow(controller, part, handle, served)

        threads = [
            threading.Thread(target=follow, args=(i, c, part), name=f"execute {c.name}", daemon=True)
            for i, (c, part) in enumerate(parts)
        ]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        return next((r for r in results if r[0] == "PREEMPTED"), None) or next(
            (r for r in results if r[0] != "SUCCESS"), ("SUCCESS", "")
        )

    def _follow(
        self, controller: Controller, trajectory: JointTrajectory, handle: Any, served: bool
    ) -> tuple[str, str]:
        """Send ``trajectory`` to ``controller``'s FollowJointTrajectory action and wait; cancel it when
        ``handle`` is."""
        client = self._trajectory_clients.get(controller.action)
        if client is None:
            client = self._trajectory_clients[controller.action] = self._on_execution_thread(
                lambda: ActionClient(self._execution_node, FollowJointTrajectory, controller.action)
            )
        if not client.wait_for_server(timeout_sec=5.0 if served else 0.1):  # the graph was waited on above
            return "CONTROL_FAILED", f"controller action {controller.action} is not available"
        goal = FollowJointTrajectory.Goal(trajectory=trajectory)
        done = threading.Event()
        box: dict[str, Any] = {}

        def on_result(f: Any) -> None:
            box["result"] = f.result()
            done.set()

        def on_goal(f: Any) -> None:
            goal_handle = f.result()
            box["goal"] = goal_handle
            if not goal_handle.accepted:
                done.set()
                return
            goal_handle.get_result_async().add_done_callback(on_result)

        def on_feedback(_msg: Any) -> None:
            box["progress"] = time.monotonic()

        # every call on the client is made on its executor's thread: made from this one, a reply that came
        # back before rclpy filed the request was dropped and its future never completed (ros2/rclpy#1123)
        on_thread = self._execution_executor.create_task
        on_thread(lambda: client.send_goal_async(goal, feedback_callback=on_feedback).add_done_callback(on_goal))
        points = list(trajectory.points)
        duration = _seconds(points[-1].time_from_start) if points else 0.0
        # MoveIt's allowed_execution_duration_scaling (1.2) and allowed_goal_duration_margin (0.5 s), in
        # wall time; a simulation running slower than real time still reports progress through the
        # controller's feedback, so the wait goes on while feedback comes, up to four times as long.
        started = time.monotonic()
        expected = duration * 1.2 + 0.5
        cancelled = False
        while not done.wait(0.02):
            if handle.is_cancel_requested and not cancelled and "goal" in box:
                on_thread(box["goal"].cancel_goal_async)
                cancelled = True
            now = time.monotonic()
            handle_ = box.get("goal")
            silent = now - box.get("progress", started)
            ended = handle_ is not None and handle_.accepted and handle_.status in _ENDED
            if handle_ is not None and handle_.accepted and (ended or (now - started > expected and silent > 0.5)):
                # the controller says the goal ended, or its time is up and its feedback stopped, but no
                # result came: ask again every 0.5 s (a result response can be lost as a service reply
                # can; the server keeps results, and answers at once for a goal that is done)
                asked = box.setdefault("asked", now)
                if now - asked > 0.5:
                    box["asked"] = now
                    on_thread(lambda h=handle_: h.get_result_async().add_done_callback(on_result))
            quiet = silent > 3.0
            if now - started > expected and (quiet or now - started > 4 * expected + 5.0):
                if "goal" in box:
                    on_thread(box["goal"].cancel_goal_async)
                return (
                    "TIMED_OUT",
                    f"{controller.name} did not finish the {duration:.2f} s trajectory within {now - started:.1f} s",
                )
        if cancelled:
            return "PREEMPTED", "stopped"
        if "result" not in box:
            return "CONTROL_FAILED", f"{controller.name} rejected the trajectory"
        res = box["result"].result
        if res.error_code != FollowJointTrajectory.Result.SUCCESSFUL:
            return "CONTROL_FAILED", f"{controller.name}: {res.error_string or res.error_code}"
        return "SUCCESS", ""


def _cover(joints: set[str], controllers: list[Controller]) -> list[Controller]:
    """The fewest of ``controllers`` (greedy: the one with most of the joints left first) whose joints
    together are ``joints``; [] when they do not cover them."""
    left, pool, chosen = set(joints), list(controllers), []
    while left:
        best = max(pool, key=lambda c: len(left & set(c.joints)), default=None)
        if best is None or not left & set(best.joints):
            return []
        chosen.append(best)
        left -= set(best.joints)
        pool.remove(best)
    return chosen


def _part(trajectory: JointTrajectory, joints: list[str]) -> JointTrajectory:
    """``trajectory`` for ``joints`` alone (the same points in time, their columns)."""
    index = [list(trajectory.joint_names).index(j) for j in joints]
    points = []
    for p in trajectory.points:
        q = JointTrajectoryPoint(time_from_start=p.time_from_start)
        for field in ("positions", "velocities", "accelerations", "effort"):
            values = list(getattr(p, field))
            if len(values) == len(trajectory.joint_names):
                setattr(q, field, [values[i] for i in index])
        points.append(q)
    return JointTrajectory(header=trajectory.header, joint_names=list(joints), points=points)


def _quat(q: np.ndarray) -> Any:
    from geometry_msgs.msg import Quaternion

    return Quaternion(x=float(q[0]), y=float(q[1]), z=float(q[2]), w=float(q[3]))


def move_group_main(argv: list[str]) -> int:
    """``gazelle move_group``: the node, with ROS arguments (``--ros-args -p ... --params-file ...``)."""
    import argparse

    parser = argparse.ArgumentParser(
        prog="gazelle move_group", description="MoveIt's move_group interfaces for one robot, planned with roboplan."
    )
    parser.add_argument("--urdf", help="the robot's URDF or xacro file (else the robot_description parameter or topic)")
    parser.add_argument("--srdf", help="the robot's SRDF or SRDF xacro file (else robot_description_semantic)")
    parser.add_argument(
        "--config",
        help="a MoveIt config folder: joint_limits.yaml, kinematics.yaml, moveit_controllers.yaml and "
        "ompl_planning.yaml are read (the last only to say that gazelle does not plan with it)",
    )
    ros_args = argv[argv.index("--ros-args") :] if "--ros-args" in argv else []
    args = parser.parse_args(argv[: len(argv) - len(ros_args)] if ros_args else argv)
    overrides: list[Parameter] = []
    try:
        for flag, name in ((args.urdf, "robot_description"), (args.srdf, "robot_description_semantic")):
            if flag:
                text = read_description_file(flag)
                if name == "robot_description_semantic":
                    _check_srdf(text, flag)
                overrides.append(Parameter(name, value=text))
        if args.config:
            overrides.extend(_config_parameters(Path(args.config)))
    except (OSError, ValueError) as err:
        print(f"gazelle move_group: {err}", file=sys.stderr)
        return 2
    # Python handlers first (rclpy's chain to them), so CPython's wakeup fd hears the signal, and a
    # watchdog that ends the process 3 s after it even while coal or roboplan holds the interpreter
    import signal

    from ..sim import start_signal_watchdog

    signal.signal(signal.SIGTERM, lambda *_a: None)  # rclpy's own handler shuts the context down
    start_signal_watchdog(SHUTDOWN_DEADLINE_SEC)
    announce_often()
    rclpy.init(args=["move_group", *ros_args])
    resolve_mesh: Any = None
    if args.urdf:  # the folder of the file the user named may be read, as for a spawn
        from ..description import ResourceResolver

        folder = Path(args.urdf).resolve().parent
        resolver = ResourceResolver().trusting(folder)

        def trusted(uri: str) -> str | None:
            path = resolver.resolve_uri(uri, folder)
            return str(path) if path is not None and path.is_file() else None

        resolve_mesh = trusted

    node = MoveGroupNode(
        parameter_overrides=overrides, srdf_source=args.srdf or "robot_description_semantic", resolve_mesh=resolve_mesh
    )
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    try:
        spin_until_shutdown(executor, node)
    finally:
        executor.shutdown()
        node.destroy_node()
        try_shutdown()
    # The end, without the interpreter's teardown: callbacks the executor had handed to its threads when the
    # signal came end in "cannot use Destroyable" inside rclpy tasks, which the garbage collector then
    # printed at exit ("The following exception was never retrieved"), after every Ctrl-C
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


def spin_until_shutdown(executor: Any, node: Node) -> None:
    """Spin until Ctrl-C (or SIGTERM) shuts the node's context down, however the shutdown lands: as an
    interrupt, as rclpy's ExternalShutdownException, or as the RCLError "the given context is not valid"
    when it came while the executor was making its next wait set (seen under load). Any other rcl error,
    with the context still up, is a real one and is raised."""
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except RCLError:
        if node.context.ok():
            raise


def _check_srdf(text: str, source: str) -> None:
    """A malformed SRDF named on the command line is an error naming its file and line (exit 2), not a
    move_group that runs unable to plan.

    Raises:
        ValueError: the SRDF does not parse.
    """
    from ..description import ModelLoadError, load_string

    try:
        load_string(text, format="srdf", source=source)
    except ModelLoadError as err:
        raise ValueError(str(err)) from None


PIPELINE_PARAMETERS = frozenset(
    {"ompl", "planning_pipelines", "planning_plugin", "planning_plugins", "request_adapters", "response_adapters"}
)
"""The first name parts of MoveIt's planning pipeline parameters (ompl_planning.yaml under ``ompl.``, and
the pipeline's own): not used by gazelle's planner, and said so at start."""


_PARAMETER_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*")


def _flat(prefix: str, data: Any) -> list[Parameter]:
    """A YAML mapping as ROS parameters named ``prefix.key.subkey`` (MoveItConfigsBuilder's layout); values
    a ROS parameter cannot hold (mixed lists, nulls) are left out."""
    out: list[Parameter] = []
    for key, value in data.items() if isinstance(data, dict) else ():
        name = f"{prefix}.{key}"
        if not _PARAMETER_NAME.fullmatch(name):
            continue  # a key no ROS parameter can be named after
        if isinstance(value, dict):
            out.extend(_flat(name, value))
        elif isinstance(value, (bool, int, float, str)):
            out.append(Parameter(name, value=value))
        elif isinstance(value, list) and value and len({type(v) for v in value}) == 1:
            if isinstance(value[0], (bool, int, float, str)):
                out.append(Parameter(name, value=value))
    return out


def _config_parameters(folder: Path) -> list[Parameter]:
    """joint_limits.yaml as robot_description_planning.*, kinematics.yaml as robot_description_kinematics.*
    (MoveIt's parameter names), moveit_controllers.yaml's controllers, and ompl_planning.yaml as ompl.*
    (so that move_group says it does not use them)."""
    import yaml

    from ..systems.ros2_control import yaml_problem

    def load(path: Path) -> Any:
        try:
            return yaml.safe_load(path.read_text(encoding="utf-8")) or {}
        except yaml.YAMLError as err:  # a file:line error for the command line, never a traceback
            raise ValueError(yaml_problem(err, str(path))) from None

    if not folder.is_dir():
        raise ValueError(f"{folder}: no such folder")
    out: list[Parameter] = []
    kinematics = folder / "kinematics.yaml"
    if kinematics.is_file():
        data = load(kinematics)
        for group, spec in data.items():
            for key, value in (spec or {}).items() if isinstance(spec, dict) else ():
                if isinstance(value, (bool, int, float, str)):
                    out.append(Parameter(f"robot_description_kinematics.{group}.{key}", value=value))
    limits = folder / "joint_limits.yaml"
    if limits.is_file():
        data = load(limits)
        for joint, spec in (data.get("joint_limits") or {}).items():
            for key, value in (spec or {}).items():
                out.append(Parameter(f"robot_description_planning.joint_limits.{joint}.{key}", value=value))
    ompl = folder / "ompl_planning.yaml"
    if ompl.is_file():
        out.extend(_flat("ompl", load(ompl)))
    controllers = folder / "moveit_controllers.yaml"
    if controllers.is_file():
        data = load(controllers)
        mscm = data.get("moveit_simple_controller_manager") or {}
        names = list(mscm.get("controller_names") or [])
        out.append(Parameter("moveit_simple_controller_manager.controller_names", value=names))
        for name in names:
            spec = mscm.get(name) or {}
            out.append(
                Parameter(f"moveit_simple_controller_manager.{name}.action_ns", value=str(spec.get("action_ns", "")))
            )
            out.append(
                Parameter(f"moveit_simple_controller_manager.{name}.joints", value=list(spec.get("joints") or []))
            )
    return out
