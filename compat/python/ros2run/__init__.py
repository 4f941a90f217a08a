"""ros2run's Python module for code that imports it (``from ros2run.api import get_executable_path``): gazelle's
own implementation of ros2cli Jazzy's ros2run/api semantics (the real package is not on PyPI; gazelle's
``ros2 run`` is gazelle/cli/ros2cli/_run.py). A sourced ROS installation's ros2run comes first on the path."""
