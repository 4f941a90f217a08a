"""``ParameterBuilder``: one node's parameters gathered from a package's files (launch_param_builder)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .utils import load_file, load_xacro, load_yaml


class ParameterBuilder:
    """Parameters read from files under one package's share folder; each method returns the builder, so calls
    chain, and :meth:`to_dict` gives what ``Node(parameters=[...])`` takes."""

    def __init__(self, package_name: str) -> None:
        """A builder reading from ``package_name``'s share folder (found in the ament index)."""
        from ament_index_python.packages import get_package_share_directory

        self._package_path = Path(get_package_share_directory(package_name))
        self._parameters: dict[str, Any] = {}

    def yaml(self, file_path: str | Path, parameter_namespace: str | None = None) -> ParameterBuilder:
        """The YAML file ``file_path`` (relative to the package) merged in: at the top level, or under
        ``parameter_namespace`` (merged with what is there already)."""
        data = load_yaml(self._package_path / file_path)
        if parameter_namespace:
            self._parameters.setdefault(parameter_namespace, {}).update(data)
        else:
            self._parameters.update(data)
        return self

    def file_parameter(self, parameter_name: str, file_path: str | Path) -> ParameterBuilder:
        """``parameter_name`` set to the text of ``file_path`` (deprecated upstream for :meth:`yaml`)."""
        self._parameters[parameter_name] = load_file(self._package_path / file_path)
        return self

    def xacro_parameter(
        self, parameter_name: str, file_path: str | Path, mappings: dict[str, str] | None = None
    ) -> ParameterBuilder:
        """``parameter_name`` set to ``file_path`` expanded by xacro with ``mappings``."""
        self._parameters[parameter_name] = load_xacro(self._package_path / file_path, mappings=mappings)
        return self

    def parameter(self, parameter_name: str, parameter_value: Any) -> ParameterBuilder:
        """``parameter_name`` set to ``parameter_value``."""
        self._parameters[parameter_name] = parameter_value
        return self

    def path_parameter(self, parameter_name: str, file_path: str | Path) -> ParameterBuilder:
        """``parameter_name`` set to the absolute path of ``file_path`` in the package."""
        self._parameters[parameter_name] = str(self._package_path / file_path)
        return self

    def to_dict(self) -> dict[str, Any]:
        """The parameters gathered (the builder's own dict, as upstream hands it out)."""
        return self._parameters
