"""move_group's execution waits, a bounded while, for its controller's action server or its joints' gz command
topics to be discovered: right after a robot is spawned, a busy machine's graph may not list them yet (seen
in a loaded test run as "controller action /panda_arm_controller/follow_joint_trajectory is not available"
for a gz Panda whose command topics were there a moment later)."""

from __future__ import annotations

import time

import pytest

from gazelle.ros import _move_group
from gazelle.ros._move_group import Controller, MoveGroupNode

JOINTS = ["panda_joint1", "panda_joint2"]
TOPICS = {j: f"/model/panda/joint/{j}/n0/cmd_pos" for j in JOINTS}


class _Graph:
    """What the graph shows ``MoveGroupNode`` from the ``after``-th query on: the action, or the topics."""

    def __init__(self, action: bool, topics: bool, after: int) -> None:
        self.action, self.topics, self.after, self.queries = action, topics, after, 0

    def _action_served(self, action: str) -> bool:
        return self.action and self.queries >= self.after

    def _position_topics(self, joints: list[str]) -> dict[str, str] | None:
        self.queries += 1
        return dict(TOPICS) if self.topics and self.queries > self.after else None


def _wait(graph: _Graph, controller: Controller | None) -> tuple[bool, dict[str, str] | None]:
    return MoveGroupNode._wait_for_execution(graph, controller, JOINTS)  # type: ignore[arg-type]


def _controller() -> Controller:
    return Controller("panda_arm_controller", "/panda_arm_controller/follow_joint_trajectory", tuple(JOINTS))


def test_gz_command_topics_discovered_late_are_streamed_to() -> None:
    graph = _Graph(action=False, topics=True, after=3)
    assert _wait(graph, _controller()) == (False, TOPICS)
    assert graph.queries == 4


def test_an_action_server_discovered_late_is_used() -> None:
    graph = _Graph(action=True, topics=False, after=3)
    assert _wait(graph, _controller()) == (True, None)


def test_with_neither_the_wait_ends_at_its_bound(monkeypatch) -> None:
    monkeypatch.setattr(_move_group, "CONTROLLER_WAIT", 0.3)
    graph = _Graph(action=False, topics=False, after=0)
    t0 = time.monotonic()
    assert _wait(graph, None) == (False, None)
    assert 0.3 <= time.monotonic() - t0 < 2.0
    assert graph.queries >= 2


@pytest.mark.parametrize("kind", ["action", "topics"])
def test_what_is_there_at_once_is_not_waited_for(kind) -> None:
    graph = _Graph(action=kind == "action", topics=kind == "topics", after=0)
    t0 = time.monotonic()
    served, topics = _wait(graph, _controller())
    assert (served, topics) == ((True, None) if kind == "action" else (False, TOPICS))
    assert time.monotonic() - t0 < 0.05
