"""Reading mesh files (STL, DAE, OBJ, ...) through trimesh, in metres.

COLLADA files declare their unit (``<unit meter="0.001"/>``); Gazebo honours it,
so we convert every mesh to metres before anything uses its vertices.
"""

from __future__ import annotations

import functools
import os

import numpy as np
import numpy.typing as npt


class MeshReadError(Exception):
    """A mesh file could not be read."""


def load_trimesh_in_metres(path: str):  # -> trimesh.Trimesh (trimesh is imported lazily)
    """A mesh file as one ``trimesh.Trimesh`` (textures kept), its vertices converted to metres from the unit
    the file declares (COLLADA's ``<unit meter="0.0254"/>``: TurtleBot3's arena wall and hexagons), as
    Gazebo reads them. The physics and the viewer both load through here, so both draw the same size."""
    import trimesh  # type: ignore[import-not-found]

    mesh = trimesh.load(path, force="mesh", process=False)
    if getattr(mesh, "units", None) not in (None, "m", "meter", "meters"):
        mesh.convert_units("meters")  # pyright: ignore[reportAttributeAccessIssue]
    return mesh


@functools.lru_cache(maxsize=256)
def _load(path: str, mtime_ns: int) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int32]]:
    del mtime_ns  # cache key only
    try:
        mesh = load_trimesh_in_metres(path)
    except Exception as err:
        raise MeshReadError(f"cannot read '{os.path.basename(path)}': {err}") from err
    vertices = np.asarray(mesh.vertices, dtype=np.float64)  # pyright: ignore[reportAttributeAccessIssue]
    faces = np.asarray(mesh.faces, dtype=np.int32)  # pyright: ignore[reportAttributeAccessIssue]
    if len(vertices) == 0 or len(faces) == 0:
        raise MeshReadError(f"'{os.path.basename(path)}' has no triangles")
    vertices.setflags(write=False)
    faces.setflags(write=False)
    return vertices, faces


def load_mesh(path: str) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int32]]:
    """Vertices (metres) and triangle indices of a mesh file; cached until the file changes.

    Raises:
        MeshReadError: missing, unreadable or empty.
    """
    try:
        mtime = os.stat(path).st_mtime_ns
    except OSError as err:
        raise MeshReadError(f"cannot read '{path}': {err.strerror}") from err
    return _load(path, mtime)
