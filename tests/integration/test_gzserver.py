"""Issue 26: launch files that run `gzserver` and `gzclient` directly (Husky's, Clearpath's, tutorials')
failed with `No such file or directory: 'gzserver'`."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from _harness import start

from gazelle.cli._gzserver import gzserver_args


def test_gzserver_options_map_to_gazelle_sim(monkeypatch) -> None:
    monkeypatch.delenv("GAZELLE_GZSERVER_VIEWER", raising=False)
    args, ignored = gzserver_args(
        ["-u", "--verbose", "-s", "libgazebo_ros_init.so", "-s", "/opt/x/libgazebo_ros_factory.so", "w.world",
         "-e", "ode", "-s", "libmy_plugin.so"]
    )  # fmt: skip
    assert args == ["w.world", "--paused"]
    assert ignored == ["--verbose", "-e ode", "-s libmy_plugin.so"]


def test_gzserver_and_gzclient_run_as_a_launch_file_runs_them(tmp_path: Path) -> None:
    bin_dir = Path(sys.executable).parent  # the venv's console scripts
    world = tmp_path / "empty.world"
    world.write_text(
        '<sdf version="1.6"><world name="empty"><include><uri>model://ground_plane</uri></include></world></sdf>'
    )
    env = {**os.environ, "GAZELLE_GZSERVER_VIEWER": "0"}
    server = start([str(bin_dir / "gzserver"), str(world), "-s", "libgazebo_ros_init.so", "--verbose"], "gzserver", env)
    client = start([str(bin_dir / "gzclient")], "gzclient", env)
    try:
        server.wait_line("gazelle: ready: world 'empty'", 60)
        assert "not used: --verbose" in server.output
        client.wait_line("the simulation is drawn in the browser", 30)
    finally:
        assert client.interrupt() == 0, client.output
        assert server.interrupt() == 0, server.output
