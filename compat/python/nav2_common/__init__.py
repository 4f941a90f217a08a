"""nav2_common's Python module for launch files that import it (``from nav2_common.launch import RewrittenYaml``):
gazelle's own implementation of navigation2 Jazzy's nav2_common/launch semantics (the real package is not on
PyPI). A sourced ROS installation's nav2_common comes first on the path."""
