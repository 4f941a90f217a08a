"""Systems (Gazebo-style plugins) with configure/reset/pre_update/update/post_update phases.

A system is created for each supported ``<plugin>`` of an entity (see :func:`create_system`),
configures while its entity is staged in the physics world, and then runs its phases around the
physics steps, at the rate it declares (:meth:`System.next_update`). Systems talk to the world
through the typed handles of :mod:`gazelle.physics` and to ROS through the :class:`Bus`; they
never import MuJoCo, the runtime or rclpy.

Where things are (docs/extending.md has the checklists):

* ``_base.py``: :class:`System` and its phases, :class:`SystemContext` (what a system may touch while it
  configures), :class:`RateGate`; the names a plugin answers to are declared on the class
  (``plugin_files``, ``gz_plugin``).
* ``_registration.py``: ``add_plugin(Cls)``, the one call at the bottom of a plugin's or sensor's own module
  that registers it (gz-sim's ``GZ_ADD_PLUGIN``); the registry imports every module of this package to find them.
* ``_registry.py``: which system runs a ``<plugin>`` or a ``<sensor>`` (derived from the registered classes'
  declarations), and the warning for each one that does not run.
* ``_bus.py``: the topics between systems and the ROS bridge (endpoints, QoS, the message types);
  ``_payloads.py``: the message payloads (plain dataclasses; ``gazelle.ros`` converts them).
* ``_plugin_config.py``: reading a ``<plugin>`` block (texts, numbers, flags, the ``<ros>`` block) and a
  gazebo_ros plugin's node.
* One module per model or world plugin: ``diff_drive.py`` (gazebo_ros's), ``gz_diff_drive.py`` (gz-sim's),
  ``joint_controllers.py`` (gz-sim's joint position and velocity controllers, gazelle's per-joint command
  topics), ``pose_publisher.py`` (gazebo_ros's P3D), ``robot_state.py`` (robot_state_publisher and the
  joint state publishers).
* ``sensors/``: one module per sensor kind; ``ros2_control/``: the controller manager, the simulated
  hardware and one module per family of controllers.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_attributes

# Imported when first used: the actuation and the systems bring MuJoCo (through gazelle.physics), which a
# client such as ``gazelle spawn`` never needs.
if TYPE_CHECKING:
    from ._actuation import PidGains as PidGains
    from ._actuation import PositionServo as PositionServo
    from ._actuation import VelocityServo as VelocityServo
    from ._actuation import add_position_servo as add_position_servo
    from ._actuation import add_velocity_servo as add_velocity_servo
    from ._actuation import add_wheel_servo as add_wheel_servo
    from ._base import PHYSICS as PHYSICS
    from ._base import PRE_PHYSICS as PRE_PHYSICS
    from ._base import RateGate as RateGate
    from ._base import System as System
    from ._base import SystemContext as SystemContext
    from ._base import SystemManager as SystemManager
    from ._base import UpdateInfo as UpdateInfo
    from ._bus import PAYLOADS as PAYLOADS
    from ._bus import Bus as Bus
    from ._bus import DeclaredMessage as DeclaredMessage
    from ._bus import Endpoint as Endpoint
    from ._bus import MessageKind as MessageKind
    from ._bus import MsgType as MsgType
    from ._bus import ParamValue as ParamValue
    from ._bus import PluginNode as PluginNode
    from ._bus import Qos as Qos
    from ._bus import resolve_topic as resolve_topic
    from ._frames import robot_state_config as robot_state_config
    from ._payloads import Altimeter as Altimeter
    from ._payloads import CameraInfo as CameraInfo
    from ._payloads import CloudLayout as CloudLayout
    from ._payloads import ContactPair as ContactPair
    from ._payloads import Contacts as Contacts
    from ._payloads import DisplayTrajectory as DisplayTrajectory
    from ._payloads import DynamicJointState as DynamicJointState
    from ._payloads import Float64 as Float64
    from ._payloads import Float64Array as Float64Array
    from ._payloads import Image as Image
    from ._payloads import Imu as Imu
    from ._payloads import InterfaceValue as InterfaceValue
    from ._payloads import JointStates as JointStates
    from ._payloads import JointStatesBlock as JointStatesBlock
    from ._payloads import JointTrajectory as JointTrajectory
    from ._payloads import LaserScan as LaserScan
    from ._payloads import MagneticField as MagneticField
    from ._payloads import NavSatFix as NavSatFix
    from ._payloads import Odometry as Odometry
    from ._payloads import PayloadBlock as PayloadBlock
    from ._payloads import PointCloud as PointCloud
    from ._payloads import Range as Range
    from ._payloads import Text as Text
    from ._payloads import TrajectoryControllerState as TrajectoryControllerState
    from ._payloads import TrajectoryPoint as TrajectoryPoint
    from ._payloads import Transform as Transform
    from ._payloads import TransformBatch as TransformBatch
    from ._payloads import Twist as Twist
    from ._payloads import TwistStamped as TwistStamped
    from ._payloads import Vector3Stamped as Vector3Stamped
    from ._payloads import WrenchStamped as WrenchStamped
    from ._plugin_config import plugin_node as plugin_node
    from ._plugin_config import plugin_node_name as plugin_node_name
    from ._plugin_config import unread_parameters as unread_parameters
    from ._plugin_names import RSP_PLUGIN as RSP_PLUGIN
    from ._registry import SensorPlan as SensorPlan
    from ._registry import audit_model as audit_model
    from ._registry import audit_world as audit_world
    from ._registry import create_system as create_system
    from ._registry import plan_sensors as plan_sensors
    from ._registry import plugin_factories as plugin_factories
    from ._registry import supported_plugins as supported_plugins
    from .robot_state import JointStatePublisher as JointStatePublisher
    from .robot_state import RobotStatePublisher as RobotStatePublisher

__getattr__ = lazy_attributes(__name__, __file__)


__all__ = [
    "Altimeter",
    "MagneticField",
    "DynamicJointState",
    "DisplayTrajectory",
    "Float64Array",
    "JointTrajectory",
    "TrajectoryControllerState",
    "TrajectoryPoint",
    "TwistStamped",
    "Bus",
    "PAYLOADS",
    "CameraInfo",
    "ContactPair",
    "Contacts",
    "Endpoint",
    "Float64",
    "Image",
    "Imu",
    "InterfaceValue",
    "JointStates",
    "JointStatesBlock",
    "LaserScan",
    "DeclaredMessage",
    "MessageKind",
    "MsgType",
    "NavSatFix",
    "Odometry",
    "ParamValue",
    "PayloadBlock",
    "PluginNode",
    "PHYSICS",
    "PRE_PHYSICS",
    "PidGains",
    "CloudLayout",
    "PointCloud",
    "PositionServo",
    "Qos",
    "RSP_PLUGIN",
    "Range",
    "RateGate",
    "JointStatePublisher",
    "RobotStatePublisher",
    "System",
    "SystemContext",
    "SystemManager",
    "Text",
    "Transform",
    "TransformBatch",
    "Twist",
    "Vector3Stamped",
    "WrenchStamped",
    "UpdateInfo",
    "VelocityServo",
    "add_position_servo",
    "add_velocity_servo",
    "add_wheel_servo",
    "SensorPlan",
    "audit_model",
    "plan_sensors",
    "plugin_factories",
    "plugin_node",
    "plugin_node_name",
    "unread_parameters",
    "audit_world",
    "create_system",
    "resolve_topic",
    "robot_state_config",
    "supported_plugins",
]
