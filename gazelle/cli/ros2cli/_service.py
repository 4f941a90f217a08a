"""``ros2 service list | type | find | call``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import sys
import time
from typing import TYPE_CHECKING

from ._graph import absolute, add_discovery_options, cli_node, graph_view, is_hidden, spin_once
from ._messages import InterfaceError, get_interface, parse_values, set_fields

if TYPE_CHECKING:
    from rclpy.node import Node


def service_main(argv: list[str]) -> int:
    """``ros2 service list|type|find|call``: ros2service's verbs with Jazzy's arguments and output."""
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
    source = call.add_mutually_exclusive_group()
    source.add_argument("values", nargs="?", default="{}", help="the request's fields in YAML")
    source.add_argument("--stdin", action="store_true", help="read the YAML values from standard input")
    call.add_argument("-r", "--rate", type=float, default=None, help="repeat the call at this rate in Hz")
    add_discovery_options(ls, typ, find)  # ros2cli's NodeStrategy options
    args = p.parse_args(argv)
    try:
        if args.cmd == "call":
            with cli_node("ros2service") as node:
                return _call(node, args)
        with graph_view("ros2service", args.no_daemon, args.spin_time) as node:
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


def _call(node: Node, args: argparse.Namespace) -> int:
    """Call as ros2cli Jazzy's ``requester()`` (ros2service/verb/call.py): wait for the service however long
    it takes (saying so once), print the request and the response as their reprs (Jazzy prints
    ``response:`` and ``std_srvs.srv.SetBool_Response(success=True, message='')``, not YAML), wait for the
    answer however long it takes, and with ``--rate`` call again each period until Ctrl-C."""
    if args.rate is not None and args.rate <= 0:
        print("rate must be greater than zero", file=sys.stderr)
        return 1
    cls = get_interface(args.service_type, "srv")
    if not (hasattr(cls, "Request") and hasattr(cls, "Response")):
        print("The passed type is not a service", file=sys.stderr)
        return 1
    request = set_fields(cls.Request(), parse_values(sys.stdin.read() if args.stdin else args.values))
    client = node.create_client(cls, args.service_name)
    if not client.service_is_ready():
        print("waiting for service to become available...", flush=True)
        while not client.wait_for_service(timeout_sec=1.0):
            pass
    period = 1.0 / args.rate if args.rate else None
    while True:
        print(f"requester: making request: {request!r}\n", flush=True)
        last_call = time.monotonic()
        future = client.call_async(request)
        while not future.done():
            spin_once(node, timeout_sec=0.1)
        print(f"response:\n{future.result()!r}\n", flush=True)
        if period is None:
            return 0
        time.sleep(max(0.0, last_call + period - time.monotonic()))
