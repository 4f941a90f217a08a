"""Parser: turns the entities of an XML or YAML launch file into a LaunchDescription (launch.frontend.Parser,
Jazzy), each tag by the parse function exposed for it. Every error is one :class:`InvalidFrontendLaunchFileError`
naming the file and line of the tag it is about."""

from __future__ import annotations

import os
from typing import Any

from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_description import LaunchDescription
from .entity import Entity, LocatedError
from .expose import instantiate_action, load_launch_extensions
from .parse_substitution import parse_if_substitutions, parse_substitution, replace_escaped_characters

XML_EXTENSIONS = (".xml", ".launch")
YAML_EXTENSIONS = (".yaml", ".yml")


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """An XML or YAML launch file gazelle cannot read: ``file:line: what``."""


class Parser:
    """Parses one file's entities; :meth:`load` picks XML or YAML by the file's extension."""

    @classmethod
    def load_launch_extensions(cls) -> None:
        """Imports the packages that expose tags and substitutions through the ``launch.frontend.launch_extension``
        entry points (launch_ros's), as launch's Parser does (:func:`launch.frontend.expose.load_launch_extensions`);
        launch's own are exposed by ``import launch``."""
        load_launch_extensions()

    def parse_action(self, entity: Entity) -> Any:
        """The action of one tag, made with the file and line it came from; an error names them."""
        self.load_launch_extensions()
        try:
            action = instantiate_action(entity, self)
        except InvalidFrontendLaunchFileError:
            raise
        except LocatedError as err:
            raise InvalidFrontendLaunchFileError(f"{err.where}: {err}") from None
        except Exception as err:
            raise InvalidFrontendLaunchFileError(f"{entity.location}: {_one_line(err)}") from None
        action._created_at = entity.location
        return action

    def parse_substitution(self, value: str) -> list[Any]:
        return parse_substitution(value)

    def parse_if_substitutions(self, value: Any) -> Any:
        return parse_if_substitutions(value)

    def escape_characters(self, value: str) -> str:
        return replace_escaped_characters(value)

    def parse_description(self, entity: Entity) -> Any:
        """The LaunchDescription of the root ``<launch>``."""
        if entity.type_name != "launch":
            raise InvalidFrontendLaunchFileError(
                f"{entity.location}: expected <launch> as the root, got <{entity.type_name}>"
            )
        try:
            deprecated = entity.get_attr("deprecated", optional=True)
            children = entity.children
            entity.assert_entity_completely_parsed()
        except Exception as err:
            raise InvalidFrontendLaunchFileError(f"{entity.location}: {_one_line(err)}") from None
        return LaunchDescription([self.parse_action(child) for child in children], deprecated_reason=deprecated)

    @classmethod
    def load(cls, path: str) -> tuple[Entity, Parser]:
        """The root entity of ``path`` and a parser for it: XML for ``.xml``/``.launch``, YAML for
        ``.yaml``/``.yml``, else whichever reads it."""
        from .xml_entity import XmlEntity, read_xml
        from .yaml_entity import YamlEntity, read_yaml

        def as_xml() -> Entity:
            return XmlEntity(read_xml(path), path)

        def as_yaml() -> Entity:
            name, value, line = read_yaml(path)
            return YamlEntity(value, str(name), path, line)

        if path.endswith(XML_EXTENSIONS):
            readers = [as_xml]
        elif path.endswith(YAML_EXTENSIONS):
            readers = [as_yaml]
        else:
            readers = [as_xml, as_yaml]
        errors = []
        for read in readers:
            try:
                return read(), cls()
            except (ValueError, OSError, UnicodeDecodeError) as err:
                errors.append(str(err))
        raise InvalidFrontendLaunchFileError("; ".join(errors))


def _one_line(err: BaseException) -> str:
    text = str(err) or type(err).__name__
    return " ".join(text.split()) if len(text) < 400 else " ".join(text[:400].split()) + " ..."


def load_frontend_launch_description(path: str) -> Any:
    """The LaunchDescription of an XML or YAML launch file (launch's FrontendLaunchDescriptionSource)."""
    if not os.path.isfile(path):
        raise InvalidLaunchFileError(f"launch file '{path}' does not exist")
    root, parser = Parser.load(path)
    return parser.parse_description(root)


__all__ = ["InvalidFrontendLaunchFileError", "Parser", "load_frontend_launch_description"]
