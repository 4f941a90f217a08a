"""Sweeps: one scenario over a grid of parameters and seeds, on every core of this machine or on Ray.

A scenario is a function ``scenario(sim, params, seed) -> dict of metrics`` in a user's file, run on a
fresh in-process :class:`~gazelle.sim.Simulation` (no ROS, no DDS) seeded with ``seed``; a metric
``passed`` says whether the run passed. ``gazelle sweep file.py::name --param friction=0.4,0.8
--seeds 0:100 -j 2`` (or :func:`sweep`) runs every combination, writes a row per run as it finishes
(``runs.jsonl``, then ``runs.parquet``), and a self-contained HTML report (``report.html``). With
``--ray local|auto|ray://host:port`` the same runs are Ray tasks (the scenario's file is shipped to the
workers as text). A run's metrics depend only on (scenario, parameters, seed).
"""

from ._report import write_report
from ._runner import REPORT, RESULTS, TABLE, SweepResult, read_rows, run_one, sweep, write_table
from ._spec import RunSpec, Scenario, SweepError, grid, load_scenario, parse_param, parse_seeds

__all__ = [
    "REPORT",
    "RESULTS",
    "TABLE",
    "RunSpec",
    "Scenario",
    "SweepError",
    "SweepResult",
    "grid",
    "load_scenario",
    "parse_param",
    "parse_seeds",
    "read_rows",
    "run_one",
    "sweep",
    "write_report",
    "write_table",
]
