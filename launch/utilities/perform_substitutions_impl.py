"""perform_substitutions: the text of a list of substitutions in a context (Jazzy:
launch/utilities/perform_substitutions_impl.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ..launch_context import LaunchContext
    from ..substitution import Substitution


def perform_substitutions(context: LaunchContext, subs: list[Substitution]) -> str:
    """The concatenated text of ``subs``."""
    return "".join(s.perform(context) for s in subs)


__all__ = ["perform_substitutions"]
