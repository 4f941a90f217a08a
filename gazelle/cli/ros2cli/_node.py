"""``ros2 node list | info``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys

from ._graph import QUIET_SEC, absolute, cli_node, discover, wait_until


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(prog="ros2 node", description="Various node related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    ls = sub.add_parser("list")
    ls.add_argument("-a", "--all", action="store_true")
    ls.add_argument("-c", "--count-nodes", action="store_true")
    info = sub.add_parser("info")
    info.add_argument("node_name")
    args = p.parse_args(argv)
    with cli_node("ros2node") as node:
        if args.cmd == "list":
            discover(node)
        names = sorted(
            f"{ns.rstrip('/')}/{n}"
            for n, ns in node.get_node_names_and_namespaces()
            if args.cmd != "list" or args.all or not n.startswith("_")
        )
        if args.cmd == "list":
            if args.count_nodes:
                print(len(names))
                return 0
            print("\n".join(names))
            return 0
        target = absolute(args.node_name)

        def node_names() -> list[str]:
            return [f"{ns.rstrip('/')}/{n}" for n, ns in node.get_node_names_and_namespaces()]

        if target not in names and wait_until(node, lambda: target in node_names()):
            names = node_names()
        if target not in names:
            print(f"Unable to find node '{target}'", file=sys.stderr)
            return 1
        ns, _, name = target.rpartition("/")
        ns = ns or "/"
        getters = (
            ("Subscribers", node.get_subscriber_names_and_types_by_node),
            ("Publishers", node.get_publisher_names_and_types_by_node),
            ("Service Servers", node.get_service_names_and_types_by_node),
            ("Service Clients", node.get_client_names_and_types_by_node),
        )

        def endpoints() -> tuple:
            return tuple(tuple(sorted(n for n, _ in get(name, ns))) for _title, get in getters)

        # its endpoints arrive after the node itself (services last): until its own lists are still
        discover(node, 0.0, QUIET_SEC, watch=endpoints)
        print(target)
        for title, getter in getters:
            print(f"  {title}:")
            for topic, types in sorted(getter(name, ns)):
                print(f"    {topic}: {', '.join(types)}")
        return 0
