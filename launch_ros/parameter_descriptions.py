"""ParameterValue, ParameterFile and Parameter (launch_ros.parameter_descriptions)."""

from __future__ import annotations

from typing import Any

from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class ParameterValue:
    """A parameter's value given as substitutions, with ``value_type`` (str keeps text as text;
    None infers the type from YAML, as launch_ros does)."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type

    def evaluate(self, context: Any) -> Any:
        return evaluate_parameter_value(context, self.value, self.value_type)


class ParameterFile:
    """A parameters YAML file (``allow_substs`` substitutes ``$(var ...)`` in it: not supported yet)."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self.param_file = normalize_to_list_of_substitutions(param_file)
        self.allow_substs = allow_substs

    def evaluate(self, context: Any) -> str:
        return perform_substitutions(context, self.param_file)


class Parameter:
    def __init__(self, name: Any, value: Any, *, value_type: Any = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.value = ParameterValue(value, value_type=value_type)


def evaluate_parameter_value(context: Any, value: Any, value_type: Any = None) -> Any:
    """A parameter value with its substitutions performed (lists element-wise)."""
    import yaml

    from launch.substitution import Substitution

    if isinstance(value, ParameterValue):
        return value.evaluate(context)
    if isinstance(value, Substitution) or (
        isinstance(value, (list, tuple))
        and value
        and all(isinstance(v, (str, Substitution)) for v in value)
        and any(isinstance(v, Substitution) for v in value)
    ):
        text = perform_substitutions(context, normalize_to_list_of_substitutions(value))
        if value_type is str:
            return text
        try:
            parsed = yaml.safe_load(text)
        except yaml.YAMLError:
            return text
        return parsed if isinstance(parsed, (bool, int, float, str, list)) else text
    if isinstance(value, (list, tuple)):
        return [evaluate_parameter_value(context, v, None) for v in value]
    if isinstance(value, str) and value_type not in (None, str):
        return yaml.safe_load(value)
    return value


__all__ = ["Parameter", "ParameterFile", "ParameterValue", "evaluate_parameter_value"]
