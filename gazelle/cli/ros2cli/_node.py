"""``ros2 node list | info``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from ._graph import QUIET_SEC, absolute, cli_node, discover, wait_until

if TYPE_CHECKING:
    from rclpy.node import Node


def main(argv: list[str]) -> int:
    """``ros2 node list [-a] [-c]`` and ``ros2 node info NODE [--include-hidden]`` as ros2node Jazzy prints
    them (verb/list.py, verb/info.py)."""
    p = argparse.ArgumentParser(prog="ros2 node", description="Various node related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    ls = sub.add_parser("list", help="Output a list of available nodes")
    ls.add_argument("-a", "--all", action="store_true", help="Display all nodes even hidden ones")
    ls.add_argument("-c", "--count-nodes", action="store_true", help="Only display the number of nodes discovered")
    info = sub.add_parser("info", help="Output information about a node")
    info.add_argument("node_name")
    info.add_argument(
        "--include-hidden", action="store_true", help="Display hidden topics, services, and actions as well"
    )
    args = p.parse_args(argv)
    with cli_node("ros2node") as node:
        if args.cmd == "list":
            discover(node)
            names = sorted(full for full in _node_names(node) if args.all or not _hidden(full))
            print(len(names) if args.count_nodes else "\n".join(names))
            return 0
        return _info(node, absolute(args.node_name), args.include_hidden)


def _node_names(node: Node) -> list[str]:
    """Every node in the graph by its full name (a name twice when two nodes have it)."""
    return [f"{ns.rstrip('/')}/{n}" for n, ns in node.get_node_names_and_namespaces()]


def _hidden(name: str) -> bool:
    """ros2node's ``_is_hidden_name``: a part of the name starts with ``_`` (hidden nodes, and the topics and
    services an action is made of: ``/x/_action/feedback``)."""
    return any(part.startswith("_") for part in name.split("/"))


def _info(node: Node, target: str, include_hidden: bool) -> int:
    """``info``: the node's subscribers, publishers, service servers and clients, action servers and clients,
    each under its title with an empty line when there are none; hidden names only with
    ``--include-hidden``; a warning on stderr when several nodes have the name, as upstream."""
    from rclpy.action.graph import get_action_client_names_and_types_by_node, get_action_server_names_and_types_by_node

    if target not in _node_names(node):
        wait_until(node, lambda: target in _node_names(node))
    count = _node_names(node).count(target)
    if count == 0:
        print(f"Unable to find node '{target}'", file=sys.stderr)
        return 1
    ns, _, name = target.rpartition("/")
    ns = ns or "/"
    sections = (
        ("Subscribers", node.get_subscriber_names_and_types_by_node),
        ("Publishers", node.get_publisher_names_and_types_by_node),
        ("Service Servers", node.get_service_names_and_types_by_node),
        ("Service Clients", node.get_client_names_and_types_by_node),
        ("Action Servers", lambda n, s: get_action_server_names_and_types_by_node(node, n, s)),
        ("Action Clients", lambda n, s: get_action_client_names_and_types_by_node(node, n, s)),
    )

    def endpoints() -> tuple:
        return tuple(tuple(sorted(n for n, _ in get(name, ns))) for _title, get in sections)

    # its endpoints arrive after the node itself (services last): until its own lists are still
    discover(node, 0.0, QUIET_SEC, watch=endpoints)
    if count > 1:
        print(
            f'There are {count} nodes in the graph with the exact name "{target}". '
            "You are seeing information about only one of them.",
            file=sys.stderr,
        )
    print(target)
    for title, getter in sections:
        print(f"  {title}:")
        shown = [(n, t) for n, t in sorted(getter(name, ns)) if include_hidden or not _hidden(n)]
        print(*[f"    {n}: {', '.join(t)}" for n, t in shown], sep="\n")
    return 0
