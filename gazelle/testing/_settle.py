"""Lockstep with the nodes under test: wait, after each chunk of stepped sim time, until the processes the
test started have done what that time asked of them.

ROS 2 has no lockstep protocol: a node with ``use_sim_time`` follows /clock whenever its executor gets to
it, and a simulator (Gazebo's as gazelle's) steps on regardless. On a busy machine a starved node then
acts late in sim time: the seed's square node once stopped the robot 0.36 s of sim time late (a 1.07 m
side) while the test stepped 10 ms chunks as fast as it could. What a node has to do after a chunk shows
in the kernel's view of it: a thread that was woken (by the /clock message, by its timer, by a message it
publishes in reply) is runnable, state ``R``, until it blocks again in its wait set. So the test waits,
after each chunk, until no thread of those processes is runnable: every node has then taken the new time,
run the timers it made due and published what they sent, before the world moves on.

Linux only (``/proc``); elsewhere :func:`busy_threads` finds nothing and stepping is as before.
"""

from __future__ import annotations

import os
import time
from collections.abc import Iterable
from pathlib import Path

_PROC = Path("/proc")


def _stat_fields(stat_path: str) -> list[bytes] | None:
    """The fields of a ``/proc/.../stat`` file after the command name (state first, process group third),
    or None if the process or thread has ended. Raw reads: a poll of a few processes' threads takes tens
    of microseconds."""
    try:
        fd = os.open(stat_path, os.O_RDONLY)
    except OSError:
        return None
    try:
        raw = os.read(fd, 1024)
    except OSError:
        return None
    finally:
        os.close(fd)
    return raw[raw.rfind(b")") + 2 :].split()


def group_members(groups: Iterable[int]) -> dict[int, int]:
    """{pid: process group} of every process in these process groups (a test's child and all it started:
    each child is the leader of a session of its own)."""
    wanted = set(groups)
    if not wanted or not _PROC.is_dir():
        return {}
    found = {}
    for entry in os.scandir(_PROC):
        if not entry.name.isdigit():
            continue
        fields = _stat_fields(f"{entry.path}/stat")
        if fields is not None and len(fields) > 2 and int(fields[2]) in wanted:
            found[int(entry.name)] = int(fields[2])
    return found


def thread_stats(pids: Iterable[int]) -> list[tuple[int, str]]:
    """(pid, path of its stat file) for each thread of these processes now."""
    found = []
    for pid in pids:
        try:
            found += [(pid, f"{task.path}/stat") for task in os.scandir(_PROC / str(pid) / "task")]
        except OSError:  # the process ended
            continue
    return found


def busy_threads(threads: Iterable[tuple[int, str]]) -> list[tuple[int, str]]:
    """(pid, thread name) of each of these threads (see :func:`thread_stats`) that is running or runnable
    (``R``) or in an uninterruptible wait (``D``: a short disk or page wait it comes back from runnable)."""
    busy = []
    for pid, stat_path in threads:
        fields = _stat_fields(stat_path)
        if fields and fields[0] in (b"R", b"D"):
            try:
                name = Path(stat_path).with_name("comm").read_text().strip()
            except OSError:
                name = stat_path
            busy.append((pid, name))
    return busy


class Settler:
    """Waits until the processes in some process groups are idle; the groups' members and their threads are
    looked up again at most once a second (nodes a launch file starts appear late)."""

    POLL_SEC = 0.0005
    QUIET_POLLS = 2
    """Idle in this many polls in a row (a millisecond): the /clock message the test heard may reach a
    node's reader a few microseconds after the test's own, so one idle look could come before its wake-up."""

    def __init__(self, timeout: float) -> None:
        """A settler that waits, after each chunk of stepped time, at most ``timeout`` seconds of wall time for the
        processes of the groups it is given to go idle (0: it does not wait)."""
        self.timeout = timeout
        self.ignored: set[int] = set()
        self._groups: tuple[int, ...] = ()
        self._members: dict[int, int] = {}
        self._threads: list[tuple[int, str]] = []
        self._looked = -1e9

    def wait(self, groups: Iterable[int]) -> list[tuple[int, str]]:
        """Wait until no thread of the groups' processes is runnable, at most ``timeout`` s of wall time.
        Returns the threads still busy then, and stops waiting for their groups from then on (``ignored``;
        the caller warns: a node that computes without pause cannot be waited for)."""
        groups = tuple(g for g in groups if g not in self.ignored)
        if self.timeout <= 0 or not groups:
            return []
        now = time.monotonic()
        if groups != self._groups or now - self._looked > 1.0:
            self._groups, self._members, self._looked = groups, group_members(groups), now
            self._threads = thread_stats(self._members)
        deadline, quiet = now + self.timeout, 0
        while True:
            busy = busy_threads(self._threads)
            quiet = 0 if busy else quiet + 1
            if quiet >= self.QUIET_POLLS:
                return []
            if time.monotonic() > deadline:
                self.ignored.update(self._members[pid] for pid, _ in busy if pid in self._members)
                return busy
            time.sleep(self.POLL_SEC)
