"""``ros2 node``, ``ros2 topic`` and ``ros2 service``'s listing verbs take ros2cli's ``NodeStrategy`` options
(ros2cli/node/strategy.py: ``--spin-time`` and ``--no-daemon``) with ros2cli's help, written once
(``gazelle/cli/ros2cli/_graph.py``'s ``add_discovery_options``): each verb's ``--help`` as before."""

from __future__ import annotations

import re
from collections.abc import Callable

import pytest
from _paths import REPO

from gazelle.cli.ros2cli._node import main as node_main
from gazelle.cli.ros2cli._service import service_main
from gazelle.cli.ros2cli._topic import main as topic_main

VERBS: list[tuple[str, Callable[[list[str]], int], str]] = [
    ("node", node_main, "list"),
    ("node", node_main, "info"),
    ("topic", topic_main, "list"),
    ("topic", topic_main, "find"),
    ("service", service_main, "list"),
    ("service", service_main, "type"),
    ("service", service_main, "find"),
]

SPIN_HELP = "Spin time in seconds to wait for discovery (only applies when not using an already running daemon)"
NO_DAEMON_HELP = "Do not spawn nor use an already running daemon"


def _help(main: Callable[[list[str]], int], verb: str, capsys: pytest.CaptureFixture[str]) -> str:
    with pytest.raises(SystemExit) as ended:
        main([verb, "--help"])
    assert ended.value.code == 0
    return capsys.readouterr().out


@pytest.mark.parametrize(("command", "main", "verb"), VERBS, ids=[f"{c}-{v}" for c, _, v in VERBS])
def test_each_listing_verb_offers_ros2clis_discovery_options(command, main, verb, capsys, monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "200")  # the usage on one line
    text = _help(main, verb, capsys)
    usage = text.splitlines()[0]
    assert usage.startswith(f"usage: ros2 {command} {verb} [-h]"), usage
    assert usage.count("[--spin-time SPIN_TIME] [--no-daemon]") == 1, usage
    flat = " ".join(text.split())
    assert f" --spin-time SPIN_TIME {SPIN_HELP} --no-daemon {NO_DAEMON_HELP}" in flat, text


def test_a_verbs_help_is_as_it_was(capsys, monkeypatch) -> None:
    """One whole help, to the letter (ros2node's ``info``: its own option, then the strategy's)."""
    monkeypatch.setenv("COLUMNS", "100")
    assert _help(node_main, "info", capsys) == (
        "usage: ros2 node info [-h] [--include-hidden] [--spin-time SPIN_TIME] [--no-daemon] node_name\n"
        "\n"
        "positional arguments:\n"
        "  node_name\n"
        "\n"
        "options:\n"
        "  -h, --help            show this help message and exit\n"
        "  --include-hidden      Display hidden topics, services, and actions as well\n"
        "  --spin-time SPIN_TIME\n"
        "                        Spin time in seconds to wait for discovery (only applies when not using an\n"
        "                        already running daemon)\n"
        "  --no-daemon           Do not spawn nor use an already running daemon\n"
    )


def test_the_options_are_written_once() -> None:
    """The three verbs take the options from ``_graph.add_discovery_options``; none writes them itself."""
    folder = REPO / "gazelle" / "cli" / "ros2cli"
    for name in ("_node.py", "_topic.py", "_service.py"):
        source = (folder / name).read_text()
        assert "add_discovery_options(" in source, name
        assert not re.search(r"add_argument\(\s*\"--no-daemon\"", source), f"{name} writes --no-daemon itself"
        assert SPIN_HELP not in source, f"{name} writes --spin-time's help itself"
    assert SPIN_HELP in (folder / "_graph.py").read_text()
