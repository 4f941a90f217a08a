"""ros2pkg's Python module (``from ros2pkg.api import get_executable_paths, PackageNotFound``), which ros2run.api
builds on: gazelle's own implementation of ros2cli Jazzy's ros2pkg/api semantics. A sourced ROS installation's
ros2pkg comes first on the path."""
