"""gazelle's implementation of ROS 2's ``launch_ros`` (Node, namespaces, parameters, FindPackageShare)
for environments without a ROS installation.

Importing it exposes its tags and substitutions to XML and YAML launch files (:mod:`launch_ros.frontend`); a
process that never imports it gets them through the ``launch.frontend.launch_extension`` entry point
``launch_ros = launch_ros`` (pyproject.toml), as Jazzy's launch_ros declares in its setup.py."""

from . import actions, descriptions, frontend, parameter_descriptions, substitutions

__all__ = ["actions", "descriptions", "frontend", "parameter_descriptions", "substitutions"]
