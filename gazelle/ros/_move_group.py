"""``move_group``: MoveIt's ROS interfaces served by :class:`gazelle.planning.ArmPlanner`.

A plain rclpy node named ``move_group``, as MoveIt's. It reads ``robot_description`` and
``robot_description_semantic`` (parameters, as MoveIt's launch files pass them, else the latched
topics of the same names), ``robot_description_planning`` (joint_limits.yaml) and
``moveit_simple_controller_manager`` (moveit_controllers.yaml).

It is built as MoveIt's move_group is (moveit_ros/move_group/src/move_group.cpp, jazzy): the node owns a
context (``_move_group_context.py``: the planners, ``_move_group_scene_monitor.py``,
``_move_group_pipeline.py``, ``_move_group_trajectory_execution.py``) and one capability a file, each
registering its own services or action and using only the context (:data:`CAPABILITIES`):
``/move_action``, ``/execute_trajectory``, ``/compute_fk`` and ``/compute_ik``, ``/plan_kinematic_path``,
``/check_state_validity``, ``/compute_cartesian_path``, ``/get_planning_scene``, ``/apply_planning_scene``,
the planner queries, ``/get_urdf`` and ``/clear_octomap``.

Trajectories are executed by the arm's ``FollowJointTrajectory`` controller that
moveit_controllers.yaml names (the simulated joint_trajectory_controller).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.utilities import try_shutdown
from std_msgs.msg import String

from ..description import read_description_file
from ..planning import ArmPlanner, PlannerPool, PlanningError, moveit_joint_limits
from ._dds import announce_often
from ._move_group_apply_planning_scene_service import ApplyPlanningSceneService
from ._move_group_capability import MoveGroupCapability
from ._move_group_cartesian_path_service import CartesianPathService
from ._move_group_clear_octomap_service import ClearOctomapService
from ._move_group_common import LATCHED, SHUTDOWN_DEADLINE_SEC, TWIN_CHECK_SEC, Controller
from ._move_group_config import PIPELINE_PARAMETERS, check_srdf, config_parameters
from ._move_group_context import MoveGroupContext
from ._move_group_execute_trajectory_action import ExecuteTrajectoryAction
from ._move_group_get_planning_scene_service import GetPlanningSceneService
from ._move_group_get_urdf_service import GetUrdfService
from ._move_group_kinematics_service import KinematicsService
from ._move_group_move_action import MoveAction
from ._move_group_pipeline import PlanningPipeline
from ._move_group_plan_service import PlanService
from ._move_group_query_planners_service import QueryPlannersService
from ._move_group_scene_monitor import PlanningSceneMonitor
from ._move_group_state_validation_service import StateValidationService
from ._move_group_trajectory_execution import TrajectoryExecutionManager
from ._signals import spin_until_shutdown

__all__ = ["PIPELINE_PARAMETERS", "Controller", "MoveGroupNode", "move_group_main"]

CAPABILITIES = (
    MoveAction,
    ExecuteTrajectoryAction,
    KinematicsService,
    PlanService,
    StateValidationService,
    CartesianPathService,
    GetPlanningSceneService,
    ApplyPlanningSceneService,
    QueryPlannersService,
    GetUrdfService,
    ClearOctomapService,
)
"""move_group's capabilities, each in its own file: MoveIt's DEFAULT_CAPABILITIES
(moveit_ros/move_group/src/move_group.cpp, jazzy) but the two geometry-file services (see
``_move_group_get_urdf_service.py``)."""


class MoveGroupNode(Node):
    """MoveIt's move_group interfaces for one robot: the node owns a :class:`MoveGroupContext` (the robot's
    planners, the planning scene monitor, the planning pipeline, the trajectory execution manager) and the
    capabilities that serve through it, as MoveIt's ``MoveGroupExe`` owns its context and capability plugins."""

    def __init__(
        self,
        *,
        srdf_source: str = "robot_description_semantic",
        resolve_mesh: Callable[[str], str | None] | None = None,
        **kwargs: Any,
    ) -> None:
        """The ``move_group`` node: it takes the robot from ``robot_description`` and ``robot_description_semantic``
        (parameters, or the latched topics), serves MoveIt's planning, kinematics and scene interfaces, and
        executes trajectories through the controllers ``moveit_simple_controller_manager`` lists. ``srdf_source``
        is what SRDF warnings name; ``resolve_mesh`` finds mesh URIs (None: the resource roots)."""
        self._srdf_source = srdf_source  # what SRDF warnings name: the file, when one was given
        self._resolve_mesh = resolve_mesh  # how mesh URIs are found (None: the resource roots)
        super().__init__("move_group", automatically_declare_parameters_from_overrides=True, **kwargs)
        self._texts: dict[str, str] = {}  # descriptions heard on their latched topics
        context = self.group_context = MoveGroupContext(self, ReentrantCallbackGroup())
        context.scene = PlanningSceneMonitor(context)
        context.pipeline = PlanningPipeline(context)
        context.execution = TrajectoryExecutionManager(context)
        self._capabilities: list[MoveGroupCapability] = []  # made once the robot is known (see _build)
        context.scene.start()
        self._take_descriptions()
        # a second move_group on the domain answers every request too: said once, after discovery
        self._twin_check = self.create_timer(TWIN_CHECK_SEC, self._warn_of_twins, callback_group=context.callback_group)

    def destroy_node(self) -> None:
        """Destroy the execution manager, then the action servers: one left alive holds its node's handle, and
        the node would stay in the graph with that action's endpoints alone."""
        self.group_context.execution.destroy()
        self.group_context.joint_states.destroy()
        for capability in self._capabilities:
            capability.destroy()
        super().destroy_node()

    # ------------------------------------------------------------------ set-up
    def _take_descriptions(self) -> None:
        """The robot from the robot_description(_semantic) parameters, or, as MoveIt's nodes do when they
        are not given, from the latched topics of those names."""
        urdf = self.group_context.param("robot_description")
        srdf = self.group_context.param("robot_description_semantic")
        if urdf and srdf:
            self._build(urdf, srdf)
            return
        for topic in ("robot_description", "robot_description_semantic"):
            self.create_subscription(
                String,
                topic,
                lambda msg, t=topic: self._on_text(t, str(getattr(msg, "data", ""))),
                LATCHED,
                callback_group=self.group_context.callback_group,
            )
        if urdf:
            self._texts["robot_description"] = urdf
        if srdf:
            self._texts["robot_description_semantic"] = srdf

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

    def _on_text(self, topic: str, text: str) -> None:
        """A robot description heard on its latched topic: the planner is built once both the URDF and the SRDF have
        arrived (parameters given at start win)."""
        if self.group_context.pool is not None:
            return
        self._texts[topic] = text
        if "robot_description" in self._texts and "robot_description_semantic" in self._texts:
            self._build(self._texts["robot_description"], self._texts["robot_description_semantic"])

    def _build(self, urdf: str, srdf: str) -> None:
        """Build the planners for the robot, with the joint limits of ``robot_description_planning``, and say once
        what of the user's MoveIt configuration is not used (kinematics solver plugins, the OMPL pipeline); a
        robot the planner cannot model is an error in the log, and nothing is served (MoveIt's move_group ends). Ends
        with MoveIt's "You can start planning now!"."""
        context = self.group_context
        prefix = "robot_description_planning.joint_limits."
        grouped: dict[str, dict[str, Any]] = {}
        for name, value in context.parameters().items():
            if name.startswith(prefix):
                joint, _, key = name[len(prefix) :].rpartition(".")
                grouped.setdefault(joint, {})[key] = value
        limits = moveit_joint_limits({"joint_limits": grouped}) if grouped else {}
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
        self._say_unused_settings()
        context.urdf_text = urdf
        context.pool = pool
        context.scene.robot_loaded()
        # MoveIt's move_group makes its capabilities once MoveItCpp has loaded the robot model (move_group.cpp,
        # main: MoveGroupExe after MoveItCpp; MoveGroupExe::configureCapabilities): until then nothing is served,
        # and a client that waits for a service or action finds one that can answer
        self._capabilities = [capability(context) for capability in CAPABILITIES]
        for capability in self._capabilities:
            capability.initialize()
        context.execution.start()
        context.ready.set()
        self.get_logger().info(
            f"You can start planning now! (groups: {', '.join(planner.groups)}; planning frame {planner.root_link})"
        )

    def _say_unused_settings(self) -> None:
        """Say once what of the user's MoveIt configuration gazelle does not use: kinematics solver plugins and
        the OMPL pipeline's settings."""
        context = self.group_context
        parameters = context.parameters()
        solvers = "robot_description_kinematics."
        for name, value in sorted(parameters.items()):
            if name.startswith(solvers) and name.endswith(".kinematics_solver"):
                group = name[len(solvers) : -len(".kinematics_solver")]
                self.get_logger().warning(
                    f"kinematics.yaml: {group}'s kinematics_solver {value} is MoveIt's plugin and is not "
                    f"loaded; gazelle's IK (roboplan) solves, within kinematics_solver_timeout "
                    f"({context.ik_timeout(group):g} s) when a request gives no timeout"
                )
        pipeline = sorted(n for n in parameters if n.split(".", 1)[0] in PIPELINE_PARAMETERS)
        if pipeline:
            shown = ", ".join(pipeline[:3]) + (f" and {len(pipeline) - 3} more" if len(pipeline) > 3 else "")
            self.get_logger().warning(
                f"MoveIt's planning pipeline settings are not used ({shown}: ompl_planning.yaml's planner "
                "configurations and adapters): gazelle plans every request with roboplan's RRT-Connect, "
                "shortcutting and TOPP-RA time parameterization within the joint limits"
            )


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
                    check_srdf(text, flag)
                overrides.append(Parameter(name, value=text))
        if args.config:
            overrides.extend(config_parameters(Path(args.config)))
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
    resolve_mesh: Callable[[str], str | None] | None = None
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


EXECUTOR_THREADS = 12
"""Threads of move_group's executor. rclpy runs one callback of an entity at a time, so a plan holds at most
one thread per planning interface (plan_kinematic_path, compute_cartesian_path, each move_action goal) and a
scene change waiting for it one per scene topic and apply_planning_scene: with four, those could take every
thread and leave none for compute_fk."""
