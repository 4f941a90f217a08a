"""A ROS_DOMAIN_ID no other process on this machine holds, reserved with a lock file.

Two test runs on one machine (two developers, or a developer and CI) that picked the same domain would
answer each other's service calls. A domain is taken by holding an exclusive ``flock`` on
``$TMPDIR/gazelle-ros-domain-<id>.lock`` while it is in use; the kernel drops the lock when the
process ends, however it ends, so a killed run never leaves a domain taken.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import tempfile
from collections.abc import Iterator, Mapping
from typing import IO

FIRST, LAST = 10, 100
"""Domains handed out. Fast DDS maps a domain to UDP ports 7400 + 250 * id and up, and Linux's ephemeral
ports start at 32768: ids up to 101 stay below them (ROS 2's own guidance for Linux)."""


class DomainReservation:
    """One reserved domain id; :meth:`release` (or the end of the process) frees it."""

    def __init__(self, domain_id: int, handle: IO[str]) -> None:
        self.domain_id = domain_id
        self._handle: IO[str] | None = handle

    def release(self) -> None:
        if self._handle is not None:
            self._handle.close()  # closing the file drops the flock
            self._handle = None


def reserve_domain(preferred: int | None = None) -> DomainReservation:
    """The first free domain in [FIRST, LAST], starting at ``preferred`` (default: one picked from the
    process id, so concurrent runs rarely contend for the same lock)."""
    span = LAST - FIRST + 1
    start = preferred if preferred is not None else FIRST + os.getpid() % span
    folder = tempfile.gettempdir()
    for k in range(span):
        domain = FIRST + (start - FIRST + k) % span
        handle = open(os.path.join(folder, f"gazelle-ros-domain-{domain}.lock"), "a+")
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        return DomainReservation(domain, handle)
    raise RuntimeError(f"no free ROS domain id in {FIRST}..{LAST}: {span} runs hold one each")


@contextlib.contextmanager
def environ_applied(values: Mapping[str, str]) -> Iterator[None]:
    """``os.environ`` with ``values`` set while the block runs, each key put back as it was (or removed)."""
    saved = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
