"""Public robot repositories run as their READMEs say (issue 49): their files (tests/data/<repo>, each with its
SOURCES.md and LICENSE) copied into a workspace, built with the real ``colcon build --symlink-install``,
started with the real ``ros2 launch``, then driven over ROS while odometry and ground truth are compared."""

from __future__ import annotations

import math
import os
import shutil
import signal
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
from _harness import Proc, RosClient, wait_for

from .test_blog_workspace import shell

DATA = Path(__file__).resolve().parents[1] / "data"


def workspace(tmp_path: Path, repo: str, packages: list[str]) -> Path:
    """``tmp_path/ws`` whose ``src`` holds the repository's packages, as a user's clone would."""
    src = tmp_path / "ws" / "src"
    src.mkdir(parents=True)
    for pkg in packages:
        shutil.copytree(DATA / repo / pkg, src / pkg)
    return tmp_path / "ws"


def colcon_build(ws: Path, timeout: float = 300) -> str:
    """``colcon build --symlink-install`` in ``ws``, which must succeed; its output."""
    build = shell(f"cd {ws} && colcon build --symlink-install", "colcon")
    assert build.wait(timeout) == 0, build.output
    return build.output


def launch(ws: Path, command: str) -> Proc:
    """``ros2 launch ...`` after ``source install/setup.bash`` (``command`` may set variables first)."""
    return shell(f"cd {ws} && source install/setup.bash && {command}", "ros2 launch")


def stop(proc: Proc) -> None:
    """Ctrl-C to the launch's process group, as a user's terminal sends it: every process must end."""
    os.killpg(proc.popen.pid, signal.SIGINT)
    rc = proc.wait(30)
    assert rc in (0, -signal.SIGINT, 130), proc.output


@dataclass
class Topic:
    """Every message of one topic, kept by a subscription of the test's node."""

    messages: list[Any] = field(default_factory=list)
    lock: threading.Lock = field(default_factory=threading.Lock)

    @classmethod
    def subscribe(cls, ros: RosClient, msg_type: Any, name: str) -> Topic:
        topic = cls()

        def keep(msg: Any) -> None:
            with topic.lock:
                topic.messages.append(msg)

        ros.node.create_subscription(msg_type, name, keep, 10)
        return topic

    def latest(self) -> Any:
        with self.lock:
            return self.messages[-1] if self.messages else None

    def count(self) -> int:
        with self.lock:
            return len(self.messages)


def _xy(pose: Any) -> tuple[float, float]:
    return pose.position.x, pose.position.y


def drive_a_metre(
    ros: RosClient, entity: str, send: Callable[[float], None], odom: Topic, speed: float = 0.3, timeout: float = 60
) -> tuple[float, float]:
    """Drives ``entity`` straight with ``send(speed)`` until its odometry says 1 m, stops it, waits until it is
    still, and returns (distance by odometry, distance by ground truth). Both must agree within 2 %."""
    wait_for(odom.latest, 60, f"odometry of {entity}")
    start_odom = _xy(odom.latest().pose.pose)
    start_truth = _xy(ros.entity_state(entity).state.pose)

    def odom_distance() -> float:
        x, y = _xy(odom.latest().pose.pose)
        return math.hypot(x - start_odom[0], y - start_odom[1])

    def go() -> bool:
        send(speed)
        return odom_distance() >= 1.0

    wait_for(go, timeout, f"1 m of driving {entity} by odometry", interval=0.05)
    settle = time.monotonic() + 10
    while time.monotonic() < settle:
        send(0.0)
        twist = odom.latest().twist.twist
        if abs(twist.linear.x) < 1e-3 and abs(twist.angular.z) < 1e-3:
            break
        time.sleep(0.05)
    send(0.0)
    end_truth = _xy(ros.entity_state(entity).state.pose)
    truth = math.hypot(end_truth[0] - start_truth[0], end_truth[1] - start_truth[1])
    by_odom = odom_distance()
    assert truth == pytest.approx(by_odom, rel=0.02), f"{entity}: odometry {by_odom:.3f} m, ground truth {truth:.3f} m"
    return by_odom, truth
