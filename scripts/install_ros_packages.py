#!/usr/bin/env python3
"""Register gazelle's stand-ins for ROS packages that are not on PyPI (compat/ros_packages/: gazebo_ros,
robot_state_publisher, controller_manager, xacro) in a virtualenv's ament index, so that
get_package_share_directory, FindPackageShare and `ros2 run` find them, as an install of the real
packages would lay them out:

    VENV/share/ament_index/resource_index/packages/PKG
    VENV/share/PKG/...            (package.xml, launch files)
    VENV/lib/PKG/EXECUTABLE       (with VENV's python in its #! line)

Idempotent; a package the venv already has for real (no gazelle marker) is left alone.

    scripts/install_ros_packages.py VENV_DIR
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MARKER = ".gazelle-compat"


def main() -> int:
    venv = Path(sys.argv[1]).resolve()
    python = venv / "bin" / "python"
    gazelle = venv / "bin" / "gazelle"
    index = venv / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True, exist_ok=True)
    for pkg in sorted((ROOT / "compat" / "ros_packages").iterdir()):
        share = venv / "share" / pkg.name
        if share.exists() and not (share / MARKER).exists():
            print(f"[setup] {pkg.name}: a real package is installed; kept")
            continue
        if share.exists():
            shutil.rmtree(share)
        share.mkdir(parents=True)
        (share / MARKER).write_text("installed by gazelle's scripts/install_ros_packages.py\n")
        for item in pkg.iterdir():
            if item.name == "lib":
                continue
            dest = share / item.name
            if item.is_dir():
                shutil.copytree(item, dest)
            else:
                shutil.copy2(item, dest)
        for launch_file in share.rglob("*.py"):
            launch_file.write_text(launch_file.read_text().replace("@GAZELLE@", str(gazelle)))
        lib = venv / "lib" / pkg.name
        if lib.exists():
            shutil.rmtree(lib)
        if (pkg / "lib").is_dir():
            lib.mkdir(parents=True)
            for exe in (pkg / "lib").iterdir():
                dest = lib / exe.name
                dest.write_text(exe.read_text().replace("@PYTHON@", str(python)))
                dest.chmod(0o755)
        (index / pkg.name).write_text("")
    # colcon chains workspaces over prefixes with a local_setup file; the venv is one
    for shell in ("sh", "bash"):
        f = venv / f"local_setup.{shell}"
        if not f.exists():
            f.write_text("# the gazelle virtualenv: nothing to set up (activate it to use it)\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
