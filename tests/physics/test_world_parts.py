"""A world's parts (its queries and its state) read the world's model, data and entities through the world, written
once (gazelle/physics/_world_part.py): after a recompile (an entity added or removed) each part sees the world's new
model and data, never the ones it was made with."""

from __future__ import annotations

from gazelle.description import Pose, World, load_string
from gazelle.physics import PhysicsWorld
from gazelle.physics._queries import WorldQueries
from gazelle.physics._state import WorldState
from gazelle.physics._world_part import WorldPart

BOX = (
    '<sdf version="1.9"><model name="crate"><link name="l"><inertial><mass>1</mass></inertial>'
    '<collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision></link></model></sdf>'
)


def test_the_parts_see_the_world_after_each_recompile() -> None:
    world = PhysicsWorld(World(name="parts"))
    for _ in range(2):
        before = world.model
        world.add_entity(load_string(BOX).model, name=f"crate{len(world.entities)}", X_WM=Pose((0.0, 0.0, 1.0)))
        assert world.model is not before  # recompiled
        for part in (world.queries, world.state):
            assert part.model is world.model and part.data is world.data and part.entities is world.entities
    world.remove_entity("crate0")
    assert world.state.model is world.model and list(world.queries.entities) == ["crate1"]
    assert world.state.state_digest() == world.state.state_digest()


def test_the_forwarding_is_written_once() -> None:
    for part in (WorldQueries, WorldState):
        assert issubclass(part, WorldPart)
        assert not {"model", "data", "entities"} & set(vars(part)), f"{part.__name__} forwards the world itself"
