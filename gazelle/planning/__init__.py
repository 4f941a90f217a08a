"""Motion planning for arms: MoveIt's requests answered with roboplan (pinocchio + coal).

Core layer: no rclpy. ``gazelle.ros._move_group`` serves it with MoveIt's ROS interfaces.
"""

from ._planner import DEFAULT_ACCELERATION as DEFAULT_ACCELERATION
from ._planner import START_BOUNDS_ERROR as START_BOUNDS_ERROR
from ._planner import ArmPlanner as ArmPlanner
from ._planner import PlanningError as PlanningError
from ._planner import SceneObject as SceneObject
from ._planner import Shape as Shape
from ._planner import Trajectory as Trajectory
from ._planner import moveit_joint_limits as moveit_joint_limits
