"""Reading mesh files (STL, DAE, OBJ, ...) through trimesh, in metres.

COLLADA files declare their unit (``<unit meter="0.001"/>``); Gazebo honours it,
so we convert every mesh to metres before anything uses its vertices.
"""

from __future__ import annotations

import dataclasses
import functools
import os

import numpy as np
import numpy.typing as npt

from .._errors import SimError


class MeshReadError(SimError):
    """A mesh file could not be read."""


def load_trimesh_in_metres(path: str):  # -> trimesh.Trimesh (trimesh is imported lazily)
    """A mesh file as one ``trimesh.Trimesh`` (textures kept), its vertices converted to metres from the unit
    the file declares (COLLADA's ``<unit meter="0.0254"/>``: TurtleBot3's arena wall and hexagons), as
    Gazebo reads them. The physics and the viewer both load through here, so both draw the same size."""
    import trimesh

    mesh = trimesh.load(path, force="mesh", process=False)
    if getattr(mesh, "units", None) not in (None, "m", "meter", "meters"):
        mesh.convert_units("meters")  # pyright: ignore[reportAttributeAccessIssue] - trimesh.load returns Scene | Trimesh; a Trimesh here (force='mesh')
    return mesh


@functools.lru_cache(maxsize=256)
def _load(path: str, mtime_ns: int) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int32]]:
    """A mesh file's vertices (metres, whatever the file's unit) and triangles, read once per file version
    (``mtime_ns``) and kept read-only; an unreadable or empty mesh is a MeshReadError naming the file."""
    del mtime_ns  # cache key only
    try:
        mesh = load_trimesh_in_metres(path)
    except Exception as err:
        raise MeshReadError(f"cannot read '{os.path.basename(path)}': {err}") from err
    vertices = np.asarray(mesh.vertices, dtype=np.float64)  # pyright: ignore[reportAttributeAccessIssue] - trimesh.load returns Scene | Trimesh; a Trimesh here (force='mesh')
    faces = np.asarray(mesh.faces, dtype=np.int32)  # pyright: ignore[reportAttributeAccessIssue] - trimesh.load returns Scene | Trimesh; a Trimesh here (force='mesh')
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


MAX_TEXTURE_PX = 4096
"""A mesh's texture is scaled down to at most this many pixels a side (as cameras are bounded)."""


@dataclasses.dataclass(frozen=True)
class MeshLook:
    """How a mesh file says it looks: its own colour, or a texture with a (u, v) per vertex of
    :func:`load_mesh`'s vertices (v from the image's bottom row, as OpenGL and the file have it)."""

    rgba: tuple[float, float, float, float] | None = None
    uv: npt.NDArray[np.float64] | None = None
    image: npt.NDArray[np.uint8] | None = None
    """H x W x 3, the first row the image's top."""


@functools.lru_cache(maxsize=64)
def _look(path: str, mtime_ns: int) -> MeshLook:
    """What a mesh file says about its own appearance: its material's base colour, or its texture image with the
    vertices' UV coordinates (images shrunk to :data:`MAX_TEXTURE_PX`); an empty look when the file has neither
    or cannot be read."""
    del mtime_ns  # cache key only
    try:
        mesh = load_trimesh_in_metres(path)
    except Exception:
        return MeshLook()
    visual = getattr(mesh, "visual", None)
    material = getattr(visual, "material", None)
    image = getattr(material, "baseColorTexture", None) or getattr(material, "image", None)
    uv = getattr(visual, "uv", None)
    rgba = None
    colour = getattr(material, "baseColorFactor", None)
    if colour is None:
        colour = getattr(material, "main_color", None)
    if colour is not None and len(colour) >= 3:
        c = np.asarray(colour, dtype=float)
        c = c / 255.0 if c.max() > 1.0 else c
        rgba = (float(c[0]), float(c[1]), float(c[2]), float(c[3]) if len(c) > 3 else 1.0)
    if image is None or uv is None or len(uv) != len(mesh.vertices):  # pyright: ignore[reportAttributeAccessIssue] - trimesh.load returns Scene | Trimesh; a Trimesh here (force='mesh')
        return MeshLook(rgba=rgba)
    img = image.convert("RGB")
    if max(img.size) > MAX_TEXTURE_PX:
        img.thumbnail((MAX_TEXTURE_PX, MAX_TEXTURE_PX))
    pixels = np.asarray(img, dtype=np.uint8)
    coords = np.asarray(uv, dtype=np.float64)
    pixels.setflags(write=False)
    coords.setflags(write=False)
    return MeshLook(rgba=None, uv=coords, image=pixels)


def load_mesh_look(path: str) -> MeshLook:
    """The colour or texture a mesh file gives itself (COLLADA/OBJ materials), for cameras; an empty look
    when it has none or cannot be read. Cached until the file changes."""
    try:
        mtime = os.stat(path).st_mtime_ns
    except OSError:
        return MeshLook()
    return _look(path, mtime)
