"""gazelle's pytest plugin (entry point ``pytest11``: loaded by every pytest in a venv with gazelle).

Fixtures for a user's own robot tests (see docs/robot_tests.md):

* ``gazelle_sim``: a headless ``gazelle sim`` on a private ROS domain with localhost discovery, started
  paused; the test moves time with ``run_for``/``run_until``; ``spawn``, ``launch`` and ``run`` start
  what the test needs, and everything ends with the test, pass or fail.
* ``ros``: the test's rclpy node on that domain (``gazelle_sim.ros``).
* ``gazelle_seed``: the seed of this test's run (``--gazelle-seed``, default 0), given to the server.
* ``gazelle_shared_sim``: one server for a whole module (``gazelle_sim_module``), reset before each test.
* ``gazelle_world``: a simulation inside the test's process, no ROS: the test steps it, publishes on its
  bus and reads its states (bit-identical from run to run).

Configure a test with ``@pytest.mark.gazelle(world=..., record=[...], paused=True, rtf=None, lockstep=True)``
(``lockstep``: after each chunk of stepped time, wait until the processes the test started are idle, so
a starved node never falls behind the world in sim time). A failing
test keeps an MCAP bag (rosbag2 layout) of the topics it named plus /tf, /tf_static and /clock, a
replay (``replay.html``: the world from above on a timeline, the named topics' values at the cursor;
it opens from disk in any browser), and the server's output, under ``--gazelle-artifacts-dir``
(default ``gazelle-artifacts/`` in pytest's root folder); ``--gazelle-artifacts=all`` keeps them for
every test, ``none`` records nothing.

Importing this module imports neither rclpy nor the simulation: a plugin loaded in every pytest run
must cost nothing where it is not used.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import signal
import time
import uuid
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from ._settle import _stat_fields

_REPORT = pytest.StashKey[dict[str, pytest.TestReport]]()
_ARTIFACTS = pytest.StashKey[tuple[Path, int]]()
_DOMAINS = pytest.StashKey[tuple[int, ...]]()
"""The ROS domains this run's tests may use (``--gazelle-domains``, else ``GAZELLE_ROS_DOMAINS``, else 10-100)."""
_SIM = pytest.StashKey[Any]()
"""The test's simulation (its server's warnings go into a failing test's report)."""
_MODULE_BAGS = pytest.StashKey[tuple[Path, list[int]]]()
"""A module's shared server: the folder of its live recording and how many bags it has handed out."""
TOKEN_VAR = "GAZELLE_TEST_TOKEN"
"""Set in the environment of everything a test starts, so a process left behind can be found."""


def pytest_addoption(parser: pytest.Parser) -> None:
    """The plugin's command-line options: the seed of every simulation, which tests keep their artifacts (bag,
    replay page, server log), and where."""
    group = parser.getgroup("gazelle", "gazelle robot tests")
    group.addoption("--gazelle-seed", type=int, default=0, help="seed of every gazelle_sim (default 0)")
    group.addoption(
        "--gazelle-artifacts",
        choices=("failed", "all", "none"),
        default="failed",
        help="keep the bag and server log of failing tests (default), of all tests, or record nothing",
    )
    group.addoption(
        "--gazelle-artifacts-dir", default=None, help="where artifacts go (default: gazelle-artifacts/ in the rootdir)"
    )
    group.addoption(
        "--gazelle-domains",
        default=None,
        metavar="IDS",
        help="the ROS domain ids tests may use, e.g. 20-29 or 20,22,25-27 (default: $GAZELLE_ROS_DOMAINS, else "
        "10-100); "
        "each test holds one no other process on the machine holds",
    )
    group.addoption(
        "--gazelle-strict",
        action="store_true",
        default=False,
        help="a warning of the server about the test's set-up (an unknown plugin, a missing mesh) fails the test, "
        "as @pytest.mark.gazelle(strict=True) does",
    )


def pytest_configure(config: pytest.Config) -> None:
    """Declare the ``gazelle`` marker, so ``--strict-markers`` accepts it; check the domains the user gave; and
    give the process's Fast DDS writers their test settings before any participant exists (see
    ``_dds_profile``: Fast DDS reads them at the process's first participant, and a test node made after
    another rclpy node of the session otherwise waited 3 s for the acknowledgements of each step after a
    publish)."""
    from ._dds_profile import writer_profile
    from ._domain import DOMAINS_VAR, domains_from_environment, parse_domains

    given = config.getoption("--gazelle-domains")
    try:
        config.stash[_DOMAINS] = (
            parse_domains(given, "--gazelle-domains") if given is not None else domains_from_environment()
        )
    except ValueError as err:
        raise pytest.UsageError(str(err).replace(DOMAINS_VAR, f"${DOMAINS_VAR}")) from None
    os.environ.update(writer_profile())
    config.addinivalue_line(
        "markers",
        "gazelle(world=None, record=(), paused=True, rtf=None, start_timeout=60, lockstep=True, strict=False): "
        "configure the gazelle_sim fixture",
    )


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]) -> Iterator[None]:
    """Keep each phase's report for the fixtures (they keep a failing test's artifacts), and add to a failing test's
    report its seed (how to run it again the same way) and where its artifacts are."""
    report = yield
    item.stash.setdefault(_REPORT, {})[report.when] = report
    if report.failed:
        _one_line_sim_error(item, call, report)
    if report.when == "teardown" and _ARTIFACTS in item.stash and not _any_failed(item):
        folder = item.stash[_ARTIFACTS][0]
        if item.config.getoption("--gazelle-artifacts") == "all" and folder.is_dir():
            report.sections.append((_KEPT_SECTION, f"artifacts (bag, replay.html, server log): {folder}"))
    if report.failed and _ARTIFACTS in item.stash:
        folder, seed = item.stash[_ARTIFACTS]
        mode = item.config.getoption("--gazelle-artifacts")
        kept = f"; artifacts (bag, replay.html, server log): {folder}" if mode != "none" else ""
        report.sections.append(("gazelle", f"seed {seed} (rerun with --gazelle-seed {seed}){kept}"))
        said = _server_warnings(item)
        if said:
            report.sections.append(("gazelle: the server's warnings", "\n".join(said)))
    return report


_KEPT_SECTION = "gazelle: artifacts kept"


def _any_failed(item: pytest.Item) -> bool:
    return any(r.failed for r in item.stash.get(_REPORT, {}).values())


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    """Note where a passing test's artifacts went (``--gazelle-artifacts=all``), for the run's summary (also
    under xdist: the workers' reports come here with their sections)."""
    for name, text in report.sections:
        if name == _KEPT_SECTION:
            _kept_list.append((report.nodeid, text))


_kept_list: list[tuple[str, str]] = []


def pytest_terminal_summary(terminalreporter: Any) -> None:
    """``--gazelle-artifacts=all``: where each passing test's artifacts are (a failing one says it in its report)."""
    if _kept_list:
        terminalreporter.write_sep("-", "gazelle: artifacts of passing tests")
        for nodeid, text in _kept_list:
            terminalreporter.write_line(f"{nodeid}: {text}")


def _server_warnings(item: pytest.Item) -> list[str]:
    """What the test's server warned since the test started (its world, what the test spawned), each once."""
    sim = item.stash.get(_SIM, None)
    if sim is None or not sim.is_open:
        return []
    return list(dict.fromkeys(sim.server_warnings()))


def _one_line_sim_error(item: pytest.Item, call: pytest.CallInfo[None], report: pytest.TestReport) -> None:
    """A :class:`~gazelle.testing.SimError` (a refused spawn, a server that died) or
    :class:`~gazelle.testing.TestTimeout` (a wait that ran out) reported as the test's line and the error's
    message, not as a traceback through the harness."""
    import sys

    harness = [getattr(sys.modules.get(f"gazelle.testing.{m}"), c, None) for m, c in _HARNESS_ERRORS]
    kinds = tuple(k for k in harness if isinstance(k, type))
    excinfo = call.excinfo
    if not kinds or excinfo is None or not isinstance(excinfo.value, kinds):
        return
    where = [e for e in excinfo.traceback if Path(str(e.path)) == Path(item.path)]
    line = f"{item.path}:{where[-1].lineno + 1}: " if where else ""
    report.longrepr = f"{line}{type(excinfo.value).__name__}: {excinfo.value}"


_HARNESS_ERRORS = (("_sim", "SimFailed"), ("_ros_node", "TestTimeout"))
"""The harness's own failures (module, class), reported in one line (see :func:`_one_line_sim_error`)."""


def _safe(nodeid: str) -> str:
    """A test's artifacts folder name: its node id with what a file name should not hold replaced by ``_`` and,
    where that changed the id, a short hash of the whole id after it, so two tests never share a folder
    (``t[a/b]`` and ``t[a_b]`` did: the second's start deleted the first's artifacts)."""
    safe = re.sub(r"[^A-Za-z0-9_.-]+", "_", nodeid).strip("_")[:150]
    if safe == nodeid:
        return safe
    return f"{safe}-{hashlib.sha256(nodeid.encode()).hexdigest()[:10]}"


def _marker_options(request: pytest.FixtureRequest) -> dict[str, Any]:
    """The ``gazelle`` marker's options for this test or module, its world file checked."""
    marker = request.node.get_closest_marker("gazelle")
    options: dict[str, Any] = dict(marker.kwargs) if marker is not None else {}
    world = options.get("world")
    if world is not None and not Path(world).is_file():
        pytest.fail(f"@pytest.mark.gazelle(world=...): no such world file: {world}", pytrace=False)
    return options


@pytest.fixture
def gazelle_seed(request: pytest.FixtureRequest) -> int:
    """The seed of this test's simulation: the marker's ``seed``, else ``--gazelle-seed``, else 0."""
    marker = request.node.get_closest_marker("gazelle")
    if marker is not None and "seed" in marker.kwargs:
        return int(marker.kwargs["seed"])
    seed = request.config.getoption("--gazelle-seed")
    return int(seed) if seed is not None else 0


def _leaked(token: str, spare: frozenset[int] = frozenset()) -> list[tuple[int, str]]:
    """(pid, command line) of live processes carrying ``token`` in their environment, besides this one.

    A process in one of the ``spare`` process groups (the harness's own children, which :meth:`Sim.close`
    has just SIGKILLed with their groups) is waited for instead, up to :data:`REAP_TIMEOUT`: SIGKILL always
    ends a process, but on a loaded machine the kernel can take seconds to tear a large one down, and such
    a process was not left running by the test."""
    deadline = time.monotonic() + REAP_TIMEOUT
    while True:
        found = _carrying(token)
        dying = [pid for pid, _cmd, group in found if group in spare]
        if not dying or time.monotonic() > deadline:
            return [(pid, cmd) for pid, cmd, _group in found]
        time.sleep(0.05)  # another process's end: nothing to wait on but /proc


REAP_TIMEOUT = 30.0
"""Seconds a SIGKILLed harness process may take to disappear before it counts as left running."""


def _carrying(token: str) -> list[tuple[int, str, int]]:
    """(pid, command line, process group) of live processes carrying ``token`` in their environment."""
    found = []
    needle = f"{TOKEN_VAR}={token}".encode()
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                if needle not in f.read().split(b"\0"):
                    continue
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmd = f.read().replace(b"\0", b" ").decode(errors="replace").strip()
        except OSError:
            continue
        fields = _stat_fields(f"/proc/{entry}/stat")
        if fields is None or fields[0] == b"Z":
            continue  # ended, or a zombie: already dead, its parent has yet to reap it
        found.append((int(entry), cmd, int(fields[2])))
    return found


@pytest.fixture
def gazelle_sim(request: pytest.FixtureRequest, gazelle_seed: int) -> Iterator[Any]:
    """A ``gazelle sim`` server of the test's own, on a ROS domain no other test uses, started paused (the test
    drives sim time), with the marker's world and options. What the test starts (rclpy's default context,
    subprocesses) runs on that domain. At the end the server stops, a process the test left running fails the
    test (and is killed), and a failing test keeps its bag, replay page and server log."""
    try:
        from ._domain import environ_applied
        from ._sim import Sim
    except ImportError as err:  # ROS 2's Python packages are not in this environment
        pytest.fail(f"gazelle_sim needs ROS 2 (rclpy) in this environment: {err}", pytrace=False)
    options = _marker_options(request)
    record = list(options.pop("record", ()))
    options.pop("seed", None)
    unknown = set(options) - {"world", "paused", "rtf", "start_timeout", "lockstep", "strict"}
    if unknown:
        pytest.fail(f"@pytest.mark.gazelle: unknown option(s) {', '.join(sorted(unknown))}", pytrace=False)
    config = request.config
    mode = config.getoption("--gazelle-artifacts")
    folder = _artifacts_base(config) / _safe(request.node.nodeid)
    request.node.stash[_ARTIFACTS] = (folder, gazelle_seed)
    if folder.exists():
        shutil.rmtree(folder)

    if mode != "none":
        folder.mkdir(parents=True, exist_ok=True)
    domain = _reserve(request.config)
    token = uuid.uuid4().hex
    env = {**os.environ, TOKEN_VAR: token}
    sim = None
    try:
        sim = _start_sim(
            Sim,
            "gazelle_sim",
            domain.domain_id,
            options,
            (folder / "bag", record) if mode != "none" else None,
            seed=gazelle_seed,
            paused=bool(options.get("paused", True)),
            rtf=options.get("rtf"),
            env=env,
            start_timeout=float(options.get("start_timeout", 60.0)),
            strict=_strict(config, options),
        )
        request.node.stash[_SIM] = sim
        # what the test itself starts (rclpy's default context, a subprocess) is on this domain too
        test_env = {"ROS_DOMAIN_ID": str(domain.domain_id), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
        with environ_applied({**test_env, TOKEN_VAR: token}):
            yield sim
    finally:
        own: frozenset[int] = frozenset()
        unsaid = _unsaid_warnings(sim)
        if sim is not None:
            own = sim.process_groups()
            sim.close()
            if mode != "none" and folder.exists():
                (folder / "server.log").write_text(sim.server.output + "\n")
        leaks = _leaked(token, own)
        for pid, _cmd in leaks:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        domain.release()
        reports = request.node.stash.get(_REPORT, {})
        failed = any(r.failed for r in reports.values()) or bool(leaks)  # a leak fails the test: keep them
        if mode == "failed" and not failed and folder.exists():
            shutil.rmtree(folder, ignore_errors=True)
        if leaks:
            listed = "; ".join(f"pid {pid} ({cmd[:120]})" for pid, cmd in leaks)
            pytest.fail(f"the test left {len(leaks)} process(es) running (killed now): {listed}", pytrace=False)
        _say_warnings(unsaid, sim is not None and sim.strict, failed)


def _strict(config: pytest.Config, options: dict[str, Any]) -> bool:
    """Whether the server's warnings fail the test: the marker's ``strict``, else ``--gazelle-strict``."""
    if "strict" in options:
        return bool(options["strict"])
    return bool(config.getoption("--gazelle-strict"))


def _unsaid_warnings(sim: Any) -> list[str]:
    """The server's warnings that no spawn returned (about the world, or a spawn from a launch file)."""
    if sim is None or not sim.is_open:
        return []
    return [w for w in dict.fromkeys(sim.server_warnings()) if not any(w in said for said in sim.warnings)]


def _say_warnings(unsaid: list[str], strict: bool, failed: bool) -> None:
    """The server's warnings no spawn said: a failure with ``strict`` (unless the test failed already: they are in
    its report), else a :class:`~gazelle.testing.GazelleWarning` each (pytest lists them under the test)."""
    if not unsaid:
        return
    if strict and not failed:
        pytest.fail("the server warned (strict): " + " | ".join(unsaid), pytrace=False)
    if not strict:
        import warnings

        from ._warnings import GazelleWarning

        for w in unsaid:
            warnings.warn(GazelleWarning(f"the server warned: {w}"), stacklevel=1)


def _reserve(config: pytest.Config) -> Any:
    """A domain of the run's (see ``--gazelle-domains``) that no other process on the machine holds; the test
    fails, in one line, when every one is held."""
    from ._domain import reserve_domain

    try:
        return reserve_domain(domains=config.stash[_DOMAINS])
    except RuntimeError as err:
        pytest.fail(str(err), pytrace=False)


def _start_sim(
    sim_class: Any,
    fixture: str,
    domain_id: int,
    options: dict[str, Any],
    bag: tuple[Path, list[str]] | None,
    **kwargs: Any,
) -> Any:
    """A started ``gazelle sim`` for ``fixture`` (the test fails, naming it, when the server does not start):
    on ``options``' world and lockstep, recording ``bag`` (folder, topics; None: nothing) with a replay page
    beside it, which the server writes as it stops (the bodies from above on a timeline, the recorded
    topics' values at the cursor)."""
    try:
        return sim_class(
            domain_id=domain_id,
            world=options.get("world"),
            settle_timeout=_settle_timeout(options),
            record=bag,
            replay=(bag[0].parent / "replay.html", bag[1]) if bag is not None else None,
            **kwargs,
        )
    except Exception as err:
        pytest.fail(f"{fixture} did not start: {err}", pytrace=False)


def _settle_timeout(options: dict[str, Any]) -> float:
    """``lockstep`` (default True): after each chunk of stepped time the world waits, up to 10 s of wall
    time, until the processes the test started are idle; ``lockstep=False`` steps on regardless."""
    return 10.0 if options.get("lockstep", True) else 0.0


def _artifacts_base(config: pytest.Config) -> Path:
    return Path(config.getoption("--gazelle-artifacts-dir") or Path(config.rootpath) / "gazelle-artifacts")


@pytest.fixture(scope="module")
def gazelle_sim_module(request: pytest.FixtureRequest) -> Iterator[Any]:
    """One server for every test of a module (options from the module's ``pytestmark =
    pytest.mark.gazelle(...)``); use it through ``gazelle_shared_sim``, which resets it for each test.
    Unless ``--gazelle-artifacts=none``, the module's bag is recorded and its server keeps a replay of
    the run since the last reset: a failing test gets both (see ``gazelle_shared_sim``)."""
    try:
        from ._sim import Sim
    except ImportError as err:
        pytest.fail(f"gazelle_sim_module needs ROS 2 (rclpy) in this environment: {err}", pytrace=False)
    options = _marker_options(request)
    record = list(options.get("record", ()))
    seed = options.get("seed", request.config.getoption("--gazelle-seed"))
    mode = request.config.getoption("--gazelle-artifacts")
    live = _artifacts_base(request.config) / (_safe(request.node.nodeid) + "__module")
    if live.exists():
        shutil.rmtree(live)
    if mode != "none":
        live.mkdir(parents=True)
    domain = _reserve(request.config)
    sim = None
    try:
        bag = (live / "bag0", record) if mode != "none" else None
        sim = _start_sim(
            Sim,
            "gazelle_sim_module",
            domain.domain_id,
            options,
            bag,
            seed=int(seed or 0),
            paused=True,
            strict=_strict(request.config, options),
        )
        request.node.stash[_MODULE_BAGS] = (live, [0])
        yield sim
    finally:
        if sim is not None:
            sim.close()
        domain.release()
        shutil.rmtree(live, ignore_errors=True)  # what a failing test needed was moved out of it


@pytest.fixture
def gazelle_shared_sim(request: pytest.FixtureRequest, gazelle_sim_module: Any) -> Iterator[Any]:
    """The module's server, reset for this test (time 0, spawned entities gone, the last test's
    processes stopped): a fraction of a second instead of a new server. A failing test gets the replay
    of its own run (the server's, since the reset before it), the module's bag since its start or its
    last failure (this test's part is its end) and the server's log, under its artifacts folder."""
    from ._domain import environ_applied

    sim = gazelle_sim_module
    mode = request.config.getoption("--gazelle-artifacts")
    folder = _artifacts_base(request.config) / _safe(request.node.nodeid)
    request.node.stash[_ARTIFACTS] = (folder, sim.seed)
    sim.reset()
    request.node.stash[_SIM] = sim
    try:
        with environ_applied({k: sim.env[k] for k in ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE")}):
            yield sim
    finally:
        reports = request.node.stash.get(_REPORT, {})
        module = request.node.getparent(pytest.Module)
        bags = module.stash.get(_MODULE_BAGS, None) if module is not None else None
        if bags is not None and mode != "none" and (mode == "all" or any(r.failed for r in reports.values())):
            _keep_shared_artifacts(sim, folder, *bags)


def _keep_shared_artifacts(sim: Any, folder: Path, live: Path, handed_out: list[int]) -> None:
    """Move a shared server's replay, bag so far and log into a test's artifacts folder (the recording
    goes on in a new bag for the module's next tests)."""
    if folder.exists():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    try:
        replay = sim.save_replay()
        if replay is not None:
            shutil.copyfile(replay, folder / "replay.html")
        handed_out[0] += 1
        bag = sim.restart_recording(live / f"bag{handed_out[0]}")
        if bag is not None and bag.exists():
            shutil.move(str(bag), str(folder / "bag"))
    finally:
        (folder / "server.log").write_text(sim.server.output + "\n")


@pytest.fixture
def gazelle_world(request: pytest.FixtureRequest, gazelle_seed: int) -> Iterator[Any]:
    """A simulation in the test's own process: no ROS, no DDS, stepped by the test (see
    gazelle.testing.InProcessWorld); the marker's ``world`` and the seed apply as to ``gazelle_sim``."""
    from ._world import InProcessWorld

    options = _marker_options(request)
    try:
        world = InProcessWorld(options.get("world"), seed=gazelle_seed)
    except Exception as err:  # a world that does not load: one line, as for gazelle_sim
        pytest.fail(f"gazelle_world did not start: {err}", pytrace=False)
    try:
        yield world
    finally:
        world.close()


@pytest.fixture
def ros(gazelle_sim: Any) -> Any:
    """The test's rclpy node on the simulation's domain (see gazelle.testing.RosTestNode)."""
    return gazelle_sim.ros
