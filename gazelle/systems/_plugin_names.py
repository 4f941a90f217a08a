"""Plugin names that clients need without the systems themselves (which bring MuJoCo)."""

RSP_PLUGIN = "gazelle_robot_state_publisher"
"""File name of the built-in robot_state_publisher, to configure or disable it in a model file."""
