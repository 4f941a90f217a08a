"""Packages whose public names are imported when first used (PEP 562), so that a client pays only for
what it uses: ``gazelle arm`` never loads MuJoCo, ``gazelle sim --no-viewer`` never loads viser.

A package lists its public names once, as the imports of its ``if TYPE_CHECKING:`` block (what type
checkers and editors read), and ends with ``__getattr__ = lazy_attributes(__name__, __file__)``: the
table of which module holds which name is read from that block, so the two cannot drift apart.
"""

from __future__ import annotations

import ast
import importlib
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any


def type_checking_imports(init_file: str) -> dict[str, tuple[str, str]]:
    """The names imported in ``init_file``'s top-level ``if TYPE_CHECKING:`` block: public name ->
    (module as written, relative to the package, attribute). ``from ._x import a as b`` gives
    ``b -> ("._x", "a")``."""
    tree = ast.parse(Path(init_file).read_text(encoding="utf-8"), init_file)
    table: dict[str, tuple[str, str]] = {}
    for node in tree.body:
        if not (isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"):
            continue
        for stmt in node.body:
            if isinstance(stmt, ast.ImportFrom):
                module = "." * stmt.level + (stmt.module or "")
                for alias in stmt.names:
                    table[alias.asname or alias.name] = (module, alias.name)
    return table


def lazy_attributes(package: str, init_file: str) -> Callable[[str], Any]:
    """The module ``__getattr__`` of ``package``, whose ``__init__.py`` is ``init_file``: a name of its
    ``if TYPE_CHECKING:`` imports is imported on its first use and then kept in the package like any other."""
    table = type_checking_imports(init_file)

    def __getattr__(name: str) -> Any:
        try:
            module, attr = table[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(module, package), attr)
        setattr(sys.modules[package], name, value)
        return value

    return __getattr__
