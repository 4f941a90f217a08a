"""Sensors, one module per kind, published as gazebo_ros's plugins and gz-sim's sensors publish them:
lidars and rays (:mod:`.lidar`), IMUs (:mod:`.imu`), magnetometers, altimeters, cameras and depth cameras,
contact sensors, GPS and force-torque. What they share (noise, rates, topic naming, the base class) is in
:mod:`._common`. A sensor kind is one class that declares its SDF types, its gazebo_ros plugins and its gz-sim
world system (:class:`SensorClass`) and registers itself at the bottom of its module (``add_plugin(Lidar)``); the
plugin registry is derived from those declarations and finds the module by itself (nothing to add here unless
a name is to be public).

Each sensor is a :class:`System` made for one ``<sensor>`` of a link (or, for ROS 1's
``libgazebo_ros_imu.so``, for a model plugin naming a ``<bodyName>``):

* **gazebo_ros** (Gazebo Classic): a ``<plugin>`` inside the ``<sensor>`` publishes it on ``~/out``,
  which is ``/<ns>/<plugin name>/out`` unless ``<ros><remapping>~/out:=scan</remapping>`` (or Dashing's
  ``<argument>~/out:=scan</argument>``) renames it,
  in ``<frame_name>`` (else the sensor's link). ``libgazebo_ros_ray_sensor.so`` takes ``<output_type>``
  (``sensor_msgs/PointCloud2`` by default, ``LaserScan`` or ``Range``), ``<radiation_type>`` and
  ``<min_intensity>``; ``libgazebo_ros_imu_sensor.so`` takes ``<initial_orientation_as_reference>``.
  ROS 1's names (``libgazebo_ros_laser.so`` with ``<topicName>``/``<frameName>``, the
  ``libgazebo_ros_imu.so`` model plugin) are read too.
* **gz-sim**: with the world's ``gz-sim-sensors-system`` (lidars) or ``gz-sim-imu-system`` (IMUs), a
  sensor publishes on its ``<topic>`` (relative names under the entity's namespace), else on
  ``/world/<w>/model/<m>/link/<l>/sensor/<s>/scan|imu``, in ``<frame_id>``/``<gz_frame_id>``, else the
  scoped ``<model>::<link>::<sensor>``; the ROS topic has the gz topic's name, as ros_gz_bridge maps it.

Measurements are taken at the sim time they are stamped with, at the sensor's ``<update_rate>`` (0:
every step) through the runtime's rate gate, and only while someone listens. Rays are cast in one
``mj_multiRay`` call against collision geoms, excluding the sensor's own link; readings beyond the
maximum range are +inf and nearer than the minimum -inf (REP 117). The IMU reads its link's proper
acceleration (+g upwards at rest) and angular velocity in its own frame. Gaussian noise (``mean``,
``stddev``; ``bias_mean``/``bias_stddev`` drawn once, with a random sign, as gz-sensors does) is
applied as configured; any other noise type is warned about with its file:line and left out.
"""

from ._common import OUTPUT_MESSAGES, Noise, SensorClass, parse_noise
from .air_pressure import AirPressureSensor as AirPressureSensor
from .altimeter import AltimeterSensor
from .camera import CAMERA_TYPES, DEPTH_TYPES, MAX_IMAGE_SIDE, Camera
from .contact import ContactSensor
from .force_torque import ForceTorqueSensor
from .gps import GpsSensor
from .imu import ImuSensor
from .lidar import LIDAR_TYPES, MAX_RAYS, Lidar, parse_lidar
from .magnetometer import Magnetometer

__all__ = [
    "CAMERA_TYPES",
    "DEPTH_TYPES",
    "LIDAR_TYPES",
    "MAX_IMAGE_SIDE",
    "MAX_RAYS",
    "OUTPUT_MESSAGES",
    "AltimeterSensor",
    "Camera",
    "ContactSensor",
    "ForceTorqueSensor",
    "GpsSensor",
    "ImuSensor",
    "Lidar",
    "Magnetometer",
    "Noise",
    "SensorClass",
    "parse_lidar",
    "parse_noise",
]
