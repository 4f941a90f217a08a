"""A step after a publish waits for the subscribers' acknowledgements (issue 50, item 1), and Fast DDS's
writers send the heartbeat that asks for them every 3 s by default: gazelle's pytest plugin gives the test
process's writers a 5 ms heartbeat. Fast DDS reads its profiles file once, at the process's first
participant: when the test's node was made after another participant of the same process (any earlier
rclpy node of the session, as in a pytest worker running a whole suite), every run_for after a publish
waited 3 s (three tests of the suite took 285-309 s instead of 3-11 s). The inner pytest below makes a
participant of its own before the fixture's node, at import."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from _paths import SEED_XACRO

pytestmark = pytest.mark.slow

INNER = textwrap.dedent(
    """
    import time

    import rclpy
    from rclpy.context import Context
    from geometry_msgs.msg import Twist

    FIRST = Context()
    rclpy.init(context=FIRST)
    FIRST_NODE = rclpy.create_node("an_earlier_node", context=FIRST)  # the process's first participant


    def test_each_run_for_after_a_publish_is_quick(gazelle_sim):
        gazelle_sim.spawn({robot!r}, "robot", pose=(0.0, 0.0, 0.07))
        pub = gazelle_sim.ros.publisher("/cmd_vel", Twist)
        gazelle_sim.ros.wait_for_subscribers(pub)
        waits = []
        for i in range(5):
            msg = Twist()
            msg.linear.x = 0.1 * (i % 2)
            pub.publish(msg)
            start = time.monotonic()
            gazelle_sim.run_for(0.01)
            waits.append(time.monotonic() - start)
        assert max(waits) < 1.5, waits  # Fast DDS's default heartbeat: 2.9-3.0 s each
    """
)


def test_a_step_after_a_publish_does_not_wait_for_fast_dds_s_default_heartbeat(tmp_path: Path) -> None:
    (tmp_path / "test_inner.py").write_text(INNER.format(robot=str(SEED_XACRO)))
    env = {k: v for k, v in os.environ.items() if k not in ("PYTEST_XDIST_WORKER", "PYTEST_ADDOPTS")}
    env.pop("FASTRTPS_DEFAULT_PROFILES_FILE", None)
    env.pop("FASTDDS_DEFAULT_PROFILES_FILE", None)
    out = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-p", "no:xdist", "-q", "test_inner.py"],
        capture_output=True,
        text=True,
        timeout=240,
        env=env,
        cwd=tmp_path,
    )
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-2000:]
