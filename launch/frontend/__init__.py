"""launch.frontend: XML and YAML launch files (Jazzy's launch.frontend with launch_xml's and launch_yaml's
readers). A tag becomes the action exposed for it (:func:`expose_action`), ``$(name ...)`` the substitution
exposed for it (:func:`expose_substitution`); :class:`Parser` reads a file into a LaunchDescription, each
error one line naming the file and line."""

from .entity import Entity
from .expose import expose_action, expose_substitution
from .parse_substitution import parse_if_substitutions, parse_substitution
from .parser import InvalidFrontendLaunchFileError, Parser, load_frontend_launch_description

__all__ = [
    "Entity",
    "InvalidFrontendLaunchFileError",
    "Parser",
    "expose_action",
    "expose_substitution",
    "load_frontend_launch_description",
    "parse_if_substitutions",
    "parse_substitution",
]
