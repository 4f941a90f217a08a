"""The layers import one way (docs/architecture.md), checked by walking every import with ``ast``.

description <- physics <- systems <- sim <- ros / viewer <- cli, and description <- planning <- ros. Physics never sees systems, the
runtime or ROS; systems never touch MuJoCo or the builder; only ``gazelle.ros`` (and the command
line, which starts it) imports rclpy; and no package reaches into another package's private modules.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest
from _paths import REPO

PACKAGE = REPO / "gazelle"
LAYERS = ("description", "physics", "systems", "sim", "ros", "viewer", "cli", "worlds", "planning", "testing", "sweep")

FORBIDDEN: dict[str, tuple[str, ...]] = {
    "description": (
        "gazelle.physics",
        "gazelle.systems",
        "gazelle.sim",
        "gazelle.ros",
        "gazelle.viewer",
        "gazelle.cli",
        "mujoco",
        "rclpy",
        "viser",
    ),
    "physics": ("gazelle.systems", "gazelle.sim", "gazelle.ros", "gazelle.viewer", "gazelle.cli", "rclpy", "viser"),
    "systems": ("mujoco", "gazelle.sim", "gazelle.ros", "gazelle.viewer", "gazelle.cli", "rclpy", "viser"),
    "sim": ("mujoco", "gazelle.ros", "gazelle.viewer", "gazelle.cli", "rclpy", "viser"),
    "ros": ("gazelle.viewer", "gazelle.cli"),
    # arms: kinematics and collisions of the description on roboplan; served by gazelle.ros
    "planning": (
        "gazelle.physics",
        "gazelle.systems",
        "gazelle.sim",
        "gazelle.ros",
        "gazelle.viewer",
        "gazelle.cli",
        "mujoco",
        "rclpy",
        "viser",
    ),
    "viewer": ("gazelle.ros", "gazelle.cli", "rclpy"),
    # many in-process runs of a scenario: the runtime without ROS
    # (ROS scenarios run on the robot-test fixtures' server)
    # (and the viewer's self-contained replay page for runs that fail)
    "sweep": ("gazelle.ros", "gazelle.cli", "rclpy", "viser"),
    # users' robot tests: gazelle's commands as processes, over ROS; in-process, the runtime's public API
    "testing": (
        "gazelle.physics",
        "gazelle.ros",
        "gazelle.viewer",
        "gazelle.planning",
        "mujoco",
        "viser",
    ),
    "worlds": (
        "gazelle.physics",
        "gazelle.systems",
        "gazelle.sim",
        "gazelle.ros",
        "gazelle.viewer",
        "gazelle.cli",
        "rclpy",
    ),
}
"""Layer -> module prefixes it must not import (directly or inside a function)."""


def _imports(path: Path) -> list[tuple[int, str]]:
    """(line, absolute module name) of every import in a file of the gazelle package."""
    rel = path.relative_to(REPO).with_suffix("")
    package = list(rel.parts[:-1]) if rel.name != "__init__" else list(rel.parts[:-1])
    out: list[tuple[int, str]] = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            out += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            out.append((node.lineno, mod))
            # `from . import _x` / `from ..physics import _world` name modules too
            out += [(node.lineno, f"{mod}.{a.name}") for a in node.names if a.name.startswith("_")]
    return out


def _violations() -> list[str]:
    found: list[str] = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE)
        layer = rel.parts[0] if len(rel.parts) > 1 else ""
        for line, mod in _imports(path):
            where = f"gazelle/{rel}:{line}"
            for bad in FORBIDDEN.get(layer, ()):
                if mod == bad or mod.startswith(bad + "."):
                    found.append(f"{where}: the {layer} layer imports {mod}")
            if layer not in ("ros", "cli", "testing") and (mod == "rclpy" or mod.startswith("rclpy.")):
                found.append(f"{where}: only gazelle.ros imports rclpy, not {layer or 'gazelle'}")
            parts = mod.split(".")
            if len(parts) >= 3 and parts[0] == "gazelle" and parts[1] in LAYERS and parts[1] != layer:
                if any(p.startswith("_") and p != "__init__" for p in parts[2:]):
                    found.append(f"{where}: imports {mod}, a private module of gazelle.{parts[1]} (use its __init__)")
    return found


def test_layers_import_one_way_and_only_public_surfaces() -> None:
    problems = _violations()
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize(
    ("layer", "source", "expected"),
    [
        ("physics", "from ..systems import System\n", "the physics layer imports gazelle.systems"),
        ("physics", "def f():\n    from ..sim import Simulation\n", "the physics layer imports gazelle.sim"),
        ("systems", "import mujoco\n", "the systems layer imports mujoco"),
        ("systems", "from ..physics._builder import scoped\n", "private module of gazelle.physics"),
        ("viewer", "from ..systems._base import RateGate\n", "private module of gazelle.systems"),
        ("sim", "import rclpy\n", "the sim layer imports rclpy"),
    ],
)
def test_the_check_finds_each_kind_of_violation(
    tmp_path: Path, monkeypatch, layer: str, source: str, expected: str
) -> None:
    """The walk itself can fail: a planted import of each forbidden kind is reported, with its file and line."""
    fake = tmp_path / "gazelle"
    (fake / layer).mkdir(parents=True)
    (fake / layer / "planted.py").write_text(source)
    monkeypatch.setattr(__import__(__name__), "PACKAGE", fake)
    monkeypatch.setattr(__import__(__name__), "REPO", tmp_path)
    problems = _violations()
    assert any(expected in p and f"gazelle/{layer}/planted.py:" in p for p in problems), problems


BENCH = REPO / "bench"


def _bench_violations(folder: Path) -> list[str]:
    """Private reaches in the bench scripts: an import of a private gazelle module, or an attribute read
    that starts with one underscore on anything but ``self``/``cls`` (issue 28: bench_rtf.py crashed for a
    turn because it read ``node._pubs``, whose keys had changed)."""
    found: list[str] = []
    for path in sorted(folder.glob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            where = f"bench/{path.name}:{getattr(node, 'lineno', 0)}"
            mods: list[str] = []
            if isinstance(node, ast.Import):
                mods = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                mods = [node.module] + [f"{node.module}.{a.name}" for a in node.names if a.name.startswith("_")]
            for mod in mods:
                parts = mod.split(".")
                if parts[0] == "gazelle" and any(p.startswith("_") and not p.startswith("__") for p in parts[1:]):
                    found.append(f"{where}: imports {mod}, a private part of gazelle")
            if (
                isinstance(node, ast.Attribute)
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
                and not (isinstance(node.value, ast.Name) and node.value.id in ("self", "cls"))
            ):
                found.append(f"{where}: reads .{node.attr}, a private attribute")
    return found


def test_benches_use_only_public_surfaces() -> None:
    problems = _bench_violations(BENCH)
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("from gazelle.ros._move_group import _pose\n", "imports gazelle.ros._move_group"),
        ("def f(node):\n    return node._pubs\n", "reads ._pubs"),
        ("from gazelle.sim import _simulation\n", "imports gazelle.sim._simulation"),
    ],
)
def test_the_bench_check_finds_a_private_reach(tmp_path: Path, source: str, expected: str) -> None:
    (tmp_path / "bench_planted.py").write_text(source)
    problems = _bench_violations(tmp_path)
    assert any(expected in p and "bench/bench_planted.py:" in p for p in problems), problems


def test_ros_clients_do_not_import_the_simulation() -> None:
    """`gazelle arm`, `gazelle spawn` and `gazelle spawner` are clients: importing gazelle.ros brought in the
    bridge, MuJoCo and the runtime (1.1 s of every `gazelle arm` answer, issue 27 item 10), and gazelle.systems
    (for a plugin's name and the YAML reader) MuJoCo again: 0.3 s of every spawn and spawner the tests run."""
    code = (
        "import sys\n"
        "from gazelle.ros import arm_main, spawn_main, spawner_main\n"
        "import gazelle.ros._arm_cli, gazelle.ros._spawn, gazelle.ros._spawner\n"
        "print(sorted(m for m in ('mujoco', 'gazelle.sim', 'gazelle.ros._bridge') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"
