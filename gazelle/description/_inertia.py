"""Mass properties: validating a link's inertia, and deriving one from collision geometry.

Shared by the URDF and SDF loaders. Everything is computed at unit density first
(volume, centre of volume, second moment), then scaled to the requested mass, so a
link with several shapes gets one consistent inertia (mass split by volume).

Meshes: binary and ASCII STL are read directly (exact volume integral over signed
tetrahedra); other formats go through ``trimesh`` when it is installed. An open mesh
(no enclosed volume) falls back to its bounding box.
"""

from __future__ import annotations

import functools
import math
import os
import struct
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._meshes import MeshReadError, load_mesh
from ._model import Box, Capsule, Cone, Cylinder, Ellipsoid, Geometry, Inertial, Mesh, Sphere
from ._pose import IDENTITY, Pose, Quat

DEFAULT_DENSITY = 1000.0
"""kg/m^3 (water), used when a mass must be derived from volume."""

DEFAULT_MASS = 1e-3
"""kg; the placeholder mass of a link that needs one but has no geometry to derive it from."""

DEFAULT_RADIUS_OF_GYRATION_SQ = 1e-3
"""m^2; placeholder inertia is ``mass * this`` on each axis (a solid sphere of radius 5 cm)."""

Matrix3 = npt.NDArray[np.float64]

# Covariance of the canonical tetrahedron (0, e1, e2, e3) at unit density.
_C0 = np.array([[2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]]) / 120.0


@dataclass(frozen=True)
class UnitProperties:
    """Mass properties of a shape at unit density, in the shape's own frame."""

    volume: float
    """m^3."""
    center: tuple[float, float, float]
    """Centre of volume in the shape frame."""
    inertia: Matrix3
    """Inertia tensor about ``center`` at density 1 (kg·m^2 per kg/m^3)."""
    note: str = ""
    """How it was obtained when approximated (e.g. bounding box), else empty."""


def _diag(x: float, y: float, z: float) -> Matrix3:
    return np.diag([x, y, z]).astype(np.float64)


def _box_props(size: Sequence[float], center: Sequence[float] = (0.0, 0.0, 0.0), note: str = "") -> UnitProperties:
    """A box of edge lengths ``size`` at unit density: volume xyz and the solid box's tensor, (y² + z²)/12 and so on
    times the volume, about ``center``."""
    x, y, z = (float(s) for s in size)
    v = x * y * z
    inertia = _diag(v * (y * y + z * z) / 12, v * (x * x + z * z) / 12, v * (x * x + y * y) / 12)
    return UnitProperties(v, (float(center[0]), float(center[1]), float(center[2])), inertia, note)


def _cylinder_props(radius: float, length: float) -> UnitProperties:
    v = math.pi * radius**2 * length
    side = v * (3 * radius**2 + length**2) / 12
    return UnitProperties(v, (0.0, 0.0, 0.0), _diag(side, side, v * radius**2 / 2))


def _cone_props(radius: float, length: float) -> UnitProperties:
    """A solid cone, base at z = -length/2: its centroid is a quarter of the height above the base."""
    v = math.pi * radius**2 * length / 3.0
    side = v * (3.0 * radius**2 / 20.0 + 3.0 * length**2 / 80.0)
    return UnitProperties(v, (0.0, 0.0, -length / 4.0), _diag(side, side, v * 3.0 * radius**2 / 10.0))


def _capsule_props(radius: float, length: float) -> UnitProperties:
    """A capsule (a cylinder of ``length`` with two hemispherical caps of ``radius``) at unit density: the
    cylinder's and the caps' volumes and moments, the caps' moved to their centres of mass at length/2 + 3r/8
    from the middle (parallel-axis theorem)."""
    v_cyl = math.pi * radius**2 * length
    v_caps = 4.0 / 3.0 * math.pi * radius**3
    axial = v_cyl * radius**2 / 2 + v_caps * 2 * radius**2 / 5
    side = v_cyl * (3 * radius**2 + length**2) / 12 + v_caps * (
        2 * radius**2 / 5 + length**2 / 4 + 3 * length * radius / 8
    )
    return UnitProperties(v_cyl + v_caps, (0.0, 0.0, 0.0), _diag(side, side, axial))


def _ellipsoid_props(a: float, b: float, c: float) -> UnitProperties:
    """A solid ellipsoid of semi-axes a, b, c at unit density: volume 4/3·π·abc, moments (b² + c²)/5 and so on times
    the volume."""
    v = 4.0 / 3.0 * math.pi * a * b * c
    return UnitProperties(
        v, (0.0, 0.0, 0.0), _diag(v * (b * b + c * c) / 5, v * (a * a + c * c) / 5, v * (a * a + b * b) / 5)
    )


# --------------------------------------------------------------------------- meshes
def _read_stl(path: str) -> npt.NDArray[np.float64]:
    """Triangles (n, 3, 3) of a binary or ASCII STL file, in the file's units (metres for ROS meshes).

    Read here rather than through trimesh because STL is most robots' collision format and this is the
    inertia path's hot spot: a binary file is one numpy view of its records (50 bytes each after the
    84-byte header, so the size check tells binary from an ASCII file that happens to start with "solid");
    an ASCII one is its ``vertex`` lines. Anything else is a :class:`MeshReadError`, which the caller
    reports with the mesh's file:line."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) >= 84:
        (count,) = struct.unpack_from("<I", data, 80)
        if 84 + 50 * count == len(data):
            record = np.dtype([("normal", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
            tris = np.frombuffer(data, dtype=record, count=count, offset=84)["v"]
            return tris.astype(np.float64)
    if data.lstrip().lower().startswith(b"solid"):
        words = data.split()
        coords = [float(words[i + 1 + k]) for i, w in enumerate(words) if w == b"vertex" for k in range(3)]
        if coords and len(coords) % 9 == 0:
            return np.array(coords, dtype=np.float64).reshape(-1, 3, 3)
    raise MeshReadError("not a valid STL file")


def _read_with_trimesh(path: str) -> npt.NDArray[np.float64]:
    """A mesh file's triangles (n x 3 x 3 vertices) for the mass-properties integration; an unreadable file is a
    MeshReadError naming why."""
    vertices, faces = load_mesh(path)
    return vertices[faces]


def _triangle_props(tris: npt.NDArray[np.float64]) -> UnitProperties:
    """Volume, centre and inertia of a closed triangle mesh (signed tetrahedra to the origin).

    Each triangle and the origin make a tetrahedron whose signed volume is det/6; summed over a closed mesh
    they give the exact volume, centroid and second moments whatever the winding (a mesh wound inside out
    gets its sign flipped). A mesh that does not close (its volume is ~0 next to its bounding box), or
    holds non-finite vertices, uses its bounding box instead, and the note says so."""
    if tris.size == 0:
        raise MeshReadError("mesh has no triangles")
    a_mats = np.transpose(tris, (0, 2, 1))  # columns are the three vertices
    dets = np.linalg.det(a_mats)
    volume = float(dets.sum() / 6.0)
    lo, hi = tris.reshape(-1, 3).min(axis=0), tris.reshape(-1, 3).max(axis=0)
    extent = hi - lo
    if not np.all(np.isfinite(tris)) or abs(volume) <= 1e-9 * max(float(np.prod(extent)), 1e-300):
        return _box_props(extent, (lo + hi) / 2, note="open mesh, used its bounding box")
    sign = 1.0 if volume > 0 else -1.0
    center = (dets[:, None] * tris.sum(axis=1)).sum(axis=0) / 24.0 / volume
    cov = np.einsum("n,nij,jk,nlk->il", dets, a_mats, _C0, a_mats) * sign
    volume *= sign
    cov_c = cov - volume * np.outer(center, center)
    inertia = np.trace(cov_c) * np.eye(3) - cov_c
    return UnitProperties(volume, (float(center[0]), float(center[1]), float(center[2])), inertia)


@functools.lru_cache(maxsize=256)
def _mesh_props_cached(path: str, mtime_ns: int, scale: tuple[float, float, float]) -> UnitProperties:
    del mtime_ns  # part of the cache key only
    tris = _read_stl(path) if path.lower().endswith(".stl") else _read_with_trimesh(path)
    return _triangle_props(tris * np.asarray(scale, dtype=np.float64))


def mesh_properties(mesh: Mesh) -> UnitProperties:
    """Unit-density mass properties of a resolved mesh.

    Raises:
        MeshReadError: the mesh has no resolved path or cannot be read.
    """
    if mesh.path is None:
        raise MeshReadError(f"mesh '{mesh.uri}' was not found")
    try:
        mtime = os.stat(mesh.path).st_mtime_ns
    except OSError as err:
        raise MeshReadError(f"cannot read '{mesh.path}': {err.strerror}") from None
    try:
        sx, sy, sz = mesh.scale
        return _mesh_props_cached(mesh.path, mtime, (float(sx), float(sy), float(sz)))
    except OSError as err:
        raise MeshReadError(f"cannot read '{mesh.path}': {err.strerror}") from None
    except (ValueError, struct.error, np.linalg.LinAlgError) as err:
        raise MeshReadError(f"cannot read '{mesh.path}': {err}") from None


def unit_properties(geometry: Geometry) -> UnitProperties | None:
    """Unit-density mass properties of a shape, or None if it encloses no volume (plane).

    Raises:
        MeshReadError: for a mesh that cannot be read.
    """
    if isinstance(geometry, Box):
        return _box_props(geometry.size)
    if isinstance(geometry, Cylinder):
        return _cylinder_props(geometry.radius, geometry.length)
    if isinstance(geometry, Sphere):
        r = geometry.radius
        v = 4.0 / 3.0 * math.pi * r**3
        return UnitProperties(v, (0.0, 0.0, 0.0), np.eye(3) * (0.4 * v * r * r))
    if isinstance(geometry, Capsule):
        return _capsule_props(geometry.radius, geometry.length)
    if isinstance(geometry, Cone):
        return _cone_props(geometry.radius, geometry.length)
    if isinstance(geometry, Ellipsoid):
        return _ellipsoid_props(*geometry.radii)
    if isinstance(geometry, Mesh):
        return mesh_properties(geometry)
    return None


# --------------------------------------------------------------------------- combining
def rotation_matrix(q: Quat) -> Matrix3:
    """3x3 rotation matrix of a unit wxyz quaternion."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


@dataclass(frozen=True)
class Derivation:
    """The result of :func:`inertia_from_geometries`."""

    inertial: Inertial
    volume: float
    """Total volume used, m^3."""
    mass_from_volume: bool
    """True when the mass was derived from the volume at the given density."""
    notes: tuple[str, ...] = ()
    """Approximations made (bounding boxes, unreadable meshes skipped)."""


def inertia_from_geometries(
    shapes: Sequence[tuple[Geometry, Pose]],
    mass: float | None,
    *,
    density: float = DEFAULT_DENSITY,
) -> Derivation | None:
    """The inertia of a link made of ``shapes`` (geometry and pose X_LG in the link frame).

    Args:
        shapes: collision geometries with their poses in the link frame.
        mass: total mass in kg, or None to derive it from the volume at ``density``.
        density: kg/m^3 used when ``mass`` is None.

    Returns:
        The derived inertial (``derived=True``; centre of mass in the link frame, full
        tensor in link axes), or None when no shape has a volume (only planes, or every
        mesh unreadable; ``notes`` of a partial result say what was skipped).
    """
    parts: list[tuple[UnitProperties, Pose]] = []
    notes: list[str] = []
    for geometry, pose in shapes:
        try:
            props = unit_properties(geometry)
        except MeshReadError as err:
            notes.append(str(err))
            continue
        if props is not None and props.volume > 0:
            parts.append((props, pose))
            if props.note:
                notes.append(props.note)
    total_volume = sum(p.volume for p, _ in parts)
    if not parts or total_volume <= 0:
        return None
    mass_from_volume = mass is None
    total_mass = total_volume * density if mass is None else mass
    rho = total_mass / total_volume
    centers = []
    for props, pose in parts:
        r = rotation_matrix(pose.orientation)
        centers.append(np.asarray(pose.position) + r @ np.asarray(props.center))
    com = np.zeros(3)
    for (p, _), c in zip(parts, centers, strict=True):
        com = com + p.volume * c  # (in order, as the volumes add up)
    com = com / total_volume
    tensor = np.zeros((3, 3))
    for (props, pose), c in zip(parts, centers, strict=True):
        r = rotation_matrix(pose.orientation)
        d = c - com
        tensor += rho * (r @ props.inertia @ r.T + props.volume * (float(d @ d) * np.eye(3) - np.outer(d, d)))
    inertial = Inertial(
        mass=float(total_mass),
        pose=Pose((float(com[0]), float(com[1]), float(com[2]))),
        ixx=float(tensor[0, 0]),
        ixy=float(tensor[0, 1]),
        ixz=float(tensor[0, 2]),
        iyy=float(tensor[1, 1]),
        iyz=float(tensor[1, 2]),
        izz=float(tensor[2, 2]),
        derived=True,
    )
    return Derivation(inertial, float(total_volume), mass_from_volume, tuple(notes))


def inertia_from_geometry(geometry: Geometry, mass: float | None, pose: Pose = IDENTITY) -> Inertial | None:
    """The inertia of one shape at ``pose`` (see :func:`inertia_from_geometries`)."""
    result = inertia_from_geometries([(geometry, pose)], mass)
    return result.inertial if result is not None else None


def default_inertial(mass: float | None = None) -> Inertial:
    """A placeholder inertial: ``mass`` (or :data:`DEFAULT_MASS`) as a 5 cm solid sphere."""
    m = mass if mass is not None and mass > 0 else DEFAULT_MASS
    i = m * DEFAULT_RADIUS_OF_GYRATION_SQ
    return Inertial(mass=m, ixx=i, iyy=i, izz=i, derived=True)


# --------------------------------------------------------------------------- validation
def inertia_problem(
    ixx: float, ixy: float, ixz: float, iyy: float, iyz: float, izz: float, *, rtol: float = 1e-6
) -> str | None:
    """Why an inertia tensor is physically impossible, or None if it is fine.

    Checks: not all zero, positive-definite, and the principal moments satisfy the
    triangle inequality (``I1 + I2 >= I3``, with relative tolerance ``rtol``).
    """
    tensor = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], dtype=np.float64)
    if not np.all(np.isfinite(tensor)):
        return "inertia has non-finite entries"
    if not np.any(tensor):
        return "inertia is zero"
    moments = np.linalg.eigvalsh(tensor)
    if moments[0] <= 0:
        return f"inertia is not positive-definite (principal moments {_fmt(moments)})"
    if moments[0] + moments[1] < moments[2] * (1 - rtol):
        return f"principal moments {_fmt(moments)} violate the triangle inequality"
    return None


def _fmt(values: npt.NDArray[np.floating] | Sequence[float]) -> str:
    return ", ".join(f"{v:.6g}" for v in values)
