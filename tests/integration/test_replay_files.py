"""``gazelle sim --replay FILE`` (issue 48, item 5), on the real command: a FILE that is not a replay (the
world itself, named twice) is refused before the run with one line, and a symlink planted where the replay's
temporary file used to go (``.FILE.<pid>.tmp``, a name anyone could guess from the process list) is neither
written through nor renamed over FILE."""

from __future__ import annotations

import signal

from _harness import GAZELLE, start

WORLD = """<?xml version="1.0"?>
<sdf version="1.9">
  <world name="mine">
    <model name="ground"><static>true</static><link name="l">
      <collision name="c"><geometry><plane><normal>0 0 1</normal><size>10 10</size></plane></geometry></collision>
    </link></model>
  </world>
</sdf>
"""


def test_a_replay_named_as_the_world_file_is_refused_before_the_run(tmp_path) -> None:
    """The issue's run: ``gazelle sim "my world.sdf" --replay "my world.sdf"`` replaced the world with the
    replay at shutdown. Now it ends at once with status 2 and one line naming the file; the world is as it
    was. (On the old code the server starts instead, and this waits 60 s for it to end.)"""
    world = tmp_path / "my world.sdf"
    world.write_text(WORLD)
    proc = start([*GAZELLE, "sim", str(world), "--replay", str(world), "--no-viewer"], "gazelle sim")
    rc = proc.wait(60)
    assert rc == 2, proc.output
    lines = [ln for ln in proc.output.splitlines() if ln.strip()]
    assert lines == [
        f"gazelle: --replay {world} exists and is not a replay: it is not overwritten "
        "(name another file, or pass --force)"
    ], proc.output
    assert world.read_text() == WORLD


def test_a_link_planted_at_the_old_temporary_name_is_not_written_through(tmp_path) -> None:
    out, victim = tmp_path / "my run.json", tmp_path / "victim.sdf"
    victim.write_text(WORLD)
    proc = start([*GAZELLE, "sim", "--no-viewer", "--replay", str(out)], "gazelle sim")
    proc.wait_line("gazelle: ready", timeout=60)
    planted = tmp_path / f".{out.name}.{proc.popen.pid}.tmp"
    planted.symlink_to(victim)
    proc.popen.send_signal(signal.SIGINT)
    assert proc.wait(30) == 0, proc.output
    assert victim.read_text() == WORLD, "the replay was written through the planted link"
    assert not out.is_symlink() and out.read_text().startswith('{"shapes":')
    assert planted.is_symlink()  # left where it was, untouched
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([out.name, victim.name, planted.name])


def test_force_replaces_a_file_that_is_not_a_replay(tmp_path) -> None:
    notes = tmp_path / "notes.json"
    notes.write_text('{"mine": true}\n')
    proc = start([*GAZELLE, "sim", "--no-viewer", "--replay", str(notes), "--force"], "gazelle sim")
    proc.wait_line("gazelle: ready", timeout=60)
    assert notes.read_text() == '{"mine": true}\n'  # not before the shutdown
    assert proc.interrupt() == 0, proc.output
    assert notes.read_text().startswith('{"shapes":')
