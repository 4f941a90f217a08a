"""``gazelle sweep``: the command line of :mod:`gazelle.sweep`, with a progress bar."""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any


def run_sweep(
    scenario: str,
    params: list[str],
    seeds: str,
    *,
    jobs: int | None,
    ray: str | None,
    out: Path | None,
    resume: bool,
    timeout: float | None = None,
    start: Path | None = None,
) -> int:
    """Run ``scenario`` (``tests/x.py::test_y``) over the ``--param`` grid and ``--seeds`` (on every core, or on
    Ray: ``local``, ``auto`` or ``ray://HOST:PORT``), with a progress bar, rows and report in ``out``
    (``out/sweep_<test>`` by default); ``--resume`` keeps the rows already there. Exit status: 0 when every run
    passed, 1 when one did not, 2 for bad arguments, 130 when interrupted (the finished runs are kept)."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    from ..sweep import SweepError, parse_param, parse_seeds, sweep

    try:
        grid = [parse_param(p) for p in params]
        seed_list = parse_seeds(seeds)
        if ray is not None and ray != "local" and ray != "auto" and not ray.startswith("ray://"):
            raise SweepError(f"--ray {ray!r}: expected local, auto or ray://HOST:PORT")
    except SweepError as err:
        print(f"gazelle sweep: {err}", file=sys.stderr)
        return 2
    folder = out or Path("out") / ("sweep_" + scenario.rpartition("::")[2])
    failures = [0]
    progress = Progress(
        TextColumn("[bold]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.fields[failed]} not passed"),
        TimeRemainingColumn(),
        transient=False,
    )
    task: dict[str, Any] = {}

    def on_row(row: dict[str, Any], done: int, total: int) -> None:
        """Each finished run: the bar moves and counts the runs that did not pass."""
        if row["status"] != "passed":
            failures[0] += 1
        if "id" not in task:
            task["id"] = progress.add_task("runs", total=total, completed=done, failed=0)
            progress.start()
        progress.update(task["id"], completed=done, failed=failures[0])

    t0 = time.perf_counter()
    try:
        result = sweep(
            scenario,
            grid,
            seed_list,
            out=folder,
            jobs=jobs,
            ray=ray,
            resume=resume,
            on_row=on_row,
            timeout=timeout,
            start=start,
        )
    except SweepError as err:
        print(f"gazelle sweep: {err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"\ngazelle sweep: interrupted; the finished runs are in {folder} (--resume goes on)", file=sys.stderr)
        return 130
    finally:
        progress.stop()
    return _summary(result.rows, result.ran, time.perf_counter() - t0, folder)


def _summary(rows: list[dict[str, Any]], ran: int, seconds: float, folder: Path) -> int:
    """The closing line (runs by status, where the report is) and the exit status: 0 when all passed."""
    passed = sum(r["status"] == "passed" for r in rows)
    errors = sum(r["status"] == "error" for r in rows)
    other = sum(r["status"] in ("timeout", "lost") for r in rows)
    print(
        f"{len(rows)} runs ({ran} now, in {seconds:.1f} s): {passed} passed, "
        f"{len(rows) - passed - errors - other} failed, {errors} raised, {other} timed out or lost; "
        f"report: {folder / 'report.html'}"
    )
    return 0 if passed == len(rows) else 1
