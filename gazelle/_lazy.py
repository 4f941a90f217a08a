"""Packages whose public names are imported when first used (PEP 562), so that a client pays only for
what it uses: ``gazelle arm`` never loads MuJoCo, ``gazelle sim --no-viewer`` never loads viser."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping
from typing import Any


def lazy_attributes(package: str, table: Mapping[str, tuple[str, str]]) -> Callable[[str], Any]:
    """The module ``__getattr__`` of ``package``: ``table`` maps a public name to (relative module, attribute).
    A name is imported on its first use and then kept in the package like any other."""

    def __getattr__(name: str) -> Any:
        try:
            module, attr = table[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(module, package), attr)
        setattr(sys.modules[package], name, value)
        return value

    return __getattr__
