"""Attribute types of launch frontends (launch/utilities/type_utils.py and launch/frontend/type_utils.py,
Jazzy): XML coerces text to the type asked for by YAML rules, YAML checks the type its loader gave.

A data type is ``str``, ``int``, ``float``, ``bool``, ``None`` (whatever YAML reads), a list of one of the
scalars (``list[int]`` or ``typing.List[int]``), or a list of entities (nested tags)."""

from __future__ import annotations

import typing
from typing import Any

import yaml

SCALARS: tuple[type, ...] = (str, int, float, bool)


def list_item_type(data_type: Any) -> Any:
    """The item type of a list type; ``...`` when ``data_type`` is not a list type."""
    if typing.get_origin(data_type) is list:
        (item,) = typing.get_args(data_type)
        return item
    return ...


def is_entity_list(data_type: Any) -> bool:
    """A list of nested entities (``List[Entity]``)."""
    from .entity import Entity

    item = list_item_type(data_type)
    return isinstance(item, type) and issubclass(item, Entity)


def data_type_from_identifier(identifier: str) -> Any:
    """A ``<param type="...">`` (launch's get_data_type_from_identifier)."""
    mapping: dict[str, Any] = {
        "str": str,
        "bool": bool,
        "float": float,
        "int": int,
        "list_of_str": list[str],
        "list_of_bool": list[bool],
        "list_of_float": list[float],
        "list_of_int": list[int],
        "yaml": None,
    }
    if identifier not in mapping:
        raise ValueError(f"Got invalid type identifier '{identifier}' (one of {', '.join(mapping)})")
    return mapping[identifier]


def is_valid_value(value: Any, can_be_str: bool = False) -> bool:
    """A scalar, or a non-mixed list of scalars (launch's is_instance_of_valid_type)."""
    if isinstance(value, list):
        if not value:
            return True
        kinds = {type(v) for v in value}
        return all(isinstance(v, SCALARS) for v in value) and (len(kinds) == 1 or (can_be_str and str in kinds))
    return isinstance(value, SCALARS)


def _as_yaml(value: str, can_be_str: bool, what: str) -> Any:
    if not value:
        return value
    try:
        out = yaml.safe_load(value)
    except yaml.YAMLError as err:
        if can_be_str:
            return value
        raise ValueError(f"{what}: yaml.safe_load() failed: {err}") from None
    if not is_valid_value(out, can_be_str):
        raise ValueError(f"{what}: output type is not allowed, got {type(out).__name__}")
    return out


def coerce_to_type(value: str, data_type: Any = None, *, can_be_str: bool = False) -> Any:
    """``value`` (text) as ``data_type`` (launch's coerce_to_type)."""
    if data_type is None:
        return _as_yaml(value, can_be_str, f"Failed to convert '{value}' using yaml rules")
    item = list_item_type(data_type)
    if item is not ...:
        out = _as_yaml(value, can_be_str, f"Cannot convert value '{value}' to a list of {item.__name__}")
        valid = (str, item) if can_be_str else (item,)
        if not isinstance(out, list) or not all(isinstance(x, valid) for x in out):
            raise ValueError(f"Cannot convert value '{value}' to a list of {item.__name__}")
        return out
    if data_type is str:
        return value
    if data_type in (int, float):
        try:
            return data_type(value)
        except ValueError:
            if can_be_str:
                return value
            raise ValueError(f"Cannot convert value '{value}' to {data_type.__name__}") from None
    if data_type is not bool:
        raise ValueError(f"data_type is invalid: {data_type!r}")
    text = {"1": "true", "0": "false"}.get(value, value)
    out = _as_yaml(text, can_be_str, f"Failed to convert '{value}' to bool")
    if isinstance(out, bool) or (can_be_str and isinstance(out, str)):
        return out
    raise ValueError(f"Cannot convert value '{value}' to bool")


def coerce_list(values: list[str], data_type: Any = None, *, can_be_str: bool = False) -> list[Any]:
    """Each text of a ``-sep`` list as ``data_type`` (launch's coerce_list)."""
    out = [coerce_to_type(v, data_type, can_be_str=can_be_str) for v in values]
    if not is_valid_value(out, can_be_str):
        raise ValueError(f"cannot convert value to {data_type}. Got value=`{values}`")
    return out


def get_typed_value(value: str | list[str], data_type: Any, *, can_be_str: bool = True) -> Any:
    """A text (or the texts of a ``-sep`` list) as ``data_type`` (launch's get_typed_value)."""
    if isinstance(value, list):
        item = None if data_type is None else list_item_type(data_type)
        if item is ...:
            raise ValueError(f"Cannot convert input '{value}' of type list to '{data_type}'")
        return coerce_list(value, item, can_be_str=can_be_str)
    return coerce_to_type(value, data_type, can_be_str=can_be_str)


def is_instance_of(value: Any, data_type: Any, *, can_be_str: bool = False) -> bool:
    """Whether a YAML value already has ``data_type`` (launch's is_instance_of)."""
    if data_type is None:
        return is_valid_value(value, can_be_str)
    item = list_item_type(data_type)
    if item is not ...:
        valid = (str, item) if can_be_str else (item,)
        return isinstance(value, list) and all(_is(v, valid) for v in value)
    valid = (str, data_type) if can_be_str else (data_type,)
    return _is(value, valid)


def _is(value: Any, kinds: tuple[type, ...]) -> bool:
    # a bool is an int to Python, not to launch
    if isinstance(value, bool) and bool not in kinds:
        return False
    if float in kinds and isinstance(value, int) and not isinstance(value, bool):
        return True
    return isinstance(value, kinds)


__all__ = ["coerce_to_type", "data_type_from_identifier", "get_typed_value", "is_entity_list", "is_instance_of"]
