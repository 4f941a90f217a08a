"""``ros2 launch PKG FILE [name:=value ...]`` or ``ros2 launch PATH ...`` with ``--show-args``,
``--debug``, ``--print`` and ``--launch-prefix``."""

from __future__ import annotations

import argparse
import os
import re
import sys
from typing import Any

_PACKAGE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
"""A ROS package name (REP 144: lower case by rule; upper case is found in the wild, so accepted)."""


def _find_launch_file(package: str, name: str) -> str:
    """The launch file ``name`` in ``package``'s share folder, as ros2launch's ``get_share_file_path_from_package``
    finds it (searched below it; two files of that name are an error naming both)."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory

    if not _PACKAGE_NAME.fullmatch(package):
        raise LookupError(f"'{package}' is neither a launch file nor a package name")
    if os.sep in name or name in (".", ".."):
        raise LookupError(f"'{name}' is a path: give the launch file's name in package '{package}'")
    try:
        share = get_package_share_directory(package)
    except (PackageNotFoundError, LookupError, ValueError):
        raise LookupError(f"Package '{package}' not found") from None
    matches = []
    for root, _dirs, files in os.walk(share, followlinks=True):
        if name in files:
            matches.append(os.path.join(root, name))
    if not matches:
        raise LookupError(
            f"file '{name}' was not found in the share directory of package '{package}' which is at '{share}'"
        )
    if len(matches) > 1:
        raise LookupError(
            f"multiple files named '{name}' found in the share directory of package '{package}': {matches}"
        )
    return matches[0]


def main(argv: list[str]) -> int:
    """``ros2 launch <package> <file> [name:=value ...]`` (or a launch file's path), with ros2launch's options: the
    launch file found in the package's share folder, then run with its arguments."""
    p = argparse.ArgumentParser(prog="ros2 launch", description="Run a launch file")
    p.add_argument("-n", "--noninteractive", action="store_true")
    p.add_argument("-d", "--debug", action="store_true", help="Put the launch system in debug mode")
    p.add_argument("-p", "--print", "--print-description", dest="print_description", action="store_true")
    p.add_argument("-s", "--show-args", "--show-arguments", dest="show_args", action="store_true")
    p.add_argument(
        "--launch-prefix",
        default=None,
        help="Prefix command, which should go before all executables (e.g. --launch-prefix 'xterm -e gdb --args')",
    )
    p.add_argument(
        "--launch-prefix-filter",
        default=None,
        help="Regex pattern for filtering which executables the --launch-prefix is applied to",
    )
    p.add_argument("package_name", help="Name of the ROS package which contains the launch file (or a path)")
    p.add_argument("launch_file_name", nargs="?", help="Name of the launch file")
    p.add_argument("launch_arguments", nargs="*", help="Arguments to the launch file; '<name>:=<value>'")
    args = p.parse_args(argv)
    from launch.logging import log

    positional = (
        [args.package_name] + ([args.launch_file_name] if args.launch_file_name else []) + args.launch_arguments
    )
    if os.path.isfile(positional[0]) or positional[0].endswith((".py", ".xml", ".yaml", ".yml")):
        path, rest = positional[0], positional[1:]
        if not os.path.isfile(path):
            log("ERROR", "launch", f"launch file '{path}' does not exist")
            return 1
    elif os.path.isdir(positional[0]):
        log("ERROR", "launch", f"'{positional[0]}' is a folder: name a launch file, or a package and its launch file")
        return 1
    else:
        if len(positional) < 2:
            p.error("a launch file name is needed after the package name")
        try:
            path = _find_launch_file(positional[0], positional[1])
        except LookupError as err:
            print(str(err), file=sys.stderr)
            return 1
        rest = positional[2:]
    launch_args: list[tuple[str, str]] = []
    for a in rest:
        if ":=" not in a:
            p.error(f"malformed launch argument '{a}', expected format '<name>:=<value>'")
        k, v = a.split(":=", 1)
        launch_args.append((k, v))
    # ros2launch's api.py: the options become the launch-prefix(-filter) launch arguments, after the user's
    if args.launch_prefix is None and args.launch_prefix_filter is not None:
        p.error("--launch-prefix must be specified if --launch-prefix-filter is provided")
    if args.launch_prefix:
        launch_args.append(("launch-prefix", args.launch_prefix))
    if args.launch_prefix_filter:
        launch_args.append(("launch-prefix-filter", args.launch_prefix_filter))
    return run_launch_file(
        path, launch_args, debug=args.debug, show_args=args.show_args, print_description=args.print_description
    )


def run_launch_file(
    path: str,
    launch_args: list[tuple[str, str]],
    *,
    debug: bool = False,
    show_args: bool = False,
    print_description: bool = False,
) -> int:
    """Run a Python launch file as ros2launch does: its declared arguments shown (``--show-args``) or its entities
    printed (``--print``), else the launch service runs it with the arguments and
    ``current_launch_file_path``/``_directory`` set. Every argument becomes a launch configuration, declared or not:
    ros2launch's ``launch_a_launch_file`` includes the file with them, and launch's ``IncludeLaunchDescription``
    (Jazzy) checks only that the declared ones without a default are given (``launch_rviz:=false`` to a file that
    declares no ``launch_rviz`` runs). XML and YAML launch files are read by launch.frontend (launch_xml and
    launch_yaml's tags and substitutions, docs/launch_xml_yaml.md)."""
    from launch import LaunchService
    from launch.logging import log

    ld = _load_description(path, debug)
    if ld is None:
        return 1
    file_locals = {
        "current_launch_file_path": os.path.abspath(path),
        "current_launch_file_directory": os.path.dirname(os.path.abspath(path)),
    }
    from launch.launch_context import LaunchContext

    walk_context = LaunchContext()
    walk_context.extend_locals(file_locals)
    declared = ld.get_launch_arguments(context=walk_context)
    if show_args:
        _show_arguments(declared)
        return 0
    if print_description:
        for e in ld.entities:
            print(type(e).__name__)
        return 0
    from gazelle.ros import LAUNCH_ID_VAR, new_launch_id

    # every process this launch starts knows it (a server it started stops if the launch ends without it)
    os.environ.setdefault(LAUNCH_ID_VAR, new_launch_id(os.getpid()))
    log("INFO", "launch", f"All log files can be found below {os.path.expanduser('~/.ros/log')}")
    log("INFO", "launch", "Default logging verbosity is set to INFO")
    service = LaunchService(argv=[f"{k}:={v}" for k, v in launch_args], debug=debug)
    for k, v in launch_args:
        service.context.launch_configurations[k] = v
    service.context.extend_locals(file_locals)
    service.include_launch_description(ld)
    return service.run()


def _load_description(path: str, debug: bool) -> Any:
    """The file's LaunchDescription; None after saying why (a bad file, or the user's own traceback:
    their frames, not ours)."""
    import traceback

    from launch import LaunchDescription
    from launch.launch_context import LaunchContext
    from launch.launch_description_sources import AnyLaunchDescriptionSource, InvalidLaunchFileError
    from launch.logging import log

    source = AnyLaunchDescriptionSource(os.path.abspath(path))
    try:
        ld = source.get_launch_description(LaunchContext())
    except InvalidLaunchFileError as err:
        log("ERROR", "launch", str(err))
        return None
    except Exception as err:
        from launch.launch_service import _user_traceback

        kind = os.path.splitext(path)[1].lstrip(".") or "py"
        log("ERROR", "launch", f"Caught exception when trying to load file of format [{kind}]: {err}")
        tb = _user_traceback(err)
        sys.stderr.write(tb if tb else "".join(traceback.format_exception(err)))
        if debug:
            traceback.print_exception(err)
        return None
    if ld is None or not isinstance(ld, LaunchDescription):
        log("ERROR", "launch", f"generate_launch_description() of '{path}' did not return a LaunchDescription")
        return None
    return ld


def _show_arguments(declared: list[Any]) -> None:
    """``ros2 launch --show-args``: each declared argument, its description, choices and default."""
    print("Arguments (pass arguments as '<name>:=<value>'):\n")
    if not declared:
        print("  No arguments.")
    for d in declared:
        print(f"    '{d.name}':")
        print(f"        {d.description}")
        if d.choices is not None:
            print(f"        Valid choices are: {d.choices}")
        default = d.default_text()
        print(f"        (default: '{default}')\n" if default is not None else "")
