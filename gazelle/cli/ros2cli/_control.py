"""``ros2 control``: ros2controlcli's verbs over a controller manager's services (list_controllers,
list_controller_types, list_hardware_interfaces, list_hardware_components, load_controller,
configure_controller, set_controller_state, switch_controllers, unload_controller), with Jazzy's
arguments and output (ros2_control's ros2controlcli/verb/*.py). Colours only on a terminal."""

from __future__ import annotations

import argparse
import sys
import time
from typing import TYPE_CHECKING, Any

from ..._errors import SimError
from ._daemon_graph import daemon_graph
from ._daemon_link import WARM_SEC
from ._graph import cli_node, spin_once, wait_until

DEFAULT_SERVICE_TIMEOUT = 10.0
MANAGER_RECHECK_SEC = 0.5
"""A manager missing from the daemon's graph is looked for again this long (it may have just started; a
short time: a missing manager is the common case, and the answer a script waits for)."""

if TYPE_CHECKING:
    from rclpy.node import Node

VERBS = (
    "list_controllers",
    "list_controller_types",
    "list_hardware_components",
    "list_hardware_interfaces",
    "load_controller",
    "configure_controller",
    "set_controller_state",
    "switch_controllers",
    "unload_controller",
)


class _Colors:
    """ros2controlcli's ``bcolors``: ANSI colours on a terminal, none when piped (what scripts parse)."""

    def __init__(self, on: bool) -> None:
        """ros2controlcli's terminal colours, or empty strings when output is not a terminal."""
        codes = {"ok_green": "\033[92m", "ok_cyan": "\033[96m", "ok_blue": "\033[94m", "warning": "\033[93m"}
        codes.update(fail="\033[91m", end="\033[0m")
        for k, v in codes.items():
            setattr(self, k, v if on else "")

    ok_green = ok_cyan = ok_blue = warning = fail = end = ""


class ControlCommandError(SimError):
    """One line for the user (no traceback)."""


def main(argv: list[str]) -> int:
    """``ros2 control VERB ...``: ros2controlcli's verbs with Jazzy's arguments (``-c`` the manager,
    ``--service-timeout``); a failure is one line on stderr and status 1."""
    p = argparse.ArgumentParser(prog="ros2 control", description="Various control related sub-commands")
    sub = p.add_subparsers(
        dest="cmd", required=True, metavar="Call `ros2 control <command> -h` for more detailed usage."
    )

    def verb(name: str, text: str) -> argparse.ArgumentParser:
        v = sub.add_parser(name, help=text, description=text)
        v.add_argument(
            "-c", "--controller-manager", default="/controller_manager", help="Name of the controller manager ROS node"
        )
        v.add_argument("--spin-time", type=float, default=0.5, help="Spin time in seconds to wait for discovery")
        v.add_argument("--include-hidden-nodes", action="store_true", help="Consider hidden nodes as well")
        v.add_argument(
            "--service-timeout",
            type=float,
            default=None,
            help="Seconds to wait for the service (default: 10 once the manager's node is in the graph; "
            "none when it is not)",
        )
        v.add_argument("--no-daemon", action="store_true", help="Do not spawn nor use an already running daemon")
        return v

    lc = verb("list_controllers", "Output the list of loaded controllers, their type and status")
    for flag in ("--claimed-interfaces", "--required-state-interfaces", "--required-command-interfaces"):
        lc.add_argument(flag, action="store_true")
    lc.add_argument("--verbose", "-v", action="store_true")
    verb("list_controller_types", "Output the available controller types and their base classes")
    verb("list_hardware_components", "Output the list of available hardware components").add_argument(
        "--verbose", "-v", action="store_true"
    )
    verb("list_hardware_interfaces", "Output the list of available command and state interfaces").add_argument(
        "--verbose", "-v", action="store_true"
    )
    load = verb("load_controller", "Load a controller in a controller manager")
    load.add_argument("controller_name")
    load.add_argument("param_file", nargs="?", default=None)
    load.add_argument("--set-state", choices=["inactive", "active"])
    configure = verb("configure_controller", "Configure a controller in a controller manager")
    configure.add_argument("controller_name")
    state = verb("set_controller_state", "Adjust the state of the controller")
    state.add_argument("controller_name")
    state.add_argument("state", choices=["unconfigured", "inactive", "active"])
    switch = verb("switch_controllers", "Switch controllers in a controller manager")
    switch.add_argument("--deactivate", nargs="*", default=[])
    switch.add_argument("--activate", nargs="*", default=[])
    switch.add_argument("--strict", action="store_true")
    switch.add_argument("--activate-asap", action="store_true")
    switch.add_argument("--switch-timeout", type=float, default=5.0)
    unload = verb("unload_controller", "Unload a controller in a controller manager")
    unload.add_argument("controller_name")
    args = p.parse_args(argv)
    colors = _Colors(sys.stdout.isatty())
    try:
        args.manager_seen = args.service_timeout is None and not args.no_daemon and _manager_in_daemon_graph(args)
        with cli_node("ros2control") as node:
            return _VERBS[args.cmd](_Manager(node, args), args, colors)
    except ControlCommandError as err:
        print(f"{colors.fail}{err}{colors.end}", file=sys.stderr)
        return 1


def _full_names(names_and_namespaces: list[tuple[str, str]]) -> set[str]:
    """``/ns/name`` of each (name, namespace)."""
    return {f"{ns.rstrip('/')}/{n}" for n, ns in names_and_namespaces}


def _no_manager(prefix: str) -> str:
    """The one line for a controller manager that is not in the graph."""
    return f"Could not contact the controller manager {prefix}: no node {prefix} in the graph (is it running?)"


def _manager_in_daemon_graph(args: argparse.Namespace) -> bool:
    """Whether the daemon's graph has the manager's node (False: no daemon answers, this verb looks itself);
    a ControlCommandError, before any rclpy is loaded, when it does not have it after being asked again for
    :data:`MANAGER_RECHECK_SEC`: waiting 10 s for the manager's service then said nothing more
    (ros2controlcli waits for ever, logging every 10 s)."""
    name = args.controller_manager
    prefix = name if name.startswith("/") else f"/{name}"
    graph = daemon_graph()
    deadline = time.monotonic() + MANAGER_RECHECK_SEC
    while graph is not None and prefix not in _full_names(graph.get_node_names_and_namespaces()):
        if time.monotonic() > deadline:
            raise ControlCommandError(_no_manager(prefix))
        time.sleep(0.05)
        graph = daemon_graph(start=False) or graph
    return graph is not None


class _Manager:
    """Calls to one controller manager's services, each waiting for the service and the reply."""

    def __init__(self, node: Node, args: argparse.Namespace) -> None:
        """The controller manager a ``ros2 control`` verb talks to (``-c``, default ``/controller_manager``), with
        the verb's service timeout."""
        self.node = node
        name = args.controller_manager
        self.prefix = name if name.startswith("/") else f"/{name}"
        self.timeout = DEFAULT_SERVICE_TIMEOUT if args.service_timeout is None else args.service_timeout
        # an explicit timeout waits it out, as before; a manager the daemon has seen needs no look of our own
        self.node_checked = args.service_timeout is not None or args.manager_seen

    def require_node(self) -> None:
        """Without the daemon: fail when this verb's own node has not seen the manager's node within
        :data:`WARM_SEC` (every participant has announced itself by then)."""

        def seen() -> bool:
            return self.prefix in _full_names(self.node.get_node_names_and_namespaces())

        if not wait_until(self.node, seen, WARM_SEC):
            raise ControlCommandError(_no_manager(self.prefix))

    def call(self, srv_type: Any, service: str, **fields: Any) -> Any:
        """Call one of the manager's services with ``fields`` set on the request; a manager that is not there, or
        does not reply within the timeout, is a ControlCommandError in ros2controlcli's words."""
        name = f"{self.prefix.rstrip('/')}/{service}"
        if not self.node_checked:
            self.require_node()
            self.node_checked = True
        client = self.node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=self.timeout):
            raise ControlCommandError(
                f"Could not contact service {name} (is the controller manager {self.prefix} running?)"
            )
        request = srv_type.Request()
        for k, v in fields.items():
            setattr(request, k, v)
        future = client.call_async(request)
        deadline = time.monotonic() + self.timeout
        while not future.done() and time.monotonic() < deadline:
            spin_once(self.node, timeout_sec=0.05)
        if not future.done():
            raise ControlCommandError(f"{name} did not reply within {self.timeout:g} s")
        return future.result()


def _list_controllers(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``list_controllers``: name, type and state in aligned columns (coloured by state on a terminal), and
    the interfaces each claims or requires with their flags or ``-v``, as ros2controlcli prints them."""
    from controller_manager_msgs.srv import ListControllers

    controllers = cm.call(ListControllers, "list_controllers").controller
    if not controllers:
        print("No controllers are currently loaded!")
        return 0
    wn = max(len(x.name) for x in controllers)
    wt = max(len(x.type) for x in controllers)
    ws = max(len(x.state) for x in controllers)
    color = {"active": c.ok_green, "inactive": c.ok_cyan, "unconfigured": c.warning}
    for x in controllers:
        col = color.get(x.state, "")
        print(f"{col}{x.name:<{wn}}{c.end} {x.type:<{wt}}  {col}{x.state:<{ws}}{c.end}")
        for flag, title, values in (
            (args.claimed_interfaces, "claimed interfaces", x.claimed_interfaces),
            (args.required_command_interfaces, "required command interfaces", x.required_command_interfaces),
            (args.required_state_interfaces, "required state interfaces", x.required_state_interfaces),
        ):
            if flag or args.verbose:
                print(f"\t{title}:")
                for v in values:
                    print(f"\t\t{v}")
    return 0


def _list_types(cm: _Manager, _args: argparse.Namespace, _c: _Colors) -> int:
    """``list_controller_types``: each type gazelle's manager can load and its base class."""
    from controller_manager_msgs.srv import ListControllerTypes

    res = cm.call(ListControllerTypes, "list_controller_types")
    width = max((len(t) for t in res.types), default=0)
    for t, base in zip(res.types, res.base_classes, strict=False):
        print(f"{t:<{width}}  {base}")
    return 0


def _list_interfaces(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``list_hardware_interfaces``: command interfaces sorted by name with [available]/[claimed], then
    state interfaces; ``-v`` adds data types."""
    from controller_manager_msgs.srv import ListHardwareInterfaces

    res = cm.call(ListHardwareInterfaces, "list_hardware_interfaces")
    print("command interfaces")
    for i in sorted(res.command_interfaces, key=lambda hwi: hwi.name):
        kind = f" [{i.data_type}]" if args.verbose else ""
        if i.is_available:
            col, claimed = (c.ok_blue, "claimed") if i.is_claimed else (c.ok_cyan, "unclaimed")
            print(f"\t{col}{i.name}{kind} [available] [{claimed}]{c.end}")
        else:
            print(f"\t{c.warning}{i.name}{kind} [unavailable] [unclaimed]{c.end}")
    print("state interfaces")
    for i in sorted(res.state_interfaces, key=lambda hwi: hwi.name):
        print(f"\t{i.name}" + (f" [{i.data_type}]" if args.verbose else ""))
    return 0


def _list_components(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``list_hardware_components``: each hardware component's name, type, plugin, lifecycle state and
    interfaces, numbered from 1 as upstream."""
    from controller_manager_msgs.srv import ListHardwareComponents

    components = cm.call(ListHardwareComponents, "list_hardware_components").component
    for i, comp in enumerate(components):
        state = comp.state.label
        col = c.ok_green if state == "active" else c.warning
        print(f"Hardware Component {i + 1}\n\tname: {comp.name}\n\ttype: {comp.type}")
        if hasattr(comp, "plugin_name"):
            print(f"\tplugin name: {comp.plugin_name}")
        print(f"\tstate: id={comp.state.id} label={col}{state}{c.end}")
        print("\tcommand interfaces")
        for ci in comp.command_interfaces:
            kind = f" [{ci.data_type}]" if args.verbose else ""
            print(f"\t\t{ci.name}{kind} [{'available' if ci.is_available else 'unavailable'}]"
                  f" [{'claimed' if ci.is_claimed else 'unclaimed'}]")  # fmt: skip
        if args.verbose:
            print("\tstate interfaces")
            for si in comp.state_interfaces:
                print(f"\t\t{si.name} [{si.data_type}]")
    return 0


def _controller_state(cm: _Manager, name: str) -> str | None:
    """The named controller's state from ``list_controllers``, or None when it is not loaded."""
    from controller_manager_msgs.srv import ListControllers

    for x in cm.call(ListControllers, "list_controllers").controller:
        if x.name == name:
            return x.state
    return None


def _switch_call(
    cm: _Manager, activate: list[str], deactivate: list[str], strict: bool, asap: bool, timeout: float
) -> bool:
    """One ``switch_controller`` request (strict or best effort, ``activate_asap``, the timeout as a
    Duration); whether the manager said ok."""
    from builtin_interfaces.msg import Duration
    from controller_manager_msgs.srv import SwitchController

    req = {
        "activate_controllers": activate,
        "deactivate_controllers": deactivate,
        "strictness": SwitchController.Request.STRICT if strict else SwitchController.Request.BEST_EFFORT,
        "activate_asap": asap,
        "timeout": Duration(sec=int(timeout), nanosec=int((timeout % 1) * 1e9)),
    }
    return bool(cm.call(SwitchController, "switch_controller", **req).ok)


def _by_name(cm: _Manager, srv_type: Any, service: str, name: str, doing: str) -> None:
    """Call a manager service that takes a controller's name; a refusal is one line."""
    if not cm.call(srv_type, service, name=name).ok:
        raise ControlCommandError(f"Error {doing} controller {name}, check controller_manager logs")


def _load(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``load_controller NAME [PARAM_FILE] [--set-state S]`` as ros2controlcli Jazzy's
    (verb/load_controller.py): a controller already loaded is a warning and not loaded again; the file's
    parameters are given to the manager first (``<name>.params_file`` and its ``type``, as
    controller_manager's ``set_controller_parameters_from_param_files``); ``--set-state`` then
    configures it and, for ``active``, activates it (strict, as soon as possible)."""
    from controller_manager_msgs.srv import ConfigureController, LoadController

    name = args.controller_name
    if _controller_state(cm, name) is not None:
        print(f"{c.warning}Controller : {name} already loaded, skipping load_controller!{c.end}")
    else:
        if args.param_file:
            _give_param_file(cm, name, args.param_file)
        if not cm.call(LoadController, "load_controller", name=name).ok:
            raise ControlCommandError(f"Failed loading controller {name} check controller_manager logs")
        print(f"{c.ok_blue}Successfully loaded controller {name}{c.end}")
    if args.set_state:
        if not cm.call(ConfigureController, "configure_controller", name=name).ok:
            raise ControlCommandError(f"Error configuring controller : {name}")
        if args.set_state == "active" and not _switch_call(cm, [name], [], True, True, 5.0):
            raise ControlCommandError(f"Error activating controller : {name}, check controller_manager logs")
        print(f"{c.ok_blue}Successfully loaded controller {name} into state {args.set_state}{c.end}")
    return 0


def _give_param_file(cm: _Manager, name: str, param_file: str) -> None:
    """Set controller ``name``'s parameters file (made absolute, as upstream) on the manager."""
    from pathlib import Path

    from rcl_interfaces.srv import SetParameters

    from ...ros import controller_file_params
    from ...systems.ros2_control import ParamsError

    path = Path(param_file)
    if not path.exists():
        raise ControlCommandError(f"Controller parameter file : {param_file} does not exist, Aborting!")
    try:
        params = controller_file_params(cm.prefix, name, str(path.absolute()))
    except ParamsError as err:
        raise ControlCommandError(str(err)) from None
    for result in cm.call(SetParameters, "set_parameters", parameters=params).results:
        if not result.successful:
            raise ControlCommandError(f"Could not set the parameters of {name} on {cm.prefix}: {result.reason}")


def _configure(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``configure_controller NAME``: unconfigured -> inactive."""
    from controller_manager_msgs.srv import ConfigureController

    _by_name(cm, ConfigureController, "configure_controller", args.controller_name, "configuring")
    print(f"{c.ok_blue}Successfully configured controller {args.controller_name}{c.end}")
    return 0


def _set_state(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``set_controller_state NAME unconfigured|inactive|active`` with ros2controlcli Jazzy's transitions
    and messages (verb/set_controller_state.py): inactive -> unconfigured cleans up, unconfigured ->
    inactive configures, active -> inactive deactivates, inactive -> active activates; anything else is
    refused naming the current state."""
    from controller_manager_msgs.srv import CleanupController, ConfigureController

    name, want = args.controller_name, args.state
    now = _controller_state(cm, name)
    if now is None:
        raise ControlCommandError(f"controller {name} does not seem to be loaded")
    if want == "unconfigured":
        if now != "inactive":
            raise ControlCommandError(f"cannot cleanup {name} from its current state {now}")
        if not cm.call(CleanupController, "cleanup_controller", name=name).ok:
            raise ControlCommandError("Error cleaning up controller, check controller_manager logs")
        print(f"{c.ok_blue}successfully cleaned up {name}{c.end}")
    elif want == "inactive" and now == "unconfigured":
        if not cm.call(ConfigureController, "configure_controller", name=name).ok:
            raise ControlCommandError("Error configuring controller, check controller_manager logs")
        print(f"{c.ok_blue}Successfully configured {name}{c.end}")
    elif want == "inactive" and now == "active":
        if not _switch_call(cm, [], [name], True, True, 5.0):
            raise ControlCommandError("Error stopping controller, check controller_manager logs")
        print(f"{c.ok_blue}Successfully deactivated {name}{c.end}")
    elif want == "inactive":
        raise ControlCommandError(f"cannot put {name} in 'inactive' state from its current state {now}")
    elif now != "inactive":
        raise ControlCommandError(f"cannot activate {name} from its current state {now}")
    elif not _switch_call(cm, [name], [], True, True, 5.0):
        raise ControlCommandError("Error activating controller, check controller_manager logs")
    else:
        print(f"{c.ok_blue}Successfully activated {name}{c.end}")
    return 0


def _switch(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``switch_controllers --activate ... --deactivate ...``: one request, strict when asked."""
    if not _switch_call(cm, args.activate, args.deactivate, args.strict, args.activate_asap, args.switch_timeout):
        raise ControlCommandError("Error switching controllers, check controller_manager logs")
    print(f"{c.ok_blue}Successfully switched controllers{c.end}")
    return 0


def _unload(cm: _Manager, args: argparse.Namespace, c: _Colors) -> int:
    """``unload_controller NAME``: the manager refuses an active one, as ros2_control does."""
    from controller_manager_msgs.srv import UnloadController

    _by_name(cm, UnloadController, "unload_controller", args.controller_name, "unloading")
    print(f"{c.ok_blue}Successfully unloaded controller {args.controller_name}{c.end}")
    return 0


_VERBS = {
    "list_controllers": _list_controllers,
    "list_controller_types": _list_types,
    "list_hardware_components": _list_components,
    "list_hardware_interfaces": _list_interfaces,
    "load_controller": _load,
    "configure_controller": _configure,
    "set_controller_state": _set_state,
    "switch_controllers": _switch,
    "unload_controller": _unload,
}
