"""gazebo_ros's Python module for launch files that import it (``from gazebo_ros import GazeboRosPaths``)."""

from .gazebo_ros_paths import GazeboRosPaths

__all__ = ["GazeboRosPaths"]
