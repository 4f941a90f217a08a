"""RewrittenYaml: a parameter file with some values, keys or its root changed, written to a new file whose
path is the substitution's value (nav2_common Jazzy, rewritten_yaml.py: what it does, in our own code).

``param_rewrites`` maps a name to a value (substitutions, performed to text):

* a plain key (``use_sim_time``): every mapping key of that name, at any depth (not inside lists), gets the value;
* a dotted path to a leaf of the file (``amcl.ros__parameters.base_frame_id``, list items by index:
  ``a.b.0``): that leaf gets it;
* a dotted path that is not a leaf of the file and has a ``ros__parameters`` part: it is added, with the
  mappings on its way (``bt_navigator.ros__parameters.new_param``).

Values are converted: ``true``/``false`` (any case) to booleans, and with ``convert_types`` numbers to int or
float (a ``.`` makes a float). ``key_rewrites`` renames mapping keys at any depth; ``root_key``, when it
performs to non-empty text, puts the whole file under that key (a namespace). The new file is written with
sorted keys, as nav2_common's yaml.dump writes it.
"""

from __future__ import annotations

from typing import Any

import yaml

from launch import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ._files import read_yaml, write_temporary

_WHO = "RewrittenYaml"


class RewrittenYaml(Substitution):
    """See the module docstring."""

    def __init__(
        self,
        source_file: Any,
        param_rewrites: dict[str, Any],
        root_key: Any = None,
        key_rewrites: dict[str, Any] | None = None,
        convert_types: bool = False,
    ) -> None:
        super().__init__()
        self._source = normalize_to_list_of_substitutions(source_file)
        self._params = {k: normalize_to_list_of_substitutions(v) for k, v in param_rewrites.items()}
        self._keys = {k: normalize_to_list_of_substitutions(v) for k, v in (key_rewrites or {}).items()}
        self._root = None if root_key is None else normalize_to_list_of_substitutions(root_key)
        self._convert_types = convert_types

    @property
    def name(self) -> list[Substitution]:
        """The source file's substitutions."""
        return self._source

    def describe(self) -> str:
        return ""

    def perform(self, context: Any) -> str:
        path = perform_substitutions(context, self._source)
        data = read_yaml(path, _WHO)
        params = {k: self.convert(perform_substitutions(context, v)) for k, v in self._params.items()}
        keys = {k: perform_substitutions(context, v) for k, v in self._keys.items()}
        if isinstance(data, dict):
            _set_named_keys(data, params)
        leaves = _leaf_paths(data)
        for dotted, where in leaves.items():
            if dotted in params:
                data = _set_at(data, where, params[dotted])
        leaves = _leaf_paths(data)
        for dotted, value in params.items():
            parts = str(dotted).split(".")
            if dotted not in leaves and "ros__parameters" in parts:
                data = _set_at(data, parts, value, create=True)
        if keys and isinstance(data, dict):
            _rename_keys(data, keys)
        root = perform_substitutions(context, self._root) if self._root is not None else ""
        if root:
            data = {root: data}
        return write_temporary(yaml.safe_dump(data, default_flow_style=False))

    def convert(self, text: str) -> Any:
        """A rewrite's text as the value it stands for: with ``convert_types`` an int, or a float when it has a
        ``.``; ``true``/``false`` in any case a bool; else the text itself."""
        if self._convert_types:
            try:
                return float(text) if "." in text else int(text)
            except ValueError:
                pass
        if text.lower() in ("true", "false"):
            return text.lower() == "true"
        return text


def _set_named_keys(mapping: dict[Any, Any], params: dict[str, Any]) -> None:
    """Every key of ``mapping`` and the mappings under it (depth first, lists not entered) whose name is one of
    ``params``' gets that value."""
    for key, value in mapping.items():
        if isinstance(value, dict):
            _set_named_keys(value, params)
        if key in params:
            mapping[key] = params[key]


def _leaf_paths(data: Any) -> dict[str, list[Any]]:
    """Each leaf of ``data`` (not a mapping or a list) by its dotted path, with the keys and indices that reach it."""
    out: dict[str, list[Any]] = {}

    def walk(node: Any, where: list[Any]) -> None:
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, [*where, k])
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, [*where, i])
        elif where:
            out[".".join(str(p) for p in where)] = where

    walk(data, [])
    return out


def _set_at(data: Any, where: list[Any], value: Any, create: bool = False) -> Any:
    """``data`` with the node at ``where`` (keys, list indices) set to ``value``; with ``create``, the mappings on
    the way are made where they are missing (or are not mappings). Returns the (possibly new) root."""
    if not where:
        return value
    head, rest = where[0], where[1:]
    if isinstance(data, list) and _index(head, len(data)) is not None:
        i = _index(head, len(data))
        assert i is not None
        data[i] = _set_at(data[i], rest, value, create)
        return data
    if not isinstance(data, dict):
        if not create:
            return data
        data = {}
    data[head] = _set_at(data.get(head, {}) if create else data.get(head), rest, value, create)
    return data


def _index(part: Any, length: int) -> int | None:
    """``part`` as an index into a list of ``length`` items, or None."""
    if isinstance(part, int):
        return part if 0 <= part < length else None
    text = str(part)
    return int(text) if text.isdigit() and int(text) < length else None


def _rename_keys(mapping: dict[Any, Any], keys: dict[str, str]) -> None:
    """Keys of ``mapping`` and the mappings under it named in ``keys`` take their new names (lists not entered)."""
    for key in list(mapping):
        value = mapping[key]
        if key in keys:
            mapping[keys[key]] = mapping.pop(key)
        if isinstance(value, dict):
            _rename_keys(value, keys)
