"""Substitutions: values computed when the launch runs, in its context (launch.Substitution)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

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


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """A string, a substitution or an iterable of them, as a list of substitutions."""
    from .substitutions.text_substitution import TextSubstitution

    if isinstance(subs, str):
        return [TextSubstitution(text=subs)]
    if isinstance(subs, Substitution):
        return [subs]
    out: list[Substitution] = []
    for s in subs:
        if isinstance(s, (str, Substitution)):
            out.extend(normalize_to_list_of_substitutions(s))
        elif isinstance(s, (int, float, bool)) and not isinstance(s, bool):
            out.append(TextSubstitution(text=str(s)))
        else:
            raise TypeError(f"expected a string or a substitution, got {type(s).__name__}: {s!r}")
    return out


def perform_substitutions(context: LaunchContext, subs: list[Substitution]) -> str:
    """The concatenated text of ``subs``."""
    return "".join(s.perform(context) for s in subs)
