"""ReplaceString: a copy of a file with some strings replaced, whose path is the substitution's value
(nav2_common Jazzy, replace_string.py: what it does, in our own code). Each line of the file has each
``replacements`` key replaced by its value (substitutions, performed to text), in the order given. With a
``condition`` that is false, the value is the source file's path, unchanged."""

from __future__ import annotations

from typing import Any

from launch import Condition, Substitution
from launch.substitutions import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ._files import read_text, write_temporary

_WHO = "ReplaceString"


class ReplaceString(Substitution):
    """See the module docstring."""

    def __init__(self, source_file: Any, replacements: dict[str, Any], condition: Condition | None = None) -> None:
        super().__init__()
        self._source = normalize_to_list_of_substitutions(source_file)
        self._replacements = {k: normalize_to_list_of_substitutions(v) for k, v in replacements.items()}
        self._condition = condition

    @property
    def name(self) -> list[Substitution]:
        """The source file's substitutions."""
        return self._source

    @property
    def condition(self) -> Condition | None:
        """When the replacement happens (always when None)."""
        return self._condition

    def describe(self) -> str:
        return ""

    def perform(self, context: Any) -> str:
        path = perform_substitutions(context, self._source)
        if self._condition is not None and not self._condition.evaluate(context):
            return path
        pairs = [(k, perform_substitutions(context, v)) for k, v in self._replacements.items()]
        for key, _ in pairs:
            if not isinstance(key, str):
                raise SubstitutionFailure(f"{_WHO}: the key {key!r} of a replacement is not a string")
        lines = read_text(path, _WHO).splitlines(keepends=True)
        out = []
        for line in lines:
            for key, value in pairs:
                line = line.replace(key, value)
            out.append(line)
        return write_temporary("".join(out))
