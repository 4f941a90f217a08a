"""Loading a package's files as parameter values: YAML, plain text and xacro (launch_param_builder.utils)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml


class ParameterBuilderFileNotFoundError(KeyError):
    """A file the builder was asked to load does not exist (a KeyError, as launch_param_builder's is: MoveIt's
    builder catches it to fall back to the robot_description topic)."""


def _existing(path: Path | str) -> Path:
    path = Path(path)
    if not path.exists():
        raise ParameterBuilderFileNotFoundError(f"File {path} doesn't exist")
    return path


def load_file(file_path: Path | str) -> str | None:
    """The text of ``file_path`` (None when it cannot be read)."""
    path = _existing(file_path)
    try:
        return path.read_text()
    except OSError:
        return None


def load_yaml(file_path: Path | str) -> Any:
    """The YAML document in ``file_path`` (None when it cannot be read). Read with PyYAML's safe loader: the
    configuration files a MoveIt package holds are plain data (launch_param_builder's FullLoader would also build
    Python objects from tags; a config that needs them is named by yaml's error, with its line)."""
    path = _existing(file_path)
    try:
        text = path.read_text()
    except OSError:
        return None
    return yaml.safe_load(text)


def load_xacro(file_path: Path | str, mappings: dict[str, str] | None = None) -> str:
    """``file_path`` expanded by xacro (its ``$(arg)`` values from ``mappings``), as XML text: what ``xacro
    file`` prints. ``$(find pkg)`` looks ``pkg`` up in the ament index, as the xacro command does."""
    import xacro

    path = _existing(file_path)
    return xacro.process_file(str(path), mappings=dict(mappings or {})).toxml()


def get_path(package_name: str, file_path: str) -> str:
    """``file_path`` under ``package_name``'s share folder."""
    from ament_index_python.packages import get_package_share_directory

    return str(Path(get_package_share_directory(package_name)) / file_path)
