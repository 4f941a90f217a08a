"""normalize_to_list_of_substitutions: what an action or substitution takes (text, a substitution or a list of
them) as a list of substitutions (Jazzy: launch/utilities/normalize_to_list_of_substitutions_impl.py).

It needs only the ground floor (the Substitution base and TextSubstitution, launch/text_substitution.py), so the
substitutions, conditions and actions above it import it and it imports none of them: launch imports
TextSubstitution inside this function ("avoid recursive import"), a circle between launch/substitution.py and
launch/substitutions/ that this layering does not have."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ..substitution import Substitution
from ..text_substitution import TextSubstitution


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """A string, a substitution or an iterable of them, as a list of substitutions.

    Like launch's it takes no bare bool or number: ``DeclareLaunchArgument('x', default_value=True)`` fails in
    ROS 2 as well. Only ``LaunchConfiguration``'s ``default`` and ``EqualsSubstitution``'s operands turn other
    values into text first (:func:`text_items`)."""
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


__all__ = ["normalize_to_list_of_substitutions", "text_items"]
