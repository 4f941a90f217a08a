"""``gazelle check``: the real CLI in a subprocess, on the seed robot, bad files and real fixtures."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
from _paths import REAL  # noqa: E402
needs_real = pytest.mark.skipif(not REAL.is_dir(), reason="shared real fixtures not available")

SEED = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
DATA = REPO / "tests/data/urdf"


def check(*argv: str | Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    """Run ``python -m gazelle.cli check ARGV...`` with a clean resource path (plus ``env``)."""
    full_env = {k: v for k, v in os.environ.items() if not k.endswith("RESOURCE_PATH")}
    full_env.update(env or {})
    return subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "check", *map(str, argv)],
        capture_output=True,
        text=True,
        env=full_env,
        cwd=REPO,
        timeout=120,
    )


def no_traceback(proc: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in proc.stdout + proc.stderr


def test_seed_robot_ok() -> None:
    proc = check(SEED)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == [
        "model simple_robot: 3 links, 2 joints, 0 sensors, 1 plugin",
        "0 errors, 0 warnings",
    ]
    assert proc.stderr == ""


def test_invalid_file_exit_1_with_compiler_line() -> None:
    path = DATA / "joint_missing_parent.urdf"
    proc = check(path)
    assert proc.returncode == 1
    assert f"{path}:5: error: [JOINT_PARENT_INVALID] joint 'shoulder' has unknown parent link 'base_QQQ'" in (
        proc.stderr.splitlines()
    )
    assert proc.stdout.strip().splitlines()[-1] == "1 error, 0 warnings"
    no_traceback(proc)


@pytest.mark.parametrize("name", ["malformed.urdf", "loop.urdf", "bad_root.urdf", "two_roots.urdf"])
def test_other_invalid_files_no_traceback(name: str) -> None:
    proc = check(DATA / name)
    assert proc.returncode == 1
    assert ": error: [" in proc.stderr
    no_traceback(proc)


def test_missing_file_one_line() -> None:
    proc = check("does/not/exist.urdf")
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines() == [
        "does/not/exist.urdf: error: [FILE_NOT_FOUND] no such file: does/not/exist.urdf"
    ]
    no_traceback(proc)


def test_unknown_suffix() -> None:
    proc = check(REPO / "pyproject.toml")
    assert proc.returncode == 1
    assert "[UNKNOWN_FORMAT]" in proc.stderr
    no_traceback(proc)


def test_warning_ok_but_strict_fails() -> None:
    path = DATA / "no_inertial.urdf"
    proc = check(path)
    assert proc.returncode == 0
    assert f"{path}:4: warning: [INERTIA_MISSING]" in proc.stderr
    assert proc.stdout.splitlines() == ["model r: 2 links, 1 joint, 0 sensors, 0 plugins", "0 errors, 1 warning"]

    proc = check("--strict", path)
    assert proc.returncode == 1
    assert f"{path}:4: error: [INERTIA_MISSING]" in proc.stderr
    no_traceback(proc)


XACRO_WITH_ARGS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="argbot">
  <xacro:arg name="prefix" default=""/>
  <xacro:arg name="links" default="1"/>
  <link name="$(arg prefix)base_link"/>
  <xacro:if value="${$(arg links) > 1}">
    <link name="second"/>
    <joint name="j" type="fixed"><parent link="left_base_link"/><child link="second"/></joint>
  </xacro:if>
</robot>
"""


def test_xacro_args(tmp_path: Path) -> None:
    path = tmp_path / "args.urdf.xacro"
    path.write_text(XACRO_WITH_ARGS)
    proc = check(path)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "model argbot: 1 link, 0 joints, 0 sensors, 0 plugins"

    proc = check(path, "--arg", "prefix:=left_", "--arg", "links:=2")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "model argbot: 2 links, 1 joint, 0 sensors, 0 plugins"
    # the joint's parent is spelled 'left_base_link': without the prefix it is an error
    proc = check(path, "--arg", "links:=2")
    assert proc.returncode == 1
    assert ": error: [JOINT_PARENT_INVALID]" in proc.stderr
    no_traceback(proc)


def test_bad_arg_syntax_is_a_usage_error(tmp_path: Path) -> None:
    proc = check(SEED, "--arg", "no_equals")
    assert proc.returncode == 2
    assert "NAME:=VALUE" in proc.stderr
    no_traceback(proc)


@needs_real
def test_turtlebot3_xacro_with_resource_path() -> None:
    case = REAL / "turtlebot3"
    path = case / "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro"
    proc = check(path, env={"GAZELLE_RESOURCE_PATH": str(case)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == [
        "model turtlebot3_burger: 7 links, 6 joints, 2 sensors, 3 plugins",
        "0 errors, 0 warnings",
    ]
    # without the resource path, $(find turtlebot3_description) cannot resolve: a clean error
    proc = check(path)
    assert proc.returncode == 1
    assert f"{path}:" in proc.stderr and ": error: [" in proc.stderr
    no_traceback(proc)


@needs_real
def test_turtlebot3_sdf_model_and_world() -> None:
    models = REAL / "turtlebot3/turtlebot3_gazebo/models"
    proc = check(models / "turtlebot3_burger/model.sdf", env={"GAZELLE_RESOURCE_PATH": str(models)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "model turtlebot3_burger: 7 links, 6 joints, 2 sensors, 2 plugins"

    world = REAL / "turtlebot3/turtlebot3_gazebo/worlds/turtlebot3_world.world"
    proc = check(world, env={"GAZELLE_RESOURCE_PATH": str(models)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0].startswith("world default: 1 model, 0 lights, ")
    assert proc.stdout.splitlines()[-1] == "0 errors, 2 warnings"  # the two Fuel includes
    assert proc.stderr.count(": warning: [URI_UNRESOLVED]") == 2
    # --strict turns those warnings into errors
    proc = check("--strict", world, env={"GAZELLE_RESOURCE_PATH": str(models)})
    assert proc.returncode == 1
    no_traceback(proc)


@needs_real
def test_panda_srdf_summary() -> None:
    proc = check(REAL / "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == [
        "semantics panda: 3 groups, 5 group states, 1 end effector, 1 virtual joint, 34 disabled collisions",
        "0 errors, 0 warnings",
    ]
