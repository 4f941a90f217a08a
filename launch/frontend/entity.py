"""Entity: one tag of an XML launch file, or one entry of a YAML one (launch.frontend.Entity, Jazzy).

An action's parse function reads the entity's attributes with :meth:`get_attr` (nested tags with
``data_type=List[Entity]``) and its nested actions with :attr:`children`; afterwards
:meth:`assert_entity_completely_parsed` refuses any attribute or nested tag that was not read. gazelle's
entities also know their file and line (:attr:`location`), so every error names them."""

from __future__ import annotations

from typing import Any


class Entity:
    """The front-end independent part; :class:`~launch.frontend.xml_entity.XmlEntity` and
    :class:`~launch.frontend.yaml_entity.YamlEntity` read their markup."""

    def __init__(self, type_name: str, file: str, line: int, parent: Entity | None = None) -> None:
        self._type_name = type_name
        self._file = file
        self._line = line
        self._parent = parent

    @property
    def type_name(self) -> str:
        return self._type_name

    @property
    def parent(self) -> Entity | None:
        return self._parent

    @property
    def location(self) -> str:
        """``file:line`` of the entity."""
        return f"{self._file}:{self._line}"

    @property
    def children(self) -> list[Entity]:
        raise NotImplementedError

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False, can_be_str: bool = True) -> Any:
        """The attribute ``name`` as ``data_type``; None when missing and ``optional``, else an error."""
        raise NotImplementedError

    def assert_entity_completely_parsed(self) -> None:
        raise NotImplementedError

    def missing(self, name: str, nested: bool) -> AttributeError:
        kind = "nested tag" if nested else "attribute"
        return AttributeError(f"<{self.type_name}> needs the {kind} '{name}'")


class LocatedError(ValueError):
    """An error at a line other than the entity's own (a nested tag's)."""

    def __init__(self, where: str, message: str) -> None:
        super().__init__(message)
        self.where = where


__all__ = ["Entity", "LocatedError"]
