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
    """What the graph shows ``MoveGroupNode`` from the ``after``-th query on: the action, or the topics;
    the controller (from moveit_controllers.yaml, or from a controller manager's list) from the
    ``named_after``-th."""

    def __init__(self, action: bool, topics: bool, after: int, named_after: int = 0) -> None:
        self.action, self.topics, self.after, self.queries = action, topics, after, 0
        self.named_after, self.lookups = named_after, 0

    def _controller_for(self, joints: list[str]) -> Controller | None:
        self.lookups += 1
        return _controller() if self.lookups > self.named_after else None

    def _action_served(self, action: str) -> bool:
        return self.action and self.queries >= self.after

    def _position_topics(self, joints: list[str]) -> dict[str, str] | None:
        self.queries += 1
        return dict(TOPICS) if self.topics and self.queries > self.after else None


def _wait(graph: _Graph) -> tuple[bool, dict[str, str] | None]:
    _, served, topics = MoveGroupNode._wait_for_execution(graph, JOINTS)  # type: ignore[arg-type]
    return served, topics


def _controller() -> Controller:
    return Controller("panda_arm_controller", "/panda_arm_controller/follow_joint_trajectory", tuple(JOINTS))


def test_gz_command_topics_discovered_late_are_streamed_to() -> None:
    graph = _Graph(action=False, topics=True, after=3)
    assert _wait(graph) == (False, TOPICS)
    assert graph.queries == 4


def test_an_action_server_discovered_late_is_used() -> None:
    graph = _Graph(action=True, topics=False, after=3)
    assert _wait(graph) == (True, None)


def test_a_controller_a_controller_manager_lists_late_is_used() -> None:
    graph = _Graph(action=True, topics=False, after=0, named_after=2)
    controller, served, topics = MoveGroupNode._wait_for_execution(graph, JOINTS)  # type: ignore[arg-type]
    assert (controller, served, topics) == (_controller(), True, None)
    assert graph.lookups == 3


def test_with_neither_the_wait_ends_at_its_bound(monkeypatch) -> None:
    monkeypatch.setattr(_move_group, "CONTROLLER_WAIT", 0.3)
    graph = _Graph(action=False, topics=False, after=0)
    t0 = time.monotonic()
    assert _wait(graph) == (False, None)
    assert 0.3 <= time.monotonic() - t0 < 2.0
    assert graph.queries >= 2


@pytest.mark.parametrize("kind", ["action", "topics"])
def test_what_is_there_at_once_is_not_waited_for(kind) -> None:
    graph = _Graph(action=kind == "action", topics=kind == "topics", after=0)
    t0 = time.monotonic()
    served, topics = _wait(graph)
    assert (served, topics) == ((True, None) if kind == "action" else (False, TOPICS))
    assert time.monotonic() - t0 < 0.05
