"""Conditions decide whether an action runs (launch.Condition)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class Condition:
    def __init__(self, *, predicate: Callable[[Any], bool] | None = None) -> None:
        self._predicate = predicate

    def evaluate(self, context: Any) -> bool:
        return self._predicate(context) if self._predicate is not None else True

    def describe(self) -> str:
        return type(self).__name__
