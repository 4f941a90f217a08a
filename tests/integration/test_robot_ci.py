"""Issue 30: gazelle's pytest plugin runs a user's own robot tests (examples/robot_tests), keeps a bag
and the server's log of a failing test, names its seed, and leaves no process behind.

Each case runs an inner pytest as a user would (a plain `pytest` in the venv: the plugin comes in
through its pytest11 entry point), with its own artifacts folder.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import uuid
from pathlib import Path

import pytest
from _paths import REAL, REPO
from _pixels import open_replay, share_near

from gazelle.viewer._browser import find_chromium

EXAMPLE = REPO / "examples" / "robot_tests"
TB3 = REAL / "turtlebot3" / "turtlebot3_gazebo"
LEAK_MARK = "GAZELLE_ROBOT_CI_CHECK"

pytestmark = pytest.mark.slow


def inner_pytest(args: list[str], tmp_path: Path, timeout: float = 300) -> tuple[subprocess.CompletedProcess, str]:
    mark = uuid.uuid4().hex
    env = {**os.environ, "TURTLEBOT3_GAZEBO": str(TB3), "MOVEIT_RESOURCES": str(REAL / "moveit_panda"), LEAK_MARK: mark}
    env.pop("PYTEST_XDIST_WORKER", None)
    env.pop("PYTEST_ADDOPTS", None)
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-p",
            "no:cacheprovider",
            "-p",
            "no:xdist",
            "-q",
            "-rA",
            "--gazelle-artifacts-dir",
            str(tmp_path / "artifacts"),
            *args,
        ],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
        cwd=tmp_path,
    )
    return out, mark


def survivors(mark: str) -> list[str]:
    """Processes still alive that the inner run started (they carry its mark in their environment)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                if f"{LEAK_MARK}={mark}".encode() not in f.read().split(b"\0"):
                    continue
            with open(f"/proc/{entry}/stat", "rb") as f:
                if f.read().split(b")")[-1].split()[0] == b"Z":
                    continue
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
            found.append(f"{entry}: {cmd}")
        except OSError:
            continue
    return found


def test_the_example_packages_robot_tests_pass_with_plain_pytest(tmp_path: Path) -> None:
    """The seed robot and TurtleBot3 (its real files, in its own world) drive to their goals under a
    P-controller node of the package's own, within 0.2 m in 60 s of sim time; TurtleBot3's lidar never
    sees anything nearer than 0.15 m; the seed robot drives the seed's square under the seed's own node,
    each side within 3 cm, and again in-process (no ROS); MoveIt's Panda moves its flange to a pose
    through a MoveGroup goal and ends where the plan ended. Passing tests keep no artifacts."""
    out, mark = inner_pytest([str(EXAMPLE / "test")], tmp_path)
    assert out.returncode == 0, out.stdout[-4000:] + out.stderr[-2000:]
    assert "5 passed" in out.stdout, out.stdout[-2000:]
    assert not (tmp_path / "artifacts").exists() or not any((tmp_path / "artifacts").iterdir())
    assert survivors(mark) == []


SLOW_NODE = """
import time

import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_msgs.msg import Float64


class SlowTicker(Node):
    \"\"\"A 10 Hz timer on sim time that takes 50 ms of CPU per tick, then says the time it read.\"\"\"

    def __init__(self):
        super().__init__("slow_ticker", parameter_overrides=[Parameter("use_sim_time", value=True)])
        self.pub = self.create_publisher(Float64, "/ticks", 100)
        self.create_timer(0.1, self.tick)

    def tick(self):
        now = self.get_clock().now().nanoseconds / 1e9
        if now == 0.0:
            return  # no /clock yet
        end = time.process_time() + 0.05
        while time.process_time() < end:
            pass
        self.pub.publish(Float64(data=now))


rclpy.init()
rclpy.spin(SlowTicker())
"""

LOCKSTEP = """
import sys

from std_msgs.msg import Float64

NODE = {node!r}


def _ticking(gazelle_sim, ros):
    # the slow ticker started and past its start-up: (its ticks, how many came before)
    ticks = ros.subscribe("/ticks", Float64)
    gazelle_sim.run([sys.executable, NODE], name="slow_ticker")
    ros.wait_until(lambda: ros.node.count_publishers("/ticks") > 0, 60, "the slow_ticker node")
    # start-up: the node's /clock subscription is matched some time after its publisher was seen (the
    # world steps on meanwhile: nothing waits for discovery), and its timer's first period is measured
    # from whichever clock it had; from its third tick on it runs on the clock the test steps
    gazelle_sim.run_until(lambda: len(ticks) >= 3, timeout=10.0, what="3 ticks", step=0.01)
    return ticks, len(ticks)


def _gaps(ticks, first):
    times = [m.data for m in ticks.messages[first - 1 :]]
    return [round(b - a, 4) for a, b in zip(times, times[1:])]


def test_a_slow_node_ticks_every_tenth_of_a_second_of_sim_time(gazelle_sim, ros):
    ticks, first = _ticking(gazelle_sim, ros)
    gazelle_sim.run_until(lambda: len(ticks) >= first + 30, timeout=10.0, what="30 more ticks", step=0.01)
    gaps = _gaps(ticks, first)
    assert len(gaps) >= 30 and all(abs(g - 0.1) < 0.011 for g in gaps), gaps


def test_one_long_run_for_waits_for_the_slow_node_too(gazelle_sim, ros):
    ticks, first = _ticking(gazelle_sim, ros)
    gazelle_sim.run_for(3.0)  # one call: stepped 50 ms at a time, waiting for the node after each
    gaps = _gaps(ticks, first)
    # a tick reads the newest /clock it has heard: at most one 50 ms chunk after its time
    assert len(gaps) >= 29 and all(abs(g - 0.1) < 0.051 for g in gaps), gaps
"""


def test_lockstep_a_node_slower_than_the_stepping_still_ticks_on_time(tmp_path: Path) -> None:
    """A node that takes 50 ms of CPU for each tick of its 10 Hz sim-time timer, while the test steps
    10 ms chunks in a few ms each: with lockstep the world waits for it after each chunk, and it reads
    the time of every tick (gaps of 0.1 s within a chunk); without (``lockstep=False``, the behaviour
    before) it fell behind, ticks skipped and its gaps grew to 0.2-0.5 s. One ``run_for(3.0)`` keeps it in
    step too (it was one step call, during which nothing waited: ticks skipped)."""
    node = tmp_path / "slow_ticker.py"
    node.write_text(SLOW_NODE)
    (tmp_path / "test_lockstep.py").write_text(LOCKSTEP.format(node=str(node)))
    out, mark = inner_pytest(["test_lockstep.py", "--gazelle-artifacts=none"], tmp_path)
    assert out.returncode == 0, out.stdout[-4000:] + out.stderr[-2000:]
    assert "2 passed" in out.stdout and "stayed busy" not in out.stdout, out.stdout[-2000:]
    assert survivors(mark) == []


FAILING = """
import pytest
from nav_msgs.msg import Odometry

ROBOT = {robot!r}


@pytest.mark.gazelle(record=["/odom"])
def test_the_robot_should_fly(gazelle_sim, ros):
    gazelle_sim.spawn(ROBOT, "simple_robot", pose=(0.0, 0.0, 0.07))
    odom = ros.subscribe("/odom", Odometry)
    gazelle_sim.run_for(1.0)
    odom.wait(1, 10)
    assert odom.last.pose.pose.position.z > 1.0, "the robot is on the ground"


def test_a_world_that_is_not_there(gazelle_sim):
    pass


test_a_world_that_is_not_there = pytest.mark.gazelle(world="/no/such/world.sdf")(test_a_world_that_is_not_there)


def test_a_test_that_leaves_a_process(gazelle_sim):
    import subprocess
    import sys

    subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
"""


def test_a_failing_test_keeps_its_bag_and_log_and_bad_input_is_one_line_each(tmp_path: Path) -> None:
    robot = REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
    (tmp_path / "test_user.py").write_text(textwrap.dedent(FAILING.format(robot=str(robot))))
    out, mark = inner_pytest(["test_user.py", "--gazelle-seed", "42"], tmp_path)
    text = out.stdout
    assert out.returncode == 1, text[-4000:] + out.stderr[-2000:]
    # the failing test: its assertion, its seed and where its artifacts are
    assert "the robot is on the ground" in text
    assert "seed 42 (rerun with --gazelle-seed 42)" in text
    (folder,) = (tmp_path / "artifacts").glob("test_user.py_test_the_robot_should_fly-*")
    assert f"artifacts (bag, replay.html, server log): {folder}" in text
    assert "gazelle: ready" in (folder / "server.log").read_text()
    # the replay: one file, opened from disk, shows the robot where the run left it and the topic it named
    replay = folder / "replay.html"
    assert replay.is_file() and replay.stat().st_size < 20_000_000
    if find_chromium() is not None:
        with open_replay(replay) as page:
            page.seek(page.frames() - 1)
            assert share_near(page.canvas(), page.to_screen(0.0, 0.0), page.color_of("simple_robot")) > 0.9
            topics = page.page.locator("#topics").inner_text()
            assert "/odom" in topics and "pose.position" in topics, topics
    bags = list((folder / "bag").glob("*.mcap"))
    assert bags and (folder / "bag" / "metadata.yaml").is_file(), list((folder / "bag").iterdir())
    from mcap.reader import make_reader

    with open(bags[0], "rb") as f:
        topics = {c.topic for _s, c, _m in make_reader(f).iter_messages()}
    assert {"/odom", "/clock"} <= topics, topics
    # bad input: one clear line each, never a traceback of the harness
    assert "no such world file: /no/such/world.sdf" in text
    assert "the test left 1 process(es) running (killed now)" in text and "time.sleep(600)" in text
    assert "Traceback" not in text
    assert survivors(mark) == []


SHARED = """
import pytest
from nav_msgs.msg import Odometry

ROBOT = {robot!r}
pytestmark = pytest.mark.gazelle(record=["/odom"])


@pytest.mark.parametrize("run", range(4))
def test_each_test_starts_from_a_reset_world(gazelle_shared_sim, run):
    sim = gazelle_shared_sim
    assert sim.time < 0.05, sim.time  # back at the start
    sim.spawn(ROBOT, "robot", pose=(0.0, 0.0, 0.07))  # the same name every time: the last one is gone
    odom = sim.ros.subscribe("/odom", Odometry)
    sim.run_for(0.5)
    odom.wait(1, 10)
    assert 0.45 <= sim.time <= 0.55
    assert run != 1, "the second test fails on purpose"
"""


def test_a_module_shares_one_server_reset_before_each_test_and_a_failing_one_keeps_its_artifacts(
    tmp_path: Path,
) -> None:
    robot = REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
    (tmp_path / "test_shared.py").write_text(SHARED.format(robot=str(robot)))
    out, mark = inner_pytest(["test_shared.py"], tmp_path)
    assert out.returncode == 1, out.stdout[-4000:] + out.stderr[-2000:]
    assert "1 failed, 3 passed" in out.stdout  # the tests after the failing one ran on, recorded anew
    folders = [f for f in (tmp_path / "artifacts").iterdir() if f.is_dir()]
    assert [f.name[:-11] for f in folders] == ["test_shared.py_test_each_test_starts_from_a_reset_world_1"], folders
    kept = folders[0]
    assert f"artifacts (bag, replay.html, server log): {kept}" in out.stdout
    # its replay: its own run only (the server's since the reset before it), half a second of the robot
    text = (kept / "replay.html").read_text()
    data = json.loads(text.split('<script id="data" type="application/json">', 1)[1].split("</script>", 1)[0])
    times = [f[0] for f in data["frames"]]
    assert times and times[0] < 0.05 and 0.4 < times[-1] <= 0.55, times[:3] + times[-3:]
    assert times == sorted(times)  # not the test before it too (its run started at 0 as well)
    assert any(name.startswith("robot::") for name in data["frames"][-1][1])
    # the module's bag up to the failure: /odom of the two tests so far, readable
    from mcap_ros2.reader import read_ros2_messages

    (bag,) = list((kept / "bag").glob("*.mcap"))
    odom = [m for m in read_ros2_messages(str(bag)) if m.channel.topic == "/odom"]
    assert len(odom) > 10
    assert "gazelle: ready" in (kept / "server.log").read_text()
    assert survivors(mark) == []


TWINS = """
import pytest


@pytest.mark.parametrize("name", ["a/b", "a_b"])
def test_twin(gazelle_sim, name):
    gazelle_sim.run_for(0.1)
"""


def test_two_tests_whose_ids_differ_only_in_what_a_file_name_cannot_hold_keep_two_folders(tmp_path: Path) -> None:
    """``test_twin[a/b]`` and ``test_twin[a_b]`` both keep their artifacts (``--gazelle-artifacts=all``), each in
    a folder of its own (before: one folder, the first test's artifacts deleted as the second started)."""
    (tmp_path / "test_twins.py").write_text(TWINS)
    out, mark = inner_pytest(["test_twins.py", "--gazelle-artifacts=all"], tmp_path)
    assert out.returncode == 0 and "2 passed" in out.stdout, out.stdout[-4000:] + out.stderr[-2000:]
    folders = sorted((tmp_path / "artifacts").iterdir())
    assert len(folders) == 2 and all(f.name.startswith("test_twins.py_test_twin_a_b-") for f in folders), folders
    assert all("gazelle: ready" in (f / "server.log").read_text() for f in folders)
    assert survivors(mark) == []


def test_colcon_test_runs_the_example_packages_tests(tmp_path: Path) -> None:
    """The same tests through `colcon test` (ament_python: pytest in the package), in a workspace that
    links the package, as a user's would."""
    ws = tmp_path / "ws"
    (ws / "src").mkdir(parents=True)
    (ws / "src" / "robot_tests").symlink_to(EXAMPLE)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTEST_XDIST_WORKER", "PYTEST_ADDOPTS")}
    colcon = str(Path(sys.prefix) / "bin" / "colcon")
    built = subprocess.run(
        [colcon, "build", "--symlink-install"], cwd=ws, capture_output=True, text=True, timeout=300, env=env
    )
    assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    tested = subprocess.run(
        [colcon, "test", "--packages-select", "robot_tests", "--pytest-args", "-k", "drives_to_a_goal or in_process", "-p", "no:cacheprovider"],
        cwd=ws, capture_output=True, text=True, timeout=300, env=env,
    )  # fmt: skip
    assert tested.returncode == 0, tested.stdout[-2000:] + tested.stderr[-2000:]
    result = subprocess.run([colcon, "test-result", "--verbose"], cwd=ws, capture_output=True, text=True, timeout=60)
    assert "2 tests, 0 errors, 0 failures" in result.stdout, result.stdout + result.stderr
