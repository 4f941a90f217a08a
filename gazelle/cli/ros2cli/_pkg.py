"""``ros2 pkg list | prefix PKG | executables [PKG]``."""

from __future__ import annotations

import argparse
import os
import sys


def main(argv: list[str]) -> int:
    """``ros2 pkg list|prefix|executables``: packages from the ament index (the venv is a prefix; a sourced
    workspace comes first), executables from ``lib/PKG`` and colcon's isolated ``bin/``."""
    p = argparse.ArgumentParser(prog="ros2 pkg", description="Various package related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    sub.add_parser("list", help="Output a list of available packages")
    pre = sub.add_parser("prefix", help="Output the prefix path of a package")
    pre.add_argument("package_name")
    pre.add_argument("--share", action="store_true", help="Show share directory for the package")
    exe = sub.add_parser("executables", help="Output a list of package specific executables")
    exe.add_argument("package_name", nargs="?")
    exe.add_argument("--full-path", action="store_true")
    args = p.parse_args(argv)
    from ament_index_python.packages import get_packages_with_prefixes

    packages = get_packages_with_prefixes()
    if args.cmd == "list":
        for name in sorted(packages):
            print(name)
        return 0
    if args.cmd == "prefix":
        if args.package_name not in packages:
            print("Package not found", file=sys.stderr)
            return 1
        prefix = packages[args.package_name]
        print(os.path.join(prefix, "share", args.package_name) if args.share else prefix)
        return 0
    names = [args.package_name] if args.package_name else sorted(packages)
    if args.package_name and args.package_name not in packages:
        print("Package not found", file=sys.stderr)
        return 1
    for name in names:
        prefix = packages[name]
        for folder in (os.path.join(prefix, "lib", name), os.path.join(prefix, "bin")):
            if not os.path.isdir(folder) or (folder.endswith("bin") and not _colcon_bin(prefix, name)):
                continue
            for exe in sorted(os.listdir(folder)):
                path = os.path.join(folder, exe)
                if os.path.isfile(path) and os.access(path, os.X_OK):
                    print(path if args.full_path else f"{name} {exe}")
    return 0


def _colcon_bin(prefix: str, name: str) -> bool:
    """Whether ``prefix/bin`` belongs to the package alone (colcon's isolated install), not a shared prefix."""
    return os.path.basename(os.path.normpath(prefix)) == name
