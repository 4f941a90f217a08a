"""A server its `ros2 launch` left running does not take the next launch's robot (issue 49.3): a launch that ended
without stopping its gazelle sim (here killed with SIGKILL, as a closed terminal or a hung Ctrl-C ends it) left
that server holding the domain, and the next launch's own server yielded to it ("another gazelle sim already
serves ROS_DOMAIN_ID"), so the next robot spawned into the old world. A server started by a launch now stops
by itself when its launch has ended, saying why, and the next launch on the domain gets its own server."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest
from _harness import Proc, wait_for

from .test_blog_workspace import shell

pytestmark = pytest.mark.slow

LAUNCH = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                PathJoinSubstitution([FindPackageShare('gazebo_ros'), 'launch', 'gzserver.launch.py'])),
            launch_arguments={'gui': 'false'}.items()),
    ])
"""


def _descendants(root: int) -> dict[int, str]:
    """The processes below ``root`` (children, their children...): pid -> command line."""
    parent: dict[int, int] = {}
    cmdlines: dict[int, str] = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
            cmdlines[int(entry.name)] = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        parent[int(entry.name)] = int(stat.rsplit(")", 1)[-1].split()[1])
    found: dict[int, str] = {}
    frontier = [root]
    while frontier:
        pid = frontier.pop()
        for child, ppid in parent.items():
            if ppid == pid and child not in found:
                found[child] = cmdlines.get(child, "")
                frontier.append(child)
    return found


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    stat = Path(f"/proc/{pid}/stat")
    return stat.exists() and stat.read_text().rsplit(")", 1)[-1].split()[0] != "Z"


def _launch(path: Path) -> Proc:
    return shell(f"ros2 launch {path}", "ros2 launch")


def test_a_server_whose_launch_ended_stops_and_the_next_launch_gets_its_own(tmp_path):
    path = tmp_path / "server.launch.py"
    path.write_text(LAUNCH)
    first = _launch(path)
    second = None
    servers: list[int] = []
    try:
        first.wait_line("gazelle: ready", 120)
        launcher = first.popen.pid  # bash runs the last command of its line in its own process
        assert " launch " in Path(f"/proc/{launcher}/cmdline").read_text().replace("\0", " ")
        servers += [pid for pid, cmd in _descendants(launcher).items() if "sim" in cmd.split()]
        assert servers
        os.kill(launcher, signal.SIGKILL)  # the launch ends without a word to its children
        wait_for(lambda: not any(_alive(p) for p in servers), 10, "the left server to stop by itself")
        second = _launch(path)
        second.wait_line("gazelle: ready", 120)
        time.sleep(1.0)  # a server that yields to an older one says so within its first announcements
        assert "another gazelle sim already serves" not in second.output, second.output
    finally:
        for proc in (first, second):
            if proc is not None:
                for pid in [*_descendants(proc.popen.pid), proc.popen.pid, *(servers if proc is first else [])]:
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
                proc.wait(10)
