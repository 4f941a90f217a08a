"""Substitutions: values computed when the launch runs, in its context (launch.Substitution)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .launch_context import LaunchContext


class Substitution:
    """Base class: :meth:`perform` returns the text for a context."""

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError(type(self).__name__)

    def describe(self) -> str:
        return f"{type(self).__name__}(...)"

    def __repr__(self) -> str:
        return self.describe()


SomeSubstitutionsType = str | Substitution | Iterable[str | Substitution]
