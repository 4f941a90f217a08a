"""``gazelle demo``: the seed's workflow, end to end, as a newcomer would run it by hand.

1. ``gazelle sim`` (embedded default world) in its own process;
2. the seed robot's xacro output published latched on ``robot_description``;
3. ``gazelle spawn -entity simple_robot -topic robot_description``;
4. the seed's ``square_movement.py`` (plain rclpy) for one square;
5. the four corners by ground truth and by /odom, and an SVG of both paths.
"""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rclpy.node import Node

REPO = Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "simple_robot" / "simple_robot"


@dataclass
class Sample:
    """A planar pose at a time (from /odom or the ground truth)."""

    t: float
    x: float
    y: float
    yaw: float

    @staticmethod
    def of(stamp: Any, pose: Any) -> Sample:
        """From a message's ``header.stamp`` and ``geometry_msgs/Pose``."""
        return Sample(stamp.sec + stamp.nanosec * 1e-9, pose.position.x, pose.position.y, _yaw(pose.orientation))


class _Child:
    """A child process whose output is echoed with a prefix and kept."""

    def __init__(self, name: str, cmd: list[str], env: dict[str, str]):
        """Start a child process of the demo (``gazelle sim``, a spawn, a driver) with its output read on a thread."""
        self.name = name
        self.lines: list[str] = []
        self.proc = subprocess.Popen(
            cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, cwd=REPO
        )
        self._ready = threading.Event()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        """Echo the child's output, prefixed with its name, and keep it for :meth:`wait_for_line`."""
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            line = line.rstrip("\n")
            self.lines.append(line)
            print(f"  [{self.name}] {line}", flush=True)

    def wait_for_line(self, needle: str, timeout: float) -> bool:
        """Whether the child printed a line containing ``needle`` within ``timeout`` seconds (checked once more when
        it exits early)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if any(needle in ln for ln in self.lines):
                return True
            if self.proc.poll() is not None:
                return any(needle in ln for ln in self.lines)
            time.sleep(0.05)
        return False

    def stop(self, timeout: float = 10.0) -> int:
        """Stop the child as Ctrl-C would (SIGINT), killing it if it does not end within ``timeout``; its exit code."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        return self.proc.returncode


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def find_corners(truth: list[Sample], min_turn_rate: float = 0.25) -> list[int]:
    """Indices of the middle sample of each turn-in-place phase (where the yaw changes fast).

    A sample with the same stamp as the one before it (the sampler asked twice while the simulation
    had not stepped, e.g. on a loaded machine) is skipped without ending the turn it falls in: it
    once split one turn into two corners at the same place.
    """
    turning: list[list[int]] = []
    prev = 0
    for i in range(1, len(truth)):
        a, b = truth[prev], truth[i]
        dt = b.t - a.t
        if dt <= 0:
            continue
        rate = abs(math.remainder(b.yaw - a.yaw, math.tau)) / dt
        if rate > min_turn_rate:
            if turning and turning[-1][-1] == prev:
                turning[-1].append(i)
            else:
                turning.append([i])
        prev = i
    return [seg[len(seg) // 2] for seg in turning if len(seg) >= 3]


def interpolate(samples: list[Sample], t: float) -> Sample | None:
    """The odometry sample at time t (linear interpolation), or None outside the record."""
    for a, b in zip(samples, samples[1:]):
        if a.t <= t <= b.t:
            w = (t - a.t) / (b.t - a.t) if b.t > a.t else 0.0
            return Sample(t, a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.yaw)
    return None


def write_svg(path: Path, truth: list[Sample], odom: list[Sample], corners: list[Sample]) -> None:
    """Both paths in metres, ground truth solid blue, /odom dashed orange, corners as dots."""
    pts = [(s.x, s.y) for s in truth + odom] or [(0.0, 0.0)]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    margin = 0.15
    x0, x1, y0, y1 = min(xs) - margin, max(xs) + margin, min(ys) - margin, max(ys) + margin
    scale = 400.0 / max(x1 - x0, y1 - y0, 1e-6)
    width, height = (x1 - x0) * scale, (y1 - y0) * scale

    def px(x: float, y: float) -> str:
        return f"{(x - x0) * scale:.1f},{(y1 - y) * scale:.1f}"

    def poly(samples: list[Sample], style: str) -> str:
        return f'<polyline fill="none" {style} points="{" ".join(px(s.x, s.y) for s in samples)}"/>'

    dots = "".join(
        f'<circle cx="{px(c.x, c.y).split(",")[0]}" cy="{px(c.x, c.y).split(",")[1]}" r="4" fill="#c00"/>'
        f'<text x="{(c.x - x0) * scale + 6:.1f}" y="{(y1 - c.y) * scale - 6:.1f}" font-size="12">{i + 1}</text>'
        for i, c in enumerate(corners)
    )
    svg = (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height + 40:.0f}" '
        f'viewBox="0 0 {width:.0f} {height + 40:.0f}">'
        f'<rect width="100%" height="100%" fill="white"/>'
        + poly(truth, 'stroke="#1f5fbf" stroke-width="3"')
        + poly(odom, 'stroke="#f08000" stroke-width="1.5" stroke-dasharray="6 4"')
        + dots
        + f'<text x="8" y="{height + 18:.0f}" font-size="13" font-family="sans-serif">'
        "gazelle demo: seed robot, one square. blue = ground truth, orange dashed = /odom, red = corners</text>"
        "</svg>"
    )
    path.write_text(svg)


def _viewer_url(sim: _Child) -> str | None:
    """The URL `gazelle sim` printed for its browser viewer (None: no viewer)."""
    for ln in sim.lines:
        if "gazelle: viewer at " in ln:
            return ln.split("gazelle: viewer at ", 1)[1].strip()
    return None


class _GroundTruth:
    """/odom heard, and the robot's pose asked of /get_entity_state every 20 ms (a thread of its own)."""

    def __init__(self, node: Node) -> None:
        """Sample the robot's true pose (gazebo_msgs GetEntityState) beside its odometry (``/odom``), to print how
        far they drift apart over the square."""
        from gazebo_msgs.srv import GetEntityState
        from nav_msgs.msg import Odometry

        self.truth: list[Sample] = []
        self.odom: list[Sample] = []
        self._lock = threading.Lock()
        self._done = threading.Event()
        self._request = GetEntityState.Request(name="simple_robot")
        node.create_subscription(Odometry, "/odom", self._on_odom, 100)
        self.client = node.create_client(GetEntityState, "/get_entity_state")
        self._thread = threading.Thread(target=self._sample, daemon=True)

    def _on_odom(self, msg: Any) -> None:
        with self._lock:
            self.odom.append(Sample.of(msg.header.stamp, msg.pose.pose))

    def _sample(self) -> None:
        """Ask for the true pose about 50 times a second until stopped (a reply that takes over 5 s is skipped)."""
        while not self._done.is_set():
            fut = self.client.call_async(self._request)
            ev = threading.Event()
            fut.add_done_callback(lambda _f, ev=ev: ev.set())
            r = fut.result() if ev.wait(5) else None
            if r is not None and r.success:
                with self._lock:
                    self.truth.append(Sample.of(r.header.stamp, r.state.pose))
            self._done.wait(0.02)

    def start(self) -> None:
        self._thread.start()

    def stop(self) -> tuple[list[Sample], list[Sample]]:
        """Stop sampling; (ground truth, /odom), each in time order."""
        self._done.set()
        self._thread.join(10)
        with self._lock:
            return sorted(self.truth, key=lambda s: s.t), sorted(self.odom, key=lambda s: s.t)


class _Recorder:
    """``--record``: the viewer recorded to ``square.mp4`` while the square drives (a thread of its own)."""

    def __init__(self, url: str, out: Path) -> None:
        """Record the viewer's page to ``out/square.mp4`` on a thread while the robot drives."""
        self.url, self.out = url, out
        self.stop_rec, self.ready = threading.Event(), threading.Event()
        self.result: list[object] = []
        self._thread = threading.Thread(target=self._record, daemon=True)

    def _record(self) -> None:
        """The recording thread: a headless browser on the viewer's page, two frames a second, until asked to stop;
        what it made (or the error) is kept for :meth:`finish`."""
        from ..viewer import record_video

        try:
            self.result.append(
                record_video(
                    self.url,
                    self.out / "square.mp4",
                    seconds=600,
                    fps=2.0,
                    stop=self.stop_rec,
                    settle_sec=0.5,
                    panel=False,
                    on_start=self.ready.set,
                )
            )
        except Exception as err:
            self.result.append(err)
        finally:
            self.ready.set()

    def start(self) -> None:
        self._thread.start()
        # the browser takes a few seconds to start: the square waits for it (at --rtf 0 it is over in ~4 s)
        self.ready.wait(60)

    def finish(self) -> None:
        """Stop recording and say where the video is (or why there is none)."""
        self.stop_rec.set()
        self._thread.join(60)
        r = self.result[0] if self.result else "no result"
        print(
            f"   video: {r[0].resolve()} ({r[1]} frames)" if isinstance(r, tuple) else f"   video failed: {r}",
            flush=True,
        )


def _report(out: Path, truth_s: list[Sample], odom_s: list[Sample], url: str | None, snapshot: bool) -> bool:
    """Step 5: the corners by ground truth and by /odom, the path image, the snapshot; True if the robot
    drove four corners."""
    corner_idx = find_corners(truth_s)
    print("5. corners (x, y in metres)", flush=True)
    print(f"   {'':8}{'ground truth':>22}{'/odom':>22}{'difference':>14}")
    corners: list[Sample] = []
    worst = 0.0
    for k, i in enumerate(corner_idx, 1):
        g = truth_s[i]
        o = interpolate(odom_s, g.t)
        corners.append(g)
        diff = math.hypot(o.x - g.x, o.y - g.y) if o else float("nan")
        worst = max(worst, diff) if o else worst
        ostr = f"({o.x:+.3f}, {o.y:+.3f})" if o else "n/a"
        print(f"   corner {k}{f'({g.x:+.3f}, {g.y:+.3f})':>22}{ostr:>22}{diff * 1000:>11.2f} mm")
    svg = out / "square.svg"
    write_svg(svg, truth_s, odom_s, corners)
    print(f"   path image: {svg.resolve()}")
    if snapshot and url:
        from ..viewer import screenshot

        try:
            png = screenshot(url, out / "viewer.png", settle_sec=1.0, panel=False)
            print(f"   viewer snapshot: {png.resolve()}", flush=True)
        except Exception as err:
            print(f"   viewer snapshot failed: {type(err).__name__}: {err}", flush=True)
    if len(corners) != 4:
        print(f"gazelle demo: expected 4 corners, found {len(corners)}", file=sys.stderr)
        return False
    sides = [math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(corners, corners[1:])]
    print(
        "   sides between corners: "
        + ", ".join(f"{s:.3f} m" for s in sides)
        + f"; worst /odom error {worst * 1000:.2f} mm"
    )
    return True


def _publish_description(node: Node) -> None:
    """Step 2: the seed robot's xacro expanded, latched on robot_description (as robot_state_publisher)."""
    import xacro
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    print("2. robot_description <- xacro examples/simple_robot/simple_robot/robot.urdf.xacro", flush=True)
    qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    pub = node.create_publisher(String, "robot_description", qos)
    pub.publish(String(data=xacro.process_file(str(EXAMPLE / "robot.urdf.xacro")).toxml()))  # pyright: ignore[reportAttributeAccessIssue] - xacro.process_file returns a minidom Document, typed as None-able


def _drive(env: dict[str, str], rtf: float, children: list[_Child], recorder: _Recorder | None) -> bool:
    """Step 4: the seed's square_movement node drives one square (recorded if asked); True if it ended well."""
    print("4. square_movement.py (the seed's node, plain rclpy): one square", flush=True)
    node_cmd = [sys.executable, str(EXAMPLE / "square_movement.py"), "--ros-args", "-p", "max_sides:=4"]
    if rtf != 1.0:
        node_cmd += ["-p", "use_sim_time:=true"]
    if recorder is not None:
        recorder.start()
    square = _Child("square_movement", node_cmd, env)
    children.append(square)
    square_rc = square.proc.wait(300)
    if recorder is not None:
        recorder.finish()
    if square_rc != 0:
        print("gazelle demo: square_movement failed", file=sys.stderr)
        return False
    return True


def run_demo(out: Path, *, rtf: float = 1.0, snapshot: bool = False, record: bool = False) -> int:
    """Run the demo; returns the exit code (0 = the robot drove a square)."""
    env = os.environ.copy()
    env.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    os.environ.update({k: env[k] for k in ("ROS_AUTOMATIC_DISCOVERY_RANGE",)})
    out.mkdir(parents=True, exist_ok=True)
    import rclpy
    from rclpy.context import Context
    from rclpy.executors import SingleThreadedExecutor

    gazelle = [sys.executable, "-m", "gazelle.cli"]
    print(f"gazelle demo: ROS_DOMAIN_ID={env.get('ROS_DOMAIN_ID', '0')}, real-time factor {rtf:g}", flush=True)
    print("1. gazelle sim (embedded default world)", flush=True)
    sim = _Child("sim", [*gazelle, "sim", "--rtf", str(rtf)], env)
    context = Context()
    rclpy.init(context=context)
    node = rclpy.create_node("gazelle_demo", context=context)
    executor = SingleThreadedExecutor(context=context)  # the multi-threaded one drops /odom at 100 Hz
    executor.add_node(node)
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    children = [sim]
    try:
        if not sim.wait_for_line("gazelle: ready", 60):
            print("gazelle demo: the simulator did not start", file=sys.stderr)
            return 1
        url = _viewer_url(sim)
        if url:
            print(f"   watch it in a browser: {url} (the magenta line is the robot's path)", flush=True)
        _publish_description(node)
        print("3. gazelle spawn -entity simple_robot -topic robot_description", flush=True)
        spawn = _Child("spawn", [*gazelle, "spawn", "-entity", "simple_robot", "-topic", "robot_description"], env)
        children.append(spawn)
        if spawn.proc.wait(90) != 0:
            print("gazelle demo: spawning failed", file=sys.stderr)
            return 1
        watch = _GroundTruth(node)
        if not watch.client.wait_for_service(timeout_sec=30):
            print("gazelle demo: /get_entity_state is not available", file=sys.stderr)
            return 1
        watch.start()
        if not _drive(env, rtf, children, _Recorder(url, out) if record and url else None):
            return 1
        time.sleep(0.5 if rtf == 1.0 else 0.1)  # a last few samples of the robot at rest
        truth_s, odom_s = watch.stop()
        return 0 if _report(out, truth_s, odom_s, url, snapshot) else 1
    finally:
        for c in reversed(children):
            c.stop()
        executor.shutdown(timeout_sec=2.0)
        spinner.join(5.0)  # a thread still inside rclpy's wait at interpreter exit aborts the process (rc 134)
        node.destroy_node()
        if context.ok():
            rclpy.shutdown(context=context)
        print("gazelle demo: stopped everything", flush=True)
