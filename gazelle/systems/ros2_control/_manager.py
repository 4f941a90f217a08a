"""The controller manager: one per robot with ``<ros2_control>``, as gazebo_ros2_control and
gz_ros2_control run one inside the simulator.

It owns the robot's :class:`SimHardware` and its controllers. Every ``1/update_rate`` of sim time
it runs read → update (each active controller, at its own rate) → write, on the simulation
thread, before the physics steps: deterministic, as ros2_control's loop in Gazebo is.

The ROS layer serves its controller_manager_msgs services by calling the methods here on the
simulation thread (``Simulation.call``); they raise :class:`ControlError` with the reason a
request fails, which the services return (``ok: false``) and log.

Parameters come from the plugin tag's ``<parameters>`` files (in order; a later one wins), then
from parameters set on the manager's node at run time (``<controller>.type``,
``<controller>.params_file``: what ``spawner --param-file`` sets), as in ros2_control.
"""

from __future__ import annotations

import functools
import logging
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ...description import MAX_PARAMS_FILE_BYTES, PARAMETERS_TEXT_TAG, JointType, ResourceResolver
from ...physics import PhysicsWorld
from .._base import RateGate, System, SystemContext, UpdateInfo
from .._bus import remap_problem
from .._plugin_config import child_text, parse_bool, remap_arguments, ros_remaps
from .._registration import add_plugin
from ._blocks import PlannedBlocks
from ._controller import (
    ACTIVE,
    FINALIZED,
    INACTIVE,
    UNCONFIGURED,
    Controller,
    ControllerContext,
    missing_interfaces,
    position_limits,
)
from ._controller_parameters import ControllerParameters
from ._controller_types import CONTROLLER_TYPES
from ._hardware import ControlError, SimHardware, UpdateFailed
from ._params import (
    Params,
    ParamsError,
    ParamsFile,
    load_params,
    params_file_paths,
    parse_params,
    valid_controller_name,
)

DEFAULT_UPDATE_RATE = 100
"""ros2_control's default ``update_rate`` (Hz)."""

STRICT, BEST_EFFORT = 2, 1
"""``switch_controller`` strictness (controller_manager_msgs/SwitchController)."""

_FIND = re.compile(r"\$\(find\s+([A-Za-z0-9_]+)\)")


@dataclass(frozen=True)
class ControlPluginConfig:
    """The ros2_control plugin tag (``libgazebo_ros2_control.so``, ``gz_ros2_control-system``).

    ``robot_param`` and ``robot_param_node`` are read and not needed: the robot description is
    the spawned model itself, so the manager never waits for robot_state_publisher."""

    parameters: tuple[str, ...] = ()
    """``<parameters>`` files (repeatable; a later one wins), through ``$(find pkg)`` and ``package://``."""
    controller_manager_name: str = "controller_manager"
    """``<controller_manager_name>``: the manager's node name."""
    namespace: str = ""
    """``<ros><namespace>``, else the spawn's robot namespace."""
    hold_joints: bool = True
    """``<hold_joints>``: joints no controller commands hold where they are (else they are free)."""
    robot_param: str = "robot_description"
    """``<robot_param>`` (not needed, see above)."""
    robot_param_node: str = "robot_state_publisher"
    """``<robot_param_node>`` (not needed, see above)."""
    remappings: tuple[tuple[str, str], ...] = ()
    """``<ros><remapping>from:=to`` (repeatable): the rules of every controller's node, as gz_ros2_control and
    gazebo_ros2_control pass them to the manager and ros2_control Jazzy hands them on (first match wins)."""


@dataclass
class _Loaded:
    controller: Controller
    type_name: str
    node: ControllerParameters | None = None
    """The parameters of its node, announced on the bus (the ROS layer serves them)."""
    cycle: int = 0
    last_update: float = -math.inf


class ControllerManager(System):
    """See the module docstring."""

    # gazebo_ros2_control (Classic), gz_ros2_control and its Ignition-era name, by file and by class; a robot
    # with a <ros2_control> block and none of these gets one too (see Simulation)
    plugin_files = (
        "gazebo_ros2_control",
        "gz_ros2_control-system",
        "gz_ros2_control::GazeboSimROS2ControlPlugin",
        "ign_ros2_control-system",
        "ign_ros2_control::IgnitionROS2ControlPlugin",
    )

    def __init__(self, extra_param_files: tuple[str, ...] = ()) -> None:
        """A manager with ros2_control's defaults (``/controller_manager`` at 100 Hz, no hardware yet);
        :meth:`configure` reads the plugin block and the robot's ``<ros2_control>`` hardware."""
        self.name = "controller_manager"
        self.namespace = ""
        self.update_rate = DEFAULT_UPDATE_RATE
        self.hardware: list[SimHardware] = []
        self.controllers: dict[str, _Loaded] = {}
        self.files: list[ParamsFile] = []
        self.overrides: Params = {}
        """Parameters set on the manager's node at run time (``<ctrl>.type``, ``<ctrl>.params_file``)."""
        self.node_params: dict[str, Params] = {}
        """Parameters set on each controller's own node at run time (see ``_controller_parameters.py``)."""
        self.remaps: tuple[tuple[str, str], ...] = ()
        """The plugin's ``<ros><remapping>`` rules, in order (handed on to every controller's node)."""
        self.config = ControlPluginConfig()
        self._extra_files = extra_param_files
        self._resolver = ResourceResolver()
        self._base: Path | None = None
        self._params_files: dict[str, ParamsFile] = {}
        """Every ``<ctrl>.params_file`` read so far, by the value that named it: read once, where it was
        set (a parameter set on the ROS thread, a plugin's file at configure), never on the simulation
        thread when a controller loads."""
        self._gate = RateGate()
        # no phase gate: pre_update is asked at every block boundary, as a planned block ends when the world
        # says so (a goal's path tolerance left), not at a time known in advance
        self.phase_gate = None
        self.blocks = PlannedBlocks(self)
        """The cycles run as planned blocks inside MuJoCo's steps (see ``_blocks.py``)."""
        self._ctx: SystemContext | None = None
        self.log = logging.getLogger("controller_manager")

    # ------------------------------------------------------------------ configure
    def configure(self, ctx: SystemContext) -> None:
        """Build the hardware from the ``<ros2_control>`` blocks and read the plugin's parameters."""
        self._ctx = ctx
        model = ctx.entity.model
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        # the <ros><namespace> only: gz_ros2_control / gazebo_ros2_control build the manager's node themselves,
        # without gazebo_ros's <argument> elements (ros_block's)
        ns = child_text(cfg.find("ros") if cfg is not None else None, "namespace") or ""
        # gz_ros2_control / gazebo_ros2_control pass <ros><remapping> to the manager's node as arguments, and
        # ros2_control Jazzy hands the manager's arguments on to every controller's node (controller_manager.cpp,
        # determine_controller_node_options): a remapped controller topic is remapped here the same way
        self.remaps = ros_remaps(cfg)
        ns = (ns or ctx.entity.namespace).strip("/")
        self.config = ControlPluginConfig(
            parameters=tuple(el.text.strip() for el in cfg.findall("parameters") if el.text.strip())
            if cfg is not None
            else (),
            controller_manager_name=(child_text(cfg, "controller_manager_name") or "controller_manager").strip("/")
            or "controller_manager",
            namespace=ns,
            hold_joints=parse_bool(cfg, "hold_joints", True, self.log),
            robot_param=child_text(cfg, "robot_param") or "robot_description",
            robot_param_node=child_text(cfg, "robot_param_node") or "robot_state_publisher",
            remappings=self.remaps,
        )
        self.namespace = f"/{ns}" if ns else ""
        self.name = self.config.controller_manager_name
        self.log = logging.getLogger(f"{self.namespace}/{self.name}".lstrip("/"))
        # a description that arrived as a string (``<spawn_entity:...>``) has no folder: its relative
        # <parameters> resolve nowhere, never against the server's working directory
        real_file = bool(model.source_file) and not model.source_file.startswith("<")
        self._base = Path(model.source_file).parent if real_file else None
        self._resolver = ResourceResolver().trusting(self._base)
        where = f"{cfg.location}: " if cfg is not None and cfg.location else ""
        # a <parameters> file beside the robot file, read by `gazelle spawn -file` and carried in the XML
        carried = {el.attr("file"): el.text or "" for el in cfg.findall(PARAMETERS_TEXT_TAG)} if cfg is not None else {}
        for raw in (*self.config.parameters, *self._extra_files):
            self.files.append(self.read_params_file(raw, where, carried.get(raw)))
        for key, value in self.manager_params().items():
            if key.endswith(".params_file"):
                for raw in params_file_paths(value):
                    self._params_files.setdefault(raw, self.read_params_file(raw, where))
        for rc in model.ros2_control:
            if not rc.simulated:
                where = f"{rc.location}: " if rc.location else ""
                self.log.warning(
                    f"{where}ros2_control '{rc.name}': hardware plugin '{rc.hardware_plugin or '(none)'}' is a real "
                    "robot's driver; the simulation stands in for it (as gazebo_ros2_control/GazeboSystem)"
                )
            enforce = self.manager_params().get("enforce_command_limits", False)
            self.hardware.append(
                SimHardware(
                    rc,
                    ctx.world,
                    ctx.entity,
                    self.log,
                    hold=self.config.hold_joints,
                    enforce_command_limits=enforce is True,
                )
            )
        rate = self.manager_params().get("update_rate", DEFAULT_UPDATE_RATE)
        if not isinstance(rate, (int, float)) or isinstance(rate, bool) or rate <= 0:
            raise ControlError(f"controller_manager: update_rate must be a positive number, got {rate!r}")
        self.update_rate = int(rate)
        ctx.bus.add_component(ctx.entity.name, self)
        self.log.info(
            f"controller manager '{self.node_name}' at {self.update_rate} Hz over "
            f"{sum(len(h.joints) for h in self.hardware)} joint(s) of {', '.join(h.name for h in self.hardware)}"
        )

    @staticmethod
    def _resolve(raw: str, resolver: ResourceResolver, base: Path | None) -> Path | None:
        """The file a ``<parameters>`` entry names: ``$(find pkg)`` and package://, model://, file:// URIs through
        the resource roots, a relative path against the description's folder; None when it cannot be found or
        lies outside the roots (the caller reports it)."""
        text = raw
        m = _FIND.search(text)
        if m is not None:
            pkg = resolver.find_package(m.group(1))
            if pkg is None:
                return None
            text = text.replace(m.group(0), str(pkg))
        if text.startswith(("package://", "model://", "file://")):
            return resolver.resolve_uri(text, base)
        p = Path(text)
        if not p.is_absolute():
            if base is None:
                return None
            p = base / p
        return p if resolver.allowed(p) else None

    def read_params_file(self, raw: str, where: str = "", text: str | None = None) -> ParamsFile:
        """Read a parameters file this manager was given (a ``<parameters>`` of its plugin, a
        ``<ctrl>.params_file``): only from the resource roots and the folder of the robot's own file
        (:class:`ResourceResolver`, symbolic links resolved), only a regular file, bounded in size and in
        YAML expansion (:func:`~._params.load_params`). Safe to call from any thread.

        With ``text``, the file's content as the client that named it read it (gazelle's spawner and spawn
        read the file the user named on their own command line, with their own rights, and send it as
        ``<ctrl>.params_file_yaml``): parsed with the same bounds, and nothing is read here.

        Raises:
            ControlError: the file is outside those folders or cannot be used (named, never its content).
        """
        if not isinstance(raw, str) or not raw or len(raw) > 4096 or any(ord(c) < 32 for c in raw):
            raise ControlError(f"{where}a parameters file must be named by a path of at most 4096 printable characters")
        if text is not None:
            if len(text) > MAX_PARAMS_FILE_BYTES:
                raise ControlError(
                    f"{where}{raw}: more than the {MAX_PARAMS_FILE_BYTES} bytes a parameters file may have"
                )
            try:
                return parse_params(text, raw)
            except ParamsError as err:
                raise ControlError(f"{where}{err}") from None
        path = self._resolve(raw, self._resolver, self._base)
        if path is None:
            raise ControlError(
                f"{where}parameters file '{raw}' is not in a package or model folder gazelle may read "
                "(the resource roots, e.g. GAZELLE_RESOURCE_PATH or the ament index, and the robot file's folder)"
            )
        try:
            return load_params(path)
        except ParamsError as err:
            raise ControlError(f"{where}{err}") from None

    @property
    def node_name(self) -> str:
        """The manager's fully qualified node name (``/controller_manager``, ``/r1/controller_manager``)."""
        return f"{self.namespace}/{self.name}"

    def manager_params(self) -> Params:
        """The manager node's own parameters (``update_rate``, ``<ctrl>.type``...)."""
        out: Params = {}
        for f in self.files:
            out.update(f.for_node(self.name, self.namespace))
        out.update(self.overrides)
        return out

    def controller_params(self, name: str) -> Params:
        """A controller's parameters: its sections in the plugin's files, then its ``params_file``."""
        out: Params = {}
        for f in self.files:
            out.update(f.for_node(name, self.namespace))
        for raw in params_file_paths(self.manager_params().get(f"{name}.params_file")):
            loaded = self._params_files.get(raw)
            if loaded is None:  # set by a path that never went through set_parameter's read
                raise ControlError(f"parameters file '{raw}' of controller '{name}' was not read when it was set")
            out.update(loaded.for_node(name, self.namespace))
        out.update(self.node_params.get(name, {}))
        return out

    def controller_type(self, name: str) -> str | None:
        """The type configured for controller ``name`` (manager's ``<name>.type``, else its own ``type``)."""
        t = self.manager_params().get(f"{name}.type")
        if isinstance(t, str) and t:
            return t
        own = self.controller_params(name).get("type")
        return own if isinstance(own, str) and own else None

    # ------------------------------------------------------------------ the loop
    def next_update(self, sim_time_sec: float) -> float:
        """The next cycle (none while a planned block runs: the world's steps run its cycles)."""
        if self.blocks.running:
            return math.inf
        return self._gate.next

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """A world reset: cycle again at once; the controllers keep their state."""
        self.settle()
        self._gate.reset()
        for loaded in self.controllers.values():
            loaded.last_update = -math.inf

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """read → update → write, at ``update_rate``; or a block of cycles planned at once, which the
        world's steps run (see :meth:`_plan_block`).

        As ros2_control's loop: every hardware is read, then each active controller updates in load order
        (one slower than the manager runs every ``update_rate / its rate`` cycles, given the time since its
        own last update as its period), then every hardware is written. A controller that raises is
        deactivated with its error and the robot holds (ros2_control would take the process down)."""
        if info.paused:
            return
        if self.blocks.active:
            if self.blocks.running and not self.blocks.interrupted():
                self.blocks.publish_so_far()
                return
            self.settle()
        if not self._gate.due(info.sim_time_sec, self.update_rate):
            return
        for hw in self.hardware:
            hw.start()
        t = info.sim_time_sec
        for hw in self.hardware:
            hw.read()
        if self.blocks.allowed and self.blocks.plan(t, world):
            return
        states, commands = self._merged()
        for name, loaded in list(self.controllers.items()):
            c = loaded.controller
            if c.state != ACTIVE:
                continue
            loaded.cycle += 1
            if c.update_rate and c.update_rate < self.update_rate:
                every = max(1, round(self.update_rate / c.update_rate))
                if (loaded.cycle - 1) % every:
                    continue
            period = t - loaded.last_update if math.isfinite(loaded.last_update) else 1.0 / self.update_rate
            loaded.last_update = t
            try:
                c.update(t, period, states, commands)
            except UpdateFailed:  # return_type::ERROR: Jazzy's controller_manager.cpp update() deactivates it
                self.log.error(f"Deactivating controllers : [ {name} ] as their update resulted in an error!")
                self._deactivate(name)
            except Exception as err:  # a controller that raises is deactivated, the robot holds
                self.log.error(f"controller '{name}' raised in update: {type(err).__name__}: {err}; it is deactivated")
                self._deactivate(name)
        self._split(commands)
        for hw in self.hardware:
            hw.write(t)

    def settle(self) -> None:
        """End a planned block of cycles at the cycles run so far (see :meth:`PlannedBlocks.settle`)."""
        self.blocks.settle()

    @property
    def blocks_allowed(self) -> bool:
        """Whether cycles may run as planned blocks (False: every cycle in Python, as a reference)."""
        return self.blocks.allowed

    @blocks_allowed.setter
    def blocks_allowed(self, value: bool) -> None:
        self.blocks.allowed = value

    @property
    def block_cycles(self) -> int:
        """Cycles run in planned blocks so far (the benches and tests read it)."""
        return self.blocks.cycles

    def _merged(self) -> tuple[dict[str, float], dict[str, float]]:
        """The state and command values of every hardware block as one mapping each (the one block's own dicts when
        there is only one: no copy on the usual robot)."""
        if len(self.hardware) == 1:
            return self.hardware[0].states, self.hardware[0].commands
        states: dict[str, float] = {}
        commands: dict[str, float] = {}
        for hw in self.hardware:
            states.update(hw.states)
            commands.update(hw.commands)
        return states, commands

    def _split(self, commands: dict[str, float]) -> None:
        """Write the merged command values back into each hardware block's commands (nothing to do with one block:
        the controllers wrote into its own dict)."""
        if len(self.hardware) == 1:
            return
        for hw in self.hardware:
            for k in hw.commands:
                hw.commands[k] = commands[k]

    def shutdown(self) -> None:
        """The robot is deleted: controllers are cleaned up, the manager's node goes."""
        self.settle()
        for hw in self.hardware:
            hw.drop_block()
        for name in list(self.controllers):
            try:
                self.unload_controller(name, force=True)
            except ControlError:
                pass
        if self._ctx is not None:
            self._ctx.bus.remove_component(self)

    # ------------------------------------------------------------------ services (sim thread)
    def all_state_interfaces(self) -> list[str]:
        """Every state interface of every hardware component."""
        return [n for hw in self.hardware for n in hw.state_interfaces()]

    def all_command_interfaces(self) -> list[str]:
        """Every command interface of every hardware component."""
        return [n for hw in self.hardware for n in hw.command_interfaces()]

    def claimed(self) -> dict[str, str]:
        """Command interface -> the active controller claiming it."""
        out: dict[str, str] = {}
        for name, loaded in self.controllers.items():
            if loaded.controller.state == ACTIVE:
                for i in loaded.controller.command_interfaces():
                    out[i] = name
        return out

    def load_controller(self, name: str) -> Controller:
        """Load (create) controller ``name`` from its configured type; it is ``unconfigured``.

        Raises:
            ControlError: already loaded, no type configured, or a type that does not exist.
        """
        why = valid_controller_name(name)
        if why is not None:
            raise ControlError(why)
        if name in self.controllers:
            raise ControlError(f"a controller named '{name}' is already loaded")
        type_name = self.controller_type(name)
        if type_name is None:
            raise ControlError(
                f"the 'type' of controller '{name}' is not set: the parameter '{name}.type' of "
                f"{self.node_name}, or 'type' under '{name}: ros__parameters' in a parameters file, names it"
            )
        cls = CONTROLLER_TYPES.get(type_name)
        if cls is None:
            raise ControlError(
                f"controller type '{type_name}' of '{name}' does not exist; the types are: "
                + ", ".join(sorted(CONTROLLER_TYPES))
            )
        assert self._ctx is not None
        ctx = self._ctx
        remaps = self._controller_remaps(name)
        cctx = ControllerContext(
            ctx.bus,
            ctx.entity.name,
            self.namespace,
            logging.getLogger(f"{self.namespace}/{name}".lstrip("/")),
            tuple(self.all_state_interfaces()),
            tuple(self.all_command_interfaces()),
            tuple(j for hw in self.hardware for j in hw.joints),
            add_component=functools.partial(ctx.bus.add_component, ctx.entity.name),
            remove_component=ctx.bus.remove_component,
            remaps=remaps,
            manager_rate=self.update_rate,
            description_joints=tuple(j.name for j in ctx.entity.model.joints if j.type is not JointType.FIXED)
            if ctx.entity.model.urdf
            else None,
            position_limits=position_limits(ctx.entity.model.joints),
        )
        controller = cls(name, self.controller_params(name), cctx)
        loaded = self.controllers[name] = _Loaded(controller, type_name, ControllerParameters(self, name))
        ctx.bus.add_component(ctx.entity.name, loaded.node)  # its node, with its parameters
        self.log.info(f"Loaded controller '{name}' ({type_name})")
        return controller

    # ------------------------------------------------------------------ checkpoints
    def checkpoint_structure(self) -> dict[str, object]:
        """What a checkpoint rebuilds before it writes the state back: the parameters given at run time
        and the controllers loaded, with their lifecycle states (see ``gazelle.sim`` checkpoints)."""
        self.settle()  # a block's cycles so far are taken back: the controllers' state is whole
        return {
            "files": list(self.files),
            "params_files": dict(self._params_files),
            "overrides": dict(self.overrides),
            "controllers": [(name, loaded.controller.state) for name, loaded in self.controllers.items()],
        }

    def restore_structure(self, structure: dict[str, Any]) -> None:
        """Load, configure and activate the checkpoint's controllers as the spawner did, in their order.

        A checkpoint saves which controllers were loaded and in which state, with the parameter files and
        overrides they were read from, rather than the controllers themselves: restoring goes through the
        same load, configure and switch a spawner uses, so a restored controller has read its parameters and
        claimed its interfaces exactly as the original had. The active ones are switched on together."""
        self.files[:] = structure["files"]
        self._params_files.update(structure["params_files"])
        self.overrides.update(structure["overrides"])
        active = []
        for name, state in structure["controllers"]:
            if name not in self.controllers:
                self.load_controller(name)
            if state in (INACTIVE, ACTIVE) and self.controllers[name].controller.state == UNCONFIGURED:
                self.configure_controller(name)
            if state == ACTIVE:
                active.append(name)
        if active:
            self.switch_controller(active, [])

    def configure_controller(self, name: str) -> None:
        """``unconfigured`` → ``inactive`` (reads its parameters again, declares its topics).

        Raises:
            ControlError: not loaded, active, or a parameter or interface problem (named).
        """
        loaded = self._get(name)
        c = loaded.controller
        if c.state == ACTIVE:
            raise ControlError(f"controller '{name}' is active; deactivate it before configuring it")
        if c.state == INACTIVE:
            c.on_cleanup()
        c.params = self.controller_params(name)
        try:
            c.configure()
            self._check_interfaces(c)
        except ControlError:
            c.drop_endpoints()
            c.state = UNCONFIGURED
            raise
        except Exception as err:
            c.drop_endpoints()
            c.state = UNCONFIGURED
            raise ControlError(f"controller '{name}' failed to configure: {type(err).__name__}: {err}") from None
        c.state = INACTIVE
        if loaded.node is not None:
            loaded.node.changed()
        self.log.info(f"Configured controller '{name}'")

    def _check_interfaces(self, c: Controller) -> None:
        """Refuse a controller whose interfaces the hardware does not have (see :func:`missing_interfaces`)."""
        why = missing_interfaces(c, self.all_command_interfaces(), self.all_state_interfaces())
        if why:
            raise ControlError(why)

    def switch_controller(self, activate: list[str], deactivate: list[str], strictness: int = STRICT) -> list[str]:
        """Deactivate then activate controllers, all at once between two cycles.

        With STRICT, any problem refuses the whole switch; with BEST_EFFORT, the controllers that
        can switch do and the problems are returned. Returns the problems (empty: all switched).

        Raises:
            ControlError: STRICT and a problem (the reason lists them all).
        """
        self.settle()
        for name in (*activate, *deactivate):
            why = valid_controller_name(name)
            if why is not None:
                raise ControlError(why)
        problems: list[str] = []
        for name in deactivate:
            if name not in self.controllers:
                problems.append(f"controller '{name}' is not loaded")
            elif self.controllers[name].controller.state != ACTIVE:
                problems.append(f"controller '{name}' is not active")
        claimed = {i: n for i, n in self.claimed().items() if n not in deactivate}
        for name in activate:
            if name not in self.controllers:
                problems.append(f"controller '{name}' is not loaded")
                continue
            c = self.controllers[name].controller
            if c.state == ACTIVE and name not in deactivate:
                problems.append(f"controller '{name}' is already active")
                continue
            if c.state != INACTIVE and not (c.state == ACTIVE and name in deactivate):
                problems.append(f"controller '{name}' is {c.state}; configure it first")
                continue
            for i in c.command_interfaces():
                if i in claimed:
                    problems.append(f"command interface '{i}' of '{name}' is claimed by '{claimed[i]}'")
                claimed[i] = name
        if problems and strictness == STRICT:
            raise ControlError("; ".join(problems))
        for name in deactivate:
            if name in self.controllers and self.controllers[name].controller.state == ACTIVE:
                self._deactivate(name)
        bad = set()
        for p in problems:
            m = re.search(r"'([^']+)'", p)
            if m:
                bad.add(m.group(1))
        for name in activate:
            if name in bad or name not in self.controllers:
                continue
            c = self.controllers[name].controller
            if c.state != INACTIVE:
                continue
            try:
                self._activate(name)
            except ControlError as err:
                if strictness == STRICT:
                    raise
                problems.append(str(err))
        return problems

    def _activate(self, name: str) -> None:
        """Activate a controller: the hardware started and read, its command interfaces claimed (the joints' command
        modes follow the claims), then the controller's ``on_activate`` with the current values; a failure there
        gives the claims back and the controller stays inactive."""
        loaded = self.controllers[name]
        c = loaded.controller
        for hw in self.hardware:
            hw.start()
            hw.read()
        states, commands = self._merged()
        claimed = set(self.claimed()) | set(c.command_interfaces())
        for hw in self.hardware:
            hw.claim(claimed)
        states, commands = self._merged()
        try:
            c.on_activate(states, commands)
        except ControlError:
            for hw in self.hardware:
                hw.claim(set(self.claimed()))
            raise
        c.state = ACTIVE
        loaded.cycle = 0
        loaded.last_update = -math.inf
        self.log.info(f"Activated controller '{name}'")

    def _deactivate(self, name: str) -> None:
        """Deactivate a controller and release its command interfaces (its joints hold their last command)."""
        c = self.controllers[name].controller
        c.on_deactivate()
        c.state = INACTIVE
        for hw in self.hardware:
            hw.claim(set(self.claimed()))
        self.log.info(f"Deactivated controller '{name}'")

    def unload_controller(self, name: str, force: bool = False) -> None:
        """Unload an inactive (or unconfigured) controller.

        Raises:
            ControlError: not loaded, or active (unless ``force``).
        """
        self.settle()
        loaded = self._get(name)
        c = loaded.controller
        if c.state == ACTIVE:
            if not force:
                raise ControlError(f"controller '{name}' is active; deactivate it before unloading it")
            self._deactivate(name)
        if c.state == INACTIVE:
            c.on_cleanup()
        c.state = FINALIZED
        del self.controllers[name]
        self.node_params.pop(name, None)  # its node goes, and what was set on it
        if loaded.node is not None and self._ctx is not None:
            self._ctx.bus.remove_component(loaded.node)
        self.log.info(f"Unloaded controller '{name}'")

    def cleanup_controller(self, name: str) -> None:
        """``inactive`` → ``unconfigured``."""
        c = self._get(name).controller
        if c.state != INACTIVE:
            raise ControlError(f"controller '{name}' is {c.state}; only an inactive one can be cleaned up")
        c.on_cleanup()
        c.state = UNCONFIGURED

    def set_hardware_component_state(self, component: str, state: str) -> str:
        """Set a hardware component's lifecycle state (``active``, ``inactive``, ``unconfigured``,
        ``finalized``); an inactive component holds its joints. Returns the state now."""
        hw = next((h for h in self.hardware if h.name == component), None)
        if hw is None:
            raise ControlError(
                f"no hardware component '{component}' (there are: {', '.join(h.name for h in self.hardware)})"
            )
        if state not in ("active", "inactive", "unconfigured", "finalized"):
            raise ControlError(f"'{state}' is not a lifecycle state of a hardware component")
        self.settle()
        if state != "active":
            users = [
                n
                for n, ld in self.controllers.items()
                if ld.controller.state == ACTIVE and any(i in hw.commands for i in ld.controller.command_interfaces())
            ]
            for n in users:
                self._deactivate(n)
        hw.state = state
        return hw.state

    def _get(self, name: str) -> _Loaded:
        """A loaded controller by name; an invalid name or one not loaded is a ControlError listing what is loaded."""
        loaded = self.controllers.get(name)
        if loaded is None:
            why = valid_controller_name(name)
            if why is not None:
                raise ControlError(why)
            raise ControlError(
                f"controller '{name}' is not loaded"
                + (f" (loaded: {', '.join(self.controllers)})" if self.controllers else " (none is loaded)")
            )
        return loaded

    def _controller_remaps(self, name: str) -> tuple[tuple[str, str], ...]:
        """The remapping rules of controller ``name``'s node: the manager's (with ros2_control Jazzy's warning
        that passing them on is deprecated), then the ``<name>.node_options_args`` the spawner's
        ``--controller-ros-args`` set; any other node argument there is named in a warning, not applied."""
        if self.remaps:
            # controller_manager.cpp's words, logged at each load as it does
            self.log.warning(
                "The use of remapping arguments to the controller_manager node is deprecated. Please use the "
                "'--controller-ros-args' argument of the spawner to pass remapping arguments to the "
                "controller node."
            )
        args = self.manager_params().get(f"{name}.node_options_args")
        if args is None:
            return self.remaps
        if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
            raise ControlError(f"'{name}.node_options_args' must be a list of strings, got {args!r}")
        rules, others = remap_arguments(args)
        if others:
            self.log.warning(
                f"controller '{name}': node arguments {' '.join(others)[:200]} are not applied "
                "(gazelle applies remappings, -r from:=to)"
            )
        for src, dst in (*self.remaps, *rules):
            # rcl refuses a rule whose names are not valid ROS names, and the node is not made (a ROS peer sets
            # node_options_args: what comes back to it is quoted, bounded and escaped)
            bad = remap_problem(src, dst, self.namespace, name)
            if bad is not None:
                shown = repr(f"{src}:={dst}"[:80])
                raise ControlError(f"controller '{name}': remapping {shown} names {bad[:40]!r}, not a valid ROS name")
        return self.remaps + rules

    def set_parameter(self, name: str, value: object, files: dict[str, ParamsFile] | None = None) -> None:
        """A parameter set on the manager's node at run time (``<ctrl>.type``, ``<ctrl>.params_file``...).

        From the ROS layer, a ``<ctrl>.params_file`` comes with ``files``, the files it names already read
        by :meth:`read_params_file` on the ROS thread, confined to the resource roots (the simulation
        thread never opens a file a ROS peer named). Without ``files`` the caller is the user's own
        program (the in-process API), whose files are read as named, bounded but not confined.

        Raises:
            ControlError: a ``params_file`` that cannot be read or parsed."""
        if name.endswith(".params_file"):
            for raw in params_file_paths(value):
                if files is not None and raw in files:
                    self._params_files[raw] = files[raw]
                elif files is not None:
                    raise ControlError(f"parameters file '{raw}' of '{name}' was not read")
                else:
                    try:
                        self._params_files[raw] = load_params(raw)
                    except ParamsError as err:
                        raise ControlError(str(err)) from None
        self.overrides[name] = value  # type: ignore[assignment] - a parameter set at run time is any YAML value; ParamValue is the declared subset


add_plugin(ControllerManager)
