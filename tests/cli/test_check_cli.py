"""``gazelle check``: the real CLI in a subprocess, on the seed robot, bad files and real fixtures."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from _paths import REAL, REPO

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


def test_unknown_suffix(tmp_path: Path) -> None:
    # a file of its own: the repository's pyproject.toml once held "<node>" in a comment, and was sniffed as XML
    path = tmp_path / "settings.toml"
    path.write_text('[tool.example]\nname = "robot"\n')
    proc = check(path)
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
  <link name="$(arg prefix)base_link">
    <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
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
        # check tells what spawn would: the lidar runs through libgazebo_ros_laser.so and the IMU through the
        # libgazebo_ros_imu.so model plugin; the plugin-less <sensor type="imu"> publishes nothing, as in Classic;
        # and that ROS 1 plugin's <alwaysOn> and <serviceName> (its calibration service) are not read
        "0 errors, 3 warnings",
    ]
    assert proc.stderr.count("is not read by libgazebo_ros_imu.so; it is ignored") == 2, proc.stderr
    assert (
        "turtlebot3_burger.gazebo.xacro:43: warning: [ELEMENT_UNSUPPORTED] sensor 'imu' (imu) on link 'imu_link' "
        "publishes nothing: it has no gazebo_ros plugin" in proc.stderr
    )
    assert "lds_lfcd_sensor" not in proc.stderr and "is not supported" not in proc.stderr  # both plugins run
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
    # its sensors run through the gz-sim sensor systems of the world they go into: nothing to say here
    assert "hls_lfcd_lds" not in proc.stderr and "tb3_imu" not in proc.stderr
    # the DiffDrive's own configuration check, at its file:line (as spawning it would log)
    assert "model.sdf:376: warning: [PLUGIN_CONFIG_INVALID] plugin 'gz::sim::systems::DiffDrive'" in proc.stderr

    world = REAL / "turtlebot3/turtlebot3_gazebo/worlds/turtlebot3_world.world"
    proc = check(world, env={"GAZELLE_RESOURCE_PATH": str(models)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0].startswith("world default: 2 models, 1 light, ")  # Fuel's, built in
    # the gz-sim sensor and IMU systems it lists run the burger's lidar and IMU: no warning
    assert proc.stdout.splitlines()[-1] == "0 errors, 0 warnings", proc.stderr
    no_traceback(proc)


@needs_real
def test_panda_srdf_summary() -> None:
    proc = check(REAL / "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == [
        "semantics panda: 3 groups, 5 group states, 1 end effector, 1 virtual joint, 34 disabled collisions",
        "0 errors, 0 warnings",
    ]


def test_check_tells_what_spawn_would_tell(tmp_path: Path) -> None:
    """A plugin name typo, a diff drive joint that is not there, and the seed's wheels that drive backwards."""
    seed = SEED.read_text()
    typo = tmp_path / "typo.urdf.xacro"
    typo.write_text(seed.replace("libgazebo_ros_diff_drive.so", "libgazebo_ros_diff_drve.so"))
    proc = check("--strict", typo)
    assert proc.returncode == 1
    assert "[PLUGIN_UNSUPPORTED]" in proc.stderr and "did you mean 'libgazebo_ros_diff_drive.so'?" in proc.stderr

    missing = tmp_path / "missing.urdf.xacro"
    missing.write_text(seed.replace("<left_joint>base_left_wheel_joint<", "<left_joint>base_left_whel_joint<"))
    proc = check(missing)
    assert proc.returncode == 1
    line = next(ln for ln in proc.stderr.splitlines() if "base_left_whel_joint" in ln)
    assert f"{missing}:" in line and ": error: [PLUGIN_CONFIG_INVALID]" in line
    assert "The model's joints: base_left_wheel_joint (continuous), base_right_wheel_joint (continuous)" in line

    # the blog's original wheels (+pi/2 about x): they point right, so cmd_vel drives backwards
    backwards = tmp_path / "blog.urdf.xacro"
    backwards.write_text(seed.replace('rpy="${-PI/2} 0 0"', 'rpy="${PI/2} 0 0"'))
    assert 'rpy="${PI/2} 0 0"' in backwards.read_text()
    proc = check(backwards)
    assert proc.returncode == 0 and "0 errors, 1 warning" in proc.stdout
    assert "a positive cmd_vel drives this robot backwards" in proc.stderr
    proc = check(SEED)
    assert proc.returncode == 0 and "0 errors, 0 warnings" in proc.stdout, proc.stderr


@pytest.mark.parametrize(
    ("argv", "port", "origins"),
    [
        (["sim", "--foxglove"], 8765, None),
        (["sim", "--foxglove", "--paused"], 8765, None),
        (["sim", "--foxglove", "9000", "--viewer-allow-origin", "http://a:1"], 9000, ["http://a:1"]),
        (["sim"], None, None),
    ],
)
def test_sim_options_parse_as_the_help_says(argv: list[str], port: int | None, origins: list[str] | None) -> None:
    """`--foxglove` alone serves on 8765, as its help says (typer 0.29 reads no optional option values: the
    bare flag was refused); the options declared once as Annotated types keep their names."""
    from typer.main import get_group

    from gazelle.cli._main import _bare_foxglove, app

    command = get_group(app).commands["sim"]
    ctx = command.make_context("sim", _bare_foxglove(argv)[1:])
    assert ctx.params["foxglove"] == port
    assert list(ctx.params["viewer_allow_origin"] or []) == (origins or [])
    assert _bare_foxglove(["sim", "--", "--foxglove"]) == ["sim", "--", "--foxglove"]  # after --: not an option
