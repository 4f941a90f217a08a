"""ros2_control's ROS interfaces for each simulated controller manager.

For every :class:`~gazelle.systems.ros2_control.ControllerManager` announced on the bus, a node
named as the manager (``/controller_manager``, ``/<ns>/controller_manager``) serves the
controller_manager_msgs services the stock ``spawner`` calls, and holds the parameters users set
on it (``<controller>.type``, ``<controller>.params_file``). Each joint_trajectory_controller gets
its ``~/follow_joint_trajectory`` action server on that node.

Every request runs on the simulation thread (``Simulation.call``); a refused one answers
``ok: false`` and says why in the log, as ros2_control does, and the server keeps serving.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol, TypeVar, cast, runtime_checkable

from control_msgs.action import FollowJointTrajectory, GripperCommand
from controller_manager_msgs.msg import ControllerState, HardwareComponentState, HardwareInterface
from controller_manager_msgs.srv import (
    CleanupController,
    ConfigureController,
    ListControllers,
    ListControllerTypes,
    ListHardwareComponents,
    ListHardwareInterfaces,
    LoadController,
    SetHardwareComponentState,
    SwitchController,
    UnloadController,
)
from lifecycle_msgs.msg import State
from rcl_interfaces.msg import SetParametersResult
from rclpy.action.server import ActionServer, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node

from ..sim import Simulation
from ..systems.ros2_control import (
    ACTIVE,
    CONTROLLER_TYPES,
    INACTIVE,
    UNCONFIGURED,
    ControlError,
    ControllerManager,
    GoalState,
    GripperActionController,
    GripperGoal,
    JointTrajectoryController,
    TrajectoryGoal,
    TrajectoryResult,
    params_file_paths,
    segment_tolerances,
)
from ._convert import from_duration, from_joint_trajectory_msg, to_trajectory_point_msg
from ._replies import serve, serve_action

if TYPE_CHECKING:
    from rclpy.action.server import ServerGoalHandle
    from rclpy.context import Context
    from rclpy.parameter import Parameter

    from ..systems.ros2_control import Controller

Req = TypeVar("Req")
Res = TypeVar("Res")


class _NamedRequest(Protocol):
    """A controller_manager request naming one controller (Load, Configure, Cleanup, Unload)."""

    @property
    def name(self) -> str: ...


@runtime_checkable
class _OkResponse(Protocol):
    """A controller_manager response that says whether it was done."""

    @property
    def ok(self) -> bool: ...

    @ok.setter
    def ok(self, value: bool) -> None: ...


_Ok = TypeVar("_Ok", bound=_OkResponse)

_LIFECYCLE = {
    UNCONFIGURED: (State.PRIMARY_STATE_UNCONFIGURED, "unconfigured"),
    INACTIVE: (State.PRIMARY_STATE_INACTIVE, "inactive"),
    ACTIVE: (State.PRIMARY_STATE_ACTIVE, "active"),
    "finalized": (State.PRIMARY_STATE_FINALIZED, "finalized"),
}
_BY_ID = {State.PRIMARY_STATE_UNCONFIGURED: "unconfigured", State.PRIMARY_STATE_INACTIVE: "inactive",
          State.PRIMARY_STATE_ACTIVE: "active", State.PRIMARY_STATE_FINALIZED: "finalized"}  # fmt: skip

PARAMS_FILE_YAML = ".params_file_yaml"
"""The parameter beside ``<ctrl>.params_file`` in which gazelle's spawner sends the file's text."""

ACTION_MONITOR_SEC = 0.05
"""How often an action's progress is looked at (JTC's default action_monitor_rate, 20 Hz)."""


def _state(label: str) -> State:
    """lifecycle_msgs/State of a controller or hardware state label (an unknown label keeps its text, id UNKNOWN)."""
    sid, text = _LIFECYCLE.get(label, (State.PRIMARY_STATE_UNKNOWN, label))
    return State(id=sid, label=text)


class ControllerManagerNode(Node):
    """The ROS face of one controller manager (see the module docstring)."""

    def __init__(self, sim: Simulation, manager: ControllerManager, context: Context | None) -> None:
        """The node named as the manager (in its namespace) with the ten controller_manager services the spawner and
        ``ros2 control`` call, each guarded so that a refusal answers ``ok: false``; ``update_rate`` is declared
        as the manager read it."""
        super().__init__(
            manager.name,
            namespace=manager.namespace or "/",
            context=context,
            allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=False,
        )
        self.sim = sim
        self.manager = manager
        self._log = logging.getLogger(manager.node_name.lstrip("/"))
        self._cb = ReentrantCallbackGroup()
        self._actions: dict[int, ActionServer] = {}
        self._lock = threading.Lock()
        self._texts: dict[str, object] = {}
        """``<ctrl>.params_file_yaml`` values waiting for their ``<ctrl>.params_file``."""
        self.declare_parameter("update_rate", manager.update_rate)
        self.add_on_set_parameters_callback(self._on_set_parameters)
        guarded = self._guard
        cb = self._cb
        serve(self, ListControllers, "~/list_controllers", guarded("list_controllers", self._list_controllers), cb)
        serve(
            self, ListControllerTypes, "~/list_controller_types", guarded("list_controller_types", self._list_types), cb
        )
        serve(
            self,
            ListHardwareInterfaces,
            "~/list_hardware_interfaces",
            guarded("list_hardware_interfaces", self._list_interfaces),
            cb,
        )
        serve(
            self,
            ListHardwareComponents,
            "~/list_hardware_components",
            guarded("list_hardware_components", self._list_components),
            cb,
        )
        load = self._by_name(manager.load_controller)
        serve(self, LoadController, "~/load_controller", guarded("load_controller", load), cb)
        configure = self._by_name(manager.configure_controller)
        serve(self, ConfigureController, "~/configure_controller", guarded("configure_controller", configure), cb)
        cleanup = self._by_name(manager.cleanup_controller)
        serve(self, CleanupController, "~/cleanup_controller", guarded("cleanup_controller", cleanup), cb)
        serve(self, SwitchController, "~/switch_controller", guarded("switch_controller", self._switch), cb)
        unload = self._by_name(manager.unload_controller)
        serve(self, UnloadController, "~/unload_controller", guarded("unload_controller", unload), cb)
        serve(
            self,
            SetHardwareComponentState,
            "~/set_hardware_component_state",
            guarded("set_hardware_component_state", self._set_hw_state),
            cb,
        )

    # ------------------------------------------------------------------ plumbing
    def _guard(self, name: str, fn: Callable[[Req, Res], Res]) -> Callable[[Req, Res], Res]:
        """``fn`` as a service callback that never raises: a ControlError (a refusal the user caused), a timeout of
        the simulation thread or an internal error is logged on this node's logger and answered ``ok: false``, as
        ros2_control answers a refused request; the server keeps serving."""

        def wrapper(req: Req, res: Res) -> Res:
            # refusals go to this node's logger: on the console and on /rosout as the manager's own
            # lines, where the spawner finds the reason to print
            try:
                return fn(req, res)
            except ControlError as err:
                self.get_logger().error(f"{name}: {err}")
            except TimeoutError:
                self.get_logger().error(f"{name}: the simulation did not answer in time")
            except Exception as err:
                self._log.error(f"{name}: internal error", exc_info=err)
                self.get_logger().error(f"{name}: internal error: {type(err).__name__}: {err}")
            if isinstance(res, _OkResponse):
                res.ok = False
            return res

        return wrapper

    def _on_set_parameters(self, params: list[Parameter]) -> SetParametersResult:
        """Parameters set on the manager node (``ros2 param set``, the spawner's ``<ctrl>.type`` and
        ``<ctrl>.params_file``): ``update_rate`` is refused (the manager reads it once, as ros2_control does); a
        parameters file is read here, on the ROS thread, and the values are applied on the simulation thread in
        one call, so a controller sees a consistent set."""
        for p in params:
            if p.name == "update_rate":
                return SetParametersResult(successful=False, reason="update_rate is read when the manager starts")
        given = {p.name: p.value for p in params}
        values = [(n, v) for n, v in given.items() if not n.endswith(PARAMS_FILE_YAML)]
        for n, v in given.items():  # rclpy sets a request's parameters one at a time: kept for the next
            if n.endswith(PARAMS_FILE_YAML):
                if len(self._texts) >= 64 and n not in self._texts:
                    return SetParametersResult(successful=False, reason="too many parameters file texts")
                self._texts[n] = v
        # a <ctrl>.params_file is read here, on the ROS thread, confined and bounded: a FIFO, a device or a
        # file outside the resource roots is refused in the reply, and the simulation never waits on it.
        # gazelle's own clients send the file's text beside it (<ctrl>.params_file_yaml): then nothing is read
        files = {}
        try:
            for name, value in values:
                if name.endswith(".params_file"):
                    paths = params_file_paths(value)
                    texts = params_file_paths(given.get(name + "_yaml", self._texts.pop(name + "_yaml", None)))
                    for i, raw in enumerate(paths):
                        text = texts[i] if len(texts) == len(paths) else None
                        files[raw] = self.manager.read_params_file(raw, f"{name}: ", text)
        except ControlError as err:
            self.get_logger().error(str(err))
            return SetParametersResult(successful=False, reason=str(err))

        def apply() -> None:
            for name, value in values:
                self.manager.set_parameter(name, value, files)

        try:
            self.sim.call(apply)
        except (ControlError, TimeoutError) as err:
            return SetParametersResult(successful=False, reason=str(err) or "the simulation did not answer in time")
        return SetParametersResult(successful=True)

    # ------------------------------------------------------------------ services
    def _list_controllers(
        self, req: ListControllers.Request, res: ListControllers.Response
    ) -> ListControllers.Response:
        """ListControllers: each loaded controller's state, type, update rate and interfaces (claimed ones, and
        those it requires once configured), read in one simulation-thread call so the answer is one moment's."""

        def query() -> list[ControllerState]:
            claimed = self.manager.claimed()
            out = []
            for name, loaded in self.manager.controllers.items():
                c = loaded.controller
                mine = sorted(i for i, owner in claimed.items() if owner == name)
                out.append(
                    ControllerState(
                        name=name,
                        state=c.state,
                        type=loaded.type_name,
                        is_async=False,
                        update_rate=c.update_rate or self.manager.update_rate,
                        claimed_interfaces=mine,
                        required_command_interfaces=c.command_interfaces() if c.state != UNCONFIGURED else [],
                        required_state_interfaces=(c.state_interfaces() or self.manager.all_state_interfaces())
                        if c.state != UNCONFIGURED
                        else [],
                    )
                )
            return out

        res.controller = self.sim.call(query)
        return res

    def _list_types(
        self, req: ListControllerTypes.Request, res: ListControllerTypes.Response
    ) -> ListControllerTypes.Response:
        """ListControllerTypes: the controller types gazelle simulates (every one a ControllerInterface)."""
        res.types = sorted(CONTROLLER_TYPES)
        res.base_classes = ["controller_interface::ControllerInterface"] * len(res.types)
        return res

    def _list_interfaces(
        self, req: ListHardwareInterfaces.Request, res: ListHardwareInterfaces.Response
    ) -> ListHardwareInterfaces.Response:
        """ListHardwareInterfaces: every command interface (claimed or not) and every state interface, all doubles."""

        def query() -> tuple[list[HardwareInterface], list[HardwareInterface]]:
            claimed = self.manager.claimed()
            cmds = [
                HardwareInterface(name=n, data_type="double", is_available=True, is_claimed=n in claimed)
                for n in self.manager.all_command_interfaces()
            ]
            states = [
                HardwareInterface(name=n, data_type="double", is_available=True, is_claimed=False)
                for n in self.manager.all_state_interfaces()
            ]
            return cmds, states

        res.command_interfaces, res.state_interfaces = self.sim.call(query)
        return res

    def _list_components(
        self, req: ListHardwareComponents.Request, res: ListHardwareComponents.Response
    ) -> ListHardwareComponents.Response:
        """ListHardwareComponents: each ``<ros2_control>`` block's hardware with its lifecycle state and interfaces;
        ``rw_rate`` is the manager's rate, at which the simulated hardware is read and written."""

        def query() -> list[HardwareComponentState]:
            claimed = self.manager.claimed()
            return [
                HardwareComponentState(
                    name=hw.name,
                    type=hw.type,
                    is_async=False,
                    rw_rate=self.manager.update_rate,
                    class_type=hw.plugin,
                    plugin_name=hw.plugin,
                    state=_state(hw.state),
                    command_interfaces=[
                        HardwareInterface(name=n, data_type="double", is_available=True, is_claimed=n in claimed)
                        for n in hw.command_interfaces()
                    ],
                    state_interfaces=[
                        HardwareInterface(name=n, data_type="double", is_available=True, is_claimed=False)
                        for n in hw.state_interfaces()
                    ],
                )
                for hw in self.manager.hardware
            ]

        res.component = self.sim.call(query)
        return res

    def _by_name(self, action: Callable[[str], object]) -> Callable[[_NamedRequest, _Ok], _Ok]:
        """A service whose request is a controller's ``name``: ``action(name)`` on the simulation thread."""

        def serve(req: _NamedRequest, res: _Ok) -> _Ok:
            self.sim.call(lambda: action(req.name))
            res.ok = True
            return res

        return serve

    def _switch(self, req: SwitchController.Request, res: SwitchController.Response) -> SwitchController.Response:
        """SwitchController: activate and deactivate in one switch. STRICT (2) refuses the whole switch on a
        problem; BEST_EFFORT (1) does what it can and says what it could not in ``message``. AUTO and FORCE_AUTO
        (Jazzy's 3 and 4, which would also switch the controllers a chain needs) are read as STRICT."""
        activate, deactivate = list(req.activate_controllers), list(req.deactivate_controllers)
        strictness = req.strictness if req.strictness in (1, 2) else 2  # AUTO / FORCE_AUTO: as strict
        problems = self.sim.call(lambda: self.manager.switch_controller(activate, deactivate, strictness))
        for p in problems:
            self._log.warning(f"switch_controller (best effort): {p}")
        res.ok = True
        res.message = "; ".join(problems) if problems else "Switch successful"
        return res

    def _set_hw_state(
        self, req: SetHardwareComponentState.Request, res: SetHardwareComponentState.Response
    ) -> SetHardwareComponentState.Response:
        """SetHardwareComponentState: move a hardware component to a lifecycle state, by id or by label; the reply
        carries the state it reached."""
        target = _BY_ID.get(req.target_state.id) or req.target_state.label
        state = self.sim.call(lambda: self.manager.set_hardware_component_state(req.name, target))
        res.ok = True
        res.state = _state(state)
        return res

    # ------------------------------------------------------------------ controllers' actions
    def add_controller_action(self, controller: Controller) -> None:
        """Serve a controller's action, by the type it declares (``Controller.action_type``):
        ``follow_joint_trajectory`` of a JTC, ``gripper_cmd`` of a gripper. A type gazelle does not serve
        is an error naming it (a new controller's action needs its server here)."""
        if controller.action_type == "control_msgs/action/FollowJointTrajectory":
            jtc = cast(JointTrajectoryController, controller)
            server = serve_action(
                self,
                FollowJointTrajectory,
                jtc.action_name,
                lambda handle: self._execute(jtc, handle),
                self._cb,
                accept=lambda goal: self._accept(jtc, goal),
            )
        elif controller.action_type == "control_msgs/action/GripperCommand":
            gripper = cast(GripperActionController, controller)
            server = serve_action(
                self,
                GripperCommand,
                gripper.action_name,
                lambda handle: self._execute_gripper(gripper, handle),
                self._cb,
                accept=lambda _goal: GoalResponse.ACCEPT if gripper.state == ACTIVE else GoalResponse.REJECT,
            )
        else:
            self._log.error(f"controller '{controller.name}': its action {controller.action_type} is not served")
            return
        with self._lock:
            self._actions[id(controller)] = server

    def remove_controller_action(self, controller: Controller) -> None:
        """Stop serving a controller's action (it was cleaned up or unloaded)."""
        with self._lock:
            server = self._actions.pop(id(controller), None)
        if server is not None:
            server.destroy()

    def destroy_node(self) -> None:
        """Destroy the controllers' action servers, then the node: an action server left alive holds the
        node's handle, and the node would stay in the ROS graph with the action's endpoints alone."""
        with self._lock:
            servers, self._actions = list(self._actions.values()), {}
        for server in servers:
            server.destroy()
        super().destroy_node()

    def _execute_gripper(self, gripper: GripperActionController, handle: ServerGoalHandle) -> GripperCommand.Result:
        """GripperCommand's execute callback: submit the goal to the gripper controller, feed back the finger's
        position, effort and whether it stalled, and end as the goal ended."""
        cmd = handle.request.command
        goal = GripperGoal(float(cmd.position), float(cmd.max_effort))
        self.sim.call(lambda: gripper.submit(goal))

        def feedback() -> GripperCommand.Feedback:
            q, effort = goal.feedback
            return GripperCommand.Feedback(
                position=q, effort=effort, stalled=goal.stalled, reached_goal=goal.reached_goal
            )

        self._follow(handle, goal, lambda: gripper.cancel(goal), feedback)
        q, effort = goal.feedback
        return GripperCommand.Result(position=q, effort=effort, stalled=goal.stalled, reached_goal=goal.reached_goal)

    def _follow(
        self,
        handle: ServerGoalHandle,
        goal: TrajectoryGoal | GripperGoal,
        cancel: Callable[[], object],
        feedback: Callable[[], object | None],
    ) -> None:
        """Watch a submitted goal until it ends: feedback at the monitor rate, a cancel request passed on
        to the controller, and the action ended as the goal did (succeeded, canceled or aborted)."""
        while not goal.done.wait(ACTION_MONITOR_SEC):
            if handle.is_cancel_requested:
                self.sim.call(cancel)
                break
            if not handle.is_active:
                break
            fb = feedback()
            if fb is not None:
                handle.publish_feedback(fb)
        if goal.status is GoalState.SUCCEEDED:
            handle.succeed()
        elif goal.status is GoalState.CANCELED and handle.is_cancel_requested:
            handle.canceled()
        else:
            handle.abort()

    def _accept(self, jtc: JointTrajectoryController, goal: FollowJointTrajectory.Goal) -> GoalResponse:
        """FollowJointTrajectory's goal callback: the trajectory is checked on the simulation thread (the controller
        is active, its joints are the controller's, its points are well formed and not all in the past) and
        refused with the reason in the log, as the JTC refuses it."""
        traj = from_joint_trajectory_msg(goal.trajectory)
        try:
            why = self.sim.call(lambda: jtc.validate(traj, self.sim.world.time))
        except TimeoutError:
            why = (TrajectoryResult.INVALID_GOAL, "the simulation did not answer in time")
        if why is not None:
            self._log.error(f"{jtc.name}: goal rejected: {why[1]}")
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _execute(self, jtc: JointTrajectoryController, handle: ServerGoalHandle) -> FollowJointTrajectory.Result:
        """FollowJointTrajectory's execute callback: the goal with its path and goal tolerances (the controller's
        own where the request gives none) is submitted; feedback is the controller's last state at the monitor
        rate; the result carries the controller's error code and text (PATH_TOLERANCE_VIOLATED,
        GOAL_TOLERANCE_VIOLATED, ...)."""
        req = handle.request
        traj = from_joint_trajectory_msg(req.trajectory)
        path = [(t.name, t.position, t.velocity, t.acceleration) for t in req.path_tolerance]
        goal_tol = [(t.name, t.position, t.velocity, t.acceleration) for t in req.goal_tolerance]
        tolerances = segment_tolerances(jtc, path, goal_tol, from_duration(req.goal_time_tolerance))
        goal = TrajectoryGoal(traj, tolerances.path, tolerances.goal, tolerances.goal_time)
        result = FollowJointTrajectory.Result()
        try:
            self.sim.call(lambda: jtc.submit(goal))
        except TimeoutError:
            handle.abort()
            result.error_code, result.error_string = FollowJointTrajectory.Result.INVALID_GOAL, "simulation busy"
            return result

        def feedback() -> FollowJointTrajectory.Feedback | None:
            state = jtc.last_state
            if state is None:
                return None
            fb = FollowJointTrajectory.Feedback()
            fb.header.stamp = self.get_clock().now().to_msg()
            fb.joint_names = list(state.joint_names)
            fb.desired = to_trajectory_point_msg(state.reference)
            fb.actual = to_trajectory_point_msg(state.feedback)
            fb.error = to_trajectory_point_msg(state.error)
            return fb

        self._follow(handle, goal, lambda: jtc.cancel(goal), feedback)
        result.error_code, result.error_string = goal.error_code, goal.error_string
        return result
