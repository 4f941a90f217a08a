"""``ros2 action list | info | type | send_goal``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, Any

from ._graph import QUIET_SEC, absolute, cli_node, discover, wait_until
from ._messages import InterfaceError, get_interface, parse_values, set_fields, to_yaml

if TYPE_CHECKING:
    from rclpy.node import Node

_STATUS = {1: "ACCEPTED", 2: "EXECUTING", 3: "CANCELING", 4: "SUCCEEDED", 5: "CANCELED", 6: "ABORTED"}
"""action_msgs/GoalStatus codes."""


def main(argv: list[str]) -> int:
    """``ros2 action list|info|type|send_goal``: ros2action's verbs with Jazzy's arguments and output."""
    p = argparse.ArgumentParser(prog="ros2 action", description="Various action related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    ls = sub.add_parser("list", help="Output a list of action names")
    ls.add_argument("-t", "--show-types", action="store_true")
    ls.add_argument("-c", "--count-actions", action="store_true")
    info = sub.add_parser("info", help="Print information about an action")
    info.add_argument("action_name")
    info.add_argument("-t", "--show-types", action="store_true")
    info.add_argument("-c", "--count", action="store_true")
    typ = sub.add_parser("type", help="Print a action's type")
    typ.add_argument("action_name")
    goal = sub.add_parser("send_goal", help="Send an action goal")
    goal.add_argument("action_name")
    goal.add_argument("action_type")
    source = goal.add_mutually_exclusive_group()
    source.add_argument("goal", nargs="?", default="{}", help="the goal's fields in YAML")
    source.add_argument("--stdin", action="store_true", help="read the goal from standard input")
    goal.add_argument("-f", "--feedback", action="store_true", help="echo the goal's feedback")
    args = p.parse_args(argv)
    try:
        with cli_node("ros2action") as node:
            return {"list": _list, "info": _info, "type": _type, "send_goal": _send_goal}[args.cmd](node, args)
    except InterfaceError as err:
        print(str(err), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


def _actions(node: Node) -> list[tuple[str, list[str]]]:
    """(name, types) of every action in the graph, as rclpy's action graph finds them."""
    from rclpy.action.graph import get_action_names_and_types

    return get_action_names_and_types(node)


def _list(node: Node, args: argparse.Namespace) -> int:
    """``list [-t] [-c]``: the actions, sorted, after discovery."""
    discover(node)
    actions = sorted(_actions(node))
    if args.count_actions:
        print(len(actions))
        return 0
    for name, types in actions:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
    return 0


def _info(node: Node, args: argparse.Namespace) -> int:
    """``info NAME [-t] [-c]``: the nodes serving and calling the action, once the graph has settled."""
    from rclpy.action import graph

    name = absolute(args.action_name)

    def clients_and_servers() -> tuple[list[tuple[str, list[str]]], list[tuple[str, list[str]]]]:
        clients: list[tuple[str, list[str]]] = []
        servers: list[tuple[str, list[str]]] = []
        for node_name, ns in node.get_node_names_and_namespaces():
            full = f"{ns.rstrip('/')}/{node_name}"
            for found, kinds in ((clients, "client"), (servers, "server")):
                by_node = getattr(graph, f"get_action_{kinds}_names_and_types_by_node")(node, node_name, ns)
                found.extend((full, types) for action, types in by_node if action == name)
        return sorted(clients), sorted(servers)

    wait_until(node, lambda: name in dict(_actions(node)))
    # a client alone makes the name appear: until the action's own clients and servers are still
    discover(node, 0.0, QUIET_SEC, watch=lambda: repr(clients_and_servers()))
    clients, servers = clients_and_servers()
    print(f"Action: {args.action_name}")
    for title, found in (("Action clients", clients), ("Action servers", servers)):
        print(f"{title}: {len(found)}")
        if not args.count:
            for full, types in found:
                print(f"    {full} [{', '.join(types)}]" if args.show_types else f"    {full}")
    return 0


def _type(node: Node, args: argparse.Namespace) -> int:
    """``type NAME``: the action's type; "Unknown action" with status 1."""
    name = absolute(args.action_name)
    wait_until(node, lambda: name in dict(_actions(node)))
    types = dict(_actions(node)).get(name)
    if not types:
        print(f"Unknown action '{name}'", file=sys.stderr)
        return 1
    print("\n".join(types))
    return 0


def _send_goal(node: Node, args: argparse.Namespace) -> int:
    """As ros2cli Jazzy's ``send_goal()`` (ros2action/verb/send_goal.py): wait for the server however long it
    takes, send the goal, print its feedback with ``-f``, and its result and final status; Ctrl-C while it
    runs cancels it."""
    import rclpy
    from rclpy.action.client import ActionClient

    cls = get_interface(args.action_type, "action")
    goal = set_fields(cls.Goal(), parse_values(sys.stdin.read() if args.stdin else args.goal))
    client = ActionClient(node, cls, args.action_name)
    print("Waiting for an action server to become available...", flush=True)
    client.wait_for_server()
    print(f"Sending goal:\n     {to_yaml(goal)}", flush=True)

    def on_feedback(feedback: Any) -> None:
        print(f"Feedback:\n    {to_yaml(feedback.feedback)}", flush=True)

    sent = client.send_goal_async(goal, on_feedback if args.feedback else None)
    rclpy.spin_until_future_complete(node, sent)
    handle = sent.result()
    if handle is None:
        print(f"Exception while sending goal: {sent.exception()!r}", file=sys.stderr)
        return 1
    if not handle.accepted:
        print("Goal was rejected.")
        return 0
    print(f"Goal accepted with ID: {bytes(handle.goal_id.uuid).hex()}\n", flush=True)
    done = handle.get_result_async()
    try:
        rclpy.spin_until_future_complete(node, done)
    except KeyboardInterrupt:
        print("Canceling goal...")
        canceled = handle.cancel_goal_async()
        rclpy.spin_until_future_complete(node, canceled, timeout_sec=5.0)
        print("Goal canceled.")
        return 0
    result = done.result()
    if result is None:
        print(f"Exception while getting result: {done.exception()!r}", file=sys.stderr)
        return 1
    print(f"Result:\n    {to_yaml(result.result)}")
    print(f"Goal finished with status: {_STATUS.get(result.status, 'UNKNOWN')}", flush=True)
    return 0
