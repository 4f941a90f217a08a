"""The one way a system makes itself known: a call at the bottom of its own module, ``add_plugin(DiffDrive)``,
as every gz-sim system's file ends with ``GZ_ADD_PLUGIN(DiffDrive, System, ...)`` (gz-sim's
``src/systems/diff_drive/DiffDrive.cc``; the macro is gz-plugin's ``Register.hh``).

What the class declares says what it runs for: a model's or world's ``<plugin>`` by its ``plugin_files`` and
``gz_plugin`` (:class:`~._base.System`), a ``<sensor>`` by its ``sdf_types``, ``classic_plugins`` and
``gz_system`` (``sensors/_common.py``); a class may declare both (the IMU, which ROS 1 ran as a model plugin).
``_registry.py`` derives every table from these declarations.

No list of modules is kept by hand: the first time the registry is asked, every module of this package (and of
its sub-packages) is imported once, as gz-sim's ``SystemLoader`` finds a plugin by searching its plugin path, so
the module that defines a system is the only file a new system needs."""

from __future__ import annotations

import functools
import importlib
import pkgutil
from typing import TypeVar

from ._base import System

S = TypeVar("S", bound=type[System])

_ADDED: list[type[System]] = []


def add_plugin(cls: S) -> S:
    """Register ``cls``, a :class:`System` that declares what runs it; called once at the bottom of its module
    (gz-sim's ``GZ_ADD_PLUGIN``). Returns the class.

    Raises:
        TypeError: ``cls`` is not a :class:`System`.
    """
    if not (isinstance(cls, type) and issubclass(cls, System)):
        raise TypeError(f"add_plugin takes a System class, got {cls!r}")
    if cls not in _ADDED:
        _ADDED.append(cls)
    return cls


@functools.cache
def _import_all() -> None:
    """Import each module of ``gazelle.systems`` and its sub-packages, once: each registers its own systems."""
    package = importlib.import_module(__package__ or "gazelle.systems")
    for info in pkgutil.walk_packages(package.__path__, f"{package.__name__}."):
        importlib.import_module(info.name)


def registered() -> tuple[type[System], ...]:
    """Every registered system class, ordered by module and class name (so the tables derived from them do not
    depend on which module happened to load first)."""
    _import_all()
    return tuple(sorted(_ADDED, key=lambda cls: (cls.__module__, cls.__qualname__)))
