"""gazelle's implementation of ROS 2's ``launch_ros`` (Node, namespaces, parameters, FindPackageShare)
for environments without a ROS installation."""

from . import actions, parameter_descriptions, substitutions

__all__ = ["actions", "parameter_descriptions", "substitutions"]
