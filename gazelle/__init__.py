"""gazelle: Gazebo-style ROS 2 simulation on MuJoCo.

The names a script or a sweep scenario needs, importable from the package root
(``from gazelle import Simulation, load, Pose``), each loaded on first use (``gazelle/_lazy.py``):
``import gazelle`` alone loads none of MuJoCo, rclpy or the sweep machinery.

- :class:`Simulation`: an in-process world (``spawn``, ``step``, ``world.entity_state``): what a sweep
  scenario's ``sim`` is (docs/sweeps.md, "The scenario API").
- :func:`load` / :func:`load_string`: a robot or world file (URDF, xacro, SDF) into a model to spawn;
  :class:`ResourceResolver` says which folders a file may read.
- :class:`Pose`, :func:`quat_to_rpy`, :func:`quat_from_rpy`: poses (metres; quaternions w, x, y, z).
- :class:`DiffDrive`: the diff drive system a spawned robot's plugin becomes (``command(v, w)``).

``sweep`` is not among them: ``gazelle.sweep`` is the sweeps package (``from gazelle.sweep import sweep``),
and a package attribute of that name would be replaced by the subpackage once it is imported.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ._lazy import lazy_attributes

if TYPE_CHECKING:
    from .description import Pose, ResourceResolver, load, load_string, quat_from_rpy, quat_to_rpy
    from .sim import Simulation
    from .systems.diff_drive import DiffDrive

__all__ = [
    "DiffDrive",
    "Pose",
    "ResourceResolver",
    "Simulation",
    "load",
    "load_string",
    "quat_from_rpy",
    "quat_to_rpy",
]

__getattr__ = lazy_attributes(__name__, __file__)
