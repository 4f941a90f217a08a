"""Replays and checkpoints are written whole, never through a link, and never over a file that is not one
(issue 48, item 5): ``gazelle sim --replay "my world.sdf"`` replaced the world, and a symlink planted at the
writer's guessable ``.<name>.<pid>.tmp`` made it write through into another file and leave the target a link.
The real ``gazelle sim`` is tested in ``tests/integration/test_replay_files.py``; here, the writers in-process.
"""

from __future__ import annotations

import os
import pickle
import stat
from pathlib import Path

import pytest
from _sim import new_simulation

from gazelle._files import atomic_write
from gazelle.sim import CheckpointError, ReplayRecorder, Simulation
from gazelle.viewer import replay_html

PRECIOUS = "<sdf version='1.9'><world name='mine'/></sdf>\n"


@pytest.fixture
def sim() -> Simulation:
    made = new_simulation(seed=1)
    made.step(10)
    return made


def _planted(target: Path, victim: Path, names: list[str]) -> None:
    """Links at the temporary names the writers used to pick beside ``target``, each to ``victim``."""
    for name in names:
        (target.parent / name).symlink_to(victim)


def test_a_replay_is_not_written_through_a_link_planted_at_its_temporary_name(tmp_path: Path, sim) -> None:
    target, victim = tmp_path / "run.json", tmp_path / "victim.sdf"
    victim.write_text(PRECIOUS)
    _planted(target, victim, [f".{target.name}.{os.getpid()}.tmp"])
    recorder = ReplayRecorder(sim)
    recorder.write(target)
    assert victim.read_text() == PRECIOUS, "the replay was written through the planted link"
    assert not target.is_symlink() and target.read_text().startswith('{"shapes":')
    assert target.stat().st_mode & 0o777 == 0o666 & ~_umask()  # as a plain open would make it


def test_a_checkpoint_is_not_written_through_a_link_planted_at_its_temporary_name(tmp_path: Path, sim) -> None:
    target, victim = tmp_path / "a.ckpt", tmp_path / "victim.sdf"
    victim.write_text(PRECIOUS)
    _planted(target, victim, [f"{target.name}.{os.getpid()}.tmp"])
    sim.checkpoint(target)
    assert victim.read_text() == PRECIOUS, "the checkpoint was written through the planted link"
    assert not target.is_symlink() and stat.S_IMODE(target.stat().st_mode) == 0o600
    assert pickle.loads(target.read_bytes())["magic"] == "gazelle-checkpoint"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [target.name, victim.name, f"{target.name}.{os.getpid()}.tmp"]
    )


def test_a_replay_refuses_to_replace_a_file_that_is_not_one_unless_forced(tmp_path: Path, sim) -> None:
    world = tmp_path / "my world.sdf"
    world.write_text(PRECIOUS)
    recorder = ReplayRecorder(sim)
    with pytest.raises(FileExistsError, match=r"my world\.sdf exists and is not a replay: it is not overwritten"):
        recorder.write(world, replay_html(recorder.data()))
    assert world.read_text() == PRECIOUS
    recorder.write(world, force=True)
    assert world.read_text().startswith('{"shapes":')


def test_a_replay_replaces_an_earlier_replay_page_or_data_of_any_version(tmp_path: Path, sim) -> None:
    """Writing the replay again (SIGUSR1, then the shutdown; a test run again) is what replays are for: an
    earlier page (this version's, or one without the generator mark, as gazelle wrote them before) or data
    file is replaced without --force."""
    recorder = ReplayRecorder(sim)
    page = tmp_path / "run.html"
    recorder.write(page, replay_html(recorder.data(), title="first"))
    recorder.write(page, replay_html(recorder.data(), title="second"))
    assert "second" in page.read_text()
    page.write_text(replay_html(recorder.data()).replace('<meta name="generator" content="gazelle replay">', ""))
    recorder.write(page, replay_html(recorder.data(), title="third"))
    assert "third" in page.read_text()
    data = tmp_path / "run.json"
    recorder.write(data)
    recorder.write(data)
    assert data.read_text().startswith('{"shapes":')


def test_a_replay_never_replaces_a_link_or_a_fifo_unless_forced_and_then_the_link_itself(tmp_path: Path, sim) -> None:
    recorder = ReplayRecorder(sim)
    victim = tmp_path / "victim.sdf"
    victim.write_text(PRECIOUS)
    link = tmp_path / "run.json"
    link.symlink_to(victim)
    with pytest.raises(FileExistsError, match="exists and is a link"):
        recorder.write(link)
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    with pytest.raises(FileExistsError, match="is not a replay"):  # read without waiting on a writer
        recorder.write(fifo)
    recorder.write(link, force=True)
    assert victim.read_text() == PRECIOUS and not link.is_symlink()


def test_a_checkpoint_refuses_to_replace_a_file_that_is_not_one_unless_forced(tmp_path: Path, sim) -> None:
    world = tmp_path / "world.sdf"
    world.write_text(PRECIOUS)
    with pytest.raises(CheckpointError, match=r"world\.sdf exists and is not a checkpoint: it is not overwritten"):
        sim.checkpoint(world)
    assert world.read_text() == PRECIOUS
    again = tmp_path / "b.ckpt"
    sim.checkpoint(again)
    sim.step(5)
    sim.checkpoint(again)  # an earlier checkpoint is replaced
    assert Simulation.from_checkpoint(again).world.time == pytest.approx(sim.world.time)
    sim.checkpoint(world, force=True)
    assert pickle.loads(world.read_bytes())["magic"] == "gazelle-checkpoint"


def test_the_atomic_writer_leaves_the_old_file_and_no_temporary_when_it_fails(tmp_path: Path, monkeypatch) -> None:
    target = tmp_path / "x.txt"
    target.write_text("old")

    def fail(*_args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OSError, match="No space left"):
        atomic_write(target, "new")
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["x.txt"]


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
