"""The tags and substitution names XML and YAML launch files may use (launch.frontend.expose, Jazzy).

``expose_action('tag')`` registers a parse function ``(entity, parser) -> (action_type, kwargs)`` (or a class
with a ``parse`` classmethod); after it runs, every attribute and nested tag of the entity must have been
read, else the file has one the action does not know. ``expose_substitution('name')`` registers
``(args) -> (substitution_type, kwargs)`` where ``args`` is a list of argument substitution lists.

This registry is the bottom of the front end: the modules that expose tags register themselves when they are
imported (launch's own, launch/launch_exposures.py, by ``import launch``), and the other packages'
through the ``launch.frontend.launch_extension`` entry points, loaded once before the first tag or
substitution is made (launch's Parser.load_launch_extensions; launch_ros declares one). So the reader of
files knows no action, and launch knows no launch_ros.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

from ..logging import log

EXTENSION_GROUP = "launch.frontend.launch_extension"
"""The entry-point group through which other packages expose their tags and substitutions (Jazzy's launch reads
it; launch_ros's setup.py declares ``launch_ros = launch_ros`` in it, and so does gazelle's pyproject.toml)."""

action_parse_methods: dict[str, Callable[..., Any]] = {}
substitution_parse_methods: dict[str, Callable[..., Any]] = {}


def _parse_method(exposed: Any, name: str, kind: str) -> Callable[..., Any]:
    if inspect.isclass(exposed):
        method = getattr(exposed, "parse", None)
        if method is None or not inspect.ismethod(method):
            raise RuntimeError(f"Did not find a class method called 'parse' in the {kind} exposed as '{name}'")
        return method
    if inspect.isfunction(exposed):
        return exposed
    raise RuntimeError(f"Exposed {kind} parser for {name} is not a callable or a class containing a parse method")


def expose_action(name: str) -> Callable[[Any], Any]:
    """Decorator: ``<name>`` (XML) / ``- name:`` (YAML) makes the decorated action."""

    def decorate(exposed: Any) -> Any:
        method = _parse_method(exposed, name, "action")
        known = action_parse_methods.get(name)
        if known is not None and getattr(known, "__wrapped__", None) is not method:
            raise RuntimeError(f"Two action parsing methods exposed with the same name: [{name}].")

        def wrapper(entity: Any, parser: Any) -> Any:
            result = method(entity, parser)
            entity.assert_entity_completely_parsed()
            return result

        wrapper.__wrapped__ = method  # type: ignore[attr-defined] - a function attribute, read above
        action_parse_methods[name] = wrapper
        return exposed

    return decorate


def expose_substitution(name: str) -> Callable[[Any], Any]:
    """Decorator: ``$(name ...)`` makes the decorated substitution."""

    def decorate(exposed: Any) -> Any:
        method = _parse_method(exposed, name, "substitution")
        known = substitution_parse_methods.get(name)
        if known is not None and known is not method:
            raise RuntimeError(f"Two substitution parsing methods exposed with the same name: [{name}].")
        substitution_parse_methods[name] = method
        return exposed

    return decorate


_extensions_loaded = False


def load_launch_extensions() -> None:
    """Imports, once, every package declared in :data:`EXTENSION_GROUP` (their modules expose their tags as
    they are imported); one that fails to load is one warning line, as launch's warns, and the rest load."""
    global _extensions_loaded
    if _extensions_loaded:
        return
    _extensions_loaded = True
    import importlib.metadata  # ~20 ms: only for the first file read, not at every `import launch`

    for entry_point in importlib.metadata.entry_points(group=EXTENSION_GROUP):
        try:
            entry_point.load()
        except Exception as err:
            log("WARNING", "launch", f"Failed to load the launch extension: {entry_point.name}: {err}")


def instantiate_action(entity: Any, parser: Any) -> Any:
    """The action the entity's tag is exposed as."""
    load_launch_extensions()
    method = action_parse_methods.get(entity.type_name)
    if method is None:
        raise ValueError(f"Unrecognized tag <{entity.type_name}>")
    action_type, kwargs = method(entity, parser)
    return action_type(**kwargs)


def instantiate_substitution(type_name: str, args: list[Any] | None = None) -> Any:
    """The substitution ``$(type_name ...)`` with its arguments."""
    load_launch_extensions()
    method = substitution_parse_methods.get(type_name)
    if method is None:
        raise ValueError(f"Unknown substitution: $({type_name} ...)")
    subst_type, kwargs = method(list(args or []))
    return subst_type(**kwargs)


__all__ = [
    "expose_action",
    "expose_substitution",
    "instantiate_action",
    "instantiate_substitution",
    "load_launch_extensions",
]
