"""launch.conditions."""

from __future__ import annotations

from typing import Any

from ..condition import Condition
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

_TRUE = ("true", "1")
_FALSE = ("false", "0")


class InvalidConditionExpressionError(ValueError):
    pass


def evaluate_condition_expression(context: Any, expression: Any) -> bool:
    """'true'/'1' or 'false'/'0' (any case), as launch accepts them."""
    text = perform_substitutions(context, expression).strip().lower()
    if text in _TRUE:
        return True
    if text in _FALSE:
        return False
    raise InvalidConditionExpressionError(
        f"Unexpected condition value '{text}': expected one of 'true', 'false', '1', '0' (any case)"
    )


class IfCondition(Condition):
    def __init__(self, predicate_expression: Any) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda ctx: evaluate_condition_expression(ctx, self.expression))


class UnlessCondition(Condition):
    def __init__(self, predicate_expression: Any) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda ctx: not evaluate_condition_expression(ctx, self.expression))


class LaunchConfigurationEquals(Condition):
    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        self.name = launch_configuration_name
        self.expected = None if expected_value is None else normalize_to_list_of_substitutions(expected_value)
        super().__init__(predicate=self._check)

    def _check(self, ctx: Any) -> bool:
        value = ctx.launch_configurations.get(self.name)
        if self.expected is None:
            return value is None
        return value == perform_substitutions(ctx, self.expected)


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def evaluate(self, context: Any) -> bool:
        return not self._check(context)


__all__ = [
    "IfCondition",
    "InvalidConditionExpressionError",
    "LaunchConfigurationEquals",
    "LaunchConfigurationNotEquals",
    "UnlessCondition",
    "evaluate_condition_expression",
]
