"""``ros2 node list | info``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys
import time
from typing import TYPE_CHECKING

from ._daemon_graph import SECTIONS, DaemonGraph, daemon_graph
from ._graph import QUIET_SEC, SETTLE_SEC, absolute, add_discovery_options, cli_node, discover, graph_view, wait_until

TITLES = ("Subscribers", "Publishers", "Service Servers", "Service Clients", "Action Servers", "Action Clients")

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
    add_discovery_options(ls, info)  # ros2cli's NodeStrategy options
    args = p.parse_args(argv)
    if args.cmd == "list":
        with graph_view("ros2node", args.no_daemon, args.spin_time) as graph:
            names = sorted(full for full in _node_names(graph) if args.all or not _hidden(full))
        print(len(names) if args.count_nodes else "\n".join(names))
        return 0
    target = absolute(args.node_name)
    graph = None if args.no_daemon else daemon_graph()
    if graph is not None:
        return _daemon_info(graph, target, args.include_hidden)
    with cli_node("ros2node") as node:
        return _info(node, target, args.include_hidden)


def _node_names(node: Node | DaemonGraph) -> list[str]:
    """Every node in the graph by its full name (a name twice when two nodes have it)."""
    return [f"{ns.rstrip('/')}/{n}" for n, ns in node.get_node_names_and_namespaces()]


def _hidden(name: str) -> bool:
    """ros2node's ``_is_hidden_name``: a part of the name starts with ``_`` (hidden nodes, and the topics and
    services an action is made of: ``/x/_action/feedback``)."""
    return any(part.startswith("_") for part in name.split("/"))


def _daemon_info(graph: DaemonGraph, target: str, include_hidden: bool) -> int:
    """``info`` from the daemon's graph: a node not in it is looked for again for :data:`SETTLE_SEC` (it may
    be starting), then "Unable to find node"."""
    deadline = time.monotonic() + SETTLE_SEC
    while target not in _node_names(graph) and time.monotonic() < deadline:
        time.sleep(0.05)
        graph = daemon_graph(start=False) or graph
    count = _node_names(graph).count(target)
    if count == 0:
        print(f"Unable to find node '{target}'", file=sys.stderr)
        return 1
    ns, _, name = target.rpartition("/")
    found = graph.endpoints(name, ns or "/")
    _print_info(target, count, [found[s] for s in SECTIONS], include_hidden)
    return 0


def _print_info(target: str, count: int, lists: list[list[tuple[str, list[str]]]], include_hidden: bool) -> None:
    """ros2node's ``info`` output: a warning when several nodes have the name, then each section."""
    if count > 1:
        print(
            f'There are {count} nodes in the graph with the exact name "{target}". '
            "You are seeing information about only one of them.",
            file=sys.stderr,
        )
    print(target)
    for title, found in zip(TITLES, lists, strict=True):
        print(f"  {title}:")
        shown = [(n, t) for n, t in sorted(found) if include_hidden or not _hidden(n)]
        print(*[f"    {n}: {', '.join(t)}" for n, t in shown], sep="\n")


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
    _print_info(target, count, [list(getter(name, ns)) for _title, getter in sections], include_hidden)
    return 0
