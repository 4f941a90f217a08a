"""Running a sweep: one run in a worker, many on a pool of this machine's cores or on Ray, the results
appended as they come, so an interrupted sweep keeps what it did and ``resume`` skips it."""

from __future__ import annotations

import json
import math
import multiprocessing
import os
import socket
import sys
import tempfile
import time
import traceback
from collections.abc import Callable, Iterator, Mapping, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .._errors import SimError
from .._files import atomic_write, private_folder
from ._spec import ParamValue, RunSpec, SweepError, grid, load_scenario, scenario_from_file

RESULTS = "runs.jsonl"
"""One JSON object a line, one line a finished run, appended and flushed as each run ends."""
TABLE = "runs.parquet"
"""The same rows as :data:`RESULTS`, as one Arrow table written when the sweep ends (pandas / polars read it
with the parameters and metrics as typed columns)."""
REPORT = "report.html"
"""The sweep's self-contained HTML report (:func:`~gazelle.sweep._report.write_report`)."""
REPLAY_RATE_HZ = 10.0
"""Body poses a sim second in the replay of an in-process run that does not pass."""
MAX_TIMEOUT = 365 * 86400.0
"""The longest ``timeout`` a run may have, in seconds (a year; the kernel's interval timer takes no more than
about 1e9 s, and infinity or NaN none at all)."""


def _metric(value: Any) -> Any:
    """A value a run returned, as the results table keeps it: numbers as floats (NaN and infinities as their text,
    which Arrow and JSON keep), strings, booleans and None as they are, anything else as its text."""
    if isinstance(value, bool | int | str) or value is None:
        return value
    try:
        f = float(value)
    except (TypeError, ValueError):
        return str(value)
    return f if math.isfinite(f) else str(f)


class _RunTimeout(SimError):
    pass


def _on_alarm(_signum: int, _frame: Any) -> None:
    raise _RunTimeout


def run_one(
    path: str,
    name: str,
    spec: RunSpec,
    source: str | None = None,
    timeout: float | None = None,
    start: str | None = None,
    artifacts: str | None = None,
) -> dict[str, Any]:
    """Run the scenario once, in this process, and return its row. Never raises: a scenario that raises
    gives a row with status ``error`` and its traceback; one that runs longer than ``timeout`` seconds of
    wall time is stopped (at its next Python line: a single long MuJoCo call finishes first) and gives
    status ``timeout``. ``start``: a checkpoint the run goes on from (its noise streams reseeded with the
    run's seed), instead of a fresh world. ``artifacts``: a folder where a run that does not pass leaves
    its replay (``<key>/replay.html``; a ROS scenario also its bag and server log), named in its row as
    ``artifact.*`` paths relative to the folder's parent (where the report is)."""
    import signal

    row: dict[str, Any] = {"key": spec.key, "seed": spec.seed}
    row.update({f"param.{k}": v for k, v in spec.params})
    row.update(status="error", error="", wall_sec=0.0, sim_sec=0.0, worker=f"{socket.gethostname()}:{os.getpid()}")
    t0 = time.perf_counter()
    timer = False
    previous: Any = None
    if timeout is not None and timeout > 0:
        try:
            previous = signal.signal(signal.SIGALRM, _on_alarm)
            signal.setitimer(signal.ITIMER_REAL, timeout)
            timer = True
        except ValueError:  # not the main thread of its process: no wall-clock limit here
            pass
    folder = Path(artifacts) / spec.key if artifacts is not None else None
    run: _InProcessRun | _RosRun | None = None
    try:
        fn = scenario_from_file(_source_file(source, path) if source is not None else Path(path), name)
        run = _RosRun(fn, spec, folder) if is_ros_scenario(fn) else _InProcessRun(fn, spec, start)
        metrics = run.call()
        if not isinstance(metrics, Mapping):
            raise TypeError(f"the scenario returned {type(metrics).__name__}, not a dict of metrics")
        row.update({f"metric.{k}": _metric(v) for k, v in metrics.items()})
        row["status"] = "passed" if bool(metrics.get("passed", True)) else "failed"
    except _RunTimeout:
        row["status"] = "timeout"
        row["error"] = f"the run took longer than {timeout:g} s of wall time and was stopped"
    except Exception:
        row["error"] = traceback.format_exc(limit=-8)
    finally:
        if timer:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
        if run is not None:
            try:
                row["sim_sec"] = run.sim_sec()
                kept = run.finish(folder if row["status"] != "passed" else None)
            except Exception:  # tearing down (a server that would not stop): said in the row, never raised
                row["error"] += "\n" + traceback.format_exc(limit=-4)
                kept = {}
            if artifacts is not None:
                row.update({f"artifact.{k}": f"{Path(artifacts).name}/{spec.key}/{v}" for k, v in kept.items()})
    row["wall_sec"] = time.perf_counter() - t0
    return row


def is_ros_scenario(fn: Callable[..., Any]) -> bool:
    """A ROS scenario takes the robot-test fixtures' server: ``def name(gazelle_sim, params, seed)``."""
    import inspect

    try:
        first = next(iter(inspect.signature(fn).parameters), "")
    except (TypeError, ValueError):
        return False
    return first == "gazelle_sim"


class _InProcessRun:
    """A run on an in-process Simulation (no ROS), fresh or from a checkpoint, its bodies recorded for a
    replay page kept if the run does not pass."""

    def __init__(self, fn: Callable[..., Any], spec: RunSpec, start: str | None) -> None:
        """A run of a scenario function in this process: its world (the function's ``world`` file, else the default
        world) in a Simulation without pacing (``rtf=0``) seeded with the run's seed, or, for a branch, the
        checkpoint's world as it was with a fresh draw of its noise; a replay of the bodies' poses is recorded as
        it runs."""
        from ..description import World, load
        from ..sim import ReplayRecorder, Simulation
        from ..worlds import default_world

        self.fn, self.spec = fn, spec
        world_file = getattr(fn, "world", None)
        world = load(world_file).value if world_file is not None else default_world()
        if start is not None:  # a branch: the checkpoint's world as it was, another draw of its noise
            given = world if world_file is not None and isinstance(world, World) else None
            self.sim = Simulation.from_checkpoint(start, world=given)
            self.sim.reseed(spec.seed)
        else:
            if not isinstance(world, World):
                raise ValueError(f"{world_file}: not a world (it describes a {type(world).__name__.lower()})")
            self.sim = Simulation(world, rtf=0, seed=spec.seed)
        # 10 poses a sim second: enough to see what went wrong, 2-3 % of a run's time (30 Hz: 7 %)
        self.replay = ReplayRecorder(self.sim, rate_hz=REPLAY_RATE_HZ)

    def call(self) -> Any:
        return self.fn(self.sim, self.spec.as_dict(), self.spec.seed)

    def sim_sec(self) -> float:
        return float(self.sim.world.time)

    def finish(self, keep: Path | None) -> dict[str, str]:
        """Stop recording; with ``keep`` (a failing or kept run), write its replay page there and say so."""
        self.replay.close()
        if keep is None:
            return {}
        from ..viewer import replay_html

        keep.mkdir(parents=True, exist_ok=True)
        self.replay.write(keep / "replay.html", replay_html(self.replay.data(), title=f"run {self.spec.key}"))
        return {"replay": "replay.html"}


class _RosRun:
    """A run on the robot-test fixtures' server (``gazelle sim`` on a ROS domain of its own, localhost
    discovery, paused: the scenario steps it), recording the scenario's ``record`` topics and a replay."""

    def __init__(self, fn: Callable[..., Any], spec: RunSpec, folder: Path | None) -> None:
        """A run that needs ROS: a ``gazelle sim`` server on a domain of its own (so parallel runs never hear each
        other), seeded with the run's seed, recording the function's ``record`` topics to a bag and its replay
        beside it, in a temporary folder."""
        from ..testing import Sim, environ_applied, reserve_domain

        self.fn, self.spec, self.folder = fn, spec, folder
        self._environ = environ_applied
        self.domain = reserve_domain()
        topics = list(getattr(fn, "record", ()))
        self.where = Path(tempfile.mkdtemp(prefix=f"gazelle-run-{spec.key}-"))
        try:
            self.sim = Sim(
                domain_id=self.domain.domain_id,
                world=getattr(fn, "world", None),
                seed=spec.seed,
                record=(self.where / "bag", topics),
                server_args=[
                    "--replay",
                    str(self.where / "replay.html"),
                    *[a for t in topics for a in ("--replay-topic", t)],
                ],
            )
        except BaseException:
            self.domain.release()
            raise

    def call(self) -> Any:
        env = {"ROS_DOMAIN_ID": str(self.domain.domain_id), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
        with self._environ(env):
            return self.fn(self.sim, self.spec.as_dict(), self.spec.seed)

    def sim_sec(self) -> float:
        return float(self.sim.time) if self.sim.is_open else 0.0

    def finish(self, keep: Path | None) -> dict[str, str]:
        """Stop the server and free its domain; with ``keep``, move the replay, the bag and the server's log there.
        The temporary folder goes either way."""
        import shutil

        try:
            self.sim.close()
            (self.where / "server.log").write_text(self.sim.server.output + "\n")
        finally:
            self.domain.release()
        kept: dict[str, str] = {}
        if keep is not None:
            keep.mkdir(parents=True, exist_ok=True)
            for item, label in (("replay.html", "replay"), ("bag", "bag"), ("server.log", "log")):
                if (self.where / item).exists():
                    shutil.move(str(self.where / item), str(keep / item))
                    kept[label] = item
        shutil.rmtree(self.where, ignore_errors=True)
        return kept


def lost_row(spec: RunSpec, why: str) -> dict[str, Any]:
    """The row of a run whose worker died under it twice."""
    row: dict[str, Any] = {"key": spec.key, "seed": spec.seed}
    row.update({f"param.{k}": v for k, v in spec.params})
    row.update(status="lost", error=why, wall_sec=0.0, sim_sec=0.0, worker="")
    return row


def _source_file(source: str, origin: str) -> Path:
    """A scenario shipped as text (to a Ray worker): the file itself where this machine has it unchanged
    (so paths relative to it hold), else written once, owner-only, and imported from there."""
    import hashlib

    original = Path(origin)
    try:
        if original.is_file() and original.read_text() == source:
            return original
    except OSError:
        pass

    digest = hashlib.sha256((origin + "\0" + source).encode()).hexdigest()[:16]
    folder = _own_folder(f"gazelle-scenarios-{os.getuid()}")
    path = folder / f"{digest}_{Path(origin).name}"
    if not path.is_file() or path.read_text() != source:
        atomic_write(path, source, mode=0o600)
    return path


def _own_folder(name: str) -> Path:
    """``$TMPDIR/name``, this user's own (made 0700; see :func:`gazelle._files.private_folder`), for the files a
    Ray worker is shipped (a scenario is code, a checkpoint a pickle: no other user may replace them).

    Raises:
        PermissionError: it exists and is not this user's own, or others may write to it.
    """
    folder = private_folder(Path(tempfile.gettempdir()) / name, "the folder of a sweep's shipped files")
    if folder is None:
        raise PermissionError(f"{Path(tempfile.gettempdir()) / name} is not this user's own folder")
    return folder


def _ray_task(
    source: str,
    origin: str,
    name: str,
    spec: RunSpec,
    timeout: float | None,
    start: bytes | None = None,
    artifacts: str | None = None,
) -> dict[str, Any]:
    """One run on a Ray worker: the scenario's source travels with the task (the worker need not have the file), and
    a branch's checkpoint as bytes, written to a file there."""
    return run_one(
        origin, name, spec, source=source, timeout=timeout, start=_checkpoint_file(start), artifacts=artifacts
    )


def _checkpoint_file(blob: bytes | None) -> str | None:
    """A checkpoint shipped as bytes (to a Ray worker on another machine), written once, owner-only."""
    if blob is None:
        return None
    import hashlib

    folder = _own_folder(f"gazelle-checkpoints-{os.getuid()}")
    path = folder / f"{hashlib.sha256(blob).hexdigest()[:24]}.ckpt"
    if not path.is_file() or hashlib.sha256(path.read_bytes()).digest() != hashlib.sha256(blob).digest():
        atomic_write(path, blob, mode=0o600)
    return str(path)


@dataclass
class SweepResult:
    """What a sweep left in its output folder ``out`` (results, table, report, replays of the failures), and
    its rows in memory."""

    out: Path
    rows: list[dict[str, Any]] = field(default_factory=list)
    """Every finished run (from this sweep and, with resume, before it)."""
    ran: int = 0
    """Runs done by this call."""

    @property
    def failures(self) -> list[dict[str, Any]]:
        """The rows of runs that did not pass: ``failed`` (its ``passed`` metric was false), ``error`` (it
        raised), ``timeout`` or ``lost`` (its worker died twice)."""
        return [r for r in self.rows if r["status"] != "passed"]


def read_rows(path: Path) -> list[dict[str, Any]]:
    """The rows of a results file; a torn last line (the sweep was killed mid-write) is ignored."""
    rows = []
    if path.is_file():
        for line in path.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except json.JSONDecodeError:
                continue
    return rows


def _pool_runs(
    path: Path,
    name: str,
    todo: Sequence[RunSpec],
    jobs: int,
    timeout: float | None = None,
    start: str | None = None,
    artifacts: str | None = None,
) -> Iterator[dict[str, Any]]:
    """The runs on this machine's cores, ``jobs`` at a time, in forked worker processes (warm: gazelle and the
    scenario already imported). A worker that dies under a run (killed, or a crash in C) breaks the pool without
    saying which run did it: the runs in flight then go again one at a time, and one that kills its worker a
    second time is reported as lost while the others' rows stand."""
    # fork: the workers start with gazelle's runtime and the scenario's module already imported (warm),
    # and a user's script needs no `if __name__ == "__main__"` guard (spawn and forkserver run it again).
    # With fork, the pool starts all its workers at the first submit, before anything here starts a thread.
    from concurrent.futures.process import BrokenProcessPool

    from ..sim import Simulation  # noqa: F401 - imported before the fork: every worker has it
    from ..worlds import default_world  # noqa: F401

    ctx = multiprocessing.get_context("fork")
    queue = list(todo)
    while queue:
        # a worker killed under a run breaks the whole pool, and which run killed it cannot be told: the
        # runs that were in flight go again one at a time, each in a pool of its own; one that kills
        # that one too is "lost" (tried twice), the others' rows are as if nothing happened
        suspects: list[RunSpec] = []
        with ProcessPoolExecutor(max_workers=jobs, mp_context=ctx) as pool:
            pending: dict[Future[dict[str, Any]], RunSpec] = {}
            while (queue or pending) and not suspects:
                while queue and len(pending) < 2 * jobs:  # a few queued ahead, not the whole sweep
                    spec = queue.pop(0)
                    pending[pool.submit(run_one, str(path), name, spec, None, timeout, start, artifacts)] = spec
                done, _ = wait(list(pending), return_when=FIRST_COMPLETED)
                for f in done:
                    spec = pending.pop(f)
                    try:
                        yield f.result()
                    except BrokenProcessPool:
                        suspects.append(spec)
            if suspects:
                suspects += list(pending.values())
                pool.shutdown(wait=True, cancel_futures=True)
        for spec in suspects:
            with ProcessPoolExecutor(max_workers=1, mp_context=ctx) as alone:
                try:
                    yield alone.submit(run_one, str(path), name, spec, None, timeout, start, artifacts).result()
                except BrokenProcessPool:
                    yield lost_row(spec, "its worker process died under it twice (killed, or crashed in C)")


def _ray_runs(
    path: Path,
    name: str,
    todo: Sequence[RunSpec],
    address: str,
    jobs: int,
    timeout: float | None = None,
    start: str | None = None,
    artifacts: str | None = None,
) -> Iterator[dict[str, Any]]:
    """The runs on Ray (``address``: ``local`` for a Ray of this machine's ``jobs`` cores on its loopback, else
    the cluster's, see :func:`~gazelle.sweep._ray.ray_session`), one CPU each, a dead worker's run retried once and
    then reported as lost."""
    from ._ray import ray_session

    with ray_session(address, jobs) as ray:
        from ray.exceptions import RayError

        source = path.read_text()
        task = ray.remote(num_cpus=1, max_retries=1)(_ray_task)  # a dead worker's run goes again once
        blob = ray.put(Path(start).read_bytes()) if start is not None else None  # once, to every node
        refs = [task.remote(source, str(path), name, spec, timeout, blob, artifacts) for spec in todo]
        specs = dict(zip(refs, todo, strict=True))
        while refs:
            done, refs = ray.wait(refs, num_returns=1)
            try:
                yield ray.get(done[0])
            except RayError as err:  # its worker died twice
                yield lost_row(specs[done[0]], f"Ray could not run it: {type(err).__name__}")


def sweep(
    scenario: str,
    params: Sequence[tuple[str, Sequence[ParamValue]]],
    seeds: Sequence[int],
    *,
    out: str | os.PathLike[str],
    jobs: int | None = None,
    ray: str | None = None,
    resume: bool = False,
    on_row: Callable[[dict[str, Any], int, int], None] | None = None,
    report: bool = True,
    timeout: float | None = None,
    start: str | os.PathLike[str] | None = None,
) -> SweepResult:
    """Run ``scenario`` (``file.py::function``) for every combination of ``params`` and every seed.

    ``jobs`` worker processes on this machine (default: one per core), or Ray tasks (``ray``: ``"local"``
    for a Ray instance of ``jobs`` CPUs on this machine, listening on 127.0.0.1 only, ``"auto"`` (the cluster
    in ``RAY_ADDRESS`` or the one ``ray start`` recorded) or ``"ray://host:port"`` for a cluster). Rows go to
    ``out/runs.jsonl`` as runs finish; at the end ``out/runs.parquet`` and the report ``out/report.html``.
    ``resume`` keeps the rows already in ``out`` and runs only the others.
    ``on_row(row, done, total)`` is called after each run (progress). ``timeout``: seconds of wall time
    a run may take (status ``timeout``); a run whose worker dies is run once more, then is ``lost``.
    ``start``: a checkpoint (``Simulation.checkpoint``) every run goes on from, its noise reseeded with
    the run's seed: N perturbed continuations of one moment.
    """
    path, name, _fn = load_scenario(scenario)  # bad input fails here, before anything starts
    begin = _checked_start(timeout, start)
    specs = grid(params, seeds)
    jobs = max(1, jobs if jobs is not None else (os.cpu_count() or 1))
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    log = folder / RESULTS
    previous = read_rows(log) if resume else []
    if resume:  # the whole rows only: a line torn by a kill mid-write is dropped (its run runs again)
        atomic_write(log, "".join(json.dumps(r, sort_keys=True) + "\n" for r in previous))  # a kill keeps the old
    done_keys = {r.get("key") for r in previous}
    todo = [s for s in specs if s.key not in done_keys]
    about = {
        "scenario": f"{path}::{name}",
        "params": {n: list(v) for n, v in params},
        "seeds": list(seeds),  # as given, in order (was [min, max, count]: --seeds 1,4,9 read as [1, 9, 3])
        "runs": len(specs),
        "from": begin,
        "python": sys.version.split()[0],
    }
    atomic_write(folder / "sweep.json", json.dumps(about, indent=2))
    result = SweepResult(folder, rows=list(previous))
    mode = "a" if resume else "w"
    artifacts = str(folder.resolve() / "artifacts")  # a run that does not pass leaves its replay here
    runs = (
        _ray_runs(path, name, todo, ray, jobs, timeout, begin, artifacts)
        if ray
        else _pool_runs(path, name, todo, jobs, timeout, begin, artifacts)
    )
    with open(log, mode) as f:
        for row in runs:
            f.write(json.dumps(row, sort_keys=True) + "\n")
            f.flush()
            result.rows.append(row)
            result.ran += 1
            if on_row is not None:
                on_row(row, len(result.rows), len(specs))
    write_table(result.rows, folder / TABLE)
    if report:
        from ._report import write_report

        write_report(result.rows, folder / REPORT, title=f"{path.name}::{name}")
    return result


def _checked_start(timeout: float | None, start: str | os.PathLike[str] | None) -> str | None:
    """The sweep's options checked once, before anything starts (bad input is one line, nothing run): a ``timeout``
    must be finite seconds in (0, :data:`MAX_TIMEOUT`], a ``start`` checkpoint must load. Returns the checkpoint's
    absolute path."""
    if timeout is not None and not (math.isfinite(timeout) and 0 < timeout <= MAX_TIMEOUT):
        raise SweepError(f"--timeout {timeout:g}: expected seconds, more than 0 and at most {MAX_TIMEOUT:.0f} (a year)")
    if start is None:
        return None
    from ..sim import CheckpointError, Simulation

    begin = str(Path(start).resolve())
    try:
        Simulation.from_checkpoint(begin)
    except CheckpointError as err:
        raise SweepError(f"--from {start}: {err}") from None
    return begin


def write_table(rows: Sequence[Mapping[str, Any]], path: Path) -> None:
    """The rows as a Parquet table (columns: key, seed, param.*, metric.*, status, error, times)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    columns = sorted({k for r in rows for k in r})
    table = pa.Table.from_pylist([{c: r.get(c) for c in columns} for r in rows]) if rows else pa.table({})
    pq.write_table(table, path)
