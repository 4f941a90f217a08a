"""``ros2 param list | get | set | describe | dump | load``, with ros2cli Jazzy's arguments and output,
through the nodes' standard parameter services (rclpy's AsyncParameterClient)."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, Any

import yaml

from ..._errors import SimError
from ._graph import absolute, cli_node, discover, wait_until

if TYPE_CHECKING:
    from rclpy.node import Node

SERVICE_TIMEOUT_SEC = 5.0

_GET_LABELS = {
    1: "Boolean value is:",
    2: "Integer value is:",
    3: "Double value is:",
    4: "String value is:",
    5: "Byte values are:",
    6: "Boolean values are:",
    7: "Integer values are:",
    8: "Double values are:",
    9: "String values are:",
}
_TYPE_NAMES = {
    0: "not set",
    1: "boolean",
    2: "integer",
    3: "double",
    4: "string",
    5: "byte array",
    6: "boolean array",
    7: "integer array",
    8: "double array",
    9: "string array",
}


class ParamError(SimError):
    """A one-line failure (printed to stderr, exit status 1)."""


def main(argv: list[str]) -> int:
    """``ros2 param VERB ...``: ros2param's verbs and arguments (Jazzy); the exit status is 1 with one line on
    stderr for a node, service or file that is not there, as upstream."""
    p = argparse.ArgumentParser(prog="ros2 param", description="Various param related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    ls = sub.add_parser("list", help="Output a list of available parameters")
    ls.add_argument("node_name", nargs="?")
    ls.add_argument("--include-hidden-nodes", action="store_true")
    ls.add_argument("--param-prefixes", nargs="+", default=[])
    ls.add_argument("--param-type", action="store_true")
    get = sub.add_parser("get", help="Get parameter")
    get.add_argument("node_name")
    get.add_argument("parameter_name")
    get.add_argument("--include-hidden-nodes", action="store_true")
    get.add_argument("--hide-type", action="store_true")
    st = sub.add_parser("set", help="Set parameter")
    st.add_argument("node_name")
    st.add_argument("params_and_values", nargs="+", metavar="name value")
    st.add_argument("--include-hidden-nodes", action="store_true")
    st.add_argument("--timeout", type=int, default=1)
    desc = sub.add_parser("describe", help="Show descriptive information about declared parameters")
    desc.add_argument("node_name")
    desc.add_argument("parameter_names", nargs="+")
    desc.add_argument("--include-hidden-nodes", action="store_true")
    dump = sub.add_parser("dump", help="Show all of the parameters of a node in a YAML file format")
    dump.add_argument("node_name")
    dump.add_argument("--include-hidden-nodes", action="store_true")
    load = sub.add_parser("load", help="Load parameter file for a node")
    load.add_argument("node_name")
    load.add_argument("parameter_file")
    load.add_argument("--include-hidden-nodes", action="store_true")
    load.add_argument("--no-use-wildcard", action="store_true")
    args = p.parse_args(argv)
    if args.cmd == "set" and len(args.params_and_values) % 2:
        print(
            "Parameters must be provided as name/value pairs: name value [name value ...]. "
            f"Got {len(args.params_and_values)} argument(s).",
            file=sys.stderr,
        )
        return 1
    try:
        with cli_node("ros2param") as node:
            return {"list": _list, "get": _get, "set": _set, "describe": _describe, "dump": _dump, "load": _load}[
                args.cmd
            ](node, args)
    except ParamError as err:
        print(str(err), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


# --------------------------------------------------------------------------- helpers
def _node_names(node: Node, hidden: bool) -> list[str]:
    """The graph's nodes as full names; hidden ones (a name part starting with ``_``) only when asked."""
    out = []
    for name, ns in node.get_node_names_and_namespaces():
        full = f"{ns.rstrip('/')}/{name}"
        if hidden or not any(part.startswith("_") for part in full.split("/") if part):
            out.append(full)
    return sorted(set(out))


def _find_node(node: Node, name: str, hidden: bool) -> str:
    """The full name of the node the user named, once discovery has seen it; "Node not found" otherwise
    (ros2param's message)."""
    full = absolute(name)
    if not wait_until(node, lambda: full in _node_names(node, True)):
        raise ParamError("Node not found")
    return full


def _client(node: Node, target: str) -> Any:
    """An rclpy parameter client for ``target``, its services ready; an error naming the node when they never
    appear (a node started with ``start_parameter_services=False``)."""
    from rclpy.parameter_client import AsyncParameterClient

    client = AsyncParameterClient(node, target)
    if not client.wait_for_services(timeout_sec=SERVICE_TIMEOUT_SEC):
        raise ParamError(f"Node '{target}' has no parameter services")
    return client


def _result(node: Node, future: Any, what: str) -> Any:
    """Spin until a parameter service's answer; an error naming the node after
    :data:`SERVICE_TIMEOUT_SEC` (upstream waits forever; a wedged node must not hang a script)."""
    import rclpy

    rclpy.spin_until_future_complete(node, future, timeout_sec=SERVICE_TIMEOUT_SEC)
    if not future.done() or future.result() is None:
        raise ParamError(f"{what}: no answer within {SERVICE_TIMEOUT_SEC:g} s")
    return future.result()


def _python(value: Any) -> Any:
    """A ParameterValue as the Python value ros2param prints (arrays as lists)."""
    from rclpy.parameter import parameter_value_to_python

    v = parameter_value_to_python(value)
    return list(v) if not isinstance(v, (bool, int, float, str)) and v is not None else v


# --------------------------------------------------------------------------- verbs
def _list(node: Node, args: argparse.Namespace) -> int:
    """``list [NODE]``: each node's parameter names, sorted, under a ``/node:`` line when no node is named;
    ``--param-type`` adds each one's type as ``describe`` names it."""
    if args.node_name:
        names = [_find_node(node, args.node_name, args.include_hidden_nodes)]
    else:
        discover(node)
        names = _node_names(node, args.include_hidden_nodes)
    services = {n for n, _ in node.get_service_names_and_types()}
    for target in names:
        if f"{target}/list_parameters" not in services and not args.node_name:
            continue
        client = _client(node, target)
        listed = _result(node, client.list_parameters(prefixes=args.param_prefixes or None), target)
        param_names = sorted(listed.result.names)
        types: dict[str, str] = {}
        if args.param_type and param_names:
            described = _result(node, client.describe_parameters(param_names), target)
            types = {d.name: _TYPE_NAMES.get(d.type, "?") for d in described.descriptors}
        if not args.node_name:
            print(f"{target}:")
        for name in param_names:
            print(f"  {name} (type: {types[name]})" if args.param_type else f"  {name}")
    return 0


def _get(node: Node, args: argparse.Namespace) -> int:
    """``get NODE NAME``: ros2param's ``Double value is: 0.34`` (the label by type), ``--hide-type`` the value
    alone, "Parameter not set." for an undeclared one."""
    target = _find_node(node, args.node_name, args.include_hidden_nodes)
    got = _result(node, _client(node, target).get_parameters([args.parameter_name]), target)
    if not got.values:
        raise ParamError("Parameter not set")
    if got.values[0].type == 0:
        print("Parameter not set.")
        return 0
    value = got.values[0]
    shown = _python(value)
    print(shown if args.hide_type else f"{_GET_LABELS[value.type]} {shown}")
    return 0


def _set(node: Node, args: argparse.Namespace) -> int:
    """``set NODE NAME VALUE [NAME VALUE ...]``: each value parsed as YAML (``0.5`` a double, ``true`` a bool,
    ``[1, 2]`` an array), as ros2param's ``get_parameter_value``; one result line each, a refusal on stderr
    with the node's reason and status 1."""
    from rcl_interfaces.msg import Parameter
    from rclpy.parameter import get_parameter_value

    target = _find_node(node, args.node_name, args.include_hidden_nodes)
    pairs = list(zip(args.params_and_values[::2], args.params_and_values[1::2], strict=True))
    params = [Parameter(name=n, value=get_parameter_value(string_value=v)) for n, v in pairs]
    answer = _result(node, _client(node, target).set_parameters(params), target)
    failed = False
    for (name, _), result in zip(pairs, answer.results, strict=True):
        ok = "Set parameter successful" if result.successful else "Setting parameter failed"
        text = f"{ok}: {result.reason}" if result.reason else ok
        text = f"{name}: {text}" if len(pairs) > 1 else text
        print(text, file=sys.stdout if result.successful else sys.stderr)
        failed |= not result.successful
    return 1 if failed else 0


def _describe(node: Node, args: argparse.Namespace) -> int:
    """``describe NODE NAME...``: type, description and constraints (read only, ranges) as ros2param
    prints them."""
    target = _find_node(node, args.node_name, args.include_hidden_nodes)
    described = _result(node, _client(node, target).describe_parameters(args.parameter_names), target)
    for d in described.descriptors:
        print("Parameter name:", d.name)
        print("  Type:", _TYPE_NAMES.get(d.type, "?"))
        if d.description:
            print("  Description:", d.description)
        print("  Constraints:")
        if d.read_only:
            print("    Read only: true")
        ranges = list(d.floating_point_range) + list(d.integer_range)
        if ranges:
            print("    Min value:", ranges[0].from_value)
            print("    Max value:", ranges[0].to_value)
            if ranges[0].step:
                print("    Step:", ranges[0].step)
        if d.additional_constraints:
            print("    Additional constraints:", d.additional_constraints)
    return 0


def _dump(node: Node, args: argparse.Namespace) -> int:
    """``dump NODE``: every parameter as a parameters file (``/node: ros__parameters: ...``, dotted names
    nested), which ``load`` and ``--params-file`` read back."""
    target = _find_node(node, args.node_name, args.include_hidden_nodes)
    client = _client(node, target)
    names = sorted(_result(node, client.list_parameters(), target).result.names)
    values = _result(node, client.get_parameters(names), target).values if names else []
    params: dict[str, Any] = {}
    for name, value in zip(names, values, strict=True):
        level = params
        *parents, leaf = name.split(".")
        for part in parents:
            level = level.setdefault(part, {})
        level[leaf] = _python(value)
    print(yaml.safe_dump({target: {"ros__parameters": params}}, sort_keys=False, default_flow_style=False), end="")
    return 0


def _load(node: Node, args: argparse.Namespace) -> int:
    """``load NODE FILE``: the file's sections for this node (``/**`` first, the node's own over it) set in
    one call; one line per parameter, refusals on stderr."""
    from rclpy.parameter import Parameter

    target = _find_node(node, args.node_name, args.include_hidden_nodes)
    try:
        with open(args.parameter_file, encoding="utf-8") as f:
            data = yaml.safe_load(f) or {}
    except OSError as err:
        raise ParamError(f"could not read '{args.parameter_file}': {err.strerror}") from None
    except yaml.YAMLError as err:
        raise ParamError(f"{args.parameter_file}: not valid YAML ({err})") from None
    # the wildcard's section first, then the node's own, which wins where both set a parameter, as rclpy's
    # parameter_dict_from_yaml_file orders them (rclpy/parameter.py, Jazzy). Upstream's `ros2 param load`
    # then sets every section of the file on the node, other nodes' too; gazelle takes the node's alone.
    keys = ([] if args.no_use_wildcard else ["/**"]) + [target.lstrip("/"), target]
    section: dict[str, Any] = {}
    for key in keys:
        entry = data.get(key) if isinstance(data, dict) else None
        if entry is None:
            continue
        if not (isinstance(entry, dict) and isinstance(entry.get("ros__parameters"), dict)):
            raise ParamError(f"YAML file is not a valid ROS parameter file for node {key}")
        section.update(entry["ros__parameters"])
    if not section:
        raise ParamError(f"Param file does not contain parameters for {target}")
    flat: dict[str, Any] = {}

    def walk(prefix: str, value: Any) -> None:
        """Flatten nested mappings into dotted parameter names."""
        if isinstance(value, dict):
            for k, v in value.items():
                walk(f"{prefix}{k}.", v)
        else:
            flat[prefix.rstrip(".")] = value

    walk("", section)
    params = [Parameter(name, value=value) for name, value in flat.items()]
    answer = _result(node, _client(node, target).set_parameters(params), target)
    failed = False
    for name, result in zip(flat, answer.results, strict=True):
        ok = "successful" if result.successful else "failed"
        reason = f": {result.reason}" if result.reason else ""
        print(f"Set parameter {name} {ok}{reason}", file=sys.stdout if result.successful else sys.stderr)
        failed |= not result.successful
    return 1 if failed else 0
