"""Helpers of the integration tests (real `gazelle sim` processes, real DDS): starting and watching
processes, waiting for conditions with timeouts (never bare sleeps), and a plain rclpy client. The
fixtures that use them are in tests/integration/conftest.py (and tests/viewer/conftest.py); the session's
``ros_env`` fixture (a ROS domain of its own, discovery on localhost) is here, for both to import.
"""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
import rclpy
import rclpy.context
from _paths import REPO, SEED_XACRO  # noqa: F401 - the ros and viewer tests import them from here
from _ros_domain import reserved_domain_id

from gazelle.testing._ros_node import poll_until
from gazelle.testing._sim import collect_lines

SQUARE_NODE = REPO / "examples" / "simple_robot" / "simple_robot" / "square_movement.py"
GAZELLE = [sys.executable, "-m", "gazelle.cli"]


def wait_for(predicate: Callable[[], Any], timeout: float, what: str, interval: float = 0.02) -> Any:
    """Poll ``predicate`` until it returns something truthy; fail the test after ``timeout`` s."""
    return poll_until(predicate, timeout, f"waiting for {what}", lambda: time.sleep(interval))


@dataclass
class Proc:
    """A child process whose output is collected line by line."""

    popen: subprocess.Popen
    name: str
    lines: list[str] = field(default_factory=list)
    _cond: threading.Condition = field(default_factory=threading.Condition)
    _reader: threading.Thread | None = None

    def start_reader(self) -> None:
        self._reader = threading.Thread(target=collect_lines, args=(self.popen, self.lines, self._cond), daemon=True)
        self._reader.start()

    def wait_line(self, needle: str, timeout: float) -> str:
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                for line in self.lines:
                    if needle in line:
                        return line
                if self.popen.poll() is not None:
                    self._cond.wait(0.2)
                    if not any(needle in ln for ln in self.lines):
                        pytest.fail(
                            f"{self.name} exited ({self.popen.returncode}) before printing {needle!r}:\n" + self.output
                        )
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    pytest.fail(f"{self.name} did not print {needle!r} within {timeout:g} s:\n" + self.output)
                self._cond.wait(remaining)

    @property
    def output(self) -> str:
        with self._cond:
            return "\n".join(self.lines[-80:])

    def wait(self, timeout: float) -> int:
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            dump_stacks_and_kill(self.popen)
            if self._reader is not None:
                self._reader.join(5.0)  # it has read the dumped stacks when it ends at the pipe's end
            pytest.fail(f"{self.name} did not exit within {timeout:g} s:\n" + self.output)

    def interrupt(self, timeout: float = 15.0) -> int:
        if self.popen.poll() is None:
            self.popen.send_signal(signal.SIGINT)
        return self.wait(timeout)


def dump_stacks_and_kill(popen: subprocess.Popen) -> None:
    """End a child that hung: SIGABRT first, on which a Python child (``PYTHONFAULTHANDLER``, set by
    ``ros_env``) prints every thread's stack to its stderr, so the failure says where it hung; then SIGKILL."""
    if popen.poll() is None:
        popen.send_signal(signal.SIGABRT)
        try:
            popen.wait(5.0)
        except subprocess.TimeoutExpired:
            popen.kill()
            popen.wait(5.0)


def run_or_dump(cmd: list[str], timeout: float, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """``subprocess.run(cmd, capture_output=True, text=True)``; a command that does not end within
    ``timeout`` s fails the test with its output and its threads' stacks (see :func:`dump_stacks_and_kill`)."""
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd) as p:
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            dump_stacks_and_kill(p)
            out, err = p.communicate()
            pytest.fail(f"{' '.join(cmd)} did not end within {timeout:g} s:\n{out}\n{err}")
    return subprocess.CompletedProcess(cmd, p.returncode, out, err)


def start(cmd: list[str], name: str, env: dict[str, str] | None = None, *, stdin: bool = False) -> Proc:
    p = subprocess.Popen(
        cmd,
        stdin=subprocess.PIPE if stdin else subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        cwd=REPO,
        env=env or os.environ.copy(),
    )
    proc = Proc(p, name)
    proc.start_reader()
    _STARTED.append(proc)
    return proc


_STARTED: list[Proc] = []


def start_sim(rtf: float, *extra: str) -> Proc:
    """``gazelle sim --no-viewer --rtf <rtf>`` on the default world, once it says it is ready. A test of an arm
    runs it faster than real time: the arm moves in sim time, and the suite waits less for it."""
    sim = start([*GAZELLE, "sim", "--no-viewer", "--rtf", f"{rtf:g}", *extra], "gazelle sim")
    sim.wait_line("gazelle: ready", timeout=60)
    return sim


def spawn_file(entity: str, path: Path) -> None:
    """``gazelle spawn -entity <entity> -file <path>``, which must succeed."""
    spawn = start([*GAZELLE, "spawn", "-entity", entity, "-file", str(path)], f"spawn {entity}")
    assert spawn.wait(120) == 0, spawn.output


def start_move_group(
    urdf: Path, srdf: Path, config: Path, *ros_args: str, env: dict[str, str] | None = None, via_ros2: bool = True
) -> Proc:
    """``ros2 run gazelle move_group --urdf --srdf --config`` (``gazelle move_group`` when not ``via_ros2``),
    once it says MoveIt's "You can start planning now!"; ``ros_args`` go after ``--ros-args``."""
    head = [str(Path(sys.prefix) / "bin" / "ros2"), "run", "gazelle"] if via_ros2 else list(GAZELLE)
    cmd = [*head, "move_group", "--urdf", str(urdf), "--srdf", str(srdf), "--config", str(config)]
    move_group = start([*cmd, *(["--ros-args", *ros_args] if ros_args else [])], "move_group", env)
    move_group.wait_line("You can start planning now!", timeout=120)
    return move_group


def run_spawner(params_file: Path, *controllers: str) -> None:
    """``gazelle spawner <controllers> -p <params_file>`` (controller_manager's spawner), which must succeed."""
    spawner = start([*GAZELLE, "spawner", *controllers, "-p", str(params_file)], "spawner")
    assert spawner.wait(60) == 0, spawner.output


class RosClient:
    """A plain rclpy node in the test process for observing and calling the simulation."""

    def __init__(self, name: str = "test_client"):
        # rclpy's MultiThreadedExecutor is slow enough (Jazzy) that a node taking /clock and /odom
        # at 100 Hz each plus service replies falls behind and drops most of them; one thread keeps up.
        from rclpy.executors import SingleThreadedExecutor

        self.context = rclpy.context.Context()
        rclpy.init(context=self.context)
        self.node = rclpy.create_node(name, context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._lock = threading.Lock()
        self._clients: dict[tuple[Any, str], Any] = {}
        self._closing = False
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        """Spin until close() asks it to stop. close() shuts the executor down only after this thread has
        ended: rclpy's Executor.shutdown destroys the guard condition and drops the callback generator under
        a spinning thread, which then raises whatever it meets (InvalidHandle, TypeError), not a shutdown."""
        from rclpy.executors import ExternalShutdownException, ShutdownException

        try:
            while not self._closing:
                self.executor.spin_once(timeout_sec=0.1)
        except (ExternalShutdownException, ShutdownException):
            pass  # the end of the session shut the context down under the spin
        # anything else a callback raised ends the thread loudly (pytest reports an unhandled thread exception)

    def client(self, srv_type: Any, name: str, timeout: float = 15.0) -> Any:
        """A service client, created once per (type, name) and ready to call."""
        key = (srv_type, name)
        with self._lock:
            client = self._clients.get(key)
            if client is None:
                client = self._clients[key] = self.node.create_client(srv_type, name)
        if not client.service_is_ready() and not client.wait_for_service(timeout_sec=timeout):
            pytest.fail(f"service {name} not available within {timeout} s")
        return client

    def call(
        self, srv_type: Any, name: str, request: Any, timeout: float = 15.0, resend_every: float | None = None
    ) -> Any:
        """Call ``name`` and return its response. ``resend_every`` (for a request that may be sent twice): send
        it again each time that many seconds pass without an answer. The first request of a new client can
        go unanswered on a loaded machine: rmw_fastrtps's server drops a response when it has not yet matched
        the client's response reader within its short wait (seen once in CI beside the whole suite)."""
        client = self.client(srv_type, name, timeout)
        deadline = time.monotonic() + timeout
        while True:
            future = client.call_async(request)
            done = threading.Event()
            future.add_done_callback(lambda _f, done=done: done.set())
            left = deadline - time.monotonic()
            if done.wait(min(left, resend_every) if resend_every else left):
                return future.result()
            if time.monotonic() >= deadline:
                pytest.fail(f"service {name} did not answer within {timeout} s")
            client.remove_pending_request(future)

    def send_goal(self, client: Any, goal: Any, timeout: float = 60.0, said: Callable[[], str] = lambda: "") -> Any:
        """Send an action goal and wait for its result: (accepted, the GetResult response or None).

        Sent from the executor's thread: from another one, a reply that came back before rclpy filed the
        request was dropped and the goal never answered (ros2/rclpy#1123). ``said``: what to show when no
        result comes (a server's output)."""
        done = threading.Event()
        box: dict[str, Any] = {}

        def on_goal(f: Any) -> None:
            handle = f.result()
            box["accepted"] = handle.accepted
            if not handle.accepted:
                done.set()
                return
            handle.get_result_async().add_done_callback(lambda r: (box.__setitem__("result", r.result()), done.set()))

        self.executor.create_task(lambda: client.send_goal_async(goal).add_done_callback(on_goal))
        assert done.wait(timeout), f"no result within {timeout} s; {said()}"
        return box["accepted"], box.get("result")

    def entity_state(self, name: str, reference_frame: str = "") -> Any:
        from gazebo_msgs.srv import GetEntityState

        res = self.call(
            GetEntityState, "/get_entity_state", GetEntityState.Request(name=name, reference_frame=reference_frame)
        )
        assert res.success, f"get_entity_state({name!r}) failed"
        return res

    def close(self) -> None:
        self._closing = True
        self._thread.join(5.0)  # a thread left inside rclpy at interpreter exit aborts the process
        self.executor.shutdown(timeout_sec=2.0)
        self.node.destroy_node()
        if self.context.ok():
            rclpy.shutdown(context=self.context)


def yaw_of(q: Any) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def xacro_to_urdf(path: Path) -> str:
    from xml.dom.minidom import Document

    import xacro

    document = xacro.process_file(str(path))
    assert isinstance(document, Document)  # (xacro's annotation says a file)
    return document.toxml()


@pytest.fixture(scope="session", autouse=True)
def ros_env() -> Iterator[dict[str, str]]:
    """A unique ROS_DOMAIN_ID for this test run, discovery limited to localhost."""
    saved = {
        k: os.environ.get(k)
        for k in ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE", "RMW_IMPLEMENTATION", "PYTHONFAULTHANDLER")
    }
    os.environ["ROS_DOMAIN_ID"] = str(reserved_domain_id())
    os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    os.environ["RMW_IMPLEMENTATION"] = "rmw_fastrtps_cpp"
    os.environ["PYTHONFAULTHANDLER"] = "1"  # a child that hangs prints its stacks on SIGABRT (dump_stacks_and_kill)
    yield dict(os.environ)
    for k, v in saved.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v
