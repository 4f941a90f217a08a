"""Issue 50: what a robot test reports about its own set-up. The server's warnings about what the test
spawned (a plugin file name with a typo, a mesh that is not there) reach the test's report,
``@pytest.mark.gazelle(strict=True)`` and ``--gazelle-strict`` make them failures, and a refused spawn is one
line naming the user's file and line, never a traceback of the harness.

Each case runs an inner pytest as a user would (see test_robot_ci.py)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from .test_robot_ci import inner_pytest, survivors

pytestmark = pytest.mark.slow

ROBOT = """<?xml version="1.0"?>
<robot name="bot">
  <link name="base_link">
    <inertial><mass value="2.0"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.3 0.3 0.1"/></geometry></collision>
    {visual}
  </link>
  <link name="left_wheel">
    <inertial><mass value="0.2"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
  </link>
  <link name="right_wheel">
    <inertial><mass value="0.2"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
  </link>
  <joint name="left_joint" type="{joint_type}">
    <parent link="base_link"/><child link="left_wheel"/><origin xyz="0 0.17 0"/><axis xyz="0 1 0"/>
  </joint>
  <joint name="right_joint" type="continuous">
    <parent link="base_link"/><child link="right_wheel"/><origin xyz="0 -0.17 0"/><axis xyz="0 1 0"/>
  </joint>
  <gazebo>
    <plugin name="differential_drive" filename="{plugin}">
      <left_joint>left_joint</left_joint>
      <right_joint>right_joint</right_joint>
      <wheel_separation>0.34</wheel_separation>
      <wheel_diameter>0.1</wheel_diameter>
    </plugin>
  </gazebo>
</robot>
"""

USER_TESTS = """
import pytest
from nav_msgs.msg import Odometry

TYPO, MESH, BAD = {typo!r}, {mesh!r}, {bad!r}


def test_a_plugin_name_with_a_typo(gazelle_sim, ros):
    gazelle_sim.spawn(TYPO, "bot", pose=(0.0, 0.0, 0.1))
    odom = ros.subscribe("/odom", Odometry)
    gazelle_sim.run_until(lambda: len(odom) > 0, timeout=2.0, what="first /odom")


def test_a_missing_mesh_passes_with_a_warning(gazelle_sim):
    said = gazelle_sim.spawn(MESH, "bot", pose=(0.0, 0.0, 0.1))
    assert any("nope.stl" in w for w in said), said
    gazelle_sim.run_for(0.1)


@pytest.mark.gazelle(strict=True)
def test_a_missing_mesh_strict(gazelle_sim):
    gazelle_sim.spawn(MESH, "bot", pose=(0.0, 0.0, 0.1))


def test_a_refused_spawn(gazelle_sim):
    gazelle_sim.spawn(BAD, "bot", pose=(0.0, 0.0, 0.1))
"""


def _robots(tmp_path: Path) -> tuple[Path, Path, Path, int]:
    """A plain URDF with a plugin file name typo, one with a mesh that is not there, one with a bad joint
    type (and the line of that joint)."""
    good = "libgazebo_ros_diff_drive.so"
    mesh = '<visual><geometry><mesh filename="meshes/nope.stl"/></geometry></visual>'
    typo = tmp_path / "typo.urdf"
    typo.write_text(ROBOT.format(visual="", joint_type="continuous", plugin="libgazebo_ros_diffdrive.so"))
    missing = tmp_path / "mesh.urdf"
    missing.write_text(ROBOT.format(visual=mesh, joint_type="continuous", plugin=good))
    bad = tmp_path / "bad.urdf"
    text = ROBOT.format(visual="", joint_type="bogus", plugin=good)
    bad.write_text(text)
    line = text.splitlines().index('  <joint name="left_joint" type="bogus">') + 1
    return typo, missing, bad, line


def test_the_servers_warnings_about_a_spawn_are_in_the_report_and_strict_fails_on_them(tmp_path: Path) -> None:
    """A typo in a plugin's file name failed as "first /odom: not within 2 s" with the server's "did you mean"
    only in server.log; a missing mesh passed silently; a refused plain URDF came as a traceback of the
    harness's _sim.py naming ``<spawn_entity:bot>:19``. Now: the failing test's report holds the server's
    warning with its "did you mean", the passing one lists the mesh warning, strict (marker or option)
    fails on it, and the refusal is one line naming bad.urdf and the joint's line."""
    typo, missing, bad, line = _robots(tmp_path)
    (tmp_path / "test_setup.py").write_text(
        textwrap.dedent(USER_TESTS.format(typo=str(typo), mesh=str(missing), bad=str(bad)))
    )
    out, mark = inner_pytest(["test_setup.py", "--gazelle-artifacts=none"], tmp_path)
    text = out.stdout
    assert "3 failed, 1 passed" in text, text[-6000:] + out.stderr[-2000:]
    assert "first /odom: not within 2 s of sim time" in text
    assert "gazelle: the server's warnings" in text
    assert "did you mean 'libgazebo_ros_diff_drive.so'?" in text, text[-6000:]
    assert "GazelleWarning" in text and "nope.stl" in text  # the passing test's warning, in pytest's summary
    assert "the server warned (strict)" in text
    assert f"{bad}:{line}: error: [JOINT_TYPE_INVALID]" in text, text[-6000:]
    assert "<spawn_entity:" not in text
    assert "Traceback" not in text and "_sim.py" not in text, text[-6000:]
    assert survivors(mark) == []
    out, mark = inner_pytest(
        ["test_setup.py", "--gazelle-artifacts=none", "--gazelle-strict", "-k", "passes"], tmp_path
    )
    assert out.returncode == 1 and "1 failed" in out.stdout, out.stdout[-4000:]
    assert "the server warned (strict)" in out.stdout and "nope.stl" in out.stdout
    assert survivors(mark) == []


def test_spawn_gives_a_params_file_to_the_robots_controller_manager(tmp_path: Path) -> None:
    """``gazelle_sim.spawn(file, name, params_file=...)``: the file reaches the robot's controller manager as
    ``gazelle spawn ... --ros-args --params-file`` does (before, spawn had no such argument), so the spawner
    finds the controllers' types that only the file gives."""
    from controller_manager_msgs.srv import ListControllers

    from gazelle.testing import Sim, reserve_domain
    from gazelle.testing._sim import gazelle_command

    from .test_params_wildcards_ros import DIFFBOT_URDF, TYPES, WILDCARD_YAML

    domain = reserve_domain()
    sim = Sim(domain_id=domain.domain_id, settle_timeout=0.0)
    try:
        said = sim.spawn(DIFFBOT_URDF, "bot", pose=(0.0, 0.0, 0.05), params_file=WILDCARD_YAML)
        assert all("params" not in w for w in said), said  # (the demo's hardware stood in for: a warning)
        spawner = sim.run(gazelle_command("spawner", *TYPES), name="spawner")
        assert spawner.wait(60) == 0, spawner.output
        listed = sim.ros.call("/controller_manager/list_controllers", ListControllers, ListControllers.Request())
        assert {c.name: (c.state, c.type) for c in listed.controller} == TYPES
    finally:
        sim.close()
        domain.release()


DOMAIN_TEST = """
import os


def test_on_the_given_domain(gazelle_sim):
    assert gazelle_sim.domain_id == int(os.environ["EXPECTED_DOMAIN"]) == int(os.environ["ROS_DOMAIN_ID"])
    gazelle_sim.run_for(0.1)
"""


def test_the_plugin_keeps_to_the_domains_the_user_gives(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--gazelle-domains`` and ``GAZELLE_ROS_DOMAINS`` (before: a hard-coded 10-100, whatever the user said);
    a bad range is one usage line, and a range whose every domain is held fails the test in one line. With
    ``--gazelle-artifacts=all`` the run's summary says where a passing test's artifacts went."""
    import socket

    from tests.testing.test_domain import _free_run

    (tmp_path / "test_domain_given.py").write_text(DOMAIN_TEST)
    d = _free_run(2)
    monkeypatch.setenv("EXPECTED_DOMAIN", str(d + 1))
    out, mark = inner_pytest(
        ["test_domain_given.py", "--gazelle-artifacts=all", "--gazelle-domains", str(d + 1)], tmp_path
    )
    assert out.returncode == 0, out.stdout[-3000:]
    # (issue 50 item 10) a passing test kept its artifacts, and the run says where
    (kept,) = (tmp_path / "artifacts").iterdir()
    assert "gazelle: artifacts of passing tests" in out.stdout, out.stdout[-3000:]
    assert (
        f"test_domain_given.py::test_on_the_given_domain: artifacts (bag, replay.html, server log): {kept}"
        in out.stdout
    )
    monkeypatch.setenv("GAZELLE_ROS_DOMAINS", f"{d}-{d}")
    monkeypatch.setenv("EXPECTED_DOMAIN", str(d))
    out, mark = inner_pytest(["test_domain_given.py", "--gazelle-artifacts=none"], tmp_path)
    assert out.returncode == 0, out.stdout[-3000:]
    # every domain of the range held (here by a bound port, as domain_coordinator holds one): one line
    held = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    held.bind(("127.0.0.1", 32768 + d))
    try:
        out, mark = inner_pytest(["test_domain_given.py", "--gazelle-artifacts=none"], tmp_path)
    finally:
        held.close()
    assert out.returncode == 1 and f"no free ROS domain id in {d}..{d}" in out.stdout, out.stdout[-3000:]
    assert "Traceback" not in out.stdout
    out, mark = inner_pytest(["test_domain_given.py", "--gazelle-domains", "20-x"], tmp_path)
    assert out.returncode == 4, out.stdout[-2000:] + out.stderr[-2000:]
    assert "--gazelle-domains: '20-x' is not a domain id or a range such as 20-29" in out.stderr, out.stderr[-2000:]
    assert "Traceback" not in out.stderr
    assert survivors(mark) == []
