"""A colcon workspace built over the venv gets its packages' environment hooks, as over /opt/ros/jazzy: a hook
from a ``.sh.in`` (``ament_environment_hooks(env-hooks/my_world.sh.in)``, calling ament_prepend_unique_value)
and one from a ``.dsv.in``. Before, ``source install/setup.bash`` said "ament_prepend_unique_value: command
not found" and the hook's GZ_SIM_RESOURCE_PATH and GAZEBO_MODEL_PATH were lost."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from .test_blog_workspace import VENV_ACTIVATE, shell

pytestmark = pytest.mark.slow

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>my_world</name><version>1.0.0</version><description>worlds and models for gz</description>
  <maintainer email="dev@example.com">dev</maintainer><license>BSD</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

CMAKE = """cmake_minimum_required(VERSION 3.5)
project(my_world)
find_package(ament_cmake REQUIRED)
install(DIRECTORY worlds models DESTINATION share/${PROJECT_NAME})
ament_environment_hooks("${CMAKE_CURRENT_SOURCE_DIR}/env-hooks/${PROJECT_NAME}.sh.in")
ament_environment_hooks("${CMAKE_CURRENT_SOURCE_DIR}/env-hooks/${PROJECT_NAME}_ign.dsv.in")
ament_package()
"""

# the two spellings bring-ups use in their hooks: colcon's current prefix, and the install prefix at configure time
SH_HOOK = """ament_prepend_unique_value GZ_SIM_RESOURCE_PATH "$COLCON_CURRENT_PREFIX/share/@PROJECT_NAME@/worlds"
ament_prepend_unique_value GAZEBO_MODEL_PATH "@CMAKE_INSTALL_PREFIX@/share/@PROJECT_NAME@/models"
"""
DSV_HOOK = "prepend-non-duplicate;IGN_GAZEBO_RESOURCE_PATH;share/@PROJECT_NAME@/worlds\n"

_CLEAN = ("AMENT_PREFIX_PATH", "PYTHONPATH", "COLCON_PREFIX_PATH", "GZ_SIM_RESOURCE_PATH", "GAZEBO_MODEL_PATH",
          "IGN_GAZEBO_RESOURCE_PATH", "CMAKE_PREFIX_PATH", "ROS_DISTRO", "ROS_VERSION", "ROS_PYTHON_VERSION")  # fmt: skip


def _run(shell_name: str, script: str, cwd: Path) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in _CLEAN}
    return subprocess.run([shell_name, "-c", script], cwd=cwd, env=env, capture_output=True, text=True, timeout=60)


def test_a_workspaces_env_hooks_reach_the_shell_over_the_venv(tmp_path: Path) -> None:
    """colcon build of one ament_cmake package, then its setup sourced three ways."""
    pkg = tmp_path / "ws" / "src" / "my_world"
    for folder in ("worlds", "models", "env-hooks"):
        (pkg / folder).mkdir(parents=True)
    (pkg / "worlds" / "warehouse.sdf").write_text("<sdf version='1.9'><world name='warehouse'/></sdf>")
    (pkg / "models" / "keep.txt").write_text("models")
    (pkg / "package.xml").write_text(PACKAGE_XML)
    (pkg / "CMakeLists.txt").write_text(CMAKE)
    (pkg / "env-hooks" / "my_world.sh.in").write_text(SH_HOOK)
    (pkg / "env-hooks" / "my_world_ign.dsv.in").write_text(DSV_HOOK)
    ws = tmp_path / "ws"
    build = shell(f"cd {ws} && colcon build --event-handlers console_direct+", "colcon")
    assert build.wait(300) == 0, build.output
    share = ws / "install" / "my_world" / "share" / "my_world"
    show = 'echo "GZ=$GZ_SIM_RESOURCE_PATH"; echo "MODEL=$GAZEBO_MODEL_PATH"; echo "IGN=$IGN_GAZEBO_RESOURCE_PATH"'
    expected = [f"GZ={share / 'worlds'}", f"MODEL={share / 'models'}", f"IGN={share / 'worlds'}"]
    # the README's way: the venv activated, then the workspace; and the workspace alone, in bash and in sh
    for shell_name, script in (
        ("bash", f"source {VENV_ACTIVATE} && source install/setup.bash && {show}"),
        ("bash", f"source install/setup.bash && {show}"),
        ("sh", f". install/setup.sh && {show}"),
    ):
        out = _run(shell_name, script, ws)
        assert out.returncode == 0, out.stderr
        assert out.stderr == "", f"{shell_name}: {script}\n{out.stderr}"
        assert out.stdout.splitlines() == expected, f"{shell_name}: {script}\n{out.stdout}"


def test_activation_gives_what_ros_setup_gives_a_shell(tmp_path: Path) -> None:
    """ament_prepend_unique_value (exported, no duplicate, no stray ':') and ament_append_unique_value, as
    /opt/ros/jazzy/setup.bash leaves them defined (ament_package template/prefix_level), and ros_environment's
    ROS_DISTRO, ROS_VERSION and ROS_PYTHON_VERSION, which launch files and hooks read (a sourced ROS's win)."""
    script = (
        f"source {VENV_ACTIVATE} && ament_prepend_unique_value GAZEBO_MODEL_PATH /b"
        " && ament_prepend_unique_value GAZEBO_MODEL_PATH /a && ament_prepend_unique_value GAZEBO_MODEL_PATH /b"
        " && ament_append_unique_value GAZEBO_MODEL_PATH '/z z' && ament_append_unique_value GAZEBO_MODEL_PATH /a"
        ' && sh -c \'echo "$GAZEBO_MODEL_PATH"; echo "$ROS_DISTRO $ROS_VERSION $ROS_PYTHON_VERSION"\''
    )
    out = _run("bash", script, tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == ["/a:/b:/z z", "jazzy 2 3"]
    sourced = _run("bash", f"export ROS_DISTRO=rolling; source {VENV_ACTIVATE} && echo $ROS_DISTRO", tmp_path)
    assert sourced.stdout.strip() == "rolling"
