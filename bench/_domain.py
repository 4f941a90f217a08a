"""A ROS domain of a bench's own, set before anything imports rclpy.

``GAZELLE_BENCH_DOMAIN_ID`` when given; else one reserved as gazelle's tests and robot-CI plugin reserve
theirs (:func:`gazelle.testing.reserve_domain`: a bound port, as ROS 2's domain_coordinator does, and the
lock file earlier versions held), kept until the process exits. A domain picked from
the process id (``pid % 100 + 1``) could be a test worker's reserved domain: a bench run by the suite's
smoke test on one worker then served the other worker's requests with its own world (the likely cause of
a ``set_entity_state`` that found no entity just spawned, in a run beside a CPU hog).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from gazelle.testing import DomainReservation, reserve_domain

_held: list[DomainReservation] = []


def private_ros_domain() -> int:
    """Set ``ROS_DOMAIN_ID`` (and localhost-only discovery) in this process's environment; returns it."""
    given = os.environ.get("GAZELLE_BENCH_DOMAIN_ID")
    if given:
        domain = int(given)
    else:
        reservation = reserve_domain()
        _held.append(reservation)
        domain = reservation.domain_id
    os.environ["ROS_DOMAIN_ID"] = str(domain)
    os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    return domain
