"""launch.substitutions: the substitutions Gazebo-style launch files use."""

from __future__ import annotations

import math
import os
import shlex
import shutil
import subprocess
from typing import Any

from ..launch_context import LaunchContext
from ..substitution import Substitution
from ..text_substitution import TextSubstitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from ..utilities.normalize_to_list_of_substitutions_impl import text_items


class SubstitutionFailure(RuntimeError):
    """A substitution that cannot be performed (launch.substitutions.SubstitutionFailure)."""


class LaunchConfiguration(Substitution):
    """The value of a launch argument / configuration (``LaunchConfiguration('use_sim_time')``)."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        # launch turns a default that is not text into text (default=True is 'True'; every gz_ros2_control
        # demo writes LaunchConfiguration('use_sim_time', default=True)); None means no default
        self.default = None if default is None else normalize_to_list_of_substitutions(text_items(default))

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.variable_name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.default is not None:
            return perform_substitutions(context, self.default)
        raise SubstitutionFailure(f"launch configuration '{name}' does not exist")

    def describe(self) -> str:
        return f"LaunchConfiguration({''.join(s.describe() for s in self.variable_name)})"


class PathJoinSubstitution(Substitution):
    """Path parts joined with ``os.path.join``."""

    def __init__(self, substitutions: Any) -> None:
        self.parts = [normalize_to_list_of_substitutions(s) for s in substitutions]

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform_substitutions(context, p) for p in self.parts))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        new = PathJoinSubstitution([])
        new.parts = [*self.parts, normalize_to_list_of_substitutions(other)]
        return new


class EnvironmentVariable(Substitution):
    """An environment variable of the launch (``default_value`` when unset)."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        value = context.environment.get(name)
        if value is not None:
            return value
        if self.default_value is not None:
            return perform_substitutions(context, self.default_value)
        raise SubstitutionFailure(f"environment variable '{name}' does not exist")


class FindExecutable(Substitution):
    """The path of an executable on PATH."""

    def __init__(self, *, name: Any) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        found = shutil.which(name, path=context.environment.get("PATH"))
        if found is None:
            raise SubstitutionFailure(f"executable '{name}' not found on the PATH")
        return found


class Command(Substitution):
    """The standard output of a command (``Command(['xacro ', path])``); a failure stops the launch."""

    def __init__(self, command: Any, *, on_stderr: str = "fail") -> None:
        self.command = normalize_to_list_of_substitutions(command)
        self.on_stderr = on_stderr

    def perform(self, context: LaunchContext) -> str:
        text = perform_substitutions(context, self.command)
        argv = shlex.split(text)
        try:
            out = subprocess.run(argv, capture_output=True, text=True, env=context.environment, check=False)
        except OSError as err:
            raise SubstitutionFailure(f"executed command failed. Command: {text}\n{err}") from None
        if out.returncode != 0:
            raise SubstitutionFailure(
                f"executed command failed. Command: {text}\nCaptured stderr output: {out.stderr.strip()}"
            )
        if out.stderr.strip():
            if self.on_stderr == "fail":
                raise SubstitutionFailure(
                    f"executed command showed stderr output. Command: {text}\nCaptured stderr output: {out.stderr}"
                )
            if self.on_stderr == "warn":
                import logging

                logging.getLogger("launch").warning(out.stderr.strip())
        return out.stdout


class PythonExpression(Substitution):
    """``eval`` of the joined text with ``math`` available (as launch does: it is the user's own file)."""

    def __init__(self, expression: Any, python_modules: Any = ("math",)) -> None:
        self.expression = normalize_to_list_of_substitutions(expression)
        self.python_modules = list(python_modules)

    def perform(self, context: LaunchContext) -> str:
        import importlib

        text = perform_substitutions(context, self.expression)
        names: dict[str, Any] = {}
        for mod in self.python_modules:
            name = (
                mod if isinstance(mod, str) else perform_substitutions(context, normalize_to_list_of_substitutions(mod))
            )
            names[name] = importlib.import_module(name)
        if "math" in names:
            names.update({k: getattr(names["math"], k) for k in dir(names["math"]) if not k.startswith("_")})
        return str(eval(text, names))


class ThisLaunchFileDir(Substitution):
    """The folder of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        path = getattr(context.locals, "current_launch_file_directory", None) if hasattr(context, "locals") else None
        try:
            return context.locals.current_launch_file_directory
        except AttributeError:
            if path:
                return path
            raise SubstitutionFailure("ThisLaunchFileDir used outside a launch file") from None


class ThisLaunchFile(Substitution):
    """The path of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        try:
            return context.locals.current_launch_file_path
        except AttributeError:
            raise SubstitutionFailure("ThisLaunchFile used outside a launch file") from None


class AnonName(Substitution):
    """A name made unique per launch (``AnonName('rviz')``)."""

    _made: dict[str, str] = {}

    def __init__(self, name: Any) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        import uuid

        name = perform_substitutions(context, self.name)
        return self._made.setdefault(name, f"{name}_{uuid.uuid4().hex[:8]}")


class NotSubstitution(Substitution):
    def __init__(self, value: Any) -> None:
        self.value = normalize_to_list_of_substitutions(value)

    def perform(self, context: LaunchContext) -> str:
        from ..conditions import evaluate_condition_expression

        return str(not evaluate_condition_expression(context, self.value)).lower()


class AndSubstitution(Substitution):
    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize_to_list_of_substitutions(left), normalize_to_list_of_substitutions(right)

    def perform(self, context: LaunchContext) -> str:
        from ..conditions import evaluate_condition_expression

        both = evaluate_condition_expression(context, self.left) and evaluate_condition_expression(context, self.right)
        return str(both).lower()


class OrSubstitution(Substitution):
    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize_to_list_of_substitutions(left), normalize_to_list_of_substitutions(right)

    def perform(self, context: LaunchContext) -> str:
        from ..conditions import evaluate_condition_expression

        either = evaluate_condition_expression(context, self.left) or evaluate_condition_expression(context, self.right)
        return str(either).lower()


class IfElseSubstitution(Substitution):
    """``if_value`` when ``condition`` is true, else ``else_value`` (launch's if_else_substitution.py, Jazzy): the
    condition evaluated as IfCondition evaluates it; at least one of the two values must be given."""

    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        if if_value == else_value == "":
            raise ValueError("At least one of `if_value` or `else_value` must be provided")
        self.condition = normalize_to_list_of_substitutions(condition)
        self.if_value = normalize_to_list_of_substitutions(if_value)
        self.else_value = normalize_to_list_of_substitutions(else_value)

    def perform(self, context: LaunchContext) -> str:
        from ..conditions import evaluate_condition_expression

        chosen = self.if_value if evaluate_condition_expression(context, self.condition) else self.else_value
        return perform_substitutions(context, chosen)


def _operand(value: Any) -> list[Substitution]:
    """An ``EqualsSubstitution`` operand as launch takes it (launch/substitutions/equals_substitution.py): a
    substitution, or a list of text and substitutions holding one, as it is; anything else as text, None as
    ``''`` and a bool as ``true``/``false``."""
    is_substitution = isinstance(value, Substitution) or (
        isinstance(value, (list, tuple))
        and value
        and all(isinstance(v, (str, Substitution)) for v in value)
        and any(isinstance(v, Substitution) for v in value)
    )
    if not is_substitution:
        value = "" if value is None else str(value).lower() if isinstance(value, bool) else str(value)
    return normalize_to_list_of_substitutions(value)


def _is_bool_text(text: str) -> bool:
    return text.lower() in ("true", "false", "1", "0")


def _is_float_text(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


class EqualsSubstitution(Substitution):
    """``'true'`` when both sides are equal: as booleans when both read as one (``True`` equals ``1``), as
    numbers when both read as one (``1.0`` equals ``1``), else as text (launch's EqualsSubstitution)."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = _operand(left), _operand(right)

    def perform(self, context: LaunchContext) -> str:
        left, right = perform_substitutions(context, self.left), perform_substitutions(context, self.right)
        if _is_bool_text(left) and _is_bool_text(right):
            return str((left.lower() in ("true", "1")) == (right.lower() in ("true", "1"))).lower()
        if _is_float_text(left) and _is_float_text(right):
            return str(math.isclose(float(left), float(right))).lower()
        return str(left == right).lower()


class NotEqualsSubstitution(EqualsSubstitution):
    """``'true'`` when :class:`EqualsSubstitution` of the same sides is ``'false'``."""

    def perform(self, context: LaunchContext) -> str:
        return str(super().perform(context) != "true").lower()


class LocalSubstitution(Substitution):
    """A value from ``context.locals`` (``LocalSubstitution('event.returncode')``)."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        self.expression = expression

    def perform(self, context: LaunchContext) -> str:
        return str(eval(self.expression, {}, context.get_locals_as_dict()))


__all__ = [
    "AndSubstitution",
    "AnonName",
    "Command",
    "EnvironmentVariable",
    "EqualsSubstitution",
    "FindExecutable",
    "IfElseSubstitution",
    "LaunchConfiguration",
    "LocalSubstitution",
    "NotEqualsSubstitution",
    "NotSubstitution",
    "OrSubstitution",
    "PathJoinSubstitution",
    "PythonExpression",
    "SubstitutionFailure",
    "TextSubstitution",
    "ThisLaunchFile",
    "ThisLaunchFileDir",
]
