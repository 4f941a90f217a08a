"""What the server and the spawn client say about a test's set-up, as lines for the test's report.

The server logs each warning about an entity it spawns (a plugin it does not know, with its "did you mean",
a mesh it cannot find, a parameter nothing reads) as ``[WARN] [stamp] [logger]: message`` before the line
saying it spawned it; the spawn client prints a refusal as ``[ERROR] ... [spawn_entity]: ...``. These
functions turn such lines into the one line a report shows.
"""

from __future__ import annotations

import re
from typing import Protocol

from .._errors import SimError

__all__ = ["GazelleWarning", "client_warnings", "server_warning", "spawn_failure"]

_LOGGED = re.compile(r"^\[(WARN|WARNING|ERROR|FATAL)\] (?:\[[0-9.]+\] )?\[([^\]]*)\]: (.*)$")
_REFUSAL = re.compile(r"^(?:Spawn service failed: )?(?:SpawnEntity: Failure - )?")


class GazelleWarning(SimError, UserWarning):
    """A warning of the simulation about what the test set up (pytest lists it under the test; ``strict``
    makes it a failure). A :class:`SimError`, gazelle's one root, of the built-in kind ``UserWarning``."""


class _Output(Protocol):
    @property
    def output(self) -> str: ...

    def tail(self, n: int = 20) -> str: ...


def server_warning(line: str) -> str | None:
    """``logger: message`` of a warning or error line of a ROS process's output, else None."""
    m = _LOGGED.match(line)
    if m is None:
        return None
    return m.group(3) if m.group(2) in ("gazelle", "spawn_entity") else f"{m.group(2)}: {m.group(3)}"


def client_warnings(child: _Output) -> list[str]:
    """The warnings ``gazelle spawn`` printed (an unused ROS argument)."""
    out = []
    for line in child.output.splitlines():
        m = _LOGGED.match(line)
        if m is not None and m.group(1).startswith("WARN"):
            out.append(m.group(3))
    return out


def spawn_failure(child: _Output) -> str:
    """Why ``gazelle spawn`` failed, in one line: its error lines' messages (the server's reason, with the
    file and line of a bad description), or its last line."""
    reasons = []
    for line in child.output.splitlines():
        m = _LOGGED.match(line)
        if m is not None and m.group(1) in ("ERROR", "FATAL"):
            reasons.append(_REFUSAL.sub("", m.group(3), count=1))
    if reasons:
        return "; ".join(reasons)
    tail = child.tail(1).strip()
    return tail or "it printed nothing"
