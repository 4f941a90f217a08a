"""ROS 2 parameter files (``--params-file`` YAML) as ros2_control reads them, and the names controllers may take.

A file maps node names to ``ros__parameters``; a node's sections are found by :func:`section_matches`,
rcl's rules (a fully qualified name, ``/**`` for zero or more namespace levels, ``/*`` for exactly one).
Nested mappings flatten to dotted names (``linear: {x: {max_velocity: 1.0}}`` is ``linear.x.max_velocity``),
as rclcpp does.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..._errors import SimError
from ...description import (
    MAX_PARAMS_FILE_BYTES,
    MAX_YAML_NODES,
    UntrustedInputError,
    read_regular_file,
    safe_load_bounded,
)
from ...description import yaml_problem as yaml_problem
from .._bus import NODE_NAME as _NODE_NAME

ParamValue = bool | int | float | str | list[Any]
Params = dict[str, ParamValue]


class ParamsError(SimError, ValueError):
    """A parameters file that cannot be used; the message names the file (and line where YAML says)."""


@dataclass(frozen=True)
class ParamsFile:
    """One YAML file: node name (as written) -> flattened parameters."""

    path: str
    nodes: dict[str, Params]

    def for_node(self, name: str, namespace: str = "") -> Params:
        """The parameters of node ``name`` in ``namespace``: every section that names it
        (:func:`section_matches`), merged in the order the file first names them, a later section's value
        winning, as rclcpp and rclpy merge a node's overrides (parameter_map.cpp ``parameter_map_from``,
        rclpy node.cpp ``_populate_node_parameters_from_rcl_params``): ``/**`` before ``name`` in the file
        is a default the node's own section overrides."""
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
        out: Params = {}
        for key, params in self.nodes.items():
            if section_matches(key, name, ns):
                out.update(params)
        return out

    def names_in(self, namespace: str = "") -> set[str]:
        """The node names the file's sections spell out (the last part of a key, wildcards left out) that
        apply in ``namespace``: ``/**/imu_broadcaster`` names ``imu_broadcaster`` in every namespace,
        ``/r1/diff`` names ``diff`` in ``/r1`` only."""
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
        names = {key.rsplit("/", 1)[-1] for key in self.nodes}
        return {n for n in names if "*" not in n and any(section_matches(k, n, ns) for k in self.nodes)}


def section_matches(key: str, name: str, namespace: str = "") -> bool:
    """Whether a parameters file's section ``key`` applies to node ``name`` in ``namespace`` (``""`` or
    ``/ns``): the one matcher of every parameters file gazelle reads (the controller manager's files,
    spawners' ``--param-file``, ``spawn --ros-args --params-file``).

    rcl's rules, as rclcpp and rclpy apply them to a node's fully qualified name (rclcpp parameter_map.cpp
    ``is_node_name_matched``): a key without a leading ``/`` gets one; ``/**`` is zero or more namespace
    levels and ``/*`` exactly one (one token of letters, digits and ``_``), so ``/**/controller_manager``
    is ``/controller_manager`` and ``/r1/controller_manager``, ``/**`` every node; anything else must be
    equal. One addition: a name with no namespace (``diffbot_base_controller:``, ``/diffbot_base_controller:``)
    also applies in a namespace. rcl would not match it there, but controller files are written for one
    robot and reused for namespaced copies; a ``/ns/name`` section is the way to give one of them other
    values."""
    if key in (name, "/" + name):
        return True
    fq = f"{namespace}/{name}"
    return _key_pattern(key if key.startswith("/") else "/" + key).fullmatch(fq) is not None


@functools.lru_cache(maxsize=1024)
def _key_pattern(key: str) -> re.Pattern[str]:
    """A section key as the expression rclcpp makes of it (``/*`` -> one ``/token``, its ``/**`` -> any
    number of them); every other character stands for itself (a stray ``*`` matches no valid name)."""
    parts = key.split("/*")
    out = [re.escape(parts[0])]
    for part in parts[1:]:
        if part.startswith("*"):  # "/**": zero or more levels
            out.append(r"(?:/[A-Za-z0-9_]+)*" + re.escape(part[1:]))
        else:
            out.append(r"(?:/[A-Za-z0-9_]+)" + re.escape(part))
    return re.compile("".join(out))


def _flatten(prefix: str, value: Any, out: Params, where: str) -> None:
    """``value`` under ``prefix`` as ROS 2 names parameters: nested mappings become dotted names
    (``gains: {joint1: {p: 10}}`` -> ``gains.joint1.p``), scalars and lists are kept as they are. Anything
    else YAML can hold (a date, a set) is a ParamsError: a ROS parameter has no such type."""
    if isinstance(value, dict):
        for k, v in value.items():
            _flatten(f"{prefix}.{k}" if prefix else str(k), v, out, where)
    elif isinstance(value, (bool, int, float, str)):
        out[prefix] = value
    elif isinstance(value, list):
        out[prefix] = list(value)
    elif value is None:
        return  # "key:" with nothing: rclcpp skips it too
    else:
        raise ParamsError(f"{where}: a parameter has a value of type {type(value).__name__}")


def parse_params(text: str, path: str = "<string>") -> ParamsFile:
    """Parse a parameters file's text.

    Raises:
        ParamsError: YAML that does not parse (with its line), or a layout that is not
            ``node: {ros__parameters: {...}}``.
    """
    try:
        data = safe_load_bounded(text, path, MAX_YAML_NODES)
    except UntrustedInputError as err:
        raise ParamsError(str(err)) from None
    if data is None:
        return ParamsFile(path, {})
    if not isinstance(data, dict):
        raise ParamsError(f"{path}: a parameters file maps node names to 'ros__parameters'")
    nodes: dict[str, Params] = {}

    def walk(prefix: str, section: Any) -> None:
        """One level of the file: ``ros__parameters`` is a node's parameters (merged with any given
        before for the same node, the later value winning); any other key is a namespace level, so
        ``/ns: {node: {ros__parameters: ...}}`` is the node ``/ns/node``."""
        if not isinstance(section, dict):
            # the key is the file's content: not echoed (a refused file must not leak through the log)
            raise ParamsError(f"{path}: every node's section must be a mapping with 'ros__parameters'")
        for key, value in section.items():
            if key == "ros__parameters":
                params: Params = {}
                if value is not None:
                    if not isinstance(value, dict):
                        raise ParamsError(f"{path}: a node's 'ros__parameters' must be a mapping")
                    _flatten("", value, params, path)
                nodes[prefix] = {**nodes.get(prefix, {}), **params}
            else:
                # a namespace level: /ns: {node: {ros__parameters: ...}}
                walk(f"{prefix.rstrip('/')}/{str(key).strip('/')}" if prefix else str(key), value)

    walk("", data)
    return ParamsFile(path, nodes)


def load_params(path: str | Path) -> ParamsFile:
    """Read and parse a parameters file: a regular file of at most :data:`MAX_PARAMS_FILE_BYTES`, whose
    YAML expands to at most :data:`MAX_YAML_NODES` values (never a FIFO or a device). Where the file may
    be read from is the caller's business (:class:`~gazelle.description.ResourceResolver`).

    Raises:
        ParamsError: the file cannot be read or parsed; the message never quotes the file's content.
    """
    p = Path(path)
    try:
        text = read_regular_file(p, MAX_PARAMS_FILE_BYTES, "parameters file")
    except UntrustedInputError as err:
        raise ParamsError(str(err)) from None
    return parse_params(text, str(p))


NODE_NAME_MAX = 255
"""rmw's longest node name (``RMW_NODE_NAME_MAX_NAME_LENGTH``)."""


def valid_controller_name(name: str) -> str | None:
    """Why ``name`` cannot name a controller, or None. ros2_control makes each controller a node of that
    name (controller_manager.cpp, ``load_controller``: the node is created with the controller's name and
    rcl refuses an invalid one), so a name follows rmw's node-name rules: letters, digits and ``_``, not
    starting with a digit, at most 255 characters. The refusal quotes at most 40 characters of it, with
    control characters escaped, so a hostile name can neither flood nor forge a log line."""
    if _NODE_NAME.fullmatch(name) and len(name) <= NODE_NAME_MAX:
        return None
    shown = repr(name[:40]) + (f"... ({len(name)} characters)" if len(name) > 40 else "")
    if not name:
        return "a controller name must not be empty"
    return (
        f"controller name {shown} is not a valid node name (letters, digits and '_', not starting with a digit, "
        f"at most {NODE_NAME_MAX} characters)"
    )


def params_file_paths(value: object) -> list[str]:
    """The file names of a ``params_file`` parameter: a string or a list of strings."""
    if isinstance(value, str):
        return [value] if value else []
    if isinstance(value, (list, tuple)):
        return [str(v) for v in value if v]
    return []
