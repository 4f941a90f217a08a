"""Gazebo Classic's named material colours, shared by the URDF and SDF readers."""

from __future__ import annotations

GAZEBO_COLORS: dict[str, tuple[float, float, float, float]] = {
    "Gazebo/Black": (0.0, 0.0, 0.0, 1.0),
    "Gazebo/FlatBlack": (0.1, 0.1, 0.1, 1.0),
    "Gazebo/DarkGrey": (0.175, 0.175, 0.175, 1.0),
    "Gazebo/Grey": (0.7, 0.7, 0.7, 1.0),
    "Gazebo/White": (1.0, 1.0, 1.0, 1.0),
    "Gazebo/Red": (1.0, 0.0, 0.0, 1.0),
    "Gazebo/Green": (0.0, 1.0, 0.0, 1.0),
    "Gazebo/Blue": (0.0, 0.0, 1.0, 1.0),
    "Gazebo/Yellow": (1.0, 1.0, 0.0, 1.0),
    "Gazebo/Orange": (1.0, 0.5088, 0.0468, 1.0),
    "Gazebo/Purple": (1.0, 0.0, 1.0, 1.0),
    "Gazebo/Turquoise": (0.0, 1.0, 1.0, 1.0),
    "Gazebo/Wood": (0.5, 0.3, 0.1, 1.0),
}
"""Colours of the common Gazebo Classic material scripts (diffuse RGBA), as Classic's
``media/materials/scripts/gazebo.material`` gives them (Gazebo/Wood, a texture there, as a wood colour).

A URDF's ``<gazebo reference><material>Gazebo/Red</material>`` is how most ROS 1-era robots are coloured in
Gazebo (their URDF ``<material>`` is for RViz), and Classic-era SDF worlds colour their walls and floors with
``<material><script><name>Gazebo/Grey</name></script>``: without this table they would all be grey. A script
name not listed keeps the visual's own colour."""
