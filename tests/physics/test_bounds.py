"""The world-frame boxes of an entity's collision geometry and the overlap tests (gazelle/physics/_bounds.py), which
simulation_interfaces' GetEntityBounds, GetSpawnables and the ``bounds`` entity filter answer with (issue 52)."""

from __future__ import annotations

import math

import pytest

from gazelle.description import Pose, World, load_string, quat_from_rpy
from gazelle.physics import (
    Entity,
    PhysicsWorld,
    StagedRequest,
    WorldError,
    collision_boxes,
    entity_box,
    overlapping,
)


def sdf(name: str, body: str, static: bool = False) -> str:
    return (
        f'<sdf version="1.9"><model name="{name}"><static>{str(static).lower()}</static>'
        f'<link name="l"><inertial><mass>1</mass></inertial>{body}</link></model></sdf>'
    )


BOX = '<collision name="c"><pose>0 0 0.5 0 0 0</pose><geometry><box><size>1 2 1</size></box></geometry></collision>'
SPHERE = '<collision name="c"><geometry><sphere><radius>0.25</radius></sphere></geometry></collision>'
VISUAL_ONLY = '<visual name="v"><geometry><box><size>5 5 5</size></box></geometry></visual>'
PLANE = '<collision name="c"><geometry><plane><normal>0 0 1</normal><size>10 4</size></plane></geometry></collision>'


@pytest.fixture
def world() -> PhysicsWorld:
    w = PhysicsWorld(World(name="bounds"), visual_geoms=True)
    w.add_entity(load_string(sdf("crate", BOX)).model, name="crate", X_WM=Pose((1.0, 0.0, 0.0)))
    turned = Pose((0.0, 5.0, 0.0), quat_from_rpy(0.0, 0.0, math.pi / 2))
    w.add_entity(load_string(sdf("turned", BOX)).model, name="turned", X_WM=turned)
    w.add_entity(load_string(sdf("ball", SPHERE)).model, name="ball", X_WM=Pose((-3.0, 0.0, 1.0)))
    w.add_entity(load_string(sdf("ghost", VISUAL_ONLY, True)).model, name="ghost", X_WM=Pose((7.0, 7.0, 7.0)))
    w.add_entity(load_string(sdf("ground", PLANE, True)).model, name="ground", X_WM=Pose())
    return w


def close(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return all(abs(x - y) < 1e-6 for x, y in zip(a, b, strict=True))


def test_a_box_in_the_world_frame_follows_the_entity_pose(world: PhysicsWorld) -> None:
    b = entity_box(world, "crate")
    assert close(b.lower, (0.5, -1.0, 0.0)) and close(b.upper, (1.5, 1.0, 1.0))
    t = entity_box(world, "turned")  # turned a quarter about z: the 1 x 2 footprint is 2 x 1
    assert close(t.lower, (-1.0, 4.5, 0.0)) and close(t.upper, (1.0, 5.5, 1.0))
    s = entity_box(world, "ball")
    assert close(s.lower, (-3.25, -0.25, 0.75)) and close(s.upper, (-2.75, 0.25, 1.25))


def test_visuals_are_no_collision_and_a_plane_is_its_drawn_rectangle(world: PhysicsWorld) -> None:
    assert collision_boxes(world, "ghost") == []
    g = entity_box(world, "ghost")  # no collision: the point of its (one) link's origin, not the 5 m visual
    assert close(g.lower, (7.0, 7.0, 7.0)) and close(g.upper, (7.0, 7.0, 7.0))
    p = entity_box(world, "ground")
    assert close(p.lower, (-5.0, -2.0, 0.0)) and close(p.upper, (5.0, 2.0, 0.0))


def test_an_unknown_entity_is_not_found(world: PhysicsWorld) -> None:
    with pytest.raises(WorldError, match="nobody"):
        entity_box(world, "nobody")


def test_overlap_with_a_box_and_a_sphere(world: PhysicsWorld) -> None:
    names = list(world.entities)
    # a box around x = 1 .. 2 above the ground touches the crate only (the ground is at z = 0)
    assert overlapping(world, names, box=((2.0, 1.0, 0.5), (1.2, -1.0, 3.0))) == ["crate"]
    # a sphere that reaches the ball's box but not the crate's
    assert overlapping(world, names, sphere=((-3.0, 0.0, 2.0), 0.8)) == ["ball"]
    assert overlapping(world, names, sphere=((-3.0, 0.0, 2.0), 0.7)) == []
    # a sphere at the ghost's origin: an entity without collision overlaps by its links' origins
    assert overlapping(world, names, sphere=((7.0, 7.0, 7.5), 0.6)) == ["ghost"]
    assert "ground" in overlapping(world, names, box=((-1.0, -1.0, -0.1), (0.0, 0.0, 0.1)))


def test_a_query_over_many_entities_finds_exactly_those_it_touches() -> None:
    """One pass over every geom: 400 crates on a 1 m grid, a sphere of 1.2 m about (10, 10, 0.5) touches the
    crates (1 x 2 x 1, bottom at z = 0) whose box comes within 1.2 m of it."""
    w = PhysicsWorld(World(name="grid"))
    crate = load_string(sdf("crate", BOX)).model
    grid = [
        StagedRequest(crate, f"c{i}_{j}", Pose((float(i), float(3 * j), 0.0))) for i in range(20) for j in range(20)
    ]
    staged = w.stage_many(grid)
    w.commit([e for e in staged if isinstance(e, Entity)])  # one build for all 400
    centre, r = (10.0, 10.0, 0.5), 1.2

    def touches(i: int, j: int) -> bool:
        lo, hi = (i - 0.5, 3 * j - 1.0, 0.0), (i + 0.5, 3 * j + 1.0, 1.0)
        return sum((min(max(c, a), b) - c) ** 2 for c, a, b in zip(centre, lo, hi)) <= r * r

    expected = [f"c{i}_{j}" for i in range(20) for j in range(20) if touches(i, j)]
    assert expected and overlapping(w, list(w.entities), sphere=(centre, r)) == expected
