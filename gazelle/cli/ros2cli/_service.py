"""``ros2 service list | type | find | call``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from ._graph import absolute, cli_node, discover, is_hidden, wait_until
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
