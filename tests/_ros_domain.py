"""One ROS_DOMAIN_ID per test process, reserved with a lock file so concurrent runs never share one.

Two pytest runs on one machine (two developers, or a developer and CI) that picked the same
domain would answer each other's service calls: a spawn answered by one server and a delete by
the other. Each process takes the first free domain in [10, 100] by holding an exclusive
``flock`` on /tmp/gazelle-ros-domain-<id>.lock for its lifetime (the kernel drops it on exit).
"""

from __future__ import annotations

import fcntl
import os
from typing import IO

_held: tuple[int, IO[str]] | None = None


_spare: list[tuple[int, IO[str]]] = []


def _reserve(skip: int = 0) -> tuple[int, IO[str]]:
    start = 10 + (os.getpid() + skip) % 91
    for k in range(91):
        domain = 10 + (start - 10 + k) % 91
        handle = open(f"/tmp/gazelle-ros-domain-{domain}.lock", "a+")
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        return domain, handle
    raise RuntimeError("no free ROS domain id in 10..100 (91 test runs at once?)")


def reserved_domain_id() -> int:
    """This process's domain id (reserved on first call)."""
    global _held
    if _held is None:
        _held = _reserve()
    return _held[0]


def empty_domain_id() -> int:
    """A second domain, reserved like the first for this process's lifetime, in which nothing of this
    process runs: for a test that needs no server to answer (a fixed number such as 99 was once the
    other xdist worker's reserved domain, whose server answered the spawn meant to time out)."""
    reserved_domain_id()
    if not _spare:
        _spare.append(_reserve(skip=45))
    return _spare[0][0]
