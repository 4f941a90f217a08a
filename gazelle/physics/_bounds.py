"""Axis-aligned boxes of an entity's collision geometry in the world frame, and the overlap tests of a query shape.

Plain functions over a :class:`~gazelle.physics.PhysicsWorld` (what simulation_interfaces' GetEntityBounds,
GetSpawnables and the ``bounds`` entity filter answer with): each collision geom's box is MuJoCo's own
(``geom_aabb``, the tight box of the shape in its frame: primitives, and every convex part of a mesh) turned
into the world frame with the geom's current pose, so a moved or turned entity's box follows it. A plane
collides everywhere, but its box is the rectangle the file draws (``Plane.size``, 100 m x 100 m by default),
without thickness. An entity with no collision geometry at all (a marker, a visual-only model) is the box
around its links' origins: a point at its model frame for a one-link entity.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from ..description import Model, Pose, World
from ._builder import VISUAL_GROUP
from ._contact_pairs import PROXY_GROUP
from ._entities import ErrorKind, WorldError

if TYPE_CHECKING:
    from ._world import PhysicsWorld

Vec = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class Aabb:
    """An axis-aligned box in the world frame: its lower and upper corners, metres."""

    lower: Vec
    upper: Vec


def _vec(v: np.ndarray) -> Vec:
    return (float(v[0]), float(v[1]), float(v[2]))


def _entity_bodies(world: PhysicsWorld, entity: str) -> list[int]:
    """MuJoCo body ids of an entity's links (NOT_FOUND when there is no such entity)."""
    e = world.entities.get(entity)
    if e is None:
        raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
    ids = (mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_BODY, b) for b in e.built.bodies.values())
    return [i for i in ids if i >= 0]


def _collision_mask(world: PhysicsWorld) -> np.ndarray:
    """Which geoms are collision geometry: visuals are not, and a contact proxy repeats its collision."""
    groups = world.model.geom_group
    return (groups != VISUAL_GROUP) & (groups != PROXY_GROUP)


def _geom_boxes(world: PhysicsWorld, geoms: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(lower, upper) corners, shape (n, 3), of the world-frame boxes of ``geoms`` at the current kinematics:
    MuJoCo's local box (``geom_aabb``: centre, half sizes) turned by each geom's pose; a plane its drawn rectangle."""
    m, d = world.model, world.data
    R = d.geom_xmat[geoms].reshape(-1, 3, 3)
    centre = m.geom_aabb[geoms, :3].copy()
    half = m.geom_aabb[geoms, 3:].copy()
    planes = m.geom_type[geoms] == mujoco.mjtGeom.mjGEOM_PLANE
    centre[planes] = 0.0
    half[planes] = np.column_stack([m.geom_size[geoms][planes, :2], np.zeros(int(planes.sum()))])
    c = d.geom_xpos[geoms] + np.einsum("nij,nj->ni", R, centre)
    h = np.einsum("nij,nj->ni", np.abs(R), half)
    return c - h, c + h


def collision_boxes(world: PhysicsWorld, entity: str) -> list[Aabb]:
    """The world-frame box of each collision geom of ``entity`` (every convex part of a decomposed mesh), at
    the current state; empty when it has none.

    Raises:
        WorldError: NOT_FOUND, no such entity.
    """
    bodies = _entity_bodies(world, entity)
    world.refresh_kinematics()
    geoms = np.flatnonzero(np.isin(world.model.geom_bodyid, bodies) & _collision_mask(world))
    lower, upper = _geom_boxes(world, geoms)
    return [Aabb(_vec(lo), _vec(hi)) for lo, hi in zip(lower, upper, strict=True)]


def entity_box(world: PhysicsWorld, entity: str) -> Aabb:
    """The world-frame box around all of ``entity``'s collision geometry (see the module docstring for an entity
    without any).

    Raises:
        WorldError: NOT_FOUND, no such entity.
    """
    boxes = collision_boxes(world, entity)
    if boxes:
        lower = np.min([b.lower for b in boxes], axis=0)
        upper = np.max([b.upper for b in boxes], axis=0)
        return Aabb(_vec(lower), _vec(upper))
    origins = world.data.xpos[_entity_bodies(world, entity)]
    if len(origins) == 0:
        raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no links in the world")
    return Aabb(_vec(origins.min(axis=0)), _vec(origins.max(axis=0)))


def model_box(model: Model) -> Aabb:
    """The box around a model's collision geometry in its own model frame, as it would be spawned (joints at
    their zero positions), by building it alone in a scratch world; for simulation_interfaces' GetSpawnables.

    Raises:
        WorldError: the model cannot be built (BUILD_FAILED, with the reason).
    """
    from ._world import PhysicsWorld

    scratch = PhysicsWorld(World(name="bounds"))
    scratch.add_entity(model, name="model", X_WM=Pose())
    return entity_box(scratch, "model")


def overlapping(
    world: PhysicsWorld,
    names: Sequence[str],
    *,
    box: tuple[Sequence[float], Sequence[float]] | None = None,
    sphere: tuple[Sequence[float], float] | None = None,
) -> list[str]:
    """The entities of ``names`` (in their order) one of whose collision geoms' boxes (or, with none, the box of
    their links' origins) overlaps the world-frame ``box`` (two opposite corners) or ``sphere`` (centre,
    radius), touching included; names no longer in the world are left out. Every geom's box is computed at once
    (a query over a world of thousands of entities is one pass over its geoms)."""
    present = [n for n in names if n in world.entities]
    if box is None and sphere is None:
        return present
    world.refresh_kinematics()
    owner = np.full(world.model.nbody, -1)
    for i, name in enumerate(present):
        owner[_entity_bodies(world, name)] = i
    geoms = np.flatnonzero(_collision_mask(world) & (owner[world.model.geom_bodyid] >= 0))
    lower, upper = _geom_boxes(world, geoms)
    if box is not None:
        q_lo, q_hi = np.minimum(box[0], box[1]), np.maximum(box[0], box[1])

        def hits(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
            return np.all((lo <= q_hi) & (q_lo <= hi), axis=1)
    else:
        assert sphere is not None
        centre, radius = np.asarray(sphere[0], dtype=float), float(sphere[1])

        def hits(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
            return np.sum((np.clip(centre, lo, hi) - centre) ** 2, axis=1) <= radius * radius

    owners = owner[world.model.geom_bodyid[geoms]]
    kept = set(owners[hits(lower, upper)].tolist())
    for i in set(range(len(present))) - set(owners.tolist()):  # no collision geometry: its links' origins
        b = entity_box(world, present[i])
        if hits(np.array([b.lower]), np.array([b.upper]))[0]:
            kept.add(i)
    return [n for i, n in enumerate(present) if i in kept]
