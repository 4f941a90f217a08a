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
    """A string, a substitution or an iterable of them, as a list of substitutions.

    Like launch's (launch/utilities/normalize_to_list_of_substitutions_impl.py) it takes no bare bool or
    number: ``DeclareLaunchArgument('x', default_value=True)`` fails in ROS 2 as well. Only
    ``LaunchConfiguration``'s ``default`` and ``EqualsSubstitution``'s operands turn other values into
    text first (:func:`text_items`)."""
    from .substitutions.text_substitution import TextSubstitution

    if isinstance(subs, str):
        return [TextSubstitution(text=subs)]
    if isinstance(subs, Substitution):
        return [subs]
    if not isinstance(subs, Iterable):
        raise TypeError(f"expected a string, a substitution or a list of them, got {type(subs).__name__}: {subs!r}")
    out: list[Substitution] = []
    for s in subs:
        if isinstance(s, (str, Substitution)):
            out.extend(normalize_to_list_of_substitutions(s))
        elif isinstance(s, (int, float, bool)) and not isinstance(s, bool):
            out.append(TextSubstitution(text=str(s)))
        else:
            raise TypeError(f"expected a string or a substitution, got {type(s).__name__}: {s!r}")
    return out


def text_items(value: Any) -> list[str | Substitution]:
    """``value`` (one item or an iterable of them) with every item that is neither text nor a substitution
    turned into its ``str()``: what launch's ``LaunchConfiguration`` does with its ``default``
    (launch/substitutions/launch_configuration.py), so ``default=True`` is the text ``True``."""
    items = value if isinstance(value, Iterable) else (value,)
    return [item if isinstance(item, (str, Substitution)) else str(item) for item in items]


def perform_substitutions(context: LaunchContext, subs: list[Substitution]) -> str:
    """The concatenated text of ``subs``."""
    return "".join(s.perform(context) for s in subs)
