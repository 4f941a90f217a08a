"""Issue 26: what real repositories hit, each against Gazebo's own behaviour."""

from __future__ import annotations

from pathlib import Path

import pytest
from _paths import REAL

from gazelle.description import Pose, ResourceResolver, load, load_string
from gazelle.sim import Simulation

CLASSIC_WORLD = """<?xml version="1.0"?>
<sdf version="1.6"><world name="default">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>
</world></sdf>"""

BALL = """<sdf version="1.6"><model name="ball"><link name="l">
  <inertial><mass>1</mass><inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.004</izz></inertia></inertial>
  <collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
</link></model></sdf>"""


def test_classic_stock_ground_plane_and_sun_are_built_in(monkeypatch, tmp_path: Path) -> None:
    """Gazebo Classic installs model://ground_plane and model://sun with itself: a Classic world (TurtleBot3's,
    empty.world) that includes them has a floor in gazelle too (it fell to z = -245 m in 7 s)."""
    for var in ("GAZELLE_RESOURCE_PATH", "GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "AMENT_PREFIX_PATH"):
        monkeypatch.delenv(var, raising=False)
    world_file = tmp_path / "empty.world"
    world_file.write_text(CLASSIC_WORLD)
    result = load(world_file)
    world = result.value
    assert [m.name for m in world.models] == ["ground_plane"]
    assert [light.name for light in world.lights] == ["sun"]
    assert not [d for d in result.diagnostics if "ground_plane" in d.message or "sun" in d.message]
    sim = Simulation(world, rtf=0)
    try:
        sim.spawn(load_string(BALL).value, name="ball", pose=Pose((0.0, 0.0, 0.5)))
        sim.step(2000)
        z = sim.world.entity_state("ball").pose.position[2]
        assert z == pytest.approx(0.1, abs=0.01)
    finally:
        sim.stop()


def test_an_installed_ground_plane_model_is_used_before_the_built_in_one() -> None:
    resolver = ResourceResolver(extra_paths=[REAL / "gazebo_models" / "models"], env={})
    world = load_string(CLASSIC_WORLD, resolver=resolver).value
    (ground,) = world.models
    assert "gazebo_models" in ground.source_file
