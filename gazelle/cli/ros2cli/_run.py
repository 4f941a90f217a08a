"""``ros2 run PKG EXECUTABLE [args] [--prefix P]``: the executable from the ament index or colcon's ``bin/``."""

from __future__ import annotations

import argparse
import os
import shlex
import sys


def main(argv: list[str]) -> int:
    """``ros2 run``: find the executable as launch_ros does and replace this process with it (``--prefix``
    goes before it, split as a shell would), so its signals and exit status are the program's own."""
    p = argparse.ArgumentParser(prog="ros2 run", description="Run a package specific executable")
    p.add_argument("--prefix", default=None, help="Prefix command, which should go before the executable")
    p.add_argument("package_name", help="Name of the ROS package")
    p.add_argument("executable_name", help="Name of the executable")
    p.add_argument("argv", nargs=argparse.REMAINDER, help="Pass arbitrary arguments to the executable")
    args = p.parse_args(argv)
    from launch_ros.substitutions import PackageNotFoundError, find_executable

    try:
        path = find_executable(args.package_name, args.executable_name)
    except PackageNotFoundError as err:
        print(str(err), file=sys.stderr)
        return 1
    except Exception:
        print("No executable found", file=sys.stderr)
        return 1
    cmd = [path, *args.argv]
    if args.prefix:
        cmd = shlex.split(args.prefix) + cmd
    sys.stdout.flush()
    try:
        os.execvp(cmd[0], cmd)
    except OSError as err:
        print(f"cannot run {path}: {err}", file=sys.stderr)
        return 1
    return 0  # pragma: no cover
