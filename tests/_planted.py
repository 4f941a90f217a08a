"""Packages planted on a Python path that leave a marker file when anything of them is imported: a test
puts the folder first on ``sys.path`` (or ``PYTHONPATH`` of a real ``ros2``) and checks afterwards that no
type name it fed in made gazelle import them.

``venv`` and ``unittest`` shadow the standard library's (whose ``__main__`` ran on a crafted bag:
``venv/__main__/Clock`` made the bag folder a virtualenv); no ``ros2`` verb imports either of them
otherwise. ``gz_planted`` is a name by rosidl's rules that no ament index lists."""

from __future__ import annotations

from pathlib import Path

PLANTED = ("venv", "unittest", "gz_planted")
"""The planted packages; each has ``__init__``, ``__main__`` and ``msg``/``srv``/``action`` submodules."""
PAYLOADS = ("venv/__main__/Clock", "unittest/__main__/Clock", "gz_planted/__main__/Clock", "gz_planted/msg/Clock")
"""Type names that imported one of them before the checked resolver."""


def plant(folder: Path) -> tuple[Path, Path]:
    """Write the planted packages under ``folder``: (the folder to put on the path, the folder where their
    markers appear)."""
    markers = folder / "markers"
    markers.mkdir(parents=True, exist_ok=True)
    for name in PLANTED:
        pkg = folder / "path" / name
        for module in ("__init__", "__main__", "msg/__init__", "srv/__init__", "action/__init__"):
            path = pkg / f"{module}.py"
            path.parent.mkdir(parents=True, exist_ok=True)
            marker = markers / f"{name}.{module.replace('/', '.')}"
            path.write_text(f"open({str(marker)!r}, 'w').close()\nclass Clock:\n    pass\n")
    return folder / "path", markers


def imported(markers: Path) -> list[str]:
    """The planted modules that were imported (their markers), sorted."""
    return sorted(p.name for p in markers.iterdir())
