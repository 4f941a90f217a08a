"""The ROS domain reservation (issue 48, item 8): nothing planted at a lock file's name is followed or breaks
the reservation, and a domain held is seen as held by every other scheme on the machine: another process of
this version, an earlier gazelle's lock file (another developer's checkout) and ROS 2's domain_coordinator.

The lock files live in a folder of the test's own (``TMPDIR``): the machine's /tmp ones belong to the runs
going on now. The ports are the machine's: each test picks domains whose ports are free at its start.
"""

from __future__ import annotations

import fcntl
import os
import socket
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from gazelle.testing import reserve_domain

FIRST, LAST, PORT_BASE = 10, 100, 32768


@pytest.fixture
def lock_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """``tempfile.gettempdir()`` (where the lock files go) is a folder of this test's own."""
    folder = tmp_path / "tmp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    monkeypatch.setenv("TMPDIR", str(folder))  # for the child processes
    return folder


def _free_run(n: int) -> int:
    """A domain D with the ports of D..D+n-1 free now (none reserved by a run at this moment)."""
    for d in range(FIRST + 20, LAST - n + 2):
        socks = []
        try:
            for k in range(n):
                s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
                socks.append(s)
                s.bind(("127.0.0.1", PORT_BASE + d + k))
            return d
        except OSError:
            continue
        finally:
            for s in socks:
                s.close()
    pytest.skip(f"no {n} consecutive free domains on this machine now")


def _lock(folder: Path, domain: int) -> Path:
    return folder / f"gazelle-ros-domain-{domain}.lock"


def test_a_link_planted_at_a_lock_name_is_not_followed(lock_dir: Path, tmp_path: Path) -> None:
    """A link at the preferred domain's lock name, to a file that does not exist: the plugin (often root in
    CI) created the link's target. Now that domain is skipped and nothing is created."""
    d = _free_run(2)
    target = tmp_path / "created-through-the-link"
    _lock(lock_dir, d).symlink_to(target)
    held = reserve_domain(preferred=d)
    try:
        assert not target.exists(), "the reservation created the planted link's target"
        assert held.domain_id != d
        assert _lock(lock_dir, d).is_symlink()
    finally:
        held.release()


@pytest.mark.parametrize("kind", ["directory", "fifo"])
def test_a_directory_or_fifo_at_a_lock_name_is_skipped_without_an_error(lock_dir: Path, kind: str) -> None:
    """A directory of that name raised IsADirectoryError out of the reservation (its ``open`` was outside
    the ``try``), failing the test run at its first fixture; a FIFO could block an open. Both are skipped."""
    d = _free_run(2)
    planted = _lock(lock_dir, d)
    planted.mkdir() if kind == "directory" else os.mkfifo(planted)
    held = reserve_domain(preferred=d)
    try:
        assert held.domain_id != d
    finally:
        held.release()


def _child_reserves(domain: int) -> int:
    """The domain another process gets when it prefers ``domain``."""
    code = f"from gazelle.testing import reserve_domain; print(reserve_domain(preferred={domain}).domain_id)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    return int(out.stdout.strip())


def test_a_held_domain_is_held_for_other_processes_earlier_gazelles_and_domain_coordinator(lock_dir: Path) -> None:
    d = _free_run(2)
    held = reserve_domain(preferred=d)
    assert held.domain_id == d
    try:
        assert _child_reserves(d) != d  # another process of this version
        with open(_lock(lock_dir, d), "a+") as f, pytest.raises(BlockingIOError):  # an earlier gazelle's lock
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
        coordinator = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        with coordinator, pytest.raises(OSError):  # ROS 2's domain_coordinator binds every interface
            coordinator.bind(("", PORT_BASE + d))
    finally:
        held.release()
    assert _child_reserves(d) == d  # released: free again


def test_a_domain_held_by_an_earlier_gazelle_or_domain_coordinator_is_skipped(lock_dir: Path) -> None:
    d = _free_run(3)
    with open(_lock(lock_dir, d), "a+") as old:  # an earlier gazelle's reservation: its lock file only
        fcntl.flock(old, fcntl.LOCK_EX | fcntl.LOCK_NB)
        coordinator = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        with coordinator:
            coordinator.bind(("", PORT_BASE + d + 1))  # domain_coordinator's: its port only
            held = reserve_domain(preferred=d)
            try:
                assert held.domain_id not in (d, d + 1)
            finally:
                held.release()


def test_domains_given_as_ids_and_ranges_are_the_only_ones_used(
    lock_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``GAZELLE_ROS_DOMAINS`` and ``domains=`` (issue 50 item 6): ids and ranges, in 0..232; a taken one is skipped,
    none outside is ever used; a bad value is one line naming the variable."""
    from gazelle.testing._domain import parse_domains

    assert parse_domains("20-22, 30,21") == (20, 21, 22, 30)
    for bad in ("x", "5-", "30-20", "233", "-1"):
        with pytest.raises(ValueError, match="GAZELLE_ROS_DOMAINS: "):
            parse_domains(bad)
    d = _free_run(2)
    monkeypatch.setenv("GAZELLE_ROS_DOMAINS", f"{d},{d + 1}")
    first = reserve_domain()
    second = reserve_domain()
    try:
        assert {first.domain_id, second.domain_id} == {d, d + 1}
        with pytest.raises(RuntimeError, match=f"no free ROS domain id in {d}..{d + 1}"):
            reserve_domain()
    finally:
        first.release()
        second.release()
    explicit = reserve_domain(domains=[d + 1])
    assert explicit.domain_id == d + 1
    explicit.release()
