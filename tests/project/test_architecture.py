"""The layers import one way (docs/architecture.md), checked by walking every import with ``ast``.

description <- physics <- systems <- sim <- ros / viewer <- cli, description <- planning <- ros, and estimation <- ros. Physics never sees systems, the
runtime or ROS; systems never touch MuJoCo or the builder; only ``gazelle.ros`` (and the command
line, which starts it) imports rclpy; and no package reaches into another package's private modules.
"""

from __future__ import annotations

import ast
import builtins
import io
import subprocess
import sys
import tokenize
from pathlib import Path

import pytest
from _paths import REPO

PACKAGE = REPO / "gazelle"

ALLOWED: dict[str, tuple[str, ...]] = {
    # gazelle/__init__.py (the public names a script or a sweep scenario needs, loaded on first use),
    # gazelle/_lazy.py, gazelle/_files.py and gazelle/_errors.py
    "": ("description", "sim", "systems"),
    "description": (),
    "physics": ("description",),
    "systems": ("description", "physics"),
    "sim": ("description", "physics", "systems"),
    # arms: kinematics and collisions of the description on roboplan; served by gazelle.ros
    "planning": ("description",),
    "worlds": ("description",),
    # state estimation (robot_localization's EKF) on numpy; served by gazelle.ros's ekf_node
    "estimation": (),
    "ros": ("description", "physics", "systems", "sim", "planning", "estimation"),
    "viewer": ("description", "physics", "systems", "sim"),
    # users' robot tests: gazelle's commands as processes, over ROS; in-process, the runtime's public API
    "testing": ("description", "systems", "sim", "worlds"),
    # many in-process runs of a scenario: the runtime without ROS (ROS scenarios run on the robot-test
    # fixtures' server), and the viewer's self-contained replay page for runs that fail
    "sweep": ("description", "sim", "testing", "viewer", "worlds"),
    "cli": (
        "description",
        "physics",
        "systems",
        "sim",
        "planning",
        "estimation",
        "worlds",
        "ros",
        "viewer",
        "testing",
        "sweep",
    ),
}
"""Every folder of the gazelle package -> the gazelle packages it may import (an allow-list: a new folder,
or a new arrow between two, fails until it is declared here and in docs/architecture.md). Every folder may
import ``gazelle._lazy`` (the lazy-attribute helper), ``gazelle._files`` (the one atomic writer and
private-folder check) and ``gazelle._errors`` (``SimError``, the root of every error gazelle raises)."""

LAYERS = tuple(k for k in ALLOWED if k)

THIRD_PARTY: dict[str, tuple[str, ...]] = {
    "mujoco": ("physics",),
    "rclpy": ("ros", "cli", "testing"),
    "viser": ("viewer",),
    "ray": ("sweep",),
    "foxglove": ("cli",),
    "launch": ("cli",),
    "launch_ros": ("cli",),
}
"""Libraries that only some folders may import (directly or inside a function)."""

OTHER_FOLDERS = ("compat", "scripts", "launch", "launch_ros", "launch_xml", "launch_yaml", "bench")
"""Importable folders beside the package: they may use only gazelle's public surfaces."""


def _imports(path: Path, root: Path | None = None) -> list[tuple[int, str]]:
    """(line, absolute module name) of every import in a file under ``root`` (the repository)."""
    rel = path.relative_to(root or REPO).with_suffix("")
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
        if layer not in ALLOWED:
            found.append(f"gazelle/{rel}: the folder gazelle/{layer} is not declared in ALLOWED")
            continue
        for line, mod in _imports(path):
            where = f"gazelle/{rel}:{line}"
            parts = mod.split(".")
            if parts[0] in THIRD_PARTY and layer not in THIRD_PARTY[parts[0]]:
                found.append(
                    f"{where}: the {layer or 'top'} layer imports {mod} (only {', '.join(THIRD_PARTY[parts[0]])} may)"
                )
            if parts[0] != "gazelle" or len(parts) < 2 or parts[1] in ("_lazy", "_files", "_errors", layer):
                continue
            if parts[1] not in ALLOWED[layer]:
                found.append(f"{where}: the {layer or 'top'} layer imports gazelle.{parts[1]}, which it may not")
            elif any(p.startswith("_") and p != "__init__" for p in parts[2:]):
                found.append(f"{where}: imports {mod}, a private module of gazelle.{parts[1]} (use its __init__)")
    return found


def _other_violations(root: Path, folders: tuple[str, ...]) -> list[str]:
    """Imports of a private gazelle module from the folders beside the package."""
    found: list[str] = []
    for folder in folders:
        for path in sorted((root / folder).rglob("*.py")):
            for line, mod in _imports(path, root):
                parts = mod.split(".")
                if parts[0] == "gazelle" and any(p.startswith("_") and not p.startswith("__") for p in parts[1:]):
                    found.append(f"{path.relative_to(root)}:{line}: imports {mod}, a private part of gazelle")
    return found


def test_layers_import_one_way_and_only_public_surfaces() -> None:
    problems = _violations()
    assert not problems, "\n".join(problems)


def test_every_folder_of_the_package_is_declared_and_documented() -> None:
    folders = {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    assert folders == set(LAYERS), (
        f"declare in ALLOWED: {sorted(folders - set(LAYERS))}; gone: {sorted(set(LAYERS) - folders)}"
    )
    doc = (REPO / "docs" / "architecture.md").read_text()
    assert not [f for f in folders if f"gazelle/{f}/" not in doc], "docs/architecture.md names every folder"


TEST_FOLDERS = ("integration", "project")
"""Test folders that are not named for a package: tests that start real processes (servers, ``ros2``,
move_group) over real DDS, and checks of the repository itself (layering, set-up cache, interfaces)."""


def _misplaced_tests(tests: Path) -> list[str]:
    """Test modules outside ``tests/<package>/`` (in-process tests of one gazelle package, named as it is),
    ``tests/integration/`` and ``tests/project/``; and test folders without an ``__init__.py`` (their
    modules would be imported by their bare names, so two ``test_ros2_control.py`` would collide)."""
    allowed = set(LAYERS) | set(TEST_FOLDERS)
    found = []
    for path in sorted(tests.rglob("test_*.py")):
        rel = path.relative_to(tests)
        if len(rel.parts) != 2 or rel.parts[0] not in allowed:
            found.append(f"tests/{rel}: put it in tests/<package>/ (one of {sorted(allowed)})")
        elif not (path.parent / "__init__.py").exists():
            found.append(f"tests/{rel.parts[0]}/ has no __init__.py")
    return found


def test_tests_are_laid_out_by_what_they_test() -> None:
    problems = _misplaced_tests(REPO / "tests")
    assert not problems, "\n".join(problems)


def test_the_layout_check_finds_a_misplaced_test(tmp_path: Path) -> None:
    for rel in ("test_top.py", "helpers/test_x.py", "sim/test_ok.py", "sim/__init__.py", "ros/test_y.py"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("")
    problems = _misplaced_tests(tmp_path)
    assert [p.split(":")[0] for p in problems] == [
        "tests/helpers/test_x.py",
        "tests/ros/ has no __init__.py",
        "tests/test_top.py",
    ]


def test_the_folders_beside_the_package_use_only_public_surfaces() -> None:
    problems = _other_violations(REPO, OTHER_FOLDERS)
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize(
    ("layer", "source", "expected"),
    [
        ("physics", "from ..systems import System\n", "the physics layer imports gazelle.systems, which it may not"),
        ("physics", "def f():\n    from ..sim import Simulation\n", "the physics layer imports gazelle.sim"),
        ("systems", "import mujoco\n", "the systems layer imports mujoco (only physics may)"),
        ("systems", "from ..physics._builder import scoped\n", "private module of gazelle.physics"),
        ("viewer", "from ..systems._base import RateGate\n", "private module of gazelle.systems"),
        ("sim", "import rclpy\n", "the sim layer imports rclpy"),
        ("description", "from ..planning import Planner\n", "the description layer imports gazelle.planning"),
        ("worlds", "import viser\n", "the worlds layer imports viser"),
        ("newfolder", "x = 1\n", "the folder gazelle/newfolder is not declared"),
    ],
)
def test_the_check_finds_each_kind_of_violation(
    tmp_path: Path, monkeypatch, layer: str, source: str, expected: str
) -> None:
    """The walk itself can fail: a planted import of each forbidden kind is reported, with its file and line."""
    fake = tmp_path / "gazelle"
    (fake / layer).mkdir(parents=True)
    (fake / layer / "planted.py").write_text(source)
    monkeypatch.setattr(sys.modules[__name__], "PACKAGE", fake)
    monkeypatch.setattr(sys.modules[__name__], "REPO", tmp_path)
    problems = _violations()
    assert any(expected in p and f"gazelle/{layer}/planted.py" in p for p in problems), problems


def test_the_check_finds_a_private_reach_beside_the_package(tmp_path: Path) -> None:
    (tmp_path / "scripts").mkdir()
    (tmp_path / "scripts" / "tool.py").write_text("from gazelle.systems import _registry\n")
    (tmp_path / "compat").mkdir()
    (tmp_path / "compat" / "ok.py").write_text("from gazelle.ros import spawn_main\n")
    problems = _other_violations(tmp_path, ("scripts", "compat"))
    assert problems == ["scripts/tool.py:1: imports gazelle.systems._registry, a private part of gazelle"], problems


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
        "import gazelle.ros._arm_cli, gazelle.ros._spawn_entity, gazelle.ros._controller_spawner\n"
        "print(sorted(m for m in ('mujoco', 'gazelle.sim', 'gazelle.ros._bridge') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"


MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 800
MAX_SUPPRESSIONS = 20


def _house_problems(package: Path) -> list[str]:
    """What breaks the house's limits (issue 32): a function over :data:`MAX_FUNCTION_LINES` lines, a module
    over :data:`MAX_FILE_LINES`, more than :data:`MAX_SUPPRESSIONS` type-checker suppressions in all, or one
    without its reason after it."""
    problems, suppressions = [], 0
    for path in sorted(package.rglob("*.py")):
        text = path.read_text()
        rel = path.relative_to(package.parent)
        if (n := len(text.splitlines())) > MAX_FILE_LINES:
            problems.append(f"{rel}: {n} lines (at most {MAX_FILE_LINES}: split it where a reader looks for a seam)")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                if (n := node.end_lineno - node.lineno + 1) > MAX_FUNCTION_LINES:  # type: ignore[operator] - end_lineno is set for parsed code
                    problems.append(f"{rel}:{node.lineno} {node.name}() has {n} lines (at most {MAX_FUNCTION_LINES})")
        for i, line in enumerate(text.splitlines(), 1):
            for marker in ("# type: ignore", "# pyright: ignore"):
                if marker in line:
                    suppressions += 1
                    after = line.split(marker, 1)[1].split("]", 1)[-1].strip(" -")
                    if not after:
                        problems.append(f"{rel}:{i}: a suppression without its reason after it")
    if suppressions > MAX_SUPPRESSIONS:
        problems.append(f"{suppressions} type-checker suppressions (at most {MAX_SUPPRESSIONS}): fix the types")
    return problems


def test_the_house_keeps_its_limits() -> None:
    problems = _house_problems(REPO / "gazelle")
    assert not problems, "\n".join(problems)


def test_the_house_check_finds_a_long_function_a_big_file_and_a_bare_suppression(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "long.py").write_text("def f():\n" + "    x = 1\n" * 80)
    (pkg / "big.py").write_text("x = 1\n" * 801)
    (pkg / "bare.py").write_text(
        "x: int = 'a'  # type: ignore[assignment]\ny: int = 'b'  # type: ignore[assignment] - why\n"
    )
    problems = _house_problems(pkg)
    assert [p.split(":")[0].split(" ")[0] for p in problems] == ["pkg/bare.py", "pkg/big.py", "pkg/long.py"]


WHY_PACKAGES = ("description", "physics", "systems", "sim", "planning", "estimation", "testing")
"""The packages whose readers need the why (units, frames, which Gazebo behaviour is matched and where it
differs): the ones that model, simulate, plan and test. ros, viewer, cli and sweep are glue to rclpy, viser,
typer and Ray whose why lives in these (issue 32's decision, said in the stop-51 note)."""
MIN_DOC_DENSITY = 0.35


def _doc_density(package: Path) -> float:
    """Comment and docstring lines per non-blank code line over a package's modules (a docstring of any
    module, class, function or attribute counts whole; a line holding code and a trailing comment counts as
    both)."""
    doc = code = 0
    for path in sorted(package.rglob("*.py")):
        text = path.read_text()
        lines = text.splitlines()
        docstrings: set[int] = set()
        for node in ast.walk(ast.parse(text)):
            body = getattr(node, "body", None)  # a lambda's body is one expression, not statements
            for stmt in body if isinstance(body, list) else []:
                if (
                    isinstance(stmt, ast.Expr)
                    and isinstance(stmt.value, ast.Constant)
                    and isinstance(stmt.value.value, str)
                ):
                    docstrings.update(range(stmt.lineno, (stmt.end_lineno or stmt.lineno) + 1))
        comments = {
            tok.start[0] for tok in tokenize.generate_tokens(io.StringIO(text).readline) if tok.type == tokenize.COMMENT
        }
        doc += len(docstrings) + len(comments - docstrings)
        code += sum(
            1 for i, s in enumerate(lines, 1) if s.strip() and i not in docstrings and not s.strip().startswith("#")
        )
    return doc / max(code, 1)


def test_the_packages_that_need_the_why_keep_their_doc_density() -> None:
    thin = {p: round(d, 3) for p in WHY_PACKAGES if (d := _doc_density(REPO / "gazelle" / p)) < MIN_DOC_DENSITY}
    assert not thin, f"comment and docstring lines per code line under {MIN_DOC_DENSITY}: {thin}"


def test_the_doc_density_check_counts_docstrings_and_comments(tmp_path: Path) -> None:
    bare = tmp_path / "bare"
    bare.mkdir()
    (bare / "m.py").write_text("def f(x):\n    y = x + 1\n    return y\n")
    told = tmp_path / "told"
    told.mkdir()
    (told / "m.py").write_text(
        '"""A module."""\n\n\ndef f(x):\n    """Why."""\n    y = x + 1  # metres\n    return y\n'
    )
    assert _doc_density(bare) == 0.0
    assert _doc_density(told) == pytest.approx(3 / 3)


# --------------------------------------------------------------------------- one hierarchy of errors
_BUILTIN_EXCEPTIONS = frozenset(
    name for name, value in vars(builtins).items() if isinstance(value, type) and issubclass(value, BaseException)
)

ERRORS_OUTSIDE_THE_ROOT: set[str] = set()
"""Exception classes not yet under :class:`SimError`; each is a to-do, not a rule."""


def _error_problems(package: Path) -> list[str]:
    """Every exception class of ``package`` must derive from ``SimError`` (directly or through another one of
    the package), and no two may share a name (issue 53: SimError, MeshReadError, ControlError were each
    defined twice, and 38 classes had one that derived from the root)."""
    classes: dict[str, list[tuple[str, list[str]]]] = {}
    for path in sorted(package.rglob("*.py")):
        rel = path.relative_to(package.parent).as_posix()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ClassDef):
                bases = [
                    b.id if isinstance(b, ast.Name) else b.attr
                    for b in node.bases
                    if isinstance(b, ast.Name | ast.Attribute)
                ]
                classes.setdefault(node.name, []).append((rel, bases))

    def reaches(name: str, goal: str | frozenset[str], seen: frozenset[str] = frozenset()) -> bool:
        if (name == goal) if isinstance(goal, str) else name in goal:
            return True
        if name in seen:
            return False
        return any(reaches(b, goal, seen | {name}) for _rel, bases in classes.get(name, []) for b in bases)

    problems = []
    for name, defs in sorted(classes.items()):
        errors = [(rel, bases) for rel, bases in defs if any(reaches(b, _BUILTIN_EXCEPTIONS) for b in bases)]
        if len(errors) > 1:
            problems.append(f"{name} is defined {len(errors)} times: {', '.join(rel for rel, _ in errors)}")
        for rel, bases in errors:
            if name != "SimError" and not any(reaches(b, "SimError") for b in bases):
                if f"{rel}:{name}" not in ERRORS_OUTSIDE_THE_ROOT:
                    problems.append(f"{rel}: {name} does not derive from SimError")
    return problems


def test_every_error_derives_from_the_one_root_and_none_is_defined_twice() -> None:
    problems = _error_problems(REPO / "gazelle")
    assert not problems, "\n".join(problems)


def test_the_error_check_finds_a_stray_error_and_a_twin(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "_errors.py").write_text("class SimError(Exception):\n    pass\n")
    (pkg / "a.py").write_text("class Fine(SimError, ValueError):\n    pass\nclass Stray(RuntimeError):\n    pass\n")
    (pkg / "b.py").write_text("class Fine(SimError):\n    pass\nclass NotAnError:\n    pass\n")
    assert _error_problems(pkg) == [
        "Fine is defined 2 times: pkg/a.py, pkg/b.py",
        "pkg/a.py: Stray does not derive from SimError",
    ]


# --------------------------------------------------------------------------- one class, one file
MIXIN_CHAINS_TO_UNDO: dict[str, tuple[str, ...]] = {
    # empty: every class the check found split over files by a chain of bases is a composition now (issue 53),
    # as move_group is (a context and parts); a new entry is a new class split across files
}
SUBCLASSES_BY_DESIGN = {
    # ur_controllers' ScaledJointTrajectoryController is a subclass of ros2_controllers' JTC upstream too
    # (scaled_joint_trajectory_controller.hpp): one kind of controller specialising another, not one class split
    "gazelle/systems/ros2_control/_scaled_trajectory.py:ScaledJointTrajectoryController": (
        "JointTrajectoryController",
    ),
    # a protocol that extends another: what the world's state part uses is what every part reads (the world's
    # model, data and entities, _world_part.py's WorldView) and more; nothing of a class is spread by it
    "gazelle/physics/_state.py:StatefulWorld": ("WorldView",),
}
"""Subclasses the check finds that are a kind of their base, as upstream's are: not on the to-do list."""
"""Classes still spread over files by a chain of bases, each with the bases that spread it: a to-do list that
only shrinks (a new entry is a new class split across files)."""


def _mixin_chains(package: Path) -> dict[str, tuple[str, ...]]:
    """Each class (``file:Class``) that has a base defined in another file of its own folder, imported from there,
    whose only subclass it is: one class spread over files by inheritance (``_Loader(_WorldParts(_Parts(_Reader)))``
    was four files), not a base class that several kinds share (``System``), -> those bases."""
    classes: dict[tuple[str, str], list[tuple[str, str]]] = {}  # (file, class) -> its bases as (file, class)
    for path in sorted(package.rglob("*.py")):
        rel = path.relative_to(package.parent).as_posix()
        tree = ast.parse(path.read_text())
        imported = {
            alias.asname or alias.name: (path.parent / f"{node.module}.py").relative_to(package.parent).as_posix()
            for node in tree.body
            if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module
            for alias in node.names
        }
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                names = [b.id for b in node.bases if isinstance(b, ast.Name)]
                classes[(rel, node.name)] = [(imported[n], n) for n in names if n in imported]
    subclasses: dict[tuple[str, str], list[tuple[str, str]]] = {}
    for cls, bases in classes.items():
        for base in bases:
            subclasses.setdefault(base, []).append(cls)
    out: dict[str, tuple[str, ...]] = {}
    for (rel, name), bases in classes.items():
        spread = tuple(b for b in bases if b in classes and subclasses[b] == [(rel, name)])
        if spread:
            out[f"{rel}:{name}"] = tuple(b[1] for b in spread)
    return out


def test_no_class_is_spread_over_files_by_a_mixin_chain() -> None:
    """Issue 53: a class split into bases in other files (to keep each file under the line limit) makes a reader
    search them all for where ``self._x`` comes from. One class lives in one file; what it needs from elsewhere
    it owns (composition). The entries still to be undone are listed; the list only shrinks."""
    found = {k: v for k, v in _mixin_chains(REPO / "gazelle").items() if SUBCLASSES_BY_DESIGN.get(k) != v}
    new = {cls: bases for cls, bases in found.items() if MIXIN_CHAINS_TO_UNDO.get(cls) != bases}
    assert not new, f"classes spread over files by a chain of bases: {new}"
    undone = sorted(set(MIXIN_CHAINS_TO_UNDO) - set(found))
    assert not undone, f"no longer spread: remove from MIXIN_CHAINS_TO_UNDO: {undone}"


def test_the_mixin_chain_check_finds_a_planted_chain(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "a.py").write_text("class Reader:\n    pass\n\n\nclass Shared:\n    pass\n")
    (pkg / "b.py").write_text(
        "from .a import Reader, Shared\n\n\nclass Parts(Reader):\n    pass\n\n\nclass One(Shared):\n    pass\n"
    )
    (pkg / "c.py").write_text(
        "from .a import Shared\nfrom .b import Parts\n\n\nclass Loader(Parts):\n    pass\n\n\nclass Two(Shared):\n    pass\n"
    )
    (pkg / "d.py").write_text("class Base:\n    pass\n\n\nclass Same(Base):\n    pass\n")
    assert _mixin_chains(pkg) == {"pkg/b.py:Parts": ("Reader",), "pkg/c.py:Loader": ("Parts",)}


# --------------------------------------------------------------------------- no circle inside a package
IMPORT_CIRCLES_TO_UNDO: set[tuple[str, ...]] = set()
# (move_group's context and the scene monitor, pipeline and execution manager it holds were the last: each part
# now takes the protocol of what it uses, gazelle/ros/_move_group_protocols.py, and imports no context)
"""Circles of imports still inside a package, each its files sorted: a to-do list that only shrinks."""


def _module_file(root: Path, dotted: str) -> Path | None:
    """The file of module ``dotted`` under ``root`` (``a/b.py`` or ``a/b/__init__.py``), if it is there."""
    if not dotted:
        return None
    base = root.joinpath(*dotted.split("."))
    return next((f for f in (base.with_suffix(".py"), base / "__init__.py") if f.is_file()), None)


def _imported_files(path: Path, root: Path) -> set[Path]:
    """The files under ``root`` that ``path`` imports, inside functions and under ``TYPE_CHECKING`` too (a circle a
    reader must walk all the same): ``from M import n`` names M's module ``n`` where there is one, else M itself.
    The ``__init__.py`` of the packages above a module, which Python runs first, is no arrow of its own."""
    package = list(path.relative_to(root).parts[:-1])
    found: set[Path] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found |= {f for a in node.names if (f := _module_file(root, a.name))}
        elif isinstance(node, ast.ImportFrom):
            base = package[: len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            for alias in node.names:
                target = _module_file(root, f"{module}.{alias.name}") or _module_file(root, module)
                if target is not None:
                    found.add(target)
    found.discard(path)
    return found


def _import_circles(root: Path, packages: tuple[str, ...], *, per_folder: bool = False) -> set[tuple[str, ...]]:
    """Every set of files of ``packages`` (folders of ``root``, with their sub-folders) that import each other in a
    loop, relative and absolute imports alike: Tarjan's strongly connected components of the graph of imports
    between their files (:func:`_imported_files`). A package's ``__init__.py`` is a file like any other: one that
    only hands names on carries the arrows through it. With ``per_folder`` each first-level folder of a package
    stands apart (gazelle's layers, whose one-way arrows ALLOWED checks): only a loop inside one of them counts;
    without it a loop across the packages counts too (launch and launch_ros)."""

    def unit(file: Path) -> tuple[str, ...]:
        parts = file.relative_to(root).parts
        if not per_folder:
            return ()
        return parts[:2] if len(parts) > 2 else parts[:1]

    edges: dict[str, set[str]] = {}
    for package in packages:
        for path in sorted((root / package).rglob("*.py")):
            targets = _imported_files(path, root)
            edges[path.relative_to(root).as_posix()] = {
                t.relative_to(root).as_posix()
                for t in targets
                if t.relative_to(root).parts[0] in packages and unit(t) == unit(path)
            }
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    circles: set[tuple[str, ...]] = set()

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                circles.add(tuple(sorted(component)))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return circles


def test_no_import_circle_inside_a_package() -> None:
    """Issue 53: ``entity_frame_prefix`` imported inside functions tied 15 files of systems/ into one circle."""
    found = _import_circles(REPO, ("gazelle",), per_folder=True)
    assert found - IMPORT_CIRCLES_TO_UNDO == set(), f"import circles: {sorted(found - IMPORT_CIRCLES_TO_UNDO)}"
    assert IMPORT_CIRCLES_TO_UNDO - found == set(), f"gone: remove {sorted(IMPORT_CIRCLES_TO_UNDO - found)}"


def test_the_circle_check_finds_a_planted_circle(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "a.py").write_text("def f():\n    from .b import g\n")
    (pkg / "b.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .a import f\n")
    (pkg / "c.py").write_text("from . import a\n")
    assert _import_circles(tmp_path, ("pkg",), per_folder=True) == {("pkg/a.py", "pkg/b.py")}


def test_the_circle_check_sees_a_package_init_that_defines(tmp_path: Path) -> None:
    """A package's ``__init__.py`` that defines what it exports is a module like any other: a late import of it
    from one of its own modules closes a circle (gazelle/description's ``_xacro.py`` imported ``detect_format``
    from the package inside a function)."""
    pkg = tmp_path / "pkg" / "layer"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text("from ._x import expand\n\n\ndef detect():\n    pass\n")
    (pkg / "_x.py").write_text("def expand():\n    from . import detect\n")
    (pkg / "_y.py").write_text("from . import _x\n")
    assert _import_circles(tmp_path, ("pkg",), per_folder=True) == {("pkg/layer/__init__.py", "pkg/layer/_x.py")}


LAUNCH_PACKAGES: dict[str, tuple[str, ...]] = {
    "launch": (),
    "launch_ros": ("launch",),
    "launch_xml": ("launch",),
    "launch_yaml": ("launch",),
}
"""gazelle's implementation of ROS 2's launch packages -> the others each may import: launch knows none of them
(launch_ros's tags reach launch's XML and YAML reader through the ``launch.frontend.launch_extension`` entry
point, as in Jazzy)."""


def _launch_package_violations(root: Path) -> list[str]:
    found: list[str] = []
    for package, allowed in LAUNCH_PACKAGES.items():
        for path in sorted((root / package).rglob("*.py")):
            for target in sorted(_imported_files(path, root)):
                other = target.relative_to(root).parts[0]
                if other in LAUNCH_PACKAGES and other != package and other not in allowed:
                    found.append(f"{path.relative_to(root)}: imports {target.relative_to(root)} ({package} may not)")
    return found


def test_no_import_circle_inside_the_launch_packages() -> None:
    """Issue 53: the XML and YAML front end tied ten files of launch and launch_ros into one circle (the reader of
    files imported launch_ros and the actions, the actions the description sources, the sources the reader),
    and launch/substitution.py and the TextSubstitution it makes another. A loop across the four packages
    counts too; and launch imports none of the other three."""
    assert _import_circles(REPO, tuple(LAUNCH_PACKAGES)) == set()
    assert _launch_package_violations(REPO) == []


def test_the_launch_circle_check_finds_a_planted_circle(tmp_path: Path) -> None:
    """The shape of the circle the front end had: a late import of launch_ros in launch's reader, launch_ros's
    tags importing launch's actions, whose package ``__init__.py`` defines them and imports the reader."""
    for folder in ("launch/actions", "launch/frontend", "launch_ros"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "launch" / "__init__.py").write_text("from . import actions\n")
    (tmp_path / "launch" / "actions" / "__init__.py").write_text(
        "from ..frontend.parser import read\n\n\nclass Include:\n    pass\n"
    )
    (tmp_path / "launch" / "frontend" / "__init__.py").write_text("from .parser import read\n")
    (tmp_path / "launch" / "frontend" / "parser.py").write_text("def read():\n    import launch_ros.frontend\n")
    (tmp_path / "launch" / "frontend" / "entity.py").write_text("from . import parser\n")
    (tmp_path / "launch_ros" / "__init__.py").write_text("")
    (tmp_path / "launch_ros" / "frontend.py").write_text("from launch.actions import Include\n")
    packages = ("launch", "launch_ros")
    assert _import_circles(tmp_path, packages) == {
        ("launch/actions/__init__.py", "launch/frontend/parser.py", "launch_ros/frontend.py")
    }
    assert _launch_package_violations(tmp_path) == [
        "launch/frontend/parser.py: imports launch_ros/frontend.py (launch may not)"
    ]
