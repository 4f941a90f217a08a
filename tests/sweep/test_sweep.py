"""Issue 31: sweeps. A scenario over a grid of parameters and seeds on a pool of processes or on Ray,
rows written as runs finish, --resume, a report a person reads, and bad input as one line."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import cast

import pytest
from _paths import REPO

from gazelle.sweep import RunSpec, SweepError, grid, parse_param, parse_seeds, read_rows, run_one, sweep

SCENARIO = '''
import math
from gazelle.description import Pose, load_string

BOX = """<?xml version="1.0"?>
<sdf version="1.9"><model name="box"><link name="l">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry>
    <surface><friction><ode><mu>{mu}</mu><mu2>{mu}</mu2></ode></friction></surface></collision>
</link></model></sdf>"""


def slide(sim, params, seed):
    """A box pushed along the ground: how far it slides with the given friction and a push of the seed."""
    mu = float(params["mu"])
    sim.spawn(load_string(BOX.format(mu=mu)).value, name="box", pose=Pose((0.0, 0.0, 0.1)))
    sim.step(100)
    sim.world.set_entity_state("box", sim.world.entity_state("box").pose, (1.0 + seed * 0.1, 0.0, 0.0))
    sim.step(1000)
    x = sim.world.entity_state("box").pose.position[0]
    return {"distance": x, "state": sim.world.state_digest(), "passed": x < 0.5}


def dies(sim, params, seed):
    """Seed 1's worker is killed under it (as the OOM killer would); seed 3 never ends."""
    import os, signal, time
    if seed == 1:
        os.kill(os.getpid(), signal.SIGKILL)
    if seed == 3:
        while True:
            time.sleep(0.01)
    return {"passed": True}


def boom(sim, params, seed):
    if seed == 1:
        raise RuntimeError("the scenario failed on purpose")
    return {"passed": True, "value": seed}
'''


@pytest.fixture
def scenario(tmp_path: Path) -> Path:
    path = tmp_path / "scenario.py"
    path.write_text(SCENARIO)
    return path


def test_parameters_and_seeds_are_read_as_the_command_line_writes_them() -> None:
    assert parse_param("friction=0.4,0.8,1.2") == ("friction", [0.4, 0.8, 1.2])
    assert parse_param("start_x=-1:1:5") == ("start_x", [-1.0, -0.5, 0.0, 0.5, 1.0])
    assert parse_param("mode=fast,slow") == ("mode", ["fast", "slow"])
    assert parse_seeds("0:4") == [0, 1, 2, 3] and parse_seeds("7") == [7] and parse_seeds("1,5") == [1, 5]
    for bad in ("friction", "=1,2", "x=1:2", "x=a:b:3", "x=0:1:0"):
        with pytest.raises(SweepError, match="--param"):
            parse_param(bad)
    with pytest.raises(SweepError, match="--seeds"):
        parse_seeds("a:b")
    runs = grid([("a", [1, 2]), ("b", ["x", "y", "z"])], [0, 1])
    assert len(runs) == 12 and len({r.key for r in runs}) == 12
    with pytest.raises(SweepError, match="given twice"):
        grid([("a", [1]), ("a", [2])], [0])


def test_the_pool_and_a_run_alone_give_bit_identical_final_states(scenario: Path, tmp_path: Path) -> None:
    params = [parse_param("mu=0.1,0.5,1.0")]
    two = sweep(f"{scenario}::slide", params, [0, 1, 2], out=tmp_path / "two", jobs=2, report=False)
    one = sweep(f"{scenario}::slide", params, [0, 1, 2], out=tmp_path / "one", jobs=1, report=False)
    assert two.ran == one.ran == 9 and not [r for r in two.rows if r["status"] == "error"]
    by_key = {r["key"]: r for r in one.rows}
    for row in two.rows:
        assert row["metric.distance"] == by_key[row["key"]]["metric.distance"]  # bit for bit (floats equal)
        assert row["metric.state"] == by_key[row["key"]]["metric.state"]  # the whole physics state's digest
        alone = run_one(str(scenario), "slide", RunSpec((("mu", row["param.mu"]),), row["seed"]))
        assert alone["metric.state"] == row["metric.state"]
    # friction makes the difference the report shows: low friction slides further and fails
    slid = {r["param.mu"]: r["metric.distance"] for r in two.rows if r["seed"] == 0}
    assert slid[0.1] > slid[0.5] > slid[1.0]
    assert {r["status"] for r in two.rows} == {"passed", "failed"}


def test_a_scenario_that_raises_is_a_row_with_its_traceback_and_the_sweep_goes_on(
    scenario: Path, tmp_path: Path
) -> None:
    result = sweep(f"{scenario}::boom", [], [0, 1, 2], out=tmp_path / "boom", jobs=2)
    by_seed = {r["seed"]: r for r in result.rows}
    assert [by_seed[s]["status"] for s in (0, 1, 2)] == ["passed", "error", "passed"]
    assert "RuntimeError: the scenario failed on purpose" in by_seed[1]["error"]
    assert (tmp_path / "boom" / "report.html").is_file() and (tmp_path / "boom" / "runs.parquet").is_file()


def test_resume_runs_only_what_an_interrupted_sweep_had_not_finished(scenario: Path, tmp_path: Path) -> None:
    out = tmp_path / "resume"
    params = [parse_param("mu=0.2,0.6")]
    sweep(f"{scenario}::slide", params, [0, 1, 2], out=out, jobs=2, report=False)
    log = out / "runs.jsonl"
    lines = log.read_text().splitlines()
    log.write_text("\n".join(lines[:2]) + "\n" + lines[2][:25])  # killed while writing the third row
    again = sweep(f"{scenario}::slide", params, [0, 1, 2], out=out, jobs=2, resume=True)
    assert again.ran == 4 and len(again.rows) == 6
    assert len({r["key"] for r in read_rows(log)}) == 6

    import pyarrow.parquet as pq

    table = pq.read_table(out / "runs.parquet")
    assert table.num_rows == 6 and {"param.mu", "seed", "metric.distance", "status"} <= set(table.column_names)


def test_the_command_line_prints_one_line_for_bad_input(scenario: Path, tmp_path: Path) -> None:
    gazelle = [sys.executable, "-m", "gazelle.cli", "sweep"]
    slide = [f"{scenario}::slide", "--param", "mu=1"]
    cases = [
        ([f"{tmp_path}/nope.py::x"], "no such scenario file"),
        ([f"{scenario}::missing"], "has no function 'missing'"),
        ([f"{scenario}::slide", "--param", "mu"], "expected NAME=a,b,c"),
        ([*slide, "--ray", "http://x"], "expected local, auto or ray://"),
        # nothing listens on port 9 here: one line at once (Ray's own client waits 30 s), nothing ran
        ([*slide, "--ray", "ray://127.0.0.1:9"], "cannot connect"),
        # no cluster to join: gazelle's line, not Ray's advice about an --address flag gazelle has not
        ([*slide, "--ray", "auto"], "--ray auto: no Ray cluster to join"),
        # a wall-clock limit the interval timer cannot hold (a traceback from the worker), or none at all
        ([*slide, "--timeout", "inf"], "--timeout inf: expected seconds"),
        ([*slide, "--timeout", "1e12"], "--timeout 1e+12: expected seconds"),
        ([*slide, "--timeout", "nan"], "--timeout nan: expected seconds"),
        ([*slide, "--timeout", "-1"], "--timeout -1: expected seconds"),
    ]
    # no RAY_ADDRESS, and a Ray temp folder where `ray start` recorded no cluster (whatever this machine runs)
    env = {k: v for k, v in os.environ.items() if k != "RAY_ADDRESS"} | {"RAY_TMPDIR": str(tmp_path)}
    for args, says in cases:
        out = subprocess.run(
            [*gazelle, *args, "--out", str(tmp_path / "cli")], capture_output=True, text=True, timeout=60, env=env
        )
        assert out.returncode == 2, (args, out.stdout, out.stderr)
        assert says in out.stderr and "Traceback" not in out.stderr, out.stderr
        assert "--address" not in out.stderr, out.stderr


@pytest.mark.slow
def test_the_same_rows_on_a_local_ray_instance(scenario: Path, tmp_path: Path) -> None:
    """Ray (a local instance of 2 CPUs, the scenario shipped as text) gives the pool's rows bit for bit, and
    a run alone the same final state: 10 (parameters, seed) rows."""
    params = [parse_param("mu=0.1,1.0")]
    seeds = [0, 1, 2, 3, 4]
    pool = sweep(f"{scenario}::slide", params, seeds, out=tmp_path / "pool", jobs=2, report=False)
    on_ray = sweep(f"{scenario}::slide", params, seeds, out=tmp_path / "ray", jobs=2, ray="local", report=False)
    assert on_ray.ran == 10
    assert {r["key"]: r["metric.state"] for r in on_ray.rows} == {r["key"]: r["metric.state"] for r in pool.rows}
    for row in on_ray.rows[:3]:
        alone = run_one(str(scenario), "slide", RunSpec((("mu", row["param.mu"]),), row["seed"]))
        assert alone["metric.state"] == row["metric.state"]


@pytest.mark.slow
def test_the_example_sweep_runs_from_the_command_line_and_its_report_shows_plots_and_failures(tmp_path: Path) -> None:
    out = tmp_path / "square"
    run = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{REPO}/examples/sweeps/square.py::square",
         "--param", "wheel_mu=0.05,1.0", "--param", "speed=0.1,0.3", "--seeds", "0:2", "-j", "2", "--out", str(out)],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert run.returncode == 1, run.stdout + run.stderr  # the slippery wheels fail: exit 1, as a test run
    assert "8 runs" in run.stdout and "report:" in run.stdout
    rows = [json.loads(line) for line in (out / "runs.jsonl").read_text().splitlines()]
    failed = [r for r in rows if r["status"] == "failed"]
    assert failed and all(r["param.wheel_mu"] == 0.05 for r in failed)
    assert all((out / r["artifact.replay"]).is_file() for r in failed)  # a replay of every failing run
    assert not any("artifact.replay" in r for r in rows if r["status"] == "passed")  # and only of those

    from gazelle.viewer._browser import find_chromium

    exe = find_chromium()
    if exe is None:
        pytest.skip("no chromium")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        browser = pw.chromium.launch(
            executable_path=exe, args=["--no-sandbox", "--disable-gpu", "--disable-background-networking"]
        )
        try:
            page = browser.new_page(viewport={"width": 1000, "height": 800})
            page.goto((out / "report.html").as_uri())  # from disk: no server
            page.wait_for_selector(".plot .main-svg", timeout=30_000)
            assert page.locator(".plot").count() == 2 + 2 * 2  # pass rate by 2 params; 2 metrics x 2 params
            assert page.locator("#failures + table tr").count() == 1 + len(failed)
            # each failing run's replay is linked, and opens from disk
            links = page.locator('#failures + table a[href$="replay.html"]')
            assert links.count() == len(failed)
            shot = page.screenshot()
            href = links.first.get_attribute("href")
            assert href is not None and (out / href).is_file()
            page.goto((out / href).as_uri())
            page.wait_for_function("window.gazelleReplay !== undefined", timeout=30_000)
        finally:
            browser.close()
    import io

    from PIL import Image

    img = Image.open(io.BytesIO(shot)).convert("RGB")
    pixels = cast("list[tuple[int, int, int]]", list(img.get_flattened_data()))
    bar = sum(1 for r, g, b in pixels if abs(r - 0x3B) < 12 and abs(g - 0x7D) < 12 and abs(b - 0xD8) < 12)
    assert bar > 2000, f"{bar} pixels of the pass-rate bars' blue: the plot did not draw"


def test_a_killed_worker_is_retried_once_then_lost_and_a_hung_run_times_out(scenario: Path, tmp_path: Path) -> None:
    result = sweep(f"{scenario}::dies", [], [0, 1, 2, 3], out=tmp_path / "dies", jobs=2, timeout=1.0, report=False)
    by_seed = {r["seed"]: r for r in result.rows}
    assert sorted(by_seed) == [0, 1, 2, 3], result.rows
    assert by_seed[1]["status"] == "lost" and "died under it twice" in by_seed[1]["error"]
    assert by_seed[3]["status"] == "timeout" and "longer than 1 s" in by_seed[3]["error"]
    assert by_seed[0]["status"] == by_seed[2]["status"] == "passed"


def test_the_report_keeps_a_hostile_parameter_value_out_of_its_scripts(tmp_path: Path) -> None:
    """The report's charts embed their data as JSON in scripts (plotly's, which writes ``<``, ``>`` and ``/``
    as ``\\u`` escapes); a parameter value or error from a run that would open an escaped section or end a
    script (issue 48, item 9) stays data there, and HTML-escaped in the table of failures."""
    import re

    from gazelle.sweep import write_report

    hostile = "bot<!--<script>"
    rows = [
        {"status": s, "seed": i, "param.name": hostile, "metric.d": float(i), "error": f"</script>{hostile}"}
        for i, s in enumerate(("passed", "failed"))
    ]
    path = tmp_path / "report.html"
    write_report(rows, path, title=hostile)
    page = path.read_text()
    for body in re.findall(r"<script[^>]*>(.*?)</script>", page, flags=re.S)[1:]:  # [0]: plotly.js itself
        assert not re.search(r"<!--|<script|</script", body, flags=re.I)
    assert hostile not in page and "bot&lt;!--&lt;script&gt;" in page


def test_sweep_json_lists_the_seeds_as_given(scenario: Path, tmp_path: Path) -> None:
    """``--seeds 1,4,9`` is ``"seeds": [1, 4, 9]`` in sweep.json (issue 50 item 10: it read ``[1, 9, 3]``, its
    min, max and count, which looks like three seeds that were never run)."""
    sweep(f"{scenario}::slide", [], [1, 4, 9], out=tmp_path / "s", jobs=1, report=False)
    assert json.loads((tmp_path / "s" / "sweep.json").read_text())["seeds"] == [1, 4, 9]
