"""HasNodeParams: ``True`` when a parameter file has a section for a node, else ``False``, as text for a
condition (nav2_common Jazzy, has_node_params.py: what it does, in our own code). The node's name is looked
for among the file's top-level keys, as written."""

from __future__ import annotations

from typing import Any

from launch import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ._files import read_yaml


class HasNodeParams(Substitution):
    """See the module docstring."""

    def __init__(self, source_file: Any, node_name: str) -> None:
        super().__init__()
        self._source = normalize_to_list_of_substitutions(source_file)
        self._node = node_name

    @property
    def name(self) -> list[Substitution]:
        """The source file's substitutions."""
        return self._source

    def describe(self) -> str:
        return ""

    def perform(self, context: Any) -> str:
        data = read_yaml(perform_substitutions(context, self._source), "HasNodeParams")
        return "True" if isinstance(data, dict) and self._node in data else "False"
