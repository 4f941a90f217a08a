"""``move_group``: MoveIt's ROS interfaces served by :class:`gazelle.planning.ArmPlanner`.

A plain rclpy node named ``move_group``, as MoveIt's. It reads ``robot_description`` and
``robot_description_semantic`` (parameters, as MoveIt's launch files pass them, else the latched
topics of the same names), ``robot_description_planning`` (joint_limits.yaml) and
``moveit_simple_controller_manager`` (moveit_controllers.yaml). It serves:

- the ``/move_action`` (MoveGroup) and ``/execute_trajectory`` (ExecuteTrajectory) actions;
- ``/compute_fk``, ``/compute_ik``, ``/plan_kinematic_path`` and ``/check_state_validity``;
- ``/get_urdf`` and ``/clear_octomap`` (``_move_group_model.py``).

Trajectories are executed by the arm's ``FollowJointTrajectory`` controller that
moveit_controllers.yaml names (the simulated joint_trajectory_controller).
"""

from __future__ import annotations

import math
import os
import re
import sys
import threading
from pathlib import Path
from typing import Any

import rclpy
from moveit_msgs.action import ExecuteTrajectory, MoveGroup
from moveit_msgs.msg import (
    AttachedCollisionObject,
    CollisionObject,
    DisplayTrajectory,
    PlanningScene,
    PlanningSceneWorld,
)
from moveit_msgs.srv import (
    ApplyPlanningScene,
    GetCartesianPath,
    GetGroupUrdf,
    GetMotionPlan,
    GetPlannerParams,
    GetPlanningScene,
    GetPositionFK,
    GetPositionIK,
    GetStateValidity,
    QueryPlannerInterfaces,
    SetPlannerParams,
)
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.parameter import Parameter
from rclpy.utilities import try_shutdown
from std_msgs.msg import String
from std_srvs.srv import Empty

from ..description import read_description_file, reply_text
from ..planning import ArmPlanner, PlannerPool, PlanningError, moveit_joint_limits
from ._dds import announce_often
from ._joint_state_monitor import JointStateMonitor
from ._move_group_base import (
    LATCHED,
    OBJECT_PADDING_PARAMETER,
    SHUTDOWN_DEADLINE_SEC,
    TWIN_CHECK_SEC,
    Controller,
    _failed,
    _log,
)
from ._move_group_execution import _Execution
from ._move_group_model import _ModelServices
from ._move_group_planners import _PlannerQueries
from ._replies import serve, serve_action
from ._signals import spin_until_shutdown

__all__ = ["PIPELINE_PARAMETERS", "Controller", "MoveGroupNode", "move_group_main"]


class MoveGroupNode(_Execution, _PlannerQueries, _ModelServices):
    """MoveIt's move_group interfaces for one robot."""

    def __init__(
        self, *, srdf_source: str = "robot_description_semantic", resolve_mesh: Any = None, **kwargs: Any
    ) -> None:
        """The ``move_group`` node: it takes the robot from ``robot_description`` and ``robot_description_semantic``
        (parameters, or the latched topics), serves MoveIt's planning, kinematics and scene interfaces, and
        executes trajectories through the controllers ``moveit_simple_controller_manager`` lists. ``srdf_source``
        is what SRDF warnings name; ``resolve_mesh`` finds mesh URIs (None: the resource roots)."""
        self._srdf_source = srdf_source  # what SRDF warnings name: the file, when one was given
        self._resolve_mesh = resolve_mesh  # how mesh URIs are found (None: the resource roots)
        super().__init__("move_group", automatically_declare_parameters_from_overrides=True, **kwargs)
        self._pool = None  # the robot's planners, once it is known
        self._ready = threading.Event()
        self.planner = None
        self._warned_no_state = False  # from /joint_states; the planner takes it when it plans
        self._noted = set()  # the kinds of request parts gazelle does not honour, each said once
        self._texts = {}
        self._sim_objects = set()  # ids of the objects that came from the simulation
        self._sim_world = None  # the simulation's geometry heard before the robot was known
        self.object_padding = self._object_padding()
        cb = ReentrantCallbackGroup()
        self._cb = cb
        self._joint_states = JointStateMonitor(self, "joint_states")
        self._take_descriptions()
        self._serve_interfaces()
        self._controllers = self._read_controllers()
        self._trajectory_clients = {}
        self._position_pubs = {}  # gz JointPositionController command topics
        self._controller_lists = {}  # list_controllers clients by service name
        # The controllers' FollowJointTrajectory clients live on their own node and single-threaded
        # executor: on the node's multi-threaded one, busy with /joint_states, their status and result
        # messages came seconds late or not at all (rclpy's executor is slow and its action client
        # racy across threads: ros2/rclpy#1123).
        self._execution_node = rclpy.create_node("move_group_trajectory_execution", context=self.context)
        self._execution_executor = SingleThreadedExecutor(context=self.context)
        self._execution_executor.add_node(self._execution_node)
        self._execution_thread = threading.Thread(target=self._spin_execution, name="move_group execution", daemon=True)
        self._execution_thread.start()

    def _take_descriptions(self) -> None:
        """The robot from the robot_description(_semantic) parameters, or, as MoveIt's nodes do when they
        are not given, from the latched topics of those names."""
        urdf = self._param("robot_description")
        srdf = self._param("robot_description_semantic")
        if urdf and srdf:
            self._build(urdf, srdf)
            return
        for topic in ("robot_description", "robot_description_semantic"):
            self.create_subscription(
                String,
                topic,
                lambda msg, t=topic: self._on_text(t, str(getattr(msg, "data", ""))),
                LATCHED,
                callback_group=self._cb,
            )
        if urdf:
            self._texts["robot_description"] = urdf
        if srdf:
            self._texts["robot_description_semantic"] = srdf

    def _serve_interfaces(self) -> None:
        """move_group's services, planning-scene topics, display topic and actions, under its names."""
        cb = self._cb
        # each on the planner of its kind of work (gazelle.planning's PlannerPool): FK, state validity and the
        # scene answer while a plan or an IK runs, as MoveIt's services do; a change of the scene waits for them
        for srv_type, name, fn, role in (
            (GetPositionFK, "compute_fk", self._compute_fk, "query"),
            (GetPositionIK, "compute_ik", self._compute_ik, "ik"),
            (GetMotionPlan, "plan_kinematic_path", self._plan_kinematic_path, "plan"),
            (GetStateValidity, "check_state_validity", self._check_state_validity, "query"),
            (GetCartesianPath, "compute_cartesian_path", self._compute_cartesian_path, "plan"),
            (GetPlanningScene, "get_planning_scene", self._get_planning_scene, "query"),
            (ApplyPlanningScene, "apply_planning_scene", self._apply_planning_scene, "write"),
            (QueryPlannerInterfaces, "query_planner_interface", self._query_planner_interface, "query"),
            (GetPlannerParams, "get_planner_params", self._get_planner_params, "query"),
            (SetPlannerParams, "set_planner_params", self._set_planner_params, "query"),
            (GetGroupUrdf, "get_urdf", self._get_urdf, "query"),
        ):
            serve(self, srv_type, name, self._guard(name, fn, role), cb)
        serve(self, Empty, "clear_octomap", self._clear_octomap, cb)  # needs no robot
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
        # MoveIt's trajectory execution manager listens here for "stop" (pymoveit2's cancel_execution
        # publishes it): trajectory_execution_manager.cpp, EXECUTION_EVENT_TOPIC, with rclcpp's ServicesQoS
        self.create_subscription(String, "trajectory_execution_event", self._on_execution_event, 10, callback_group=cb)
        # a second move_group on the domain answers every request too: said once, after discovery
        self._twin_check = self.create_timer(TWIN_CHECK_SEC, self._warn_of_twins, callback_group=cb)
        self._move = serve_action(self, MoveGroup, "move_action", self._execute_move_group, cb)
        self._execute = serve_action(self, ExecuteTrajectory, "execute_trajectory", self._execute_trajectory, cb)

    def destroy_node(self) -> None:
        """Destroy the action servers and clients first: one left alive holds its node's handle, and the
        node would stay in the graph with that action's endpoints alone."""
        self._execution_executor.shutdown()
        # its thread leaves its wait once the executor is shut down: wait for that before destroying what
        # the wait set may hold (the segmentation faults seen on Ctrl-C were another race, with rclpy's
        # signal thread: see _signals.py)
        self._execution_thread.join(timeout=2.0)
        for client in self._trajectory_clients.values():
            client.destroy()
        self._execution_node.destroy_node()
        self._joint_states.destroy()
        self._move.destroy()
        self._execute.destroy()
        super().destroy_node()

    # ------------------------------------------------------------------ set-up
    def _warn_of_twins(self) -> None:
        """Once, shortly after start: warn when another node of this name runs on the domain, since both would
        answer every request and action (a leftover move_group from an earlier launch)."""
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

    def _on_text(self, topic: str, text: str) -> None:
        """A robot description heard on its latched topic: the planner is built once both the URDF and the SRDF have
        arrived (parameters given at start win)."""
        if self.planner is not None:
            return
        self._texts[topic] = text
        if "robot_description" in self._texts and "robot_description_semantic" in self._texts:
            self._build(self._texts["robot_description"], self._texts["robot_description_semantic"])

    def _build(self, urdf: str, srdf: str) -> None:
        """Build the planner for the robot, with the joint limits of ``robot_description_planning``, and say once
        what of the user's MoveIt configuration is not used (kinematics solver plugins, the OMPL pipeline); a
        robot the planner cannot model is an error in the log, and the node keeps answering with that error. Ends
        with MoveIt's "You can start planning now!"."""
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
            pool = PlannerPool(
                lambda: ArmPlanner(
                    urdf, srdf, joint_limits=limits, srdf_source=self._srdf_source, resolve_mesh=self._resolve_mesh
                )
            )
        except PlanningError as err:
            self.get_logger().error(f"cannot plan for this robot: {err.message}")
            return
        except Exception as err:  # a URDF roboplan cannot model: say so once and keep serving errors
            self.get_logger().error(f"cannot plan for this robot: {type(err).__name__}: {err}")
            return
        planner = pool.primary
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
        self._urdf_text = urdf
        self.planner = planner
        self._pool = pool
        if self._sim_world is not None:
            with pool.writing():
                self._take_sim_world(self._sim_world)
        self._ready.set()
        self.get_logger().info(
            f"You can start planning now! (groups: {', '.join(planner.groups)}; planning frame {planner.root_link})"
        )

    def _read_controllers(self) -> list[Controller]:
        """The controllers MoveIt's simple controller manager would use:
        ``moveit_simple_controller_manager.controller_names`` with each one's ``action_ns`` (default
        ``follow_joint_trajectory``) and ``joints``."""
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

    # ------------------------------------------------------------------ plumbing
    def _guard(self, name: str, fn: Any, role: str) -> Any:
        """``fn(request, response, planner)`` as a service callback that answers every request: with no robot
        yet, a FAILURE saying what is missing; a PlanningError as its MoveIt error code and message; anything else
        as FAILURE naming the error (every message cut to a reply's length, its quoted values to excerpts). It
        runs on the pool's planner of ``role`` under that planner's lock, or, for ``write``, on the primary
        planner with every lock held (roboplan's scenes are not re-entrant)."""

        def wrapper(request: Any, response: Any) -> Any:
            pool = self._pool
            if pool is None:
                return _failed(
                    response,
                    "FAILURE",
                    "move_group has no robot yet (robot_description and robot_description_semantic)",
                )
            try:
                with pool.writing() if role == "write" else pool.using(role) as planner:
                    return fn(request, response, planner)
            except PlanningError as err:
                message = reply_text(err.message)
                self.get_logger().warning(f"{name}: {err.code}: {message}")
                return _failed(response, err.code, message)
            except Exception as err:
                message = reply_text(f"{type(err).__name__}: {err}")
                self.get_logger().error(f"{name}: {message}")
                return _failed(response, "FAILURE", f"{name}: internal error: {message}")

        return wrapper


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
    executor = MultiThreadedExecutor(num_threads=EXECUTOR_THREADS)
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


EXECUTOR_THREADS = 12
"""Threads of move_group's executor. rclpy runs one callback of an entity at a time, so a plan holds at most
one thread per planning interface (plan_kinematic_path, compute_cartesian_path, each move_action goal) and a
scene change waiting for it one per scene topic and apply_planning_scene: with four, those could take every
thread and leave none for compute_fk."""

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
        """A YAML file of the MoveIt config; a syntax error is a ValueError naming file:line (for the command line),
        never a traceback."""
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
