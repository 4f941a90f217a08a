"""launch's tags and substitutions for XML and YAML launch files, each read as launch's own ``parse``
classmethod reads it (Jazzy: launch/actions/*.py and launch/substitutions/*.py, cited per tag).

Tags: ``arg`` (with ``choice``), ``let``, ``include`` (with ``arg``), ``group`` (with ``keep``),
``executable`` (with ``env``), ``set_env``, ``unset_env``, ``append_env``, ``log``, ``timer``,
``shutdown``. Every tag takes ``if`` / ``unless``.
Substitutions: ``var``, ``env``, ``optenv`` (ROS 1's, which Jazzy does not have: ``env`` with an empty
default), ``find-exec``, ``command``, ``eval``, ``dirname``, ``filename``, ``anon``, ``not``, ``and``,
``or``, ``equals``, ``not-equals``, ``if``.

It stands above the actions and the front end's reader (launch/frontend/, which knows no action) and registers
them as ``import launch`` imports it; launch_ros/frontend.py is its like for launch_ros."""

from __future__ import annotations

import shlex
from typing import Any

from . import actions, substitutions
from .conditions import IfCondition, UnlessCondition
from .frontend.entity import Entity
from .frontend.expose import expose_action, expose_substitution
from .frontend.type_utils import is_entity_list
from .text_substitution import TextSubstitution

ENTITIES = list[Entity]


def condition_kwargs(entity: Entity, parser: Any) -> dict[str, Any]:
    """``if`` / ``unless`` of any tag (launch/action.py ``Action.parse``); both at once are refused."""
    if_cond = entity.get_attr("if", optional=True)
    unless_cond = entity.get_attr("unless", optional=True)
    if if_cond is not None and unless_cond is not None:
        raise ValueError("if and unless conditions can't be used simultaneously")
    if if_cond is not None:
        return {"condition": IfCondition(parser.parse_substitution(if_cond))}
    if unless_cond is not None:
        return {"condition": UnlessCondition(parser.parse_substitution(unless_cond))}
    return {}


@expose_action("arg")
def parse_arg(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """declare_launch_argument.py: ``name``, ``default``, ``description``, nested ``<choice value>``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["name"] = parser.escape_characters(entity.get_attr("name"))
    default = entity.get_attr("default", optional=True)
    if default is not None:
        kwargs["default_value"] = parser.parse_substitution(default)
    description = entity.get_attr("description", optional=True)
    if description is not None:
        kwargs["description"] = parser.escape_characters(description)
    choices = entity.get_attr("choice", data_type=ENTITIES, optional=True)
    if choices is not None:
        kwargs["choices"] = [parser.escape_characters(c.get_attr("value")) for c in choices]
        for c in choices:
            c.assert_entity_completely_parsed()
    return actions.DeclareLaunchArgument, kwargs


@expose_action("let")
def parse_let(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """set_launch_configuration.py: ``name``, ``value``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
    kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
    return actions.SetLaunchConfiguration, kwargs


def name_value_pairs(entities: list[Entity] | None, parser: Any) -> list[tuple[Any, Any]]:
    """``<arg name value>`` / ``<env name value>`` / ``<keep name value>`` nested tags, each fully read."""
    pairs = []
    for e in entities or []:
        pairs.append((parser.parse_substitution(e.get_attr("name")), parser.parse_substitution(e.get_attr("value"))))
        e.assert_entity_completely_parsed()
    return pairs


@expose_action("include")
def parse_include(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """include_launch_description.py: ``file`` (any launch file kind) and nested ``<arg name value>``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["launch_description_source"] = parser.parse_substitution(entity.get_attr("file"))
    args = entity.get_attr("arg", data_type=ENTITIES, optional=True)
    if args is not None:
        kwargs["launch_arguments"] = name_value_pairs(args, parser)
    return actions.IncludeLaunchDescription, kwargs


@expose_action("group")
def parse_group(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """group_action.py: ``scoped``, ``forwarding``, nested ``<keep name value>`` and the actions."""
    kwargs = condition_kwargs(entity, parser)
    for key in ("scoped", "forwarding"):
        value = entity.get_attr(key, data_type=bool, optional=True, can_be_str=False)
        if value is not None:
            kwargs[key] = value
    keeps = entity.get_attr("keep", data_type=ENTITIES, optional=True)
    if keeps is not None:
        kwargs["launch_configurations"] = {tuple(k): v for k, v in name_value_pairs(keeps, parser)}
    kwargs["actions"] = [parser.parse_action(e) for e in entity.children if e.type_name != "keep"]
    return actions.GroupAction, kwargs


def parse_cmdline(cmd: str, parser: Any) -> list[list[Any]]:
    """A space-separated command line with substitutions, as launch's ``ExecuteProcess._parse_cmdline``:
    text is split as a shell splits it, and a substitution joins the text it touches
    (``$(find-pkg-prefix p)/lib/x --flag`` is two arguments)."""
    result: list[list[Any]] = []
    arg: list[Any] = []

    def close() -> None:
        nonlocal arg
        result.append(arg)
        arg = []

    for sub in parser.parse_substitution(cmd):
        if not isinstance(sub, TextSubstitution):
            arg.append(sub)
            continue
        tokens = shlex.split(sub.text)
        if not tokens:
            close()
            continue
        if sub.text[0].isspace() and arg:
            close()
        arg.append(TextSubstitution(text=tokens[0]))
        if len(tokens) > 1:
            close()
            result.extend([TextSubstitution(text=t)] for t in tokens[1:-1])
            arg.append(TextSubstitution(text=tokens[-1]))
        if sub.text[-1].isspace():
            close()
    if arg:
        result.append(arg)
    return [a for a in result if a]


def process_kwargs(entity: Entity, parser: Any, ignore: tuple[str, ...] = ()) -> dict[str, Any]:
    """What ``<executable>`` and ``<node>`` share (execute_process.py ``ExecuteProcess.parse``)."""
    kwargs = condition_kwargs(entity, parser)
    if "cmd" not in ignore:
        kwargs["cmd"] = parse_cmdline(entity.get_attr("cmd"), parser)
    for key, attr in (("cwd", "cwd"), ("name", "name"), ("prefix", "launch-prefix"), ("output", "output")):
        value = entity.get_attr(attr, optional=True)
        if value is not None:
            kwargs[key] = parser.parse_substitution(value)
    respawn = entity.get_attr("respawn", optional=True)
    if respawn is not None:
        kwargs["respawn"] = parser.parse_substitution(respawn)
    on_exit = entity.get_attr("on_exit", optional=True)
    if on_exit is not None:
        if on_exit != "shutdown":
            raise ValueError(f"on_exit must be 'shutdown' (the only one launch takes), got '{on_exit}'")
        kwargs["on_exit"] = [actions.Shutdown()]
    retries = entity.get_attr("respawn_max_retries", data_type=int, optional=True)
    if retries is not None:
        kwargs["respawn_max_retries"] = retries
    for key in ("respawn_delay", "sigkill_timeout", "sigterm_timeout"):
        value = entity.get_attr(key, data_type=float, optional=True)
        if value is not None:
            if value < 0.0:
                raise ValueError(f"{key} must not be negative, got {value}")
            kwargs[key] = value
    for key in ("shell", "emulate_tty"):
        value = entity.get_attr(key, data_type=bool, optional=True, can_be_str=False)
        if value is not None:
            kwargs[key] = value
    env = entity.get_attr("env", data_type=ENTITIES, optional=True)
    if env is not None:
        kwargs["additional_env"] = {tuple(k): v for k, v in name_value_pairs(env, parser)}
    return kwargs


@expose_action("executable")
def parse_executable(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """execute_process.py: ``cmd`` and the process's attributes."""
    return actions.ExecuteProcess, process_kwargs(entity, parser)


def _name_value_action(action: type, with_value: bool) -> Any:
    def parse(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
        kwargs = condition_kwargs(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        if with_value:
            kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
        return action, kwargs

    return parse


expose_action("set_env")(_name_value_action(actions.SetEnvironmentVariable, True))
expose_action("unset_env")(_name_value_action(actions.UnsetEnvironmentVariable, False))


@expose_action("append_env")
def parse_append_env(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """append_environment_variable.py: ``name``, ``value``, ``prepend``, ``separator``."""
    kwargs = _name_value_action(actions.AppendEnvironmentVariable, True)(entity, parser)[1]
    prepend = entity.get_attr("prepend", data_type=bool, optional=True, can_be_str=True)
    if prepend is not None:
        kwargs["prepend"] = parser.parse_if_substitutions(prepend)
    separator = entity.get_attr("separator", optional=True)
    if separator is not None:
        kwargs["separator"] = parser.parse_substitution(separator)
    return actions.AppendEnvironmentVariable, kwargs


@expose_action("log")
def parse_log(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """log_info.py: ``message``."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["msg"] = parser.parse_substitution(entity.get_attr("message"))
    return actions.LogInfo, kwargs


@expose_action("timer")
def parse_timer(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """timer_action.py: ``period`` and the actions."""
    kwargs = condition_kwargs(entity, parser)
    kwargs["period"] = parser.parse_if_substitutions(entity.get_attr("period", data_type=float, can_be_str=True))
    cancel = entity.get_attr("cancel_on_shutdown", data_type=bool, optional=True, can_be_str=False)
    if cancel is not None:
        kwargs["cancel_on_shutdown"] = cancel
    kwargs["actions"] = [parser.parse_action(child) for child in entity.children]
    return actions.TimerAction, kwargs


@expose_action("shutdown")
def parse_shutdown(entity: Entity, parser: Any) -> tuple[type, dict[str, Any]]:
    """shutdown_action.py: ``reason``."""
    kwargs = condition_kwargs(entity, parser)
    reason = entity.get_attr("reason", optional=True)
    if reason:
        kwargs["reason"] = reason
    return actions.Shutdown, kwargs


# -- substitutions ---------------------------------------------------------------------------------------


def _arity(name: str, data: list[Any], low: int, high: int) -> None:
    if not low <= len(data) <= high:
        want = str(low) if low == high else f"{low} to {high}"
        raise ValueError(f"$({name}) takes {want} argument(s), got {len(data)}")


def _exposed(name: str, low: int, high: int, make: Any) -> None:
    """``$(name a b ...)`` -> ``make(*args)`` as (type, kwargs), after checking the number of arguments."""

    def parse(data: list[Any]) -> tuple[Any, dict[str, Any]]:
        _arity(name, data, low, high)
        return make(*data)

    expose_substitution(name)(parse)


S = substitutions
_exposed("var", 1, 2, lambda n, d=None: (S.LaunchConfiguration, {"variable_name": n, "default": d}))
_exposed("env", 1, 2, lambda n, d=None: (S.EnvironmentVariable, {"name": n, "default_value": d}))
_exposed("optenv", 1, 2, lambda n, d="": (S.EnvironmentVariable, {"name": n, "default_value": d}))
_exposed("find-exec", 1, 1, lambda n: (S.FindExecutable, {"name": n}))
_exposed("command", 1, 2, lambda c, o="fail": (S.Command, {"command": c, "on_stderr": _text(o)}))
_exposed("dirname", 0, 0, lambda: (S.ThisLaunchFileDir, {}))
_exposed("filename", 0, 0, lambda: (S.ThisLaunchFile, {}))
_exposed("anon", 1, 1, lambda n: (S.AnonName, {"name": n}))
_exposed("not", 1, 1, lambda v: (S.NotSubstitution, {"value": v}))
_exposed("and", 2, 2, lambda a, b: (S.AndSubstitution, {"left": a, "right": b}))
_exposed("or", 2, 2, lambda a, b: (S.OrSubstitution, {"left": a, "right": b}))
_exposed("equals", 2, 2, lambda a, b: (S.EqualsSubstitution, {"left": a, "right": b}))
_exposed("not-equals", 2, 2, lambda a, b: (S.NotEqualsSubstitution, {"left": a, "right": b}))
_exposed("if", 2, 3, lambda c, a, b="": (S.IfElseSubstitution, {"condition": c, "if_value": a, "else_value": b}))


def _text(value: Any) -> str:
    """An argument that must be plain text (no substitution in it)."""
    if isinstance(value, str):
        return value
    if all(isinstance(v, TextSubstitution) for v in value):
        return "".join(v.text for v in value)
    raise ValueError("this argument must be plain text, without substitutions")


@expose_substitution("eval")
def parse_eval(data: list[Any]) -> tuple[Any, dict[str, Any]]:
    """python_expression.py: the expression, and optionally comma-separated modules (default ``math``).
    Evaluated as launch evaluates it: the launch file is the user's own code."""
    _arity("eval", data, 1, 2)
    kwargs: dict[str, Any] = {"expression": data[0]}
    if len(data) == 2:
        kwargs["python_modules"] = [m.strip() for m in _text(data[1]).split(",") if m.strip()]
    return S.PythonExpression, kwargs


__all__ = ["condition_kwargs", "is_entity_list", "name_value_pairs", "parse_cmdline", "process_kwargs"]
