"""launch.utilities' class tests (launch Jazzy, utilities/class_tools_impl.py)."""

from __future__ import annotations

import inspect
from typing import Any


def isclassinstance(obj: Any) -> bool:
    """Whether ``obj`` is an instance of some class (in Python 3, anything is)."""
    return hasattr(obj, "__class__")


def is_a(obj: Any, entity_type: type) -> bool:
    """Whether ``obj`` is an instance of ``entity_type``.

    Raises:
        RuntimeError: ``entity_type`` is not a class, as launch raises it.
    """
    if not isclassinstance(obj):
        raise RuntimeError(f"obj '{obj}' is not a class instance")
    if not inspect.isclass(entity_type):
        raise RuntimeError(f"entity_type '{entity_type}' is not a class")
    return isinstance(obj, entity_type)


def is_a_subclass(obj: Any, entity_type: type) -> bool:
    """Whether ``obj`` is an instance of ``entity_type``, or is itself that class or a subclass of it."""
    if is_a(obj, entity_type):
        return True
    return inspect.isclass(obj) and issubclass(obj, entity_type)
