"""``gazelle spawner`` / ``gazelle unspawner``: controller_manager's spawner and unspawner, with
ros2_control Jazzy's command line, for the simulated controller managers (or any real one).

The spawner waits for the manager (``--controller-manager-timeout``; 0, the default, for ever), then for each
controller: sets its ``params_file`` (and ``type``) on the manager when ``--param-file`` is given,
loads it, configures it and, unless ``--inactive`` or ``--load-only``, activates it (strict).
With a timeout and no manager by then it says "Controller manager not available" and exits 1, as the real one
does; any refused step exits 1 with the reason the manager logged. Once the manager is there it never hangs: every
service call has ``--service-call-timeout``.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import rclpy
from controller_manager_msgs.srv import (
    ConfigureController,
    ListControllers,
    LoadController,
    SwitchController,
    UnloadController,
)
from rcl_interfaces.msg import Log, Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import SetParameters
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from ..description import MAX_PARAMS_FILE_BYTES, read_regular_file
from ..systems.ros2_control import ParamsError, load_params
from ._convert import to_duration

if TYPE_CHECKING:
    from ._replies import Req, Res, ServiceType

STRICT = SwitchController.Request.STRICT
MAX_SECONDS = 2**31 - 1
"""The longest timeout the command line takes: builtin_interfaces/Duration keeps its seconds in an int32 (the
switch's timeout travels as one), about 68 years."""
MANAGER_RETRY_SEC = 10.0
"""s between the spawner's "Could not contact service" lines while it waits for ever for the manager."""
REASON_WAIT_SEC = 10.0
"""How long a refused step waits for the manager's reason on /rosout: as long as /rosout keeps a line for a reader
that matches late (rcl's rosout QoS: lifespan 10 s; a later wait could not get it). The manager logs it before it
answers, so it is there in milliseconds on an idle machine, and the wait ends as soon as it is; beside other tests
it once came after the former 1 s wait, and the spawner said only where to look."""


def _seconds(text: str) -> float:
    """A timeout argument: finite seconds from 0 to :data:`MAX_SECONDS`. One past a Duration was a traceback as the
    switch request was built, infinity a wait for ever, NaN or a negative value none at all: now argparse's line."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None
    if not (math.isfinite(value) and 0.0 <= value <= MAX_SECONDS):
        raise argparse.ArgumentTypeError(f"{text}: expected seconds from 0 to {MAX_SECONDS}")
    return value


def build_parser(prog: str, unspawner: bool = False) -> argparse.ArgumentParser:
    """The arguments of ros2_control's spawner (or unspawner)."""
    p = argparse.ArgumentParser(prog=prog)
    p.add_argument("controller_names", nargs="+", help="names of the controllers")
    p.add_argument("-c", "--controller-manager", default="controller_manager", help="name of the controller manager")
    p.add_argument(
        "--switch-timeout", type=_seconds, default=5.0, help="time to wait for a successful state switch of controllers"
    )
    p.add_argument(
        "--service-call-timeout", type=_seconds, default=10.0, help="time to wait for a service call to answer"
    )
    if not unspawner:
        p.add_argument(
            "-p", "--param-file", action="append", default=[], help="controller parameters file (repeatable)"
        )
        p.add_argument("-n", "--namespace", default="", help="namespace of the controller manager and controllers")
        p.add_argument("--load-only", action="store_true", help="only load the controllers")
        p.add_argument(
            "--inactive", "--stopped", dest="inactive", action="store_true", help="configure, do not activate"
        )
        p.add_argument("-t", "--controller-type", default=None, help="controller type (else from the parameters)")
        p.add_argument("-u", "--unload-on-kill", action="store_true", help="unload the controllers on SIGINT")
        p.add_argument(
            "--controller-manager-timeout",
            type=_seconds,
            default=0.0,
            help="time to wait for the controller manager (0: for ever, as Jazzy's spawner)",
        )
        p.add_argument("--activate-as-group", action="store_true", help="activate all controllers in one switch")
        p.add_argument(
            "--controller-ros-args",
            action="append",
            default=None,
            help="--ros-args for the controllers' nodes, e.g. '-r ~/cmd_vel:=/cmd_vel' (repeatable)",
        )
    return p


class _Client:
    """One controller manager's services, called from the spawner's node, and the manager's ERROR lines on
    /rosout, so that a refusal can be reported with the manager's own reason (as the real spawner's user
    reads it in the manager's log)."""

    def __init__(self, node: Node, executor: SingleThreadedExecutor, manager: str, timeout: float) -> None:
        """The spawner's client of one controller manager, listening on /rosout for the manager's ERROR lines so a
        refusal can say why, as ros2_control's spawner prints it."""
        self.node, self.executor, self.manager, self.timeout = node, executor, manager, timeout
        self.errors: list[str] = []
        """The manager's ERROR lines on /rosout (why it refused a request)."""
        logger = manager.strip("/").replace("/", ".")
        qos = QoSProfile(
            depth=1000, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL
        )

        def on_log(msg: Log) -> None:
            if msg.name == logger and msg.level >= Log.ERROR:
                self.errors.append(msg.msg)

        self._rosout = node.create_subscription(Log, "/rosout", on_log, qos)

    def reason(self, about: str) -> str:
        """The manager's last logged refusal mentioning ``about``, waited for up to :data:`REASON_WAIT_SEC`."""
        deadline = time.monotonic() + REASON_WAIT_SEC
        while time.monotonic() < deadline:
            found = [e for e in self.errors if about in e]
            if found:
                return found[-1]
            self.executor.spin_once(timeout_sec=0.05)
        return f"the reason is in {self.manager}'s log"

    def call(self, srv_type: ServiceType[Req, Res], name: str, request: Req) -> Res:
        """Call the manager's service ``name``; a manager that is not there or does not answer within the timeout is
        a RuntimeError naming the service."""
        client = self.node.create_client(srv_type, f"{self.manager}/{name}")
        try:
            if not client.wait_for_service(timeout_sec=self.timeout):
                raise RuntimeError(f"service {self.manager}/{name} is not available")
            future = client.call_async(request)
            self.executor.spin_until_future_complete(future, timeout_sec=self.timeout)
            reply = future.result() if future.done() else None  # a done future holds None only if cancelled
            if reply is None:
                raise RuntimeError(f"service {self.manager}/{name} did not answer in {self.timeout:g} s")
            return reply
        finally:
            self.node.destroy_client(client)


def _error(text: str) -> None:
    """An error line as the controller_manager spawner prints it (red on a terminal)."""
    print(f"[ERROR] [spawner]: {text}", file=sys.stderr)


def _warn(text: str) -> None:
    """A warning line as the spawner prints it."""
    print(f"[WARN] [spawner]: {text}", file=sys.stderr)


def _info(text: str) -> None:
    """An info line as the spawner prints it."""
    print(f"[INFO] [spawner]: {text}", file=sys.stderr)


def _manager_name(args: argparse.Namespace) -> str:
    """The manager's full name: ``-c`` (relative names under ``--namespace``), else
    ``<namespace>/controller_manager``."""
    name = args.controller_manager
    ns = getattr(args, "namespace", "") or ""
    if not name.startswith("/"):
        name = f"/{ns.strip('/')}/{name}" if ns.strip("/") else f"/{name}"
    return name


def _wait_for_manager(cli: _Client, timeout: float) -> bool:
    """Wait for the manager's list_controllers service for ``--controller-manager-timeout`` s; False when it
    did not come. 0, the default, waits for ever, saying so every :data:`MANAGER_RETRY_SEC` s, as Jazzy's
    spawner does (controller_manager/controller_manager_services.py, ``service_caller``: "0 means waiting
    forever, retrying every 10 seconds"): a launch file's spawner that starts before a slow simulation's
    manager waits for it rather than failing after 10 s."""
    service = f"{cli.manager}/list_controllers"
    client = cli.node.create_client(ListControllers, service)
    try:
        if client.service_is_ready():
            return True
        _info(f"waiting for service {service} to become available...")
        if timeout:
            return client.wait_for_service(timeout_sec=timeout)
        while not client.wait_for_service(timeout_sec=MANAGER_RETRY_SEC):
            _warn(f"Could not contact service {service}")
        return True
    finally:
        cli.node.destroy_client(client)


def _string_param(name: str, value: str) -> Parameter:
    """An rcl_interfaces Parameter of type string."""
    return Parameter(name=name, value=ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=value))


def _set_params(cli: _Client, params: list[Parameter]) -> str | None:
    """Set parameters on the manager in one call; the first refusal's reason, or None."""
    res = cli.call(SetParameters, "set_parameters", SetParameters.Request(parameters=params))
    for r in res.results:
        if not r.successful:
            return r.reason or "refused"
    return None


def spawner_main(argv: list[str]) -> int:
    """``gazelle spawner``; returns the exit status."""
    args = build_parser("spawner").parse_args(argv)
    return _with_node("spawner", lambda cli: _spawn(cli, args), _manager_name(args), args.service_call_timeout)


def unspawner_main(argv: list[str]) -> int:
    """``gazelle unspawner``: deactivate and unload controllers; returns the exit status."""
    args = build_parser("unspawner", unspawner=True).parse_args(argv)
    return _with_node("unspawner", lambda cli: _unspawn(cli, args), _manager_name(args), args.service_call_timeout)


def _with_node(name: str, body: Callable[[_Client], int], manager: str, timeout: float) -> int:
    """Run a spawner body with a node and executor of its own, shut down after; Ctrl-C or a service that
    never answers is one error line and status 1, never a traceback."""
    context = Context()
    rclpy.init(args=[], context=context)
    node = rclpy.create_node(f"{name}_{int(time.time() * 1000) % 100000}", context=context)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    try:
        return body(_Client(node, executor, manager, timeout))
    except KeyboardInterrupt:
        _error("interrupted")
        return 1
    except RuntimeError as err:
        _error(str(err))
        return 1
    finally:
        executor.shutdown()
        node.destroy_node()
        if context.ok():
            rclpy.shutdown(context=context)


def _controller_states(cli: _Client, manager_timeout: float) -> dict[str, str] | None:
    """Controller name -> lifecycle state, once the manager answers; None (after saying so) when it does not."""
    if not _wait_for_manager(cli, manager_timeout):
        _error("Controller manager not available")
        return None
    listed = cli.call(ListControllers, "list_controllers", ListControllers.Request())
    return {c.name: c.state for c in listed.controller}


def _spawn(cli: _Client, args: argparse.Namespace) -> int:
    """``spawner NAME...`` as controller_manager's spawner.py (Jazzy): load what is not loaded (with
    ``-p`` files' parameters and type first), configure, activate (one by one, or all at once with
    ``--activate-as-group``), ``--inactive`` stops at configured, ``--load-only`` at loaded."""
    loaded = _controller_states(cli, args.controller_manager_timeout)
    if loaded is None:
        return 1
    for path in args.param_file:
        try:
            load_params(path)
        except ParamsError as err:
            _error(str(err))
            return 1
    for name in args.controller_names:
        if name in loaded:
            _info(f"Controller already loaded, skipping load_controller: {name}")
        else:
            params: list[Parameter] = []
            if args.controller_ros_args:
                # spawner.py (Jazzy): the controller's node arguments, split on spaces, as
                # <name>.node_options_args on the manager, which gives them to the controller's node
                words = [w for arg in args.controller_ros_args for w in arg.split()]
                params.append(
                    Parameter(
                        name=f"{name}.node_options_args",
                        value=ParameterValue(type=ParameterType.PARAMETER_STRING_ARRAY, string_array_value=words),
                    )
                )
            if args.controller_type:
                params.append(_string_param(f"{name}.type", args.controller_type))
            for path in args.param_file:
                params += controller_file_params(
                    cli.manager, name, path, args.namespace, typed=not args.controller_type
                )
            if params:
                why = _set_params(cli, params)
                if why is not None:
                    _error(f"Failed to set the parameters of {name} on {cli.manager}: {why}")
                    return 1
            if not cli.call(LoadController, "load_controller", LoadController.Request(name=name)).ok:
                _error(f"Failed loading controller {name}: {cli.reason(name)}")
                return 1
            _info(f"Loaded {name}")
        if args.load_only:
            continue
        if loaded.get(name, "unconfigured") == "unconfigured":
            if not cli.call(ConfigureController, "configure_controller", ConfigureController.Request(name=name)).ok:
                _error(f"Failed to configure controller {name}: {cli.reason(name)}")
                return 1
        if args.inactive or args.activate_as_group:
            if args.inactive:
                _info(f"Configured {name}")
            continue
        if loaded.get(name) == "active":
            _info(f"Controller {name} is already active")
            continue
        if not _switch(cli, [name], [], args.switch_timeout):
            _error(f"Failed to activate controller {name}: {cli.reason(name)}")
            return 1
        _info(f"Configured and activated {name}")
    if args.activate_as_group and not args.inactive and not args.load_only:
        names = [n for n in args.controller_names if loaded.get(n) != "active"]
        if not _switch(cli, names, [], args.switch_timeout):
            _error(f"Failed to activate the controllers {names}: {cli.reason('switch_controller')}")
            return 1
        _info(f"Configured and activated all the parsed controllers list: {names}")
    return 0


def _switch(cli: _Client, activate: list[str], deactivate: list[str], timeout: float) -> bool:
    """One strict switch_controller request, activating as soon as possible."""
    req = SwitchController.Request(
        activate_controllers=activate, deactivate_controllers=deactivate, strictness=STRICT, activate_asap=True
    )
    req.timeout = to_duration(timeout)
    return bool(cli.call(SwitchController, "switch_controller", req).ok)


def _unspawn(cli: _Client, args: argparse.Namespace) -> int:
    """``unspawner NAME...``: deactivate the active ones in one switch, then unload each."""
    states = _controller_states(cli, args.service_call_timeout)
    if states is None:
        return 1
    active = [n for n in args.controller_names if states.get(n) == "active"]
    if active and not _switch(cli, [], active, args.switch_timeout):
        _error(f"Failed to deactivate {active}")
        return 1
    for name in args.controller_names:
        if name not in states:
            _error(f"Controller {name} is not loaded")
            return 1
        if not cli.call(UnloadController, "unload_controller", UnloadController.Request(name=name)).ok:
            _error(f"Failed to unload {name}")
            return 1
        _info(f"Deactivated and unloaded {name}" if name in active else f"Unloaded {name}")
    return 0


def controller_file_params(
    manager: str, name: str, path: str, namespace: str = "", typed: bool = True
) -> list[Parameter]:
    """The parameters that give controller ``name`` the parameters file ``path`` on ``manager``, as
    controller_manager's ``set_controller_parameters_from_param_files`` sets them (Jazzy,
    controller_manager_services.py): ``<name>.params_file`` and, when ``typed``, ``<name>.type`` from the
    controller's own section or the file's controller_manager section (ros2_control_demos' layout). The
    file's text goes first as ``<name>.params_file_yaml``: the manager never reads a file a ROS peer names
    outside its roots. Raises :class:`ParamsError` for a file that does not read or parse."""
    pf = load_params(path)
    params = [_string_param(f"{name}.params_file_yaml", _text(path)), _string_param(f"{name}.params_file", path)]
    manager_ns, _, manager_name = manager.rstrip("/").rpartition("/")
    kind = pf.for_node(name, namespace).get("type") or pf.for_node(manager_name, manager_ns).get(f"{name}.type")
    if typed and isinstance(kind, str) and kind:
        params.append(_string_param(f"{name}.type", kind))
    return params


def _text(path: str) -> str:
    """The text of a parameters file the user named (already read once by :func:`load_params`)."""
    return read_regular_file(path, MAX_PARAMS_FILE_BYTES, "parameters file")


def give_params_files(
    node: Node, executor: SingleThreadedExecutor, manager: str, files: list[str], timeout: float
) -> str | None:
    """Hand parameter files to a controller manager as ``spawner -p`` does, for every controller they
    configure: ``<controller>.params_file`` and its ``type`` (from its own section or the file's
    ``controller_manager`` section). What ``gazelle spawn ... --ros-args --params-file F`` does after
    the spawn. Returns why it could not, or None."""
    cli = _Client(node, executor, manager, timeout)
    if not _wait_for_manager(cli, timeout):
        return f"{manager} is not available (the robot has no <ros2_control>?)"
    manager_ns, _, manager_name = manager.rstrip("/").rpartition("/")
    params: list[Parameter] = []
    for path in files:
        try:
            pf = load_params(path)
        except ParamsError as err:
            return str(err)
        absolute = str(Path(path).resolve())
        cm = pf.for_node(manager_name, manager_ns)
        names = pf.names_in(manager_ns) - {manager_name}
        names |= {k[: -len(".type")] for k in cm if k.endswith(".type")}
        text = _text(path)
        for name in sorted(names):
            params.append(_string_param(f"{name}.params_file_yaml", text))
            params.append(_string_param(f"{name}.params_file", absolute))
            kind = pf.for_node(name, manager_ns).get("type") or cm.get(f"{name}.type")
            if isinstance(kind, str) and kind:
                params.append(_string_param(f"{name}.type", kind))
    return _set_params(cli, params) if params else None
