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

    def overlaps_box(self, lower: Sequence[float], upper: Sequence[float]) -> bool:
        """Whether this box and the box between ``lower`` and ``upper`` share a point (touching counts)."""
        return all(self.lower[i] <= upper[i] and lower[i] <= self.upper[i] for i in range(3))

    def overlaps_sphere(self, centre: Sequence[float], radius: float) -> bool:
        """Whether this box and the ball of ``radius`` about ``centre`` share a point (touching counts)."""
        nearest = [min(max(centre[i], self.lower[i]), self.upper[i]) for i in range(3)]
        return sum((nearest[i] - centre[i]) ** 2 for i in range(3)) <= radius * radius


def _vec(v: np.ndarray) -> Vec:
    return (float(v[0]), float(v[1]), float(v[2]))


def _entity_bodies(world: PhysicsWorld, entity: str) -> list[int]:
    """MuJoCo body ids of an entity's links (NOT_FOUND when there is no such entity)."""
    e = world.entities.get(entity)
    if e is None:
        raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
    ids = (mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_BODY, b) for b in e.built.bodies.values())
    return [i for i in ids if i >= 0]


def collision_boxes(world: PhysicsWorld, entity: str) -> list[Aabb]:
    """The world-frame box of each collision geom of ``entity`` (every convex part of a decomposed mesh), at
    the current state; empty when it has none.

    Raises:
        WorldError: NOT_FOUND, no such entity.
    """
    bodies = _entity_bodies(world, entity)
    world.refresh_kinematics()
    m, d = world.model, world.data
    mine = np.isin(m.geom_bodyid, bodies)
    groups = m.geom_group
    out = []
    for g in np.flatnonzero(mine):
        if groups[g] in (VISUAL_GROUP, PROXY_GROUP):  # visuals are no collision; a proxy repeats its collision
            continue
        R = d.geom_xmat[g].reshape(3, 3)
        if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE:
            centre, half = np.zeros(3), np.array([m.geom_size[g][0], m.geom_size[g][1], 0.0])
        else:
            centre, half = m.geom_aabb[g][:3], m.geom_aabb[g][3:]
        c = d.geom_xpos[g] + R @ centre
        h = np.abs(R) @ half
        out.append(Aabb(_vec(c - h), _vec(c + h)))
    return out


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
    radius); names no longer in the world are left out."""
    out = []
    for name in names:
        if name not in world.entities:
            continue
        parts = collision_boxes(world, name) or [entity_box(world, name)]
        if box is not None:
            lower = [min(box[0][i], box[1][i]) for i in range(3)]
            upper = [max(box[0][i], box[1][i]) for i in range(3)]
            hit = any(p.overlaps_box(lower, upper) for p in parts)
        elif sphere is not None:
            hit = any(p.overlaps_sphere(sphere[0], sphere[1]) for p in parts)
        else:
            hit = True
        if hit:
            out.append(name)
    return out
