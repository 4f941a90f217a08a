"""State estimation: robot_localization's EKF (``ekf_node``) on numpy, without rclpy.

:class:`StateEstimator` is the node's logic (inputs in stamp order, the periodic cycle, what to publish),
:class:`Ekf` the filter (15 variables: x, y, z, roll, pitch, yaw, their rates, the linear acceleration),
:func:`read_config` the node's parameters. ``gazelle.ros``'s ``ekf_node`` serves it over ROS, with its
transforms from /tf and /tf_static in a :class:`FrameTree`.
"""

from ._config import ConfigError as ConfigError
from ._config import EkfConfig as EkfConfig
from ._config import read_config as read_config
from ._ekf import Ekf as Ekf
from ._ekf import motion_model as motion_model
from ._estimator import MAX_AHEAD_NS as MAX_AHEAD_NS
from ._estimator import MAX_QUEUED as MAX_QUEUED
from ._estimator import StateEstimator as StateEstimator
from ._frames import MAX_FRAMES as MAX_FRAMES
from ._frames import FrameTree as FrameTree
from ._measurement import STATE_NAMES as STATE_NAMES
from ._measurement import STATE_SIZE as STATE_SIZE
from ._measurement import Measurement as Measurement
from ._readings import FilterOutput as FilterOutput
from ._readings import ImuReading as ImuReading
from ._readings import PoseReading as PoseReading
from ._readings import TwistReading as TwistReading
from ._rigid import Rigid as Rigid
from ._rigid import quaternion_from_rotation as quaternion_from_rotation
from ._rigid import quaternion_from_rpy as quaternion_from_rpy
from ._rigid import rpy_from_rotation as rpy_from_rotation
from ._sensor_config import SensorConfig as SensorConfig
