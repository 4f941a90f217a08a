"""launch.utilities.normalize_to_list_of_entities (launch Jazzy, utilities/normalize_to_list_of_entities_impl.py)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ..action import Action


def normalize_to_list_of_entities(entities: Iterable[Any]) -> list[Any]:
    """``entities`` with one level of nesting flattened: an entity (an action or a launch description) is kept,
    anything else is an iterable of entities whose items take its place."""
    flat: list[Any] = []
    for entity in entities:
        if isinstance(entity, Action):
            flat.append(entity)
        else:
            flat.extend(entity)
    return flat
