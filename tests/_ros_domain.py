"""One ROS_DOMAIN_ID per test process, reserved so that concurrent runs never share one.

Two pytest runs on one machine (two developers, or a developer and CI) that picked the same
domain would answer each other's service calls: a spawn answered by one server and a delete by
the other. Each process takes the first free domain in [10, 100] for its lifetime with gazelle's own
reservation (:func:`gazelle.testing.reserve_domain`: a bound port as ROS 2's domain_coordinator does,
and the lock file earlier versions of this module used, opened without following a link).
"""

from __future__ import annotations

import os

from gazelle.testing import DomainReservation, reserve_domain

_held: DomainReservation | None = None
_spare: list[DomainReservation] = []

FIRST, SPAN = 10, 91
"""The domains reserved: 10..100 (gazelle.testing's FIRST..LAST)."""


def reserved_domain_id() -> int:
    """This process's domain id (reserved on first call, from one picked by the process id)."""
    global _held
    if _held is None:
        _held = reserve_domain()
    return _held.domain_id


def empty_domain_id() -> int:
    """A second domain, reserved like the first for this process's lifetime, in which nothing of this
    process runs: for a test that needs no server to answer (a fixed number such as 99 was once the
    other xdist worker's reserved domain, whose server answered the spawn meant to time out)."""
    reserved_domain_id()
    if not _spare:
        _spare.append(reserve_domain(preferred=FIRST + (os.getpid() + 45) % SPAN))
    return _spare[0].domain_id
