"""Robot tests on gazelle: the pytest plugin's fixtures and the classes behind them.

``gazelle.testing.plugin`` is registered as a pytest plugin (``pytest11``): a test asks for the
``gazelle_sim`` and ``ros`` fixtures and never imports gazelle. The classes are here for tests that
build a simulation themselves (outside pytest, or with other scopes):

* :class:`Sim`: a ``gazelle sim`` process on a private domain, paused, stepped by the test in sim time;
* :class:`RosTestNode`: the test's rclpy node with waits that time out;
* :func:`reserve_domain`: a ROS_DOMAIN_ID no other process on the machine holds;
* :class:`GazelleWarning`: the server's warning about what a test set up (``strict`` makes it a failure).

This layer sits beside ``gazelle.cli``: it starts gazelle's commands as processes and talks to them over
ROS, and imports rclpy only when a fixture is used.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ._domain import DomainReservation, environ_applied, reserve_domain
from ._warnings import GazelleWarning

if TYPE_CHECKING:
    from ._ros_node import MessageLog, RosTestNode, TestTimeout
    from ._sim import ChildProcess, Sim, SimError
    from ._world import InProcessWorld, WorldTimeout

_LAZY = {
    "MessageLog": "._ros_node",
    "RosTestNode": "._ros_node",
    "TestTimeout": "._ros_node",
    "ChildProcess": "._sim",
    "Sim": "._sim",
    "SimError": "._sim",
    "InProcessWorld": "._world",
    "WorldTimeout": "._world",
}


def __getattr__(name: str) -> Any:
    """The classes that need rclpy are imported on first use."""
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "ChildProcess",
    "DomainReservation",
    "GazelleWarning",
    "InProcessWorld",
    "MessageLog",
    "RosTestNode",
    "Sim",
    "SimError",
    "TestTimeout",
    "WorldTimeout",
    "environ_applied",
    "reserve_domain",
]
