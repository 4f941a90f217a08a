"""ros2_control in the simulator: the controller manager, the simulated hardware and the standard
controllers, with ros2_control Jazzy's names, parameters and lifecycle (no rclpy here: the ROS
layer serves the manager's services and the controllers' actions)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..._lazy import lazy_attributes

# Imported when first used: ``gazelle spawner`` reads parameter files (``load_params``) without the hardware,
# which brings MuJoCo.
if TYPE_CHECKING:
    from ._controller import ACTIVE as ACTIVE
    from ._controller import FINALIZED as FINALIZED
    from ._controller import INACTIVE as INACTIVE
    from ._controller import UNCONFIGURED as UNCONFIGURED
    from ._controller import Controller as Controller
    from ._controller import GoalState as GoalState
    from ._controller_parameters import ControllerParameters as ControllerParameters
    from ._controller_types import CONTROLLER_TYPES as CONTROLLER_TYPES
    from ._goal import TrajectoryGoal as TrajectoryGoal
    from ._goal import TrajectoryResult as TrajectoryResult
    from ._gripper import GripperActionController as GripperActionController
    from ._gripper import GripperGoal as GripperGoal
    from ._hardware import ControlError as ControlError
    from ._hardware import SimHardware as SimHardware
    from ._manager import BEST_EFFORT as BEST_EFFORT
    from ._manager import STRICT as STRICT
    from ._manager import ControllerManager as ControllerManager
    from ._params import ParamsError as ParamsError
    from ._params import ParamsFile as ParamsFile
    from ._params import load_params as load_params
    from ._params import params_file_paths as params_file_paths
    from ._params import parse_params as parse_params
    from ._params import section_matches as section_matches
    from ._params import valid_controller_name as valid_controller_name
    from ._params import yaml_problem as yaml_problem
    from ._scaled_trajectory import ScaledJointTrajectoryController as ScaledJointTrajectoryController
    from ._tolerances import SegmentTolerances as SegmentTolerances
    from ._tolerances import Tolerance as Tolerance
    from ._tolerances import segment_tolerances as segment_tolerances
    from ._trajectory import JointTrajectoryController as JointTrajectoryController

__getattr__ = lazy_attributes(__name__, __file__)


__all__ = [
    "GoalState",
    "TrajectoryResult",
    "ACTIVE",
    "BEST_EFFORT",
    "CONTROLLER_TYPES",
    "FINALIZED",
    "INACTIVE",
    "STRICT",
    "UNCONFIGURED",
    "ControlError",
    "Controller",
    "ControllerParameters",
    "ControllerManager",
    "GripperActionController",
    "GripperGoal",
    "JointTrajectoryController",
    "ParamsError",
    "ParamsFile",
    "ScaledJointTrajectoryController",
    "SimHardware",
    "Tolerance",
    "TrajectoryGoal",
    "SegmentTolerances",
    "segment_tolerances",
    "load_params",
    "params_file_paths",
    "parse_params",
    "section_matches",
    "valid_controller_name",
    "yaml_problem",
]
