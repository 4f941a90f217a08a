"""Motion planning for arms: MoveIt's requests answered with roboplan (pinocchio + coal).

Core layer: no rclpy. ``gazelle.ros._move_group`` serves it with MoveIt's ROS interfaces.
"""

from . import _servo as servo  # noqa: F401  (MoveIt Servo's status codes and command types, by name)
from ._collision_matrix import CollisionMatrix as CollisionMatrix
from ._group_urdf import GroupUrdfError as GroupUrdfError
from ._group_urdf import group_urdf as group_urdf
from ._names import NAME_CHARS as NAME_CHARS
from ._names import quoted as quoted
from ._path_constraints import PathConstraints as PathConstraints
from ._planner import CARTESIAN_TIMEOUT_SEC as CARTESIAN_TIMEOUT_SEC
from ._planner import MAX_CARTESIAN_STEPS as MAX_CARTESIAN_STEPS
from ._planner import MAX_IK_SEC as MAX_IK_SEC
from ._planner import MAX_PLANNING_SEC as MAX_PLANNING_SEC
from ._planner import MAX_TRAJECTORY_POINTS as MAX_TRAJECTORY_POINTS
from ._planner import PLANNERS as PLANNERS
from ._planner import ArmPlanner as ArmPlanner
from ._planner import Trajectory as Trajectory
from ._pool import PlannerPool as PlannerPool
from ._robot_scene import DEFAULT_ACCELERATION as DEFAULT_ACCELERATION
from ._robot_scene import START_BOUNDS_ERROR as START_BOUNDS_ERROR
from ._robot_scene import PlanningError as PlanningError
from ._robot_scene import RobotScene as RobotScene
from ._robot_scene import SceneObject as SceneObject
from ._robot_scene import Shape as Shape
from ._robot_scene import moveit_joint_limits as moveit_joint_limits
from ._servo import ServoCore as ServoCore
from ._servo import ServoKinematics as ServoKinematics
from ._servo import ServoSettings as ServoSettings
