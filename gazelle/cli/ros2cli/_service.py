"""``ros2 service list | type | find | call``, ``ros2 node list | info`` and ``ros2 interface show | list |
package``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import os
import sys
import time
from typing import Any

from ._graph import QUIET_SEC, absolute, cli_node, discover, is_hidden, wait_until
from ._messages import InterfaceError, get_interface, parse_values, set_fields, to_yaml


def service_main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(prog="ros2 service", description="Various service related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    ls = sub.add_parser("list")
    ls.add_argument("-t", "--show-types", action="store_true")
    ls.add_argument("-c", "--count-services", action="store_true")
    ls.add_argument("--include-hidden-services", action="store_true")
    typ = sub.add_parser("type")
    typ.add_argument("service_name")
    find = sub.add_parser("find")
    find.add_argument("service_type")
    call = sub.add_parser("call")
    call.add_argument("service_name")
    call.add_argument("service_type")
    call.add_argument("values", nargs="?", default="{}")
    call.add_argument("-r", "--rate", type=float, default=None)
    args = p.parse_args(argv)
    try:
        with cli_node("ros2service") as node:
            if args.cmd == "call":
                return _call(node, args)
            discover(node)
            services = {n: t for n, t in node.get_service_names_and_types()}
            if args.cmd == "list":
                shown = {n: t for n, t in services.items() if args.include_hidden_services or not is_hidden(n)}
                if args.count_services:
                    print(len(shown))
                for n in sorted(shown) if not args.count_services else []:
                    print(f"{n} [{', '.join(shown[n])}]" if args.show_types else n)
                return 0
            if args.cmd == "type":
                name = absolute(args.service_name)
                wait_until(node, lambda: name in dict(node.get_service_names_and_types()))
                services = dict(node.get_service_names_and_types())
                if name not in services:
                    print(f"Unknown service '{name}'", file=sys.stderr)
                    return 1
                print("\n".join(services[name]))
                return 0
            for n in sorted(n for n, t in services.items() if args.service_type in t):
                print(n)
            return 0
    except InterfaceError as err:
        print(str(err), file=sys.stderr)
        return 1


def _call(node: Any, args: argparse.Namespace) -> int:
    import rclpy

    cls = get_interface(args.service_type, "srv")
    request = set_fields(cls.Request(), parse_values(args.values))
    client = node.create_client(cls, args.service_name)
    if not client.wait_for_service(timeout_sec=10.0):
        print(
            f"waiting for service to become available... ({args.service_name} did not appear in 10 s)", file=sys.stderr
        )
        return 1
    while True:
        print(
            f"requester: making request: {type(request).__module__.split('.')[0]}.srv.{request.__class__.__name__}()\n"
        )
        future = client.call_async(request)
        rclpy.spin_until_future_complete(node, future, timeout_sec=30.0)
        if not future.done():
            print("the service did not answer in 30 s", file=sys.stderr)
            return 1
        print("response:")
        print(f"{to_yaml(future.result())}", flush=True)
        if not args.rate:
            return 0
        time.sleep(1.0 / args.rate)


def node_main(argv: list[str]) -> int:
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


def interface_main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(prog="ros2 interface", description="Show information about ROS interfaces")
    sub = p.add_subparsers(dest="cmd", required=True)
    show = sub.add_parser("show")
    show.add_argument("type")
    ls = sub.add_parser("list")
    ls.add_argument("-m", "--only-msgs", action="store_true")
    ls.add_argument("-s", "--only-srvs", action="store_true")
    ls.add_argument("-a", "--only-actions", action="store_true")
    pkg = sub.add_parser("package")
    pkg.add_argument("package_name")
    proto = sub.add_parser("proto", help="Output an interface prototype")
    proto.add_argument("type")
    args = p.parse_args(argv)
    from ament_index_python.packages import get_package_share_directory, get_packages_with_prefixes

    if args.cmd == "proto":
        kind = args.type.strip("/").split("/")[1] if args.type.count("/") >= 2 else "msg"
        try:
            cls = get_interface(args.type, kind)
        except InterfaceError as err:
            print(str(err), file=sys.stderr)
            return 1
        prototype = cls.Request() if kind == "srv" else cls.Goal() if kind == "action" else cls()
        print(f'"{to_yaml(prototype)}"')
        return 0
    if args.cmd == "show":
        parts = args.type.strip("/").split("/")
        if len(parts) != 3:
            print(f"Invalid name '{args.type}'. Expected pkg/msg|srv|action/Name", file=sys.stderr)
            return 1
        pkg_name, kind, name = parts
        try:
            path = os.path.join(get_package_share_directory(pkg_name), kind, f"{name}.{kind}")
        except (LookupError, ValueError):
            print(f"Unknown package '{pkg_name}'", file=sys.stderr)
            return 1
        if not os.path.isfile(path):
            print(f"Could not find the interface '{args.type}'", file=sys.stderr)
            return 1
        with open(path, encoding="utf-8") as f:
            print(f.read().rstrip("\n"))
        return 0
    packages = get_packages_with_prefixes()
    names = [args.package_name] if args.cmd == "package" else sorted(packages)
    if args.cmd == "package" and args.package_name not in packages:
        print(f"Unknown package '{args.package_name}'", file=sys.stderr)
        return 1
    kinds = [
        k
        for k, only in (
            ("msg", args.only_msgs if args.cmd == "list" else False),
            ("srv", getattr(args, "only_srvs", False)),
            ("action", getattr(args, "only_actions", False)),
        )
        if only
    ] or ["msg", "srv", "action"]
    titles = {"msg": "Messages", "srv": "Services", "action": "Actions"}
    for kind in kinds:
        found = []
        for name in names:
            folder = os.path.join(packages[name], "share", name, kind)
            if os.path.isdir(folder):
                found += [
                    f"{name}/{kind}/{f.rsplit('.', 1)[0]}" for f in sorted(os.listdir(folder)) if f.endswith(f".{kind}")
                ]
        if args.cmd == "package":
            print("\n".join(found)) if found else None
            continue
        if found:
            print(f"{titles[kind]}:")
            for f in found:
                print(f"    {f}")
    return 0
