"""gazelle's implementation of ROS 2's ``launch_ros`` (Node, namespaces, parameters, FindPackageShare)
for environments without a ROS installation."""

from . import actions, descriptions, parameter_descriptions, substitutions

__all__ = ["actions", "descriptions", "parameter_descriptions", "substitutions"]
