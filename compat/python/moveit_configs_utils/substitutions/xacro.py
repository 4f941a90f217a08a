"""``Xacro``: a launch substitution whose value is a xacro file expanded, its path and its mappings' keys and values
themselves substitutions (moveit_configs_utils.substitutions.Xacro)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launch_param_builder import load_xacro

from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class Xacro(Substitution):
    """The XML text of ``file_path`` expanded by xacro with ``mappings`` (``$(arg)`` values), each performed when
    the launch runs."""

    def __init__(self, file_path: Any, *, mappings: dict[Any, Any] | None = None) -> None:
        super().__init__()
        self._file_path = normalize_to_list_of_substitutions(file_path)
        self._mappings = dict(mappings or {})

    @property
    def file_path(self) -> list[Substitution]:
        return self._file_path

    @property
    def mappings(self) -> dict[Any, Any]:
        return self._mappings

    def describe(self) -> str:
        pairs = ", ".join(f"{k}:={v}" for k, v in self._mappings.items())
        return f"Xacro(file_path = {self._file_path}, mappings = {pairs})"

    def perform(self, context: Any) -> str:
        path = perform_substitutions(context, self._file_path)
        mappings = {
            perform_substitutions(context, normalize_to_list_of_substitutions(k)): perform_substitutions(
                context, normalize_to_list_of_substitutions(v)
            )
            for k, v in self._mappings.items()
        }
        return load_xacro(Path(path), mappings=mappings)
