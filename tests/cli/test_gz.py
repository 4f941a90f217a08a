"""Issue 49: a `gz` command for what gazelle serves, as gzserver and gzclient are for Gazebo Classic: `gz sim` is
`gazelle sim` with gz's options, `gz topic`/`gz service` list and read gazelle's topics and services, and anything
else is one line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from _harness import start

from gazelle.cli import gz_sim_args

GZ = str(Path(sys.executable).parent / "gz")


def test_gz_sim_options_become_gazelle_sims() -> None:
    parsed = gz_sim_args(["-r", "-s", "-v4", "--render-engine", "ogre2", "warehouse.sdf"])
    assert (parsed.gui_only, parsed.sim_args, parsed.ignored) == (
        False,
        ["warehouse.sdf"],
        ["-v4", "--render-engine ogre2"],
    )
    assert gz_sim_args(["empty.sdf"]).sim_args == ["empty.sdf", "--paused"]  # gz sim starts paused without -r
    assert gz_sim_args(["-s", "-r"], viewer=False).sim_args == ["--no-viewer"]
    assert gz_sim_args(["-g", "-v", "4"]).gui_only


def test_gz_sim_runs_the_server_and_gz_topic_lists_its_topics() -> None:
    server = start([GZ, "sim", "-r", "-s", "-v4", "empty.sdf"], "gz sim")
    try:
        server.wait_line("gazelle: ready: world", 60)
        assert "not used: -v4" in server.output and "PAUSED" not in server.output
        listed = subprocess.run([GZ, "topic", "-l"], capture_output=True, text=True, timeout=60)
        assert listed.returncode == 0 and "/clock" in listed.stdout.split(), listed.stderr
    finally:
        assert server.interrupt() == 0, server.output


def test_what_gz_does_not_have_here_is_one_line() -> None:
    for argv in (["fuel", "list"], ["service", "-s", "/world/default/create"], ["topic", "-p", "x"]):
        done = subprocess.run([GZ, *argv], capture_output=True, text=True, timeout=30)
        assert done.returncode == 1 and len(done.stderr.strip().splitlines()) == 1, done.stderr
        assert "Traceback" not in done.stderr
