"""``ros2 interface show | list | package | packages | proto``, with ros2cli Jazzy's arguments and output
(ros2interface/verb/*.py)."""

from __future__ import annotations

import argparse
import os
import sys

from ...ros import interface_file
from ._messages import InterfaceError, get_interface, to_yaml


def main(argv: list[str]) -> int:
    """``ros2 interface <verb>``: 0 on success, 1 (with ros2cli's message on stderr) for a type that does not
    exist. ``show`` prints the definition with its comments (nested ones with ``--all-comments``, none with
    ``--no-comments``), ``proto`` a YAML prototype (a service's request, an action's goal, as ros2cli does),
    ``list``/``packages``/``package`` what the ament index of this venv holds."""
    p = argparse.ArgumentParser(prog="ros2 interface", description="Show information about ROS interfaces")
    sub = p.add_subparsers(dest="cmd", required=True)
    show = sub.add_parser("show", help="Output the interface definition")
    comments = show.add_mutually_exclusive_group()
    comments.add_argument("--all-comments", action="store_true", help="Show all comments, nested ones too")
    comments.add_argument("--no-comments", action="store_true", help="Show no comments or whitespace")
    show.add_argument("type", help="e.g. nav_msgs/msg/Odometry; '-' reads it from stdin")
    for name, text in (
        ("list", "List all interface types available"),
        ("packages", "Output a list of packages that provide interfaces"),
    ):
        by_kind = sub.add_parser(name, help=text)
        by_kind.add_argument("-m", "--only-msgs", action="store_true")
        by_kind.add_argument("-s", "--only-srvs", action="store_true")
        by_kind.add_argument("-a", "--only-actions", action="store_true")
    pkg = sub.add_parser("package", help="Output a list of available interface types within one package")
    pkg.add_argument("package_name")
    proto = sub.add_parser("proto", help="Output an interface prototype")
    proto.add_argument("type")
    args = p.parse_args(argv)
    from ament_index_python.packages import get_packages_with_prefixes

    if args.cmd == "proto":
        parts = args.type.strip("/").split("/")
        kind = parts[1] if len(parts) == 3 and parts[1] in ("msg", "srv", "action") else "msg"
        try:
            cls = get_interface(args.type, kind)
        except InterfaceError as err:
            print(str(err), file=sys.stderr)
            return 1
        prototype = cls.Request() if kind == "srv" else cls.Goal() if kind == "action" else cls()
        print(f'"{to_yaml(prototype)}"')
        return 0
    if args.cmd == "show":
        name = sys.stdin.readline().strip() if args.type == "-" else args.type
        try:
            _show(name.strip("/"), not args.no_comments, args.all_comments, 0)
        except LookupError as err:
            print(str(err), file=sys.stderr)
            return 1
        return 0
    packages = get_packages_with_prefixes()
    if args.cmd == "packages":
        wanted = [
            k for k, on in (("msg", args.only_msgs), ("srv", args.only_srvs), ("action", args.only_actions)) if on
        ]
        for name in sorted(packages):
            kinds = wanted[:1] or ["msg", "srv", "action"]  # ros2interface: the first flag given wins
            if any(_definitions(packages[name], name, k) for k in kinds):
                print(name)
        return 0
    return _list(args, packages)


def _list(args: argparse.Namespace, packages: dict[str, str]) -> int:
    """``list`` (every package's interfaces under Messages/Services/Actions, ``-m``/``-s``/``-a`` one kind)
    and ``package NAME`` (its interfaces, one a line), as ros2interface prints them."""
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
        found = [f"{name}/{kind}/{d}" for name in names for d in _definitions(packages[name], name, kind)]
        if args.cmd == "package":
            print("\n".join(found)) if found else None
            continue
        if found:
            print(f"{titles[kind]}:")
            for f in found:
                print(f"    {f}")
    return 0


def _definitions(prefix: str, package: str, kind: str) -> list[str]:
    """The names of ``package``'s interfaces of ``kind`` (msg, srv, action) under its install prefix."""
    folder = os.path.join(prefix, "share", package, kind)
    if not os.path.isdir(folder):
        return []
    return sorted(f.rsplit(".", 1)[0] for f in os.listdir(folder) if f.endswith(f".{kind}"))


def _show(identifier: str, comments: bool, nested_comments: bool, indent: int) -> None:
    """ros2interface Jazzy's ``_show_interface`` (verb/show.py): the definition's lines, each field of a
    message type followed by that type's definition one tab further in; comments (whole lines and trailing
    ones) and blank lines shown at the top level unless ``--no-comments``, in nested ones only with
    ``--all-comments``. Lines are read with rosidl_adapter's parser, as upstream reads them."""
    from rosidl_adapter.parser import (
        ACTION_REQUEST_RESPONSE_SEPARATOR,
        SERVICE_REQUEST_RESPONSE_SEPARATOR,
        parse_message_string,
    )

    parts = identifier.split("/")
    if len(parts) != 3:
        raise LookupError(f"Invalid name '{identifier}'. Expected three parts separated by '/'")
    package, kind, name = parts
    try:  # the one checked way from a name to a file: rosidl's rules, the ament index's interfaces
        path = interface_file(identifier)
    except InterfaceError as err:
        raise LookupError(str(err)) from None
    with open(path, encoding="utf-8") as f:
        lines = [line.rstrip() for line in f]
    tabs = "\t" * indent
    for text in lines:
        spec = None
        if text not in (SERVICE_REQUEST_RESPONSE_SEPARATOR, ACTION_REQUEST_RESPONSE_SEPARATOR):
            spec = parse_message_string(pkg_name=package, msg_name=name, message_string=text)
        field = spec.fields[0] if spec is not None and spec.fields else None
        constant = spec.constants[0] if spec is not None and spec.constants else None
        shown = text
        if not comments:
            if not text or (spec is not None and spec.annotations.get("comment")):
                shown = ""
            else:
                element = field or constant
                trailing = element.annotations.get("comment") if element is not None else None
                if trailing:  # cut at the '#' before it (ros2interface's tests expect no '#' left)
                    shown = text[: text.rfind("#", 0, text.find(trailing[0]))].strip()
            if not shown:
                continue
        print(f"{tabs}{shown}" if shown else "")
        if field is not None and "/" in str(field.type):
            nested = str(field.type)
            nested = nested[: nested.find("[")] if field.type.is_array else nested
            _show(nested.replace("/", "/msg/"), nested_comments, nested_comments, indent + 1)
