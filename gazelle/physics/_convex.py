"""Collision meshes that are not convex: a convex decomposition, cached on disk.

MuJoCo collides a mesh as its convex hull. Gazebo collides with the triangles, so a concave mesh
(TurtleBot3's hexagonal arena wall, a cup, a U) must not become one solid block: the arena's hull
buried the burger 84° on its side. A non-convex collision mesh is split into convex parts with
CoACD (collision-aware approximate convex decomposition, the ``coacd`` wheel), each part a MuJoCo
mesh geom. The parts are cached by a hash of the scaled vertices and faces and the settings, in
memory and in ``$GAZELLE_CACHE_DIR`` (default ``~/.cache/gazelle/convex``), so only the first load
of a mesh pays for it (TurtleBot3's wall: 0.8 s, 6 parts).

The cache is not trusted: its folder is created owner-only (``0700``) and a folder or entry that another
user owns, or that others may write (the folder or any folder above it: :func:`gazelle._files.private_folder`),
is not used; an entry is read only when it is a regular file of at
most :data:`MAX_ENTRY_BYTES`, holds the key of the mesh it was computed for, no more than
:data:`COACD_MAX_PARTS` parts, and parts inside the mesh's bounding box. Anything else is recomputed
(and replaced), with a warning. "The decomposition failed" is cached with the gazelle version that
found it, and tried again by the next version.

The decomposition runs in a forked child bounded in time (``GAZELLE_DECOMPOSE_TIMEOUT``, default
30 s) and memory, off the simulation thread (:func:`prepare`); a mesh it cannot decompose in time,
or with more than ``GAZELLE_DECOMPOSE_MAX_FACES`` faces (5,000), keeps its convex hull with a
warning that says so (and that outcome is cached too). A load (all of one model's meshes) waits for
them at most ``GAZELLE_DECOMPOSE_LOAD_BUDGET`` (2 s) in all: the rest finish in a background thread
(its own bounded child), each mesh colliding as its hull meanwhile, and later loads get the parts.
"""

from __future__ import annotations

import hashlib
import io
import logging
import os
import queue
import threading
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .._files import atomic_write, private_folder
from ..description import BoundExceeded, Mesh, MeshReadError, Model, load_mesh, run_bounded

_log = logging.getLogger("gazelle.physics")

CONVEXITY_TOLERANCE = 1e-4
"""How far (as a fraction of the mesh's size) a vertex may stick out of a face's plane in a convex mesh."""
COACD_THRESHOLD = 0.05
"""CoACD's concavity threshold: the largest allowed concavity, as a fraction of the mesh's size."""
COACD_MAX_PARTS = 64
"""The most parts a mesh becomes: each is a geom MuJoCo tests for contact, so a cap keeps a detailed
wall from costing hundreds of collision pairs (and bounds what a cache entry may hold)."""
SETTINGS_VERSION = "coacd-1.0.14/t0.05/max64/v1"
"""Part of the cache key: changing the settings recomputes the parts."""
DEFAULT_TIMEOUT_SEC = 30.0
"""The most one decomposition may take (``GAZELLE_DECOMPOSE_TIMEOUT``), in its bounded child, even in the
background; past it the mesh keeps its hull, and that outcome is cached."""
LOAD_BUDGET_SEC = 2.0
"""What a load waits for a decomposition not cached yet (``GAZELLE_DECOMPOSE_LOAD_BUDGET``): one that takes
longer finishes in the background, and the mesh collides as its hull until the next load (a first launch
of TurtleBot3's house waited 25-40 s a mesh, NASA R2's 70-85 s, and spawners gave up at 30 s)."""
DEFAULT_MAX_FACES = 5000
"""Larger non-convex meshes keep their hull (with a warning) unless ``GAZELLE_DECOMPOSE_MAX_FACES`` is
raised: CoACD's time grows quickly with detail (TurtleBot3's 34,320-face burger_base.stl: 193 s), while
the concave meshes that matter for contact (walls, arenas, bins) are simple."""

PRISM_THICKNESS = 0.01
"""m: how deep behind its face each triangle of a static non-convex mesh collides (see :func:`triangle_prisms`)."""
STATIC_MAX_FACES = 20000
"""The most triangles a static non-convex mesh without convex parts may collide as
(``GAZELLE_STATIC_MESH_MAX_FACES``); past it the mesh collides as its hull, said at error level."""


@dataclass(frozen=True)
class Parts:
    """The convex pieces a collision mesh collides as (vertices in the mesh frame, scaled)."""

    pieces: tuple[np.ndarray, ...]
    """Each part's points (n x 3, metres, scaled): MuJoCo makes the convex hull of each."""
    seconds: float
    """Time spent decomposing (0 when it came from a cache)."""
    source: str
    """"computed", "disk cache", "memory", or "triangles" (a static mesh's :func:`triangle_prisms`)."""


_memory: dict[str, Parts | None] = {}
"""Cache key -> the parts, or None for a convex mesh (collide as it is)."""
_keys: dict[tuple[str, int, tuple[float, ...]], str] = {}
"""(file, its modification time, scale) -> cache key of its content."""
_hulls: dict[str, str] = {}
"""Cache key -> why that non-convex mesh has no convex parts (its decomposition failed, it is too large, or it
goes on in the background)."""
_triangles: dict[str, Parts | None] = {}
"""Cache key -> the triangle prisms a static non-convex mesh without parts collides as (None: too many faces)."""
_told: set[tuple[str, str]] = set()
"""(cache key, what) already logged: each fallback is said once per process."""
_lock = threading.Lock()


def cache_dir() -> Path:
    """Where decompositions are kept between runs."""
    env = os.environ.get("GAZELLE_CACHE_DIR")
    base = Path(env) if env else Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "gazelle"
    return base / "convex"


def is_convex(vertices: np.ndarray, faces: np.ndarray) -> bool:
    """Whether no vertex lies outside the plane of any face (within :data:`CONVEXITY_TOLERANCE` of the size)."""
    if len(faces) == 0:
        return True
    v = np.asarray(vertices, dtype=float)
    tri = v[np.asarray(faces, dtype=np.int64)]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-12
    normals, origins = normals[keep] / lengths[keep, None], tri[keep, 0]
    size = float(np.linalg.norm(v.max(axis=0) - v.min(axis=0))) or 1.0
    tol = CONVEXITY_TOLERANCE * size
    # orient every normal outwards (away from the centroid), then no vertex may be in front of any face
    centroid = v.mean(axis=0)
    flip = np.einsum("ij,ij->i", normals, origins - centroid) < 0
    normals[flip] *= -1
    step = max(1, 2_000_000 // max(len(v), 1))  # chunks of faces x vertices stay around 16 MB
    for start in range(0, len(normals), step):
        n, o = normals[start : start + step], origins[start : start + step]
        ahead = v @ n.T - np.einsum("ij,ij->i", n, o)
        if np.any(ahead > tol):
            return False
    return True


def _key(vertices: np.ndarray, faces: np.ndarray) -> str:
    """The cache key of a mesh's decomposition: a hash of the decomposition settings' version and the mesh's exact
    vertices and faces (the same mesh under another file name hits the cache)."""
    h = hashlib.sha256(SETTINGS_VERSION.encode())
    h.update(np.ascontiguousarray(vertices, dtype=np.float64).tobytes())
    h.update(np.ascontiguousarray(faces, dtype=np.int64).tobytes())
    return h.hexdigest()


def _decompose(vertices: np.ndarray, faces: np.ndarray) -> list[list[list[float]]]:
    """Run CoACD (in the bounded child); plain lists travel back as JSON."""
    import coacd

    coacd.set_log_level("error")
    parts = coacd.run_coacd(
        coacd.Mesh(np.asarray(vertices, dtype=float), np.asarray(faces, dtype=np.int64)),  # pyright: ignore[reportArgumentType] - coacd's binding declares list types; it takes numpy arrays
        threshold=COACD_THRESHOLD,
        max_convex_hull=COACD_MAX_PARTS,
        seed=0,
    )
    return [np.asarray(p[0], dtype=float).tolist() for p in parts]


MAX_ENTRY_BYTES = 16 << 20
"""The largest cache entry read (64 parts of a few hundred hull vertices are well under 1 MB)."""
BOUNDS_SLACK = 0.02
"""How far (a fraction of the mesh's size, plus 1 µm) a cached part may stick out of the mesh's box."""
CACHE_WHAT = "the convex-decomposition cache"
"""What its folder is called in a refusal's warning."""


def _gazelle_version() -> str:
    """The installed gazelle's version, stored with each cached decomposition ("unknown" for a source tree)."""
    try:
        from importlib.metadata import version

        return version("gazelle")
    except Exception:  # not installed as a distribution (a source tree on sys.path)
        return "unknown"


def _load_disk(path: Path, key: str, vertices: np.ndarray) -> tuple[tuple[np.ndarray, ...], str] | None:
    """The cached parts of the mesh with cache key ``key`` and these (scaled) vertices, and the gazelle
    version that wrote them; ``()`` records that the mesh keeps its hull. None, after a warning where the
    entry exists but is refused, when there is no usable entry."""
    try:
        info = path.lstat()
    except OSError:
        return None
    why = None
    if not path.is_file() or path.is_symlink():
        why = "is not a regular file"
    elif info.st_uid != os.getuid():
        why = "belongs to another user"
    elif info.st_size > MAX_ENTRY_BYTES:
        why = f"has {info.st_size} bytes, more than {MAX_ENTRY_BYTES}"
    if why is None:
        try:
            with np.load(path, allow_pickle=False) as data:  # plain arrays only: no pickle is ever loaded
                names = set(data.files)
                if "key" not in names or str(data["key"]) != key:
                    why = "was computed for another mesh"
                else:
                    version = str(data["version"]) if "version" in names else ""
                    count = len([n for n in names if n.startswith("p") and n[1:].isdigit()])
                    pieces = tuple(np.asarray(data[f"p{i}"], dtype=float) for i in range(count))
                    why = _implausible(pieces, vertices)
                    if why is None:
                        return pieces, version
        except (OSError, ValueError, KeyError, EOFError) as err:
            why = f"cannot be read ({type(err).__name__})"
    _log.warning(f"convex-decomposition cache entry {path} {why}; it is computed again")
    return None


def _implausible(pieces: tuple[np.ndarray, ...], vertices: np.ndarray) -> str | None:
    """Why ``pieces`` cannot be a decomposition of a mesh with these vertices, or None."""
    if len(pieces) > COACD_MAX_PARTS:
        return f"has {len(pieces)} parts, more than {COACD_MAX_PARTS}"
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    slack = BOUNDS_SLACK * float(np.linalg.norm(hi - lo)) + 1e-6
    for piece in pieces:
        if piece.ndim != 2 or piece.shape[1] != 3 or len(piece) < 4 or not np.all(np.isfinite(piece)):
            return "holds a part that is not a set of 3-D points"
        if np.any(piece.min(axis=0) < lo - slack) or np.any(piece.max(axis=0) > hi + slack):
            return "holds a part outside the mesh's bounding box"
    return None


def _save_disk(path: Path, key: str, pieces: tuple[np.ndarray, ...]) -> None:
    """Store a decomposition in the owner-only cache folder, atomically (written to a temporary file, then renamed);
    a folder that is not the user's own, or a read-only home, means no cache, never a failure."""
    folder = private_folder(path.parent, CACHE_WHAT)
    if folder is None:
        return
    blob = io.BytesIO()
    arrays = {f"p{i}": p for i, p in enumerate(pieces)}
    np.savez(blob, key=np.asarray(key), version=np.asarray(_gazelle_version()), **arrays)  # pyright: ignore[reportArgumentType] - numpy's stub types **kwds of savez narrower than the arrays it takes
    try:
        atomic_write(folder / path.name, blob.getvalue(), mode=0o600)
    except OSError as err:  # a read-only home: decompose again next time
        _log.debug(f"cannot cache a convex decomposition in {path.parent}: {err}")


def triangle_prisms(
    vertices: np.ndarray, faces: np.ndarray, thickness: float = PRISM_THICKNESS
) -> tuple[np.ndarray, ...]:
    """Each triangle of a mesh as a convex prism: the triangle and its copy ``thickness`` behind it (against the
    face's normal, by the winding's right-hand rule: into a closed mesh wound outwards, below a floor facing up).
    A static mesh collides as these where Gazebo collides its triangles; degenerate triangles are skipped."""
    v = np.asarray(vertices, dtype=float)
    tri = v[np.asarray(faces, dtype=np.int64)]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-12
    unit = normals[keep] / lengths[keep, None]
    front = tri[keep]
    prisms = np.concatenate((front, front - thickness * unit[:, None, :]), axis=1)
    return tuple(prisms)


def collision_parts(path: str, scale: tuple[float, float, float], *, static: bool = False) -> Parts | None:
    """The convex parts the collision mesh at ``path`` (scaled) collides as, or None when it collides as it is:
    convex, or (said once, as a warning) its convex hull because it has no parts (see :func:`_parts`).

    A ``static`` mesh (of a static model) without parts collides as its triangles (:func:`triangle_prisms`), as
    Gazebo collides a mesh: its hull would be a solid block, and a robot spawned inside a building would stand
    in it. Past ``GAZELLE_STATIC_MESH_MAX_FACES`` faces it collides as its hull, said at error level with what
    the user can do."""
    parts = _parts(path, scale)
    if parts is not None:
        return parts
    seen = (path, os.stat(path).st_mtime_ns, tuple(float(v) for v in scale))
    with _lock:
        key = _keys.get(seen)
        why = _hulls.get(key) if key is not None else None
    if key is None or why is None:
        return None  # convex
    if static:
        return _static_triangles(key, path, scale, why)
    _tell(
        key,
        "hull",
        logging.WARNING,
        f"collision mesh '{path}' is not convex, but {why}: it collides as its convex hull (an approximation)",
    )
    return None


def _tell(key: str, what: str, level: int, message: str) -> None:
    with _lock:
        if (key, what) in _told:
            return
        _told.add((key, what))
    _log.log(level, message)


def _static_triangles(key: str, path: str, scale: tuple[float, float, float], why: str) -> Parts | None:
    """The triangle prisms of a static non-convex mesh that has no convex parts, or None (its hull) past the
    face limit; each outcome said once."""
    with _lock:
        if key in _triangles:
            return _triangles[key]
    verts, faces = _welded(*load_mesh(path))
    verts = verts * np.asarray(scale, dtype=float)
    limit = int(float(os.environ.get("GAZELLE_STATIC_MESH_MAX_FACES") or STATIC_MAX_FACES))
    result: Parts | None = None
    if len(faces) > limit:
        _tell(
            key,
            "static",
            logging.ERROR,
            f"collision mesh '{path}' of a static model is not convex, but {why}, and its {len(faces)} faces are "
            f"more than the {limit} it may collide as (GAZELLE_STATIC_MESH_MAX_FACES): it collides as its convex "
            "hull, a solid block that whatever is inside it is pushed out of or stands on. Give the model a "
            "simpler collision mesh, several convex ones or primitives, or raise GAZELLE_STATIC_MESH_MAX_FACES",
        )
    else:
        result = Parts(triangle_prisms(verts, faces), 0.0, "triangles")
        _tell(
            key,
            "static",
            logging.WARNING,
            f"collision mesh '{path}' is not convex, but {why}: the model is static, so it collides as its "
            f"{len(result.pieces)} triangles, each a {PRISM_THICKNESS * 100:g} cm prism behind its face, as Gazebo "
            "collides a mesh's triangles",
        )
    with _lock:
        _triangles[key] = result
    return result


def _parts(path: str, scale: tuple[float, float, float]) -> Parts | None:
    """The convex parts of the collision mesh at ``path`` (scaled), or None when it is convex already.

    Raises:
        MeshReadError: the mesh cannot be read.
    """
    try:
        seen = (path, os.stat(path).st_mtime_ns, tuple(float(v) for v in scale))
    except OSError as err:
        raise MeshReadError(f"cannot read '{path}': {err.strerror}") from None
    with _lock:  # a mesh spawned again (32 chess pieces, a robot re-spawned) is neither welded nor hashed again
        key = _keys.get(seen)
        if key is not None and key in _memory:
            cached = _memory[key]
            return None if cached is None else Parts(cached.pieces, 0.0, "memory")
    # welded first (mesh files repeat vertices per face; merged, a closed mesh is manifold and CoACD skips
    # its slow remeshing), scaled (the parts are in the geom's units), then hashed: the key is the geometry,
    # not the file
    verts, faces = _welded(*load_mesh(path))
    verts = verts * np.asarray(scale, dtype=float)
    key = _key(verts, faces)
    with _lock:
        _keys[seen] = key
        if key in _memory:
            cached = _memory[key]
            return None if cached is None else Parts(cached.pieces, 0.0, "memory")
    if is_convex(verts, faces):  # most collision meshes: MuJoCo's hull is then the mesh itself
        with _lock:
            _memory[key] = None
        return None
    max_faces = int(float(os.environ.get("GAZELLE_DECOMPOSE_MAX_FACES") or DEFAULT_MAX_FACES))
    # a visual-grade mesh used for collision (100k faces) would take CoACD minutes: its hull, said
    if len(faces) > max_faces:
        return _hull(key, path, f"it has {len(faces)} faces, more than GAZELLE_DECOMPOSE_MAX_FACES={max_faces}")
    folder = cache_dir()
    real = private_folder(folder, CACHE_WHAT)
    disk = (real or folder) / f"{key}.npz"
    usable = real is not None
    entry = _load_disk(disk, key, verts) if usable else None
    if entry is not None and entry[0] == () and entry[1] != _gazelle_version():
        entry = None  # failed with another gazelle version: this one tries once more
    pieces = entry[0] if entry is not None else None
    if pieces == ():
        return _hull(key, path, "its decomposition failed before (cached)")
    if pieces is not None:
        parts = Parts(pieces, 0.0, "disk cache")
    else:
        parts = _decompose_now(key, path, disk, verts, faces, usable)
        if parts is None:
            return None  # its convex hull (_hull said why)
    with _lock:
        _memory[key] = parts
    return parts


def _decompose_now(key: str, path: str, disk: Path, verts: np.ndarray, faces: np.ndarray, usable: bool) -> Parts | None:
    """Decompose within the load's time budget and cache the parts on disk; None where the mesh collides
    as its convex hull instead (a decomposition that failed or ran out of time: with time, it goes on in
    the background and a later load uses its parts)."""
    timeout = float(os.environ.get("GAZELLE_DECOMPOSE_TIMEOUT") or DEFAULT_TIMEOUT_SEC)
    budget = min(timeout, load_budget())
    left = getattr(_load, "left", None)  # what is left of the load's budget (see prepare)
    if left is not None and left < budget:
        budget = max(left, MIN_ATTEMPT_SEC)
        if left < MIN_ATTEMPT_SEC and usable:
            _in_background(disk, key, verts, faces, timeout)
            return _hull(
                key,
                path,
                "the load's time for decompositions (GAZELLE_DECOMPOSE_LOAD_BUDGET, for all of a model's "
                "meshes) is spent: it is decomposed in the background, and loads after it has finished use "
                "its parts",
            )
    t0 = time.monotonic()
    try:
        raw = run_bounded(
            lambda: _decompose(verts, faces),
            what="its convex decomposition",
            timeout_sec=budget,
            timeout_hint="GAZELLE_DECOMPOSE_LOAD_BUDGET" if budget < timeout else "GAZELLE_DECOMPOSE_TIMEOUT",
        )
    except BoundExceeded as err:
        _spend(time.monotonic() - t0)
        if err.timed_out and budget < timeout and usable:
            _in_background(disk, key, verts, faces, timeout)
            return _hull(
                key,
                path,
                f"its decomposition takes more than the {budget:g} s a load may spend on it "
                "(GAZELLE_DECOMPOSE_LOAD_BUDGET): it goes on in the background, and loads after it has "
                "finished use its parts",
            )
        _save_disk(disk, key, ())  # not again on this machine, with this version
        return _hull(key, path, str(err))
    _spend(time.monotonic() - t0)
    pieces = tuple(np.asarray(p, dtype=float) for p in raw if len(p) >= 4)  # fewer than 4 points: no volume
    parts = Parts(pieces, time.monotonic() - t0, "computed")
    _save_disk(disk, key, pieces)
    return parts


_background: queue.Queue[tuple[Path, str, np.ndarray, np.ndarray, float]] = queue.Queue()
_background_thread: threading.Thread | None = None
background_done = threading.Condition()
"""Notified when a background decomposition has ended (tests wait on it)."""


def _in_background(disk: Path, key: str, verts: np.ndarray, faces: np.ndarray, timeout: float) -> None:
    """Finish a decomposition that overran the load budget, one at a time in a daemon thread (its bounded
    child process does the work): the parts are cached on disk, and later spawns in this process use them."""
    global _background_thread
    _background.put((disk, key, verts, faces, timeout))
    with _lock:
        if _background_thread is None or not _background_thread.is_alive():
            _background_thread = threading.Thread(target=_background_loop, name="gazelle-decompose", daemon=True)
            _background_thread.start()


def _background_loop() -> None:
    """The background decomposer: meshes queued while the world ran on their convex hulls are decomposed one at a
    time (bounded in time and memory), and the parts are cached for the next run; the thread ends after a second
    with nothing queued."""
    while True:
        try:
            disk, key, verts, faces, timeout = _background.get(timeout=1.0)
        except queue.Empty:
            return
        t0 = time.monotonic()
        try:
            raw = run_bounded(
                lambda v=verts, f=faces: _decompose(v, f),
                what="its convex decomposition",
                timeout_sec=timeout,
                timeout_hint="GAZELLE_DECOMPOSE_TIMEOUT",
            )
        except BoundExceeded:
            _save_disk(disk, key, ())
        else:
            pieces = tuple(np.asarray(p, dtype=float) for p in raw if len(p) >= 4)
            _save_disk(disk, key, pieces)
            with _lock:
                _memory[key] = Parts(pieces, time.monotonic() - t0, "computed in the background")
        with background_done:
            background_done.notify_all()


def _hull(key: str, path: str, why: str) -> None:
    """No parts for a non-convex mesh: why is kept for :func:`collision_parts`, which says what it collides as."""
    with _lock:
        _memory[key] = None
        _hulls[key] = why
    return None


def _welded(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices shared by faces merged (mesh files repeat them per face), so a closed mesh is manifold:
    CoACD then skips its slow remeshing (TurtleBot3's wall: 0.7 s instead of 10 s)."""
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.int64)
    if len(v) == 0:
        return v, f
    rounded = np.round(v, 9)
    unique, inverse = np.unique(rounded, axis=0, return_inverse=True)
    return unique, inverse.reshape(-1)[f]


def load_budget() -> float:
    """Seconds a load (all of one model's meshes) may spend decomposing: ``GAZELLE_DECOMPOSE_LOAD_BUDGET``."""
    return float(os.environ.get("GAZELLE_DECOMPOSE_LOAD_BUDGET") or LOAD_BUDGET_SEC)


_load = threading.local()
"""``left``: the seconds the :func:`prepare` running in this thread has left for decompositions."""
MIN_ATTEMPT_SEC = 0.05
"""Less than this left of a load's budget: the next decomposition goes straight to the background."""


def _spend(seconds: float) -> None:
    left = getattr(_load, "left", None)
    if left is not None:
        _load.left = left - seconds


def prepare(model: Model) -> None:
    """Decompose ``model``'s non-convex collision meshes now, in the calling thread (not the simulation's).

    The builder finds the results in the memory cache; a mesh that cannot be read is left for the
    builder to report. All of the model's decompositions share one budget (:func:`load_budget`): NASA
    R2's dozens of meshes, 2 s each, would still have kept a spawn waiting past its client's 30 s.
    """
    _load.left = load_budget()
    try:
        for link in model.links:
            for col in link.collisions:
                g = col.geometry
                if isinstance(g, Mesh) and g.path is not None:
                    try:
                        collision_parts(g.path, g.scale, static=model.static)
                    except MeshReadError:
                        pass
    finally:
        del _load.left
