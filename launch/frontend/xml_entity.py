"""XML launch files (launch_xml, Jazzy): each element an entity, its attributes text coerced to the type a
parse function asks for, its nested elements either actions (:attr:`children`) or named parts of it
(``<param>``, ``<remap>``, ``<arg>`` of an include). ``name-sep`` beside ``name`` splits ``name`` into a list.

Read with expat so that every element keeps its line (ElementTree drops it)."""

from __future__ import annotations

import xml.parsers.expat
from dataclasses import dataclass, field
from typing import Any

from .entity import Entity, LocatedError
from .type_utils import get_typed_value, is_entity_list


@dataclass
class XmlElement:
    """An element as read: tag, attributes in order, nested elements and its line."""

    tag: str
    attrib: dict[str, str]
    line: int
    children: list[XmlElement] = field(default_factory=list)


def read_xml(path: str) -> XmlElement:
    """The root element of an XML file; ``ValueError('file:line: ...')`` if it is not well-formed."""
    parser = xml.parsers.expat.ParserCreate()
    stack: list[XmlElement] = []
    roots: list[XmlElement] = []

    def start(tag: str, attrib: dict[str, str]) -> None:
        element = XmlElement(tag, dict(attrib), parser.CurrentLineNumber)
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    def end(_tag: str) -> None:
        stack.pop()

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    with open(path, "rb") as f:
        data = f.read()
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as err:
        what = xml.parsers.expat.ErrorString(err.code)
        raise ValueError(f"{path}:{err.lineno}: not well-formed XML: {what}") from None
    return roots[0]


class XmlEntity(Entity):
    def __init__(self, element: XmlElement, file: str, parent: Entity | None = None) -> None:
        super().__init__(element.tag, file, element.line, parent)
        self._element = element
        self._read_attributes: set[str] = set()
        self._read_children: set[str] = set()

    def _child(self, element: XmlElement) -> XmlEntity:
        return XmlEntity(element, self._file, self)

    @property
    def children(self) -> list[Entity]:
        self._read_children = {e.tag for e in self._element.children}
        return [self._child(e) for e in self._element.children]

    def assert_entity_completely_parsed(self) -> None:
        nested = [e for e in self._element.children if e.tag not in self._read_children]
        if nested:
            first = nested[0]
            raise LocatedError(
                f"{self._file}:{first.line}",
                f"Unexpected nested tag <{first.tag}> in <{self.type_name}>",
            )
        unread = [a for a in self._element.attrib if a not in self._read_attributes]
        if unread:
            raise ValueError(f"Unexpected attribute(s) in <{self.type_name}>: {', '.join(unread)}")

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False, can_be_str: bool = True) -> Any:
        if is_entity_list(data_type):
            found = [e for e in self._element.children if e.tag == name]
            if not found:
                if optional:
                    return None
                raise self.missing(name, nested=True)
            self._read_children.add(name)
            return [self._child(e) for e in found]
        attrib = self._element.attrib
        if name not in attrib:
            if optional:
                return None
            raise self.missing(name, nested=False)
        self._read_attributes.add(name)
        value: str | list[str] = attrib[name]
        if f"{name}-sep" in attrib:
            self._read_attributes.add(f"{name}-sep")
            value = attrib[name].split(attrib[f"{name}-sep"])
        try:
            return get_typed_value(value, data_type, can_be_str=can_be_str)
        except ValueError as err:
            raise TypeError(f"Attribute '{name}' of <{self.type_name}>: {err}") from None


__all__ = ["XmlElement", "XmlEntity", "read_xml"]
