"""Issue 48: every ``ros2`` verb that takes a type name resolves it by the one checked resolver
(:func:`gazelle.ros.resolve_interface`): ``topic pub``/``echo``, ``service call``, ``action send_goal``,
``interface show``/``proto`` answer a crafted name with one line naming it, and import nothing of it (the
planted packages shadow the standard library's ``venv`` and ``unittest``, whose ``__main__`` ran)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from _planted import PAYLOADS, imported, plant
from _ros_domain import reserved_domain_id

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")

ISSUE_PAYLOADS = PAYLOADS[:2]
"""``venv/__main__/Clock`` and ``unittest/__main__/Clock``, the names the issue reported."""
VERBS = [
    *((("topic", "pub", "--once", "-w", "0", "/crafted", p, "{}"), p) for p in PAYLOADS),
    *((("topic", "echo", "--once", "/crafted", p), p) for p in ISSUE_PAYLOADS),
    *((("service", "call", "/crafted", p.replace("Clock", "Srv")), p.replace("Clock", "Srv")) for p in PAYLOADS[2:]),
    *((("action", "send_goal", "/crafted", p, "{}"), p) for p in ISSUE_PAYLOADS),
    *((("interface", "show", p), p) for p in ISSUE_PAYLOADS),
    *((("interface", "proto", p), p) for p in ISSUE_PAYLOADS),
]


@pytest.mark.parametrize(("argv", "payload"), VERBS, ids=[" ".join(a[:2]) + f" {p}" for a, p in VERBS])
def test_a_crafted_type_name_is_one_line_and_imports_nothing(tmp_path: Path, argv: tuple[str, ...], payload: str):
    path, markers = plant(tmp_path)
    env = dict(
        os.environ,
        PYTHONPATH=os.pathsep.join(p for p in (str(path), os.environ.get("PYTHONPATH", "")) if p),
        ROS_DOMAIN_ID=str(reserved_domain_id()),
        ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
    )
    out = subprocess.run([ROS2, *argv], capture_output=True, text=True, timeout=60, env=env)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 1 and len(lines) == 1 and "Traceback" not in out.stderr, (out.returncode, out.stderr)
    assert repr(payload) in lines[0], lines[0]
    assert imported(markers) == []


def test_well_formed_names_still_resolve_through_the_verbs() -> None:
    """The resolver's rules keep what ros2cli takes: ``pkg/msg/Name``, ``pkg/Name``, a service and an action."""
    for argv, said in (
        (("interface", "proto", "std_msgs/String"), "data: ''"),
        (("interface", "proto", "std_srvs/srv/SetBool"), "data: false"),
        (("interface", "proto", "control_msgs/action/GripperCommand"), "command:"),
        (("interface", "show", "std_srvs/srv/Trigger"), "string message"),
    ):
        out = subprocess.run([ROS2, *argv], capture_output=True, text=True, timeout=60)
        assert out.returncode == 0 and said in out.stdout, (argv, out.stdout, out.stderr)
