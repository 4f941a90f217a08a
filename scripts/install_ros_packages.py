#!/usr/bin/env python3
"""Register gazelle's stand-ins for ROS packages that are not on PyPI (compat/ros_packages/: gazebo_ros,
robot_state_publisher, controller_manager, ros_gz_sim, ros_gz_bridge, ros_gz_image, rviz2, joint_state_publisher, xacro,
robot_localization (ekf_node), twist_mux, interactive_marker_twist_server, joy, teleop_twist_joy,
moveit_ros_move_group, moveit_configs_utils (its default planning pipeline configs) and gazelle itself
(move_group); compat/python/: gazebo_ros's Python module, MoveIt's moveit_configs_utils and the launch_param_builder
it builds on, colcon_gazelle (C++ targets a venv cannot build), nav2_common, ros2run, ros2pkg) in a virtualenv's
ament index, so that get_package_share_directory, FindPackageShare and `ros2 run` find them, as an install of the real
packages would lay them out:

    VENV/share/ament_index/resource_index/packages/PKG
    VENV/share/PKG/...            (package.xml, launch files)
    VENV/lib/PKG/EXECUTABLE       (with VENV's python in its #! line)

It also repairs the wheels' CMake exports (see repair_cmake_exports). Idempotent; a package the
venv already has for real (no gazelle marker) is left alone.

    scripts/install_ros_packages.py VENV_DIR
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MARKER = ".gazelle-compat"


def repair_cmake_exports(venv: Path) -> None:
    """Point the wheels' exported ``*__rosidl_generator_py`` CMake targets at this Python's headers, so
    that ``colcon build`` of a user's interface package (ament_cmake + rosidl) configures; the wheels
    name the build machine's folder, which does not exist here."""
    import subprocess

    code = "import sysconfig, numpy; print(sysconfig.get_paths()['include']); print(numpy.get_include())"
    out = subprocess.run([str(venv / "bin" / "python"), "-c", code], capture_output=True, text=True, check=True)
    include, numpy_include = out.stdout.split()
    import re

    # whatever folder a file names (the wheel builder's, or another venv's after an earlier repair of a
    # shared copy), it is pointed at this venv's headers
    python_dir = re.compile(r"[^\";]*/include/python3\.\d+")
    numpy_dir = re.compile(r"[^\";]*/numpy/_core/include")
    for export in (venv / "share").glob("*/cmake/*__rosidl_generator_pyExport.cmake"):
        text = export.read_text()
        fixed = numpy_dir.sub(numpy_include, python_dir.sub(include, text))
        if fixed != text:
            # a new file, never written in place: an installer may have hard-linked the wheel's file to
            # its cache (uv does), and an in-place write would change every later venv's copy
            tmp = export.with_name(export.name + ".gazelle-tmp")
            tmp.write_text(fixed)
            tmp.replace(export)


CONFIGURE_ONLY = (
    "urdf",
    "xacro",
    "gazebo_ros",
    "gazebo_dev",
    "gazebo_plugins",
    "robot_state_publisher",
    "joint_state_publisher",
    "controller_manager",
    "ros_gz_sim",
    "ros_gz_bridge",
    "gz_ros2_control",
    "gazebo_ros2_control",
)
"""Packages that description, launch and world packages name in ``find_package`` (and package.xml) but only
use at run time, which gazelle stands in for: each gets a CMake config that finds nothing to link, so
``colcon build`` of turtlebot3_description, husky_description or articubot_one configures unchanged."""

STANDIN_CONFIG = """# gazelle's stand-in (scripts/install_ros_packages.py): {pkg} is provided at run time by gazelle;
# there is nothing to compile or link against. A target that links it gets no flags.
set({pkg}_FOUND TRUE)
set({pkg}_VERSION "0.0.0-gazelle")
set({pkg}_INCLUDE_DIRS "")
set({pkg}_LIBRARIES "")
set({pkg}_LIBRARY_DIRS "")
set({pkg}_DEFINITIONS "")
set({pkg}_TARGETS "")
set({pkg}_INTERFACES "")
# in a colcon build (compat/python/colcon_gazelle): a compiled target that links {pkg} is not built, and says so
if(COMMAND gazelle_unavailable_package)
  gazelle_unavailable_package({pkg})
endif()
"""

LINT_AUTO_CONFIG = """# gazelle's stand-in (scripts/install_ros_packages.py) for ament_lint_auto, which the default
# `ros2 pkg create` template finds under BUILD_TESTING: the linters are not installed, so
# ament_lint_auto_find_test_dependencies() registers none, and says so once.
set(ament_lint_auto_FOUND TRUE)
set(ament_lint_common_FOUND TRUE)
macro(ament_lint_auto_find_test_dependencies)
  message(STATUS "gazelle: ament_lint_auto's linters are not installed; ${PROJECT_NAME}'s lint tests are skipped")
endmacro()
"""


def install_cmake_standins(venv: Path) -> None:
    """CMake configs for :data:`CONFIGURE_ONLY` and ament_lint_auto/ament_lint_common, where the venv has
    no real package of that name (a real one, without gazelle's marker, is left alone)."""
    configs = {pkg: STANDIN_CONFIG.format(pkg=pkg) for pkg in CONFIGURE_ONLY}
    configs["ament_lint_auto"] = LINT_AUTO_CONFIG
    configs["ament_lint_common"] = "set(ament_lint_common_FOUND TRUE)\n"
    for pkg, text in configs.items():
        share = venv / "share" / pkg
        cmake = share / "cmake" / f"{pkg}Config.cmake"
        if share.exists() and not (share / MARKER).exists():
            continue  # a real package
        cmake.parent.mkdir(parents=True, exist_ok=True)
        (share / MARKER).write_text("installed by gazelle's scripts/install_ros_packages.py\n")
        cmake.write_text(text)
        if not (share / "package.xml").exists():
            (share / "package.xml").write_text(
                f'<?xml version="1.0"?>\n<package format="3"><name>{pkg}</name><version>0.0.0</version>'
                "<description>gazelle's stand-in</description><maintainer email='none@example.com'>gazelle"
                "</maintainer><license>Apache-2.0</license><export><build_type>ament_cmake</build_type></export>"
                "</package>\n"
            )
        # not in the ament index: a launch file looking the package up at run time finds what it found before


def install_python_modules(venv: Path) -> None:
    """compat/python/* (gazebo_ros's GazeboRosPaths, moveit_configs_utils, launch_param_builder) into the venv's
    site-packages, marked as ours."""
    import sysconfig

    site = Path(sysconfig.get_paths(vars={"base": str(venv), "platbase": str(venv)})["purelib"])
    for module in sorted((ROOT / "compat" / "python").iterdir()):
        dest = site / module.name
        # a real one has Python files of its own; a folder of nothing but __pycache__ is what the bytecode cache
        # restored for an earlier venv's copy of ours (a fresh clone skipped nav2_common and failed its imports)
        real = any("__pycache__" not in p.parts for p in dest.rglob("*.py")) if dest.exists() else False
        if real and not (dest / MARKER).exists():
            continue
        if dest.exists():
            shutil.rmtree(dest)
        shutil.copytree(module, dest, ignore=shutil.ignore_patterns("__pycache__"))
        (dest / MARKER).write_text("installed by gazelle's scripts/install_ros_packages.py\n")


XACRO_COMMAND = """#!{python}
# gazelle's xacro command (scripts/install_ros_packages.py): the xacro wheel's own, whose $(find pkg) also
# finds the packages on GAZELLE_RESOURCE_PATH by their package.xml name, then the ament index
import sys

from gazelle.description import xacro_main

sys.exit(xacro_main())
"""


def install_xacro_command(venv: Path) -> None:
    """The venv's ``xacro`` command: the wheel's entry point, replaced by gazelle's (see XACRO_COMMAND)."""
    command = venv / "bin" / "xacro"
    if (
        command.exists()
        and "gazelle" not in command.read_text()
        and "from xacro import main" not in command.read_text()
    ):
        return  # someone else's
    command.write_text(XACRO_COMMAND.format(python=venv / "bin" / "python"))
    command.chmod(0o755)


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
    install_cmake_standins(venv)
    install_python_modules(venv)
    install_xacro_command(venv)
    repair_cmake_exports(venv)
    install_prefix_setup(venv)
    return 0


PREFIX_SETUP_MARKERS = ("# the gazelle virtualenv", "# gazelle virtualenv")
"""How the first line of a local_setup file gazelle wrote starts (this one's, and an earlier setup's)."""


def install_prefix_setup(venv: Path) -> None:
    """The venv prefix's ``local_setup.{sh,bash,zsh}``: colcon chains a workspace built over the venv to the
    prefixes with such a file, as it chains to /opt/ros/<distro>, and sources it first; it defines the shell
    functions ament's prefix-level setup leaves defined (scripts/ament_prefix_setup.sh), which packages'
    environment hooks call. One a user put there themselves is left alone."""
    text = (ROOT / "scripts" / "ament_prefix_setup.sh").read_text()
    for shell in ("sh", "bash", "zsh"):
        f = venv / f"local_setup.{shell}"
        if f.exists() and not f.read_text().startswith(PREFIX_SETUP_MARKERS):
            continue
        if not f.exists() or f.read_text() != text:
            f.write_text(text)


if __name__ == "__main__":
    raise SystemExit(main())
