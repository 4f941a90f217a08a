"""YAML launch files (launch_yaml, Jazzy): ``launch:`` holds a list of one-key mappings, each key the tag
and its value the attributes; nested actions are the ``children`` list (or the value itself when it is a
list), nested parts (``param``, ``remap``, ``arg``) lists of mappings. Values keep the types YAML gave them
and are checked, not coerced.

Read with a loader that keeps each mapping's line, so errors name it."""

from __future__ import annotations

from typing import Any

import yaml

from .entity import Entity
from .type_utils import is_entity_list, is_instance_of


class _Located(dict):
    """A mapping with the line it starts on."""

    line = 0


class _LineLoader(yaml.SafeLoader):
    pass


def _mapping(loader: _LineLoader, node: yaml.MappingNode) -> _Located:
    out = _Located(loader.construct_mapping(node, deep=True))
    out.line = node.start_mark.line + 1
    return out


_LineLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _mapping)


def read_yaml(path: str) -> tuple[str, Any, int]:
    """(root tag, its value, its line) of a YAML launch file; ``ValueError('file:line: ...')`` when it is not
    YAML or not one root."""
    with open(path, encoding="utf-8") as f:
        try:
            tree = yaml.load(f, Loader=_LineLoader)  # a SafeLoader subclass: no Python objects
        except yaml.YAMLError as err:
            mark = getattr(err, "problem_mark", None)
            line = mark.line + 1 if mark is not None else 1
            raise ValueError(f"{path}:{line}: not valid YAML: {getattr(err, 'problem', err)}") from None
    if not isinstance(tree, dict) or len(tree) != 1:
        raise ValueError(f"{path}:1: expected one root entry (launch:)")
    ((name, value),) = tree.items()
    return name, value, getattr(tree, "line", 1)


class YamlEntity(Entity):
    def __init__(self, element: Any, type_name: str, file: str, line: int, parent: Entity | None = None) -> None:
        super().__init__(type_name, file, line, parent)
        self._element = element
        self._read_keys: set[str] = set()
        self._children_read = False

    def _entry(self, item: Any, where: str) -> YamlEntity:
        if not isinstance(item, dict) or len(item) != 1:
            raise ValueError(f"each entry of {where} must be a mapping with one key, the tag")
        ((name, value),) = item.items()
        return YamlEntity(value, str(name), self._file, getattr(item, "line", self._line), self)

    @property
    def children(self) -> list[Entity]:
        self._children_read = True
        element = self._element
        if isinstance(element, dict):
            if "children" not in element:
                raise ValueError(f"`{self.type_name}` needs its nested entities as a `children` list")
            self._read_keys.add("children")
            element = element["children"]
        if not isinstance(element, list):
            raise TypeError(f"`{self.type_name}`: expected a list of entities, got {type(element).__name__}")
        return [self._entry(item, f"`{self.type_name}`") for item in element]

    def assert_entity_completely_parsed(self) -> None:
        if isinstance(self._element, list):
            if not self._children_read:
                raise ValueError(f"Unexpected nested entities in `{self.type_name}`")
            return
        if not isinstance(self._element, dict):
            raise ValueError(f"`{self.type_name}` must be a mapping of its attributes")
        unread = [k for k in self._element if k not in self._read_keys]
        if unread:
            raise ValueError(f"Unexpected key(s) in `{self.type_name}`: {', '.join(map(str, unread))}")

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False, can_be_str: bool = True) -> Any:
        element = self._element if isinstance(self._element, dict) else {}
        if name not in element:
            if optional:
                return None
            raise self.missing(name, nested=is_entity_list(data_type))
        self._read_keys.add(name)
        data = element[name]
        if is_entity_list(data_type):
            if isinstance(data, list) and data and all(isinstance(d, dict) for d in data):
                return [YamlEntity(d, name, self._file, getattr(d, "line", self._line), self) for d in data]
            raise TypeError(f"Attribute '{name}' of `{self.type_name}` must be a list of mappings")
        if not is_instance_of(data, data_type, can_be_str=can_be_str):
            raise TypeError(
                f"Attribute '{name}' of `{self.type_name}` must be {getattr(data_type, '__name__', data_type)},"
                f" got {type(data).__name__}"
            )
        return data


__all__ = ["YamlEntity", "read_yaml"]
