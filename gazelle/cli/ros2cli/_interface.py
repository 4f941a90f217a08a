"""``ros2 interface show | list | package``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import os
import sys

from ._messages import InterfaceError, get_interface, to_yaml


def main(argv: list[str]) -> int:
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
