"""Description geometry -> triangle meshes for the browser (trimesh; no viser here)."""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import trimesh

from ..description import Box, Capsule, Cone, Cylinder, Ellipsoid, Mesh, Plane, Sphere, load_trimesh_in_metres

_log = logging.getLogger("gazelle.viewer")

DEFAULT_RGBA = (0.7, 0.7, 0.7, 1.0)
PLANE_THICKNESS = 0.002


@dataclass(frozen=True)
class TriMesh:
    """Vertices and faces in the geometry's own frame, plus the file's colours if it has any."""

    vertices: np.ndarray
    faces: np.ndarray
    source: trimesh.Trimesh | None = None
    """For mesh files: the loaded mesh (with its own materials), for when the description gives no colour."""


def rgba_to_rgb255(rgba: tuple[float, float, float, float] | None) -> tuple[int, int, int]:
    """A description colour (0..1 floats, None: the default grey) as viser's 0..255 RGB."""
    r, g, b, _a = rgba or DEFAULT_RGBA
    return (
        int(round(255 * min(max(r, 0.0), 1.0))),
        int(round(255 * min(max(g, 0.0), 1.0))),
        int(round(255 * min(max(b, 0.0), 1.0))),
    )


@lru_cache(maxsize=256)
def _load_mesh_file(path: str) -> trimesh.Trimesh:
    """A mesh file as one trimesh mesh in metres (a COLLADA file's own unit applied, as the physics reads it); a
    file without triangles is a ValueError."""
    loaded = load_trimesh_in_metres(path)  # the unit a COLLADA file declares, as the physics
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        raise ValueError("no triangles in the file")
    return loaded


def to_trimesh(geometry: object) -> TriMesh | None:
    """Triangles for a description geometry (SDF/URDF axis conventions: cylinders and capsules along z).

    Returns None for a mesh that cannot be loaded (logged once per file) or an unknown geometry.
    """
    if isinstance(geometry, Box):
        m = trimesh.creation.box(extents=geometry.size)
    elif isinstance(geometry, Cylinder):
        m = trimesh.creation.cylinder(radius=geometry.radius, height=geometry.length, sections=32)
    elif isinstance(geometry, Sphere):
        m = trimesh.creation.icosphere(subdivisions=3, radius=geometry.radius)
    elif isinstance(geometry, Capsule):
        m = trimesh.creation.capsule(height=geometry.length, radius=geometry.radius, count=[16, 16])
    elif isinstance(geometry, Cone):
        m = trimesh.creation.cone(radius=geometry.radius, height=geometry.length, sections=32)
        m.apply_translation((0.0, 0.0, -geometry.length / 2))  # trimesh puts the base at z=0
    elif isinstance(geometry, Ellipsoid):
        m = trimesh.creation.icosphere(subdivisions=3, radius=1.0)
        m.vertices = m.vertices * np.asarray(geometry.radii)
    elif isinstance(geometry, Plane):
        # a thin slab just below the plane, so the grid drawn at z=0 stays visible
        sx, sy = geometry.size
        m = trimesh.creation.box(extents=(sx, sy, PLANE_THICKNESS))
        m.apply_translation((0.0, 0.0, -PLANE_THICKNESS / 2 - 0.001))
        n = np.asarray(geometry.normal, dtype=float)
        n = n / (np.linalg.norm(n) or 1.0)
        if not np.allclose(n, (0.0, 0.0, 1.0)):
            m.apply_transform(trimesh.geometry.align_vectors((0.0, 0.0, 1.0), n))
    elif isinstance(geometry, Mesh):
        if geometry.path is None:
            return None
        try:
            src = _load_mesh_file(geometry.path)
        except Exception as err:
            _log.warning(f"viewer: cannot load mesh {geometry.path}: {err}")
            return None
        scale = np.asarray(geometry.scale, dtype=float)
        src = src.copy()
        if not np.allclose(scale, 1.0):
            src.apply_transform(np.diag([*scale, 1.0]))
        return TriMesh(np.asarray(src.vertices, dtype=np.float32), np.asarray(src.faces, dtype=np.uint32), src)
    else:
        return None
    return TriMesh(np.asarray(m.vertices, dtype=np.float32), np.asarray(m.faces, dtype=np.uint32))
