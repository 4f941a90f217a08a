"""``MoveItConfigsBuilder``: a MoveIt configuration package's parameters, found by MoveIt Setup Assistant's layout.

Written from the behaviour of MoveIt 2 Jazzy's ``moveit_configs_utils/moveit_configs_builder.py``. The package
``<robot>_moveit_config`` (or ``package_name``) is found in the ament index, and in it:

* the URDF: ``config/<robot>.urdf.xacro`` when it exists (what Setup Assistant writes, with ros2_control), else
  the one ``.setup_assistant`` names (``urdf``/``URDF``: ``package`` and ``relative_path``, ``xacro_args``), else
  ``config/<robot>.urdf``; expanded by xacro;
* the SRDF: ``.setup_assistant``'s ``srdf``/``SRDF`` ``relative_path``, else ``config/<robot>.srdf``;
* ``config/kinematics.yaml`` (``robot_description_kinematics``), ``config/joint_limits.yaml``
  (``robot_description_planning``), ``config/pilz_cartesian_limits.yaml`` (added to ``robot_description_planning``
  when the Pilz pipeline is loaded), ``config/sensors_3d.yaml``, ``config/moveit_cpp.yaml`` (on request);
* the planning pipelines: every ``config/<name>_planning.yaml``, plus moveit_configs_utils' own defaults
  (``default_configs/``: ompl, chomp, pilz_industrial_motion_planner, stomp) unless ``load_all`` is false;
  ``ompl`` gets the default ``planner_configs`` when its file has none;
* the controllers: ``config/<name>_controllers.yaml`` (one file; of several, ``moveit``, ``moveit2`` or the
  robot's name), under ``trajectory_execution`` with ``moveit_manage_controllers``.

Every method returns the builder, so calls chain; :meth:`MoveItConfigsBuilder.to_moveit_configs` loads what was not
asked for and returns a :class:`MoveItConfigs`, whose :meth:`MoveItConfigs.to_dict` is move_group's parameters.
"""

from __future__ import annotations

import logging
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ament_index_python.packages import get_package_share_directory
from launch_param_builder import ParameterBuilder, ParameterBuilderFileNotFoundError, load_xacro, load_yaml

from launch_ros.parameter_descriptions import ParameterValue

from .substitutions import Xacro

_log = logging.getLogger("moveit_configs_utils")
_CONFIG = Path("config")
_DEFAULT_PIPELINES = "default_configs"
_CONTROLLER_FILE_PREFERENCE = ("moveit", "moveit2")
"""Of several ``*_controllers.yaml``, the names tried first (then the robot's own)."""


def _default_configs() -> Path:
    """moveit_configs_utils' ``default_configs`` folder (its share folder, as installed)."""
    return Path(get_package_share_directory("moveit_configs_utils")) / _DEFAULT_PIPELINES


def get_pattern_matches(folder: Path, pattern: re.Pattern[str]) -> list[Any]:
    """The files directly in ``folder`` whose name ``pattern`` finds, by name: the first group of each match when
    the pattern has groups, else the file's path (an empty list when ``folder`` does not exist)."""
    if not folder.is_dir():
        return []
    out: list[Any] = []
    for child in sorted(folder.iterdir()):
        m = pattern.search(child.name) if child.is_file() else None
        if m:
            out.append(m.group(1) if m.groups() else child)
    return out


@dataclass
class MoveItConfigs:
    """The parameters of one MoveIt configuration, each a dict of parameters (names to values)."""

    package_path: Path | None = None
    robot_description: dict[str, Any] = field(default_factory=dict)
    robot_description_semantic: dict[str, Any] = field(default_factory=dict)
    robot_description_kinematics: dict[str, Any] = field(default_factory=dict)
    planning_pipelines: dict[str, Any] = field(default_factory=dict)
    trajectory_execution: dict[str, Any] = field(default_factory=dict)
    planning_scene_monitor: dict[str, Any] = field(default_factory=dict)
    sensors_3d: dict[str, Any] = field(default_factory=dict)
    move_group_capabilities: dict[str, Any] = field(
        default_factory=lambda: {"capabilities": "", "disable_capabilities": ""}
    )
    joint_limits: dict[str, Any] = field(default_factory=dict)
    moveit_cpp: dict[str, Any] = field(default_factory=dict)
    pilz_cartesian_limits: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """Every parameter in one dict (what move_group is given): the descriptions, kinematics, pipelines,
        trajectory execution, planning scene monitor, 3D sensors, joint limits and MoveItCpp's, with the Pilz
        cartesian limits added to ``robot_description_planning``."""
        out: dict[str, Any] = {}
        for part in (
            self.robot_description,
            self.robot_description_semantic,
            self.robot_description_kinematics,
            self.planning_pipelines,
            self.trajectory_execution,
            self.planning_scene_monitor,
            self.sensors_3d,
            self.joint_limits,
            self.moveit_cpp,
        ):
            out.update(part)
        for key, limits in self.pilz_cartesian_limits.items():
            merged = dict(out.get(key) or {})
            merged.update(limits or {})
            out[key] = merged
        return out


class MoveItConfigsBuilder(ParameterBuilder):
    """See the module docstring."""

    def __init__(
        self, robot_name: str, robot_description: str = "robot_description", package_name: str | None = None
    ) -> None:
        """The configuration of ``robot_name`` in ``package_name`` (default ``<robot_name>_moveit_config``);
        ``robot_description`` is the parameter the URDF goes to and the prefix of ``_semantic``,
        ``_kinematics`` and ``_planning``."""
        super().__init__(package_name or f"{robot_name}_moveit_config")
        self._configs = MoveItConfigs(package_path=self._package_path)
        self._robot_name = robot_name
        self._prefix = robot_description
        self._urdf: Path | None = None
        self._urdf_args: dict[str, str] | None = None
        self._srdf: Path | None = None
        own = _CONFIG / f"{robot_name}.urdf.xacro"
        if (self._package_path / own).exists():
            self._urdf = self._package_path / own
        self._read_setup_assistant(self._package_path / ".setup_assistant")
        if self._urdf is None:
            _log.warning(f"Cannot infer URDF from `{self._package_path}`. -- using config/{robot_name}.urdf")
            self._urdf = self._package_path / _CONFIG / f"{robot_name}.urdf"
        if self._srdf is None:
            _log.warning(f"Cannot infer SRDF from `{self._package_path}`. -- using config/{robot_name}.srdf")
            self._srdf = _CONFIG / f"{robot_name}.srdf"

    def _read_setup_assistant(self, path: Path) -> None:
        """What ``.setup_assistant`` says of the URDF (its package and path, unless the config package has its own
        ``config/<robot>.urdf.xacro``; its xacro arguments) and of the SRDF (its path in the package)."""
        if not path.exists():
            return
        data = load_yaml(path) or {}
        config = data.get("moveit_setup_assistant_config") or {}
        urdf = config.get("urdf", config.get("URDF"))
        if urdf:
            if self._urdf is None:
                self._urdf = Path(get_package_share_directory(urdf["package"])) / urdf["relative_path"]
            if urdf.get("xacro_args"):
                self._urdf_args = dict(arg.split(":=", 1) for arg in str(urdf["xacro_args"]).split(" ") if arg)
        srdf = config.get("srdf", config.get("SRDF"))
        if srdf:
            self._srdf = Path(srdf["relative_path"])

    def _in_package(self, file_path: Any, default: Path) -> Path:
        """``file_path`` (relative to the package, or absolute), or ``default`` when None."""
        return self._package_path / (default if file_path is None else file_path)

    @staticmethod
    def _plain(mappings: dict[Any, Any] | None) -> bool:
        """Whether ``mappings`` are text only (then the file is expanded now; else when the launch runs)."""
        return mappings is None or all(isinstance(k, str) and isinstance(v, str) for k, v in mappings.items())

    def robot_description(self, file_path: Any = None, mappings: dict[Any, Any] | None = None) -> MoveItConfigsBuilder:
        """The URDF (see the module docstring; ``file_path`` relative to the package) expanded by xacro with
        ``mappings`` (else ``.setup_assistant``'s xacro arguments). A file that does not exist is a warning: move_group
        then reads the robot from the ``/robot_description`` topic, as upstream's does."""
        assert self._urdf is not None
        path = self._urdf if file_path is None else self._package_path / file_path
        if self._plain(mappings):
            try:
                text = load_xacro(path, mappings=mappings or self._urdf_args)
            except ParameterBuilderFileNotFoundError as err:
                _log.warning(str(err).strip("'\""))
                _log.warning("The robot description will be loaded from /robot_description topic ")
            else:
                self._configs.robot_description = {self._prefix: text}
        else:
            self._configs.robot_description = {
                self._prefix: ParameterValue(Xacro(str(path), mappings=mappings), value_type=str)
            }
        return self

    def robot_description_semantic(
        self, file_path: Any = None, mappings: dict[Any, Any] | None = None
    ) -> MoveItConfigsBuilder:
        """The SRDF (a plain SRDF or an SRDF xacro), expanded with ``mappings``."""
        assert self._srdf is not None
        path = self._in_package(file_path, self._srdf)
        key = f"{self._prefix}_semantic"
        if self._plain(mappings):
            self._configs.robot_description_semantic = {key: load_xacro(path, mappings=mappings)}
        else:
            self._configs.robot_description_semantic = {
                key: ParameterValue(Xacro(str(path), mappings=mappings), value_type=str)
            }
        return self

    def robot_description_kinematics(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """``config/kinematics.yaml``: the IK solver of each group."""
        data = load_yaml(self._in_package(file_path, _CONFIG / "kinematics.yaml"))
        self._configs.robot_description_kinematics = {f"{self._prefix}_kinematics": data}
        return self

    def joint_limits(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """``config/joint_limits.yaml``: the planner's velocity and acceleration limits over the URDF's."""
        data = load_yaml(self._in_package(file_path, _CONFIG / "joint_limits.yaml"))
        self._configs.joint_limits = {f"{self._prefix}_planning": data}
        return self

    def moveit_cpp(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """``config/moveit_cpp.yaml``: MoveItCpp's parameters (never loaded unless asked for, as upstream)."""
        self._configs.moveit_cpp = load_yaml(self._in_package(file_path, _CONFIG / "moveit_cpp.yaml"))
        return self

    def trajectory_execution(
        self, file_path: Any = None, moveit_manage_controllers: bool = True
    ) -> MoveItConfigsBuilder:
        """The controllers file (see the module docstring) and ``moveit_manage_controllers``.

        Raises:
            RuntimeError: several ``*_controllers.yaml`` and none of them the preferred names (listed).
        """
        self._configs.trajectory_execution = {"moveit_manage_controllers": moveit_manage_controllers}
        if file_path is None:
            folder = self._package_path / _CONFIG
            names = get_pattern_matches(folder, re.compile(r"^(.*)_controllers\.yaml$"))
            if not names:
                _log.warning(
                    f"trajectory_execution: `Parameter file_path is undefined and no matches for "
                    f"{folder}/*_controllers.yaml"
                )
                return self
            chosen = names[0] if len(names) == 1 else None
            for name in (*_CONTROLLER_FILE_PREFERENCE, self._robot_name):
                if chosen is None and name in names:
                    chosen = name
            if chosen is None:
                options = "\n - ".join(f"{n}_controllers.yaml" for n in names)
                raise RuntimeError(
                    f"trajectory_execution: Unable to guess which parameter file to load. Options:\n - {options}"
                )
            path = folder / f"{chosen}_controllers.yaml"
        else:
            path = self._package_path / file_path
        self._configs.trajectory_execution.update(load_yaml(path) or {})
        return self

    def planning_scene_monitor(
        self,
        publish_planning_scene: bool = True,
        publish_geometry_updates: bool = True,
        publish_state_updates: bool = True,
        publish_transforms_updates: bool = True,
        publish_robot_description: bool = False,
        publish_robot_description_semantic: bool = False,
    ) -> MoveItConfigsBuilder:
        """What the planning scene monitor publishes (its parameters at the node's top level, as upstream)."""
        self._configs.planning_scene_monitor = {
            "publish_planning_scene": publish_planning_scene,
            "publish_geometry_updates": publish_geometry_updates,
            "publish_state_updates": publish_state_updates,
            "publish_transforms_updates": publish_transforms_updates,
            "publish_robot_description": publish_robot_description,
            "publish_robot_description_semantic": publish_robot_description_semantic,
        }
        return self

    def sensors_3d(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """``config/sensors_3d.yaml`` when it exists and lists a sensor."""
        path = self._in_package(file_path, _CONFIG / "sensors_3d.yaml")
        if path.exists():
            data = load_yaml(path) or {}
            sensors = data.get("sensors") or []
            if sensors and sensors[0]:
                self._configs.sensors_3d = data
        return self

    def planning_pipelines(
        self, default_planning_pipeline: str | None = None, pipelines: list[str] | None = None, load_all: bool = True
    ) -> MoveItConfigsBuilder:
        """The planning pipelines (see the module docstring): ``pipelines`` by name, else every
        ``config/*_planning.yaml`` (and, with ``load_all``, the defaults'); the default is ``ompl`` when loaded,
        else the first.

        Raises:
            RuntimeError: no pipeline at all, or a ``default_planning_pipeline`` that is not one of them.
        """
        config = self._package_path / _CONFIG
        defaults = _default_configs()
        pattern = re.compile(r"^(.*)_planning\.yaml$")
        if pipelines is None:
            pipelines = get_pattern_matches(config, pattern)
            if load_all:
                pipelines += [p for p in get_pattern_matches(defaults, pattern) if p not in pipelines]
        pipelines = list(pipelines)
        if not pipelines:
            raise RuntimeError(f"planning_pipelines: no pipeline given and no {config}/*_planning.yaml")
        if not default_planning_pipeline:
            default_planning_pipeline = "ompl" if "ompl" in pipelines else pipelines[0]
        if default_planning_pipeline not in pipelines:
            raise RuntimeError(
                f"default_planning_pipeline: `{default_planning_pipeline}` doesn't name any of the input pipelines "
                f"`{','.join(pipelines)}`"
            )
        out: dict[str, Any] = {"planning_pipelines": pipelines, "default_planning_pipeline": default_planning_pipeline}
        for name in pipelines:
            own = config / f"{name}_planning.yaml"
            out[name] = load_yaml(own if own.exists() else defaults / f"{name}_planning.yaml") or {}
        if "ompl" in out and "planner_configs" not in out["ompl"]:
            out["ompl"].update(load_yaml(defaults / "ompl_defaults.yaml") or {})
        self._configs.planning_pipelines = out
        return self

    def pilz_cartesian_limits(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """``config/pilz_cartesian_limits.yaml`` (the old name ``cartesian_limits.yaml`` is warned about)."""
        if (self._package_path / _CONFIG / "cartesian_limits.yaml").exists():
            _log.warning("cartesian_limits.yaml is deprecated, please rename to pilz_cartesian_limits.yaml")
        data = load_yaml(self._in_package(file_path, _CONFIG / "pilz_cartesian_limits.yaml"))
        self._configs.pilz_cartesian_limits = {f"{self._prefix}_planning": data}
        return self

    def to_moveit_configs(self) -> MoveItConfigs:
        """Everything not loaded yet, loaded from the package's defaults (MoveItCpp's parameters excepted; the Pilz
        cartesian limits when the Pilz pipeline is loaded), as a :class:`MoveItConfigs`."""
        c = self._configs
        for loaded, load in (
            (c.robot_description, self.robot_description),
            (c.robot_description_semantic, self.robot_description_semantic),
            (c.robot_description_kinematics, self.robot_description_kinematics),
            (c.planning_pipelines, self.planning_pipelines),
            (c.trajectory_execution, self.trajectory_execution),
            (c.planning_scene_monitor, self.planning_scene_monitor),
            (c.sensors_3d, self.sensors_3d),
            (c.joint_limits, self.joint_limits),
        ):
            if not loaded:
                load()
        if "pilz_industrial_motion_planner" in c.planning_pipelines and not c.pilz_cartesian_limits:
            self.pilz_cartesian_limits()
        return c

    def to_dict(self, include_moveit_configs: bool = True) -> dict[str, Any]:
        """The builder's own parameters (:class:`ParameterBuilder`'s), with every MoveIt parameter unless
        ``include_moveit_configs`` is false."""
        parameters = self._parameters
        if include_moveit_configs:
            parameters.update(self.to_moveit_configs().to_dict())
        return parameters
