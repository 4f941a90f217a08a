"""Worlds at run time, in process: ``Simulation.worlds`` replaces the world and every entity, or takes it away,
while the simulation object, its bus listeners and its step listeners stay (the ROS side is
tests/integration/test_worlds_at_run_time.py)."""

from __future__ import annotations

import dataclasses
import threading

import pytest

from gazelle.description import Model, Pose, World, load_string
from gazelle.physics import ErrorKind, WorldError
from gazelle.sim import MAX_WORLD_MODELS, WorldBusy
from gazelle.worlds import default_world

BOX_SDF = """<?xml version="1.0"?>
<sdf version="1.9"><model name="crate"><link name="l"><inertial><mass>1</mass></inertial>
<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>"""


_CRATE = load_string(BOX_SDF).model


def box(name: str, z: float = 1.0) -> Model:
    return dataclasses.replace(_CRATE, name=name, pose=Pose((0.0, 0.0, z)))


def world_of(name: str, *models: Model) -> World:
    return World(name=name, models=models)


def test_load_replaces_the_world_and_every_entity_and_stops_the_clock(make_sim) -> None:
    sim = make_sim()
    sim.spawn(load_string(BOX_SDF).model, name="spawned", pose=Pose((0.0, 0.0, 1.0)))
    sim.step(50)
    heard: list[float] = []
    sim.add_step_listener(lambda info: heard.append(info.sim_time_sec))
    generation = sim.world.generation
    loaded = sim.worlds.load(world_of("shelves", box("shelf_a"), box("shelf_b")), uri="file:///x/shelves.sdf")
    assert loaded.name == "shelves" and loaded.uri == "file:///x/shelves.sdf"
    assert sorted(sim.world.entities) == ["shelf_a", "shelf_b"]
    assert sim.world_name == "shelves"
    assert sim.world.generation > generation  # what was cached against the old world is stale in the new
    assert sim.world.time == 0.0 and sim.iterations == 0 and sim.paused  # the standard's STOPPED
    assert sim.worlds.current is not None and sim.worlds.current.name == "shelves"
    sim.step(10)
    assert heard and heard[-1] == pytest.approx(10 * sim.world.timestep)  # the step listener stayed
    # a reset after a load goes back to the loaded world, not the first
    sim.spawn(load_string(BOX_SDF).model, name="later", pose=Pose((1.0, 0.0, 1.0)))
    sim.reset()
    assert sorted(sim.world.entities) == ["shelf_a", "shelf_b"]


def test_unload_leaves_an_empty_simulation_that_refuses_spawns(make_sim) -> None:
    sim = make_sim()
    sim.worlds.unload()
    assert sim.worlds.current is None and not sim.world.entities
    with pytest.raises(WorldError) as err:
        sim.spawn(load_string(BOX_SDF).model)
    assert err.value.kind is ErrorKind.INCORRECT_STATE and "no world is loaded" in str(err.value)
    with pytest.raises(WorldError) as again:
        sim.worlds.unload()
    assert again.value.kind is ErrorKind.NOT_FOUND
    sim.worlds.load(default_world(), uri="empty.sdf")
    assert "ground_plane" in sim.world.entities
    sim.spawn(load_string(BOX_SDF).model)
    assert "crate" in sim.world.entities


def test_a_world_over_the_bound_is_refused_and_nothing_changes(make_sim) -> None:
    sim = make_sim()
    before = sorted(sim.world.entities)
    big = world_of("huge", *(box(f"b{i}") for i in range(MAX_WORLD_MODELS + 1)))
    with pytest.raises(WorldError, match=f"more than the {MAX_WORLD_MODELS}"):
        sim.worlds.load(big)
    assert sorted(sim.world.entities) == before and sim.worlds.current is sim.worlds.first


def test_a_load_is_refused_while_a_client_steps_and_a_step_while_a_load_runs(make_sim) -> None:
    sim = make_sim()
    with sim.worlds.stepping("a SimulateSteps goal"):
        with pytest.raises(WorldBusy, match="a SimulateSteps goal is stepping the world"):
            sim.worlds.load(world_of("other", box("x")))
        with pytest.raises(WorldBusy):
            sim.worlds.unload()
    sim.worlds.load(world_of("other", box("x")))  # released: it loads
    # while a load runs (held in the sim thread here), a step on request and a second load are refused
    sim.start()
    started, release = threading.Event(), threading.Event()

    def hold() -> None:
        started.set()
        release.wait(10)

    blocker = threading.Thread(target=lambda: sim.call(hold))
    blocker.start()
    assert started.wait(10)
    loader = threading.Thread(target=lambda: sim.worlds.load(world_of("third", box("y"))))
    loader.start()
    try:
        for _ in range(500):
            if sim.worlds.loading:
                break
            threading.Event().wait(0.01)
        assert sim.worlds.loading
        with pytest.raises(WorldBusy, match="loading world 'third' is under way"):
            sim.worlds.load(world_of("fourth", box("z")))
        with pytest.raises(WorldBusy, match="under way"):
            with sim.worlds.stepping("a StepSimulation call"):
                pass
    finally:
        release.set()
        blocker.join(10)
        loader.join(30)
    assert sim.worlds.current is not None and sim.worlds.current.name == "third"
    sim.stop()


def test_a_world_that_fails_to_build_leaves_no_world(make_sim) -> None:
    sim = make_sim()
    bad = dataclasses.replace(_CRATE, name="bad", pose=Pose((float("nan"), 0.0, 0.0)))
    with pytest.raises(WorldError):
        sim.worlds.load(world_of("broken", box("fine"), bad))
    assert sim.worlds.current is None and not sim.world.entities
