"""launch.launch_description_sources: Python launch files, and XML and YAML ones through launch.frontend."""

from __future__ import annotations

import importlib.util
import os
import sys
from typing import Any

from ..frontend.parser import load_frontend_launch_description
from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_context import LaunchContext
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions


def load_python_launch_file_as_module(path: str) -> Any:
    """Import a ``*.launch.py`` file as a module."""
    name = "launch_file_" + os.path.basename(path).replace(".", "_").replace("-", "_")
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise InvalidLaunchFileError(f"cannot load launch file '{path}'")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def get_launch_description_from_python_launch_file(path: str) -> Any:
    """The LaunchDescription a Python launch file's ``generate_launch_description()`` returns."""
    module = load_python_launch_file_as_module(path)
    if not hasattr(module, "generate_launch_description"):
        raise InvalidLaunchFileError(f"launch file '{path}' has no function generate_launch_description()")
    return module.generate_launch_description()


class LaunchDescriptionSource:
    def __init__(self, launch_description: Any = None, location: str = "<script>", method: str = "") -> None:
        self._ld = launch_description
        self.location = location
        self.method = method

    def get_launch_description(self, context: Any) -> Any:
        return self._ld

    def try_get_launch_description_without_context(self) -> Any:
        return self._ld


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """A ``.launch.py`` file (its path may be substitutions)."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(None, "<python launch file>", "interpreted python launch file")
        self._path = normalize_to_list_of_substitutions(launch_file_path)
        self._loaded: dict[str, Any] = {}

    def path(self, context: Any) -> str:
        return perform_substitutions(context, self._path)

    def get_launch_description(self, context: Any) -> Any:
        path = self.path(context)
        self.location = path
        if path not in self._loaded:
            if not os.path.isfile(path):
                raise InvalidLaunchFileError(f"launch file '{path}' does not exist")
            self._loaded[path] = get_launch_description_from_python_launch_file(path)
        return self._loaded[path]

    def try_get_launch_description_without_context(self) -> Any:
        try:
            return self.get_launch_description(LaunchContext())
        except Exception:
            return None


class FrontendLaunchDescriptionSource(PythonLaunchDescriptionSource):
    """An XML or YAML launch file (launch's FrontendLaunchDescriptionSource): read by launch.frontend."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path)
        self.method = "interpreted frontend launch file"

    def get_launch_description(self, context: Any) -> Any:
        path = self.path(context)
        self.location = path
        if path not in self._loaded:
            self._loaded[path] = load_frontend_launch_description(path)
        return self._loaded[path]


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """launch_xml.launch_description_sources.XMLLaunchDescriptionSource."""


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource."""


class AnyLaunchDescriptionSource(PythonLaunchDescriptionSource):
    """By extension, as launch's: ``.py`` is Python, anything else is read by the XML or YAML front end."""

    def get_launch_description(self, context: Any) -> Any:
        path = self.path(context)
        if path.endswith(".py"):
            return super().get_launch_description(context)
        self.location = path
        if path not in self._loaded:
            self._loaded[path] = load_frontend_launch_description(path)
        return self._loaded[path]


__all__ = [
    "AnyLaunchDescriptionSource",
    "FrontendLaunchDescriptionSource",
    "InvalidLaunchFileError",
    "LaunchDescriptionSource",
    "PythonLaunchDescriptionSource",
    "XMLLaunchDescriptionSource",
    "YAMLLaunchDescriptionSource",
    "get_launch_description_from_python_launch_file",
]
