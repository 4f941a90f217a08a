"""Models a world names but no package ships (issue 49 item 4): read where Gazebo keeps its downloads, and when a
model is not there, one error-level line saying how to get it; the world loads without it, as gz-sim and Gazebo
Classic go on. Nothing is downloaded.

- gz-sim: Fuel's local cache as gz-fuel-tools lays it out (src/ClientConfig.cc: ``GZ_FUEL_CACHE_PATH``, else
  ``cache: path:`` of ``~/.gz/fuel/config.yaml``, else ``~/.gz/fuel``; ModelIdentifier::UniqueName:
  ``<cache>/<host>/<owner>/models/<name>/<version>`` lowercased), with files inside a model named by Fuel's
  ``.../<version>/files/<path>`` URLs (FuelClient::CachedModelFile).
- Gazebo Classic: ``model://NAME`` from ``~/.gazebo/models`` (gazebo/common/SystemPaths.cc puts it first among the
  model paths; its ModelDatabase downloads from GAZEBO_MODEL_DATABASE_URI into it).
"""

from __future__ import annotations

from pathlib import Path

import pytest
import trimesh
from _fuel_depot import DEPOT_URI, fuel_depot

from gazelle.description import ErrorCode, Pose, Severity, load_string


def depot_world() -> str:
    """nav2_minimal_tb4_sim's depot.sdf in shape: a Fuel include with a whitespace-padded URI and
    experimental:params removing visuals."""
    return f"""<?xml version="1.0"?>
<sdf version="1.6" xmlns:experimental="http://sdformat.org/schemas/experimental">
  <world name="depot">
    <include>
      <uri>
        {DEPOT_URI}
      </uri>
      <experimental:params>
        <visual element_id="main::ROOF_visual" action="remove"/>
      </experimental:params>
    </include>
  </world>
</sdf>"""


@pytest.fixture
def home(tmp_path: Path, monkeypatch) -> Path:
    """An empty home: no Fuel cache, no ~/.gazebo, no variable naming either."""
    home = tmp_path / "home"
    home.mkdir()
    monkeypatch.setenv("HOME", str(home))
    for var in ("GZ_FUEL_CACHE_PATH", "IGN_FUEL_CACHE_PATH", "GAZEBO_MODEL_PATH", "GAZEBO_MODEL_DATABASE_URI"):
        monkeypatch.delenv(var, raising=False)
    return home


def test_a_fuel_model_in_gz_fuel_cache_path_comes_with_the_meshes_its_file_urls_name(home, tmp_path, monkeypatch):
    folder = fuel_depot(tmp_path / "cache")
    monkeypatch.setenv("GZ_FUEL_CACHE_PATH", str(tmp_path / "cache"))
    result = load_string(depot_world())
    assert [d for d in result.diagnostics if d.code is not ErrorCode.ELEMENT_UNSUPPORTED] == []
    [depot] = result.world.models
    [link] = depot.links
    mesh = link.collisions[0].geometry
    assert Path(mesh.path) == (folder / "meshes" / "depot.stl").resolve(), mesh  # type: ignore[union-attr]


def test_the_cache_a_fuel_config_file_names_is_read_and_gz_fuel_cache_path_wins_over_it(home, tmp_path, monkeypatch):
    """ClientConfig::LoadConfig: ``cache: path:`` in ~/.gz/fuel/config.yaml moves the cache; GZ_FUEL_CACHE_PATH
    overrides the file."""
    fuel_depot(tmp_path / "elsewhere")
    (home / ".gz" / "fuel").mkdir(parents=True)
    (home / ".gz" / "fuel" / "config.yaml").write_text(
        f"---\nservers:\n  -\n    url: https://fuel.gazebosim.org\ncache:\n  path: {tmp_path / 'elsewhere'}\n"
    )
    assert [m.name for m in load_string(depot_world()).world.models] == ["Depot"]
    monkeypatch.setenv("GZ_FUEL_CACHE_PATH", str(tmp_path / "empty"))
    (tmp_path / "empty").mkdir()
    result = load_string(depot_world())
    assert result.world.models == () and len(result.diagnostics) == 1


def test_a_fuel_model_in_no_cache_is_one_error_line_saying_how_to_get_it_and_the_world_loads(home):
    world = depot_world().replace("</world>", "<include><uri>model://ground_plane</uri></include></world>")
    result = load_string(world)
    [d] = result.diagnostics
    assert d.severity is Severity.SKIPPED and d.code is ErrorCode.URI_UNRESOLVED
    line = d.format()
    assert "\n" not in line and ": error: [URI_UNRESOLVED] Fuel model 'OpenRobotics/Depot'" in line, line
    assert f'`gz fuel download -u "{DEPOT_URI}"`' in line and "GZ_FUEL_CACHE_PATH" in line
    assert [m.name for m in result.world.models] == ["ground_plane"]  # the rest of the world is there


def test_a_ball_rests_on_the_cached_fuel_depots_floor(home, tmp_path, monkeypatch, make_sim):
    """The Depot's floor is its mesh (the depot world has no ground plane): a ball dropped in the hall rests on the
    slab's top at z = 0 (the mesh named by a Fuel file URL was left out before: the ball fell through)."""
    fuel_depot(tmp_path / "cache")
    monkeypatch.setenv("GZ_FUEL_CACHE_PATH", str(tmp_path / "cache"))
    sim = make_sim(load_string(depot_world()).world)
    ball = (
        '<sdf version="1.9"><model name="b"><link name="l"><inertial><mass>1</mass></inertial><collision name="c">'
        "<geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link></model></sdf>"
    )
    sim.spawn(load_string(ball).value, name="b", pose=Pose((-3.0, 0.0, 0.5)))
    sim.step(1500)
    assert sim.world.entity_state("b").pose.position[2] == pytest.approx(0.1, abs=0.01)


def test_a_classic_model_in_dot_gazebo_models_is_included(home):
    folder = home / ".gazebo" / "models" / "jersey_barrier"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text("<model><name>Jersey Barrier</name><sdf>model.sdf</sdf></model>")
    (folder / "model.sdf").write_text(
        '<sdf version="1.4"><model name="jersey_barrier"><static>true</static><link name="link"><collision name="c">'
        "<geometry><box><size>4 0.6 1</size></box></geometry></collision></link></model></sdf>"
    )
    result = load_string(
        '<sdf version="1.4"><world name="default"><include><uri>model://jersey_barrier</uri>'
        "<pose>1 2 0 0 0 2.36</pose></include></world></sdf>"
    )
    assert result.diagnostics == ()
    assert [m.name for m in result.world.models] == ["jersey_barrier"]


def test_a_classic_model_found_nowhere_is_one_error_line_naming_the_model_database(home, monkeypatch):
    monkeypatch.setenv("GAZEBO_MODEL_DATABASE_URI", "http://models.example.org")
    result = load_string(
        '<sdf version="1.4"><world name="default"><include><uri>model://ground_plane</uri></include>'
        "<include><uri>model://jersey_barrier</uri></include></world></sdf>"
    )
    [d] = result.diagnostics
    assert d.severity is Severity.SKIPPED
    line = d.format()
    assert "error: [URI_UNRESOLVED] model 'jersey_barrier' is not on the model paths" in line, line
    assert str(home / ".gazebo" / "models") in line and "http://models.example.org" in line
    assert "github.com/osrf/gazebo_models" in line and "\n" not in line
    assert [m.name for m in result.world.models] == ["ground_plane"]


def test_a_saved_classic_world_names_each_missing_database_model_once_and_reads_those_in_dot_gazebo_models(home):
    """Husky's playpen is a world Gazebo Classic saved: the database's models are inlined and their meshes named
    ``model://construction_barrel/meshes/...``, 18 barrels. Each model found nowhere is one error line (not one
    warning per mesh); a model in ~/.gazebo/models gives its mesh."""
    folder = home / ".gazebo" / "models" / "construction_cone" / "meshes"
    folder.mkdir(parents=True)
    trimesh.creation.box(extents=(0.4, 0.4, 0.7)).export(folder / "cone.stl")

    def barrel(i: int, model: str, mesh: str) -> str:
        uri = f"<mesh><uri>model://{model}/meshes/{mesh}</uri></mesh>"
        return (
            f'<model name="{model}_{i}"><static>true</static><link name="link"><collision name="c"><geometry>{uri}'
            f'</geometry></collision><visual name="v"><geometry>{uri}</geometry></visual></link></model>'
        )

    models = "".join(barrel(i, "construction_barrel", "construction_barrel.dae") for i in range(3))
    result = load_string(
        f'<sdf version="1.6"><world name="default">{models}{barrel(0, "construction_cone", "cone.stl")}</world></sdf>'
    )
    [d] = result.diagnostics
    assert d.severity is Severity.SKIPPED and "model 'construction_barrel' is not on the model paths" in d.message
    cone = result.world.models[-1].links[0].collisions[0].geometry
    assert Path(cone.path) == (folder / "cone.stl").resolve()  # type: ignore[union-attr]
