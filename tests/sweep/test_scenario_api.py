"""Issue 50 item 9: a sweep scenario written against gazelle's public names (``from gazelle import ...``), a
cheap ``import gazelle``, and ``runs.parquet`` read with pyarrow alone, as docs/sweeps.md shows."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

from _paths import REPO

SCENARIO = '''
import math

from gazelle import Pose, Simulation, load_string, quat_to_rpy

BOX = """<?xml version="1.0"?>
<sdf version="1.9"><model name="box"><link name="l">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
</link></model></sdf>"""


def drop(sim: Simulation, params: dict, seed: int) -> dict:
    sim.spawn(load_string(BOX, format="sdf").value, name="box", pose=Pose((0.0, 0.0, float(params["z"]))))
    sim.step(round(1.0 / sim.world.timestep))
    state = sim.world.entity_state("box").pose
    roll = quat_to_rpy(state.orientation)[0]
    return {"z_m": state.position[2], "passed": abs(state.position[2] - 0.1) < 0.01 and abs(roll) < math.radians(1)}
'''


def test_the_public_names_load_on_first_use_and_import_gazelle_loads_none_of_them() -> None:
    probe = textwrap.dedent(
        """
        import sys
        import gazelle
        heavy = [m for m in ("mujoco", "rclpy", "gazelle.sim", "gazelle.sweep", "numpy") if m in sys.modules]
        assert not heavy, heavy
        from gazelle import DiffDrive, Pose, ResourceResolver, Simulation, load, load_string, quat_to_rpy
        from gazelle.sim import Simulation as Internal
        assert Simulation is Internal and sorted(gazelle.__all__) == gazelle.__all__
        print("ok")
        """
    )
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "ok", out.stdout + out.stderr


def test_a_scenario_on_the_public_names_sweeps_and_its_table_reads_with_pyarrow(tmp_path: Path) -> None:
    """The reader docs/sweeps.md gives (`pyarrow.parquet.read_table(path).to_pylist()`; pyarrow is a dependency,
    pandas is not) gives the rows of runs.jsonl."""
    (tmp_path / "drop.py").write_text(SCENARIO)
    out = tmp_path / "out"
    run = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{tmp_path}/drop.py::drop", "--param", "z=0.5,1.0",
         "--seeds", "0:2", "-j", "1", "--out", str(out)],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert run.returncode == 0, run.stdout + run.stderr
    import pyarrow.parquet

    rows = pyarrow.parquet.read_table(out / "runs.parquet").to_pylist()
    logged = [json.loads(line) for line in (out / "runs.jsonl").read_text().splitlines()]
    assert len(rows) == 4 and all(r["status"] == "passed" for r in rows), rows
    assert sorted((r["key"], r["metric.z_m"]) for r in rows) == sorted((r["key"], r["metric.z_m"]) for r in logged)


def test_the_examples_import_only_public_names() -> None:
    """A user copies the examples: their gazelle imports are the package root's or a documented package's."""
    for example in (REPO / "examples" / "sweeps").glob("*.py"):
        text = example.read_text()
        assert "from gazelle.systems.diff_drive" not in text and "expand_xacro_bounded" not in text, example
