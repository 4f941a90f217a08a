"""``gazelle move_group``'s command-line configuration: a MoveIt config folder read as the ROS parameters
MoveItConfigsBuilder would give move_group (joint_limits.yaml, kinematics.yaml, moveit_controllers.yaml,
ompl_planning.yaml), and the SRDF checked before the node starts."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from rclpy.parameter import Parameter


def check_srdf(text: str, source: str) -> None:
    """A malformed SRDF named on the command line is an error naming its file and line (exit 2), not a
    move_group that runs unable to plan.

    Raises:
        ValueError: the SRDF does not parse.
    """
    from ..description import ModelLoadError, load_string

    try:
        load_string(text, format="srdf", source=source)
    except ModelLoadError as err:
        raise ValueError(str(err)) from None


PIPELINE_PARAMETERS = frozenset(
    {"ompl", "planning_pipelines", "planning_plugin", "planning_plugins", "request_adapters", "response_adapters"}
)
"""The first name parts of MoveIt's planning pipeline parameters (ompl_planning.yaml under ``ompl.``, and
the pipeline's own): not used by gazelle's planner, and said so at start."""


_PARAMETER_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*")


def _flat(prefix: str, data: object) -> list[Parameter]:
    """A YAML mapping as ROS parameters named ``prefix.key.subkey`` (MoveItConfigsBuilder's layout); values
    a ROS parameter cannot hold (mixed lists, nulls) are left out."""
    out: list[Parameter] = []
    for key, value in data.items() if isinstance(data, dict) else ():
        name = f"{prefix}.{key}"
        if not _PARAMETER_NAME.fullmatch(name):
            continue  # a key no ROS parameter can be named after
        if isinstance(value, dict):
            out.extend(_flat(name, value))
        elif isinstance(value, (bool, int, float, str)):
            out.append(Parameter(name, value=value))
        elif isinstance(value, list) and value and len({type(v) for v in value}) == 1:
            if isinstance(value[0], (bool, int, float, str)):
                out.append(Parameter(name, value=value))
    return out


def config_parameters(folder: Path) -> list[Parameter]:
    """joint_limits.yaml as robot_description_planning.*, kinematics.yaml as robot_description_kinematics.*
    (MoveIt's parameter names), moveit_controllers.yaml's controllers, and ompl_planning.yaml as ompl.*
    (so that move_group says it does not use them)."""
    import yaml

    from ..systems.ros2_control import yaml_problem

    def load(path: Path) -> Any:
        """A YAML file of the MoveIt config; a syntax error is a ValueError naming file:line (for the command line),
        never a traceback."""
        try:
            return yaml.safe_load(path.read_text(encoding="utf-8")) or {}
        except yaml.YAMLError as err:  # a file:line error for the command line, never a traceback
            raise ValueError(yaml_problem(err, str(path))) from None

    if not folder.is_dir():
        raise ValueError(f"{folder}: no such folder")
    out: list[Parameter] = []
    kinematics = folder / "kinematics.yaml"
    if kinematics.is_file():
        data = load(kinematics)
        for group, spec in data.items():
            for key, value in (spec or {}).items() if isinstance(spec, dict) else ():
                if isinstance(value, (bool, int, float, str)):
                    out.append(Parameter(f"robot_description_kinematics.{group}.{key}", value=value))
    limits = folder / "joint_limits.yaml"
    if limits.is_file():
        data = load(limits)
        for joint, spec in (data.get("joint_limits") or {}).items():
            for key, value in (spec or {}).items():
                out.append(Parameter(f"robot_description_planning.joint_limits.{joint}.{key}", value=value))
    ompl = folder / "ompl_planning.yaml"
    if ompl.is_file():
        out.extend(_flat("ompl", load(ompl)))
    controllers = folder / "moveit_controllers.yaml"
    if controllers.is_file():
        data = load(controllers)
        mscm = data.get("moveit_simple_controller_manager") or {}
        names = list(mscm.get("controller_names") or [])
        out.append(Parameter("moveit_simple_controller_manager.controller_names", value=names))
        for name in names:
            spec = mscm.get(name) or {}
            out.append(
                Parameter(f"moveit_simple_controller_manager.{name}.action_ns", value=str(spec.get("action_ns", "")))
            )
            out.append(
                Parameter(f"moveit_simple_controller_manager.{name}.joints", value=list(spec.get("joints") or []))
            )
            if isinstance(spec.get("default"), bool):
                out.append(Parameter(f"moveit_simple_controller_manager.{name}.default", value=spec["default"]))
    return out
