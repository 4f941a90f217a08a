"""launch.utilities.ensure_argument_type (launch Jazzy, utilities/ensure_argument_type_impl.py)."""

from __future__ import annotations

import inspect
from collections.abc import Iterable
from typing import Any


def ensure_argument_type(
    argument: Any, types: type | Iterable[type], argument_name: str, caller: str | None = None
) -> None:
    """Check that ``argument`` is an instance of one of ``types`` (a type or an iterable of types).

    Raises:
        TypeError: it is not, with launch's message: "Expected 'NAME' to be one of [TYPES], but got 'VALUE'
            of type 'TYPE'" (``'CALLER' expected ...`` when ``caller`` is given); or the call's own arguments
            are not a type (or types), a str and a str or None.
    """
    if not isinstance(types, (type, Iterable)):
        expected = "type, collections.abc.Iterable of type"
        raise TypeError(_message("'ensure_argument_type()' e", "types", expected, types))
    if not isinstance(argument_name, str):
        raise TypeError(_message("'ensure_argument_type()' e", "argument_name", "str", argument_name))
    if caller is not None and not isinstance(caller, str):
        raise TypeError(_message("'ensure_argument_type()' e", "caller", "str, None", caller))
    candidates = [types] if isinstance(types, type) else list(types)
    if any(inspect.isclass(candidate) and isinstance(argument, candidate) for candidate in candidates):
        return
    lead = "E" if caller is None else f"'{caller}' e"
    raise TypeError(_message(lead, argument_name, ", ".join(str(t) for t in candidates), argument))


def _message(lead: str, name: str, expected: str, value: Any) -> str:
    return f"{lead}xpected '{name}' to be one of [{expected}], but got '{value}' of type '{type(value)}'"
