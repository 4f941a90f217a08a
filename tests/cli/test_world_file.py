"""``gazelle sim WORLD`` finds WORLD where ``gz sim`` does (gz-sim Harmonic's cmdsim.rb.in): the path as given,
then GZ_SIM_RESOURCE_PATH (IGN_GAZEBO_RESOURCE_PATH only when it is unset), then the installed worlds; the
command as a process, and ros_gz_sim's gz_sim.launch.py with a bare name in gz_args."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from gazelle.cli._sim import load_world
from gazelle.description import ModelLoadError
from gazelle.worlds import default_world

WAREHOUSE = """<?xml version="1.0"?>
<sdf version="1.9">
  <world name="{name}">
    <physics name="1ms" type="ignored"><max_step_size>0.001</max_step_size><real_time_factor>1.0</real_time_factor></physics>
    <model name="ground_plane"><static>true</static>
      <link name="link"><collision name="c"><geometry><plane><normal>0 0 1</normal></plane></geometry></collision></link>
    </model>
  </world>
</sdf>
"""


@pytest.fixture
def worlds(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    """Two resource folders holding warehouse.sdf (the first one's world is 'first'), no search variables set,
    and a current folder with nothing in it."""
    for name in ("first", "second"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "warehouse.sdf").write_text(WAREHOUSE.format(name=name))
    (tmp_path / "cwd").mkdir()
    monkeypatch.chdir(tmp_path / "cwd")
    for var in ("GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH"):
        monkeypatch.delenv(var, raising=False)
    return tmp_path


def test_a_bare_world_name_is_found_on_gz_sim_resource_path_in_its_order(worlds, monkeypatch):
    monkeypatch.setenv("GZ_SIM_RESOURCE_PATH", f"{worlds / 'missing'}::{worlds / 'first'}:{worlds / 'second'}")
    assert load_world(Path("warehouse.sdf"), {}).name == "first"
    # the path as given comes first
    (worlds / "cwd" / "warehouse.sdf").write_text(WAREHOUSE.format(name="here"))
    assert load_world(Path("warehouse.sdf"), {}).name == "here"


def test_the_ignition_variable_counts_only_when_gz_sim_resource_path_is_unset(worlds, monkeypatch, capsys):
    monkeypatch.setenv("IGN_GAZEBO_RESOURCE_PATH", str(worlds / "second"))
    assert load_world(Path("warehouse.sdf"), {}).name == "second"
    assert "deprecated environment variable [IGN_GAZEBO_RESOURCE_PATH]" in capsys.readouterr().err
    monkeypatch.setenv("GZ_SIM_RESOURCE_PATH", "")  # set, even empty: gz reads it alone
    with pytest.raises(ModelLoadError, match=r"no such world file: warehouse\.sdf \(searched the path as given, "):
        load_world(Path("warehouse.sdf"), {})


def test_installed_worlds_come_last_and_a_missing_world_names_the_search(worlds, monkeypatch):
    assert load_world(Path("empty.sdf"), {}) == default_world()
    (worlds / "first" / "empty.sdf").write_text(WAREHOUSE.format(name="my_empty"))
    monkeypatch.setenv("GZ_SIM_RESOURCE_PATH", str(worlds / "first"))
    assert load_world(Path("empty.sdf"), {}).name == "my_empty"
    with pytest.raises(ModelLoadError) as err:
        load_world(Path("nowhere.sdf"), {})
    assert str(err.value).count("\n") == 0
    assert "GZ_SIM_RESOURCE_PATH (1 folder)" in str(err.value)
    assert "empty.sdf" in str(err.value)


def test_gazelle_sim_with_a_world_nowhere_is_one_line_and_status_1(worlds):
    env = {**os.environ, "GZ_SIM_RESOURCE_PATH": str(worlds / "second")}
    env.pop("IGN_GAZEBO_RESOURCE_PATH", None)
    bad = subprocess.run([sys.executable, "-m", "gazelle.cli", "sim", "--no-viewer", "nowhere.sdf"], env=env,
                         capture_output=True, text=True, timeout=60, cwd=worlds / "cwd")  # fmt: skip
    assert bad.returncode == 1
    assert "Traceback" not in bad.stderr
    assert bad.stderr.strip().splitlines()[-1].startswith("nowhere.sdf: error: [FILE_NOT_FOUND] no such world file")
