"""What a replay shows: every body's collision shapes once, where each body was (sampled in sim time), and
the values of some topics of the simulation.

:class:`ReplayRecorder` samples the world on the simulation thread (a step listener, :data:`RATE_HZ` frames
per sim second, every body's pose in one array read: ~10 us a frame, so a run at 50 times real time pays
1.5 % for it). It is bounded: past :data:`MAX_SAMPLES` link poses it keeps every other frame and samples
half as often, and past :data:`MAX_TOPIC_SAMPLES` messages a topic does the same, so an hour-long run costs
what a short one does. :meth:`ReplayRecorder.data` is plain JSON-ready data that
:func:`gazelle.viewer.replay_html` draws.
"""

from __future__ import annotations

import dataclasses
import enum
import json
import math
import os
import stat
import threading
from pathlib import Path
from typing import Any

import numpy as np

from .._files import atomic_write
from ..physics import WorldError
from ..systems import UpdateInfo
from ..systems.sensors import Lidar
from ._scene import SceneShape, link_shapes

RATE_HZ = 30.0
"""Frames per sim second, at first."""
MAX_SAMPLES = 400_000
"""Link poses kept (7 numbers each) before the recording thins itself: ~20 MB of JSON at most."""
MAX_TOPIC_SAMPLES = 2_000
"""Messages kept per topic before that topic thins itself."""
MAX_FIELDS = 24
"""Fields shown of a message."""
MAX_RAYS = 120
"""Lidar hits kept per lidar and frame (every n-th hit of a scan): the rays the page draws at the cursor."""
REPLAY_SIGNATURES = (
    b'{"shapes":',
    b'<meta name="generator" content="gazelle replay">',
    b'<script id="data" type="application/json">',
)
"""What a replay file holds in its first :data:`SIGNATURE_BYTES` bytes: its data (JSON) starts with the first;
a replay page (:func:`gazelle.viewer.replay_html`) has the second in its head, and one that an earlier gazelle
wrote the third. A file with none of them is not overwritten by a replay unless forced."""
SIGNATURE_BYTES = 4096
FLOAT32_FIELDS = ("ranges", "intensities")
"""Byte fields of the bus's messages that hold float32 arrays (LaserScan's)."""


def _starts_like_a_replay(path: Path) -> bool:
    """Whether the regular file ``path`` starts as a replay does (:data:`REPLAY_SIGNATURES`); opened without
    following a link, or waiting on a FIFO."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError:
        return False
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return False
        head = f.read(SIGNATURE_BYTES)
    return head.startswith(REPLAY_SIGNATURES[0]) or any(mark in head for mark in REPLAY_SIGNATURES[1:])


def _shape(s: SceneShape) -> dict[str, Any]:
    """A shape as the replay page reads it: kind, sizes and pose in its link (x, y, z, qw, qx, qy, qz).
    Positions are rounded to 0.1 mm and quaternions to 1e-5 (~2e-5 rad), finer than a browser's pixel at
    any zoom a page is looked at, and a third of the JSON of full floats."""
    p = s.pose
    pose = [round(float(v), 4) for v in p.position] + [round(float(v), 5) for v in p.orientation]
    return {"kind": s.kind, "size": [round(v, 5) for v in s.dimensions], "pose": pose}


def flatten(msg: Any, prefix: str = "", out: dict[str, Any] | None = None, depth: int = 0) -> dict[str, Any]:
    """A message's fields as ``{"a.b": value}``: numbers rounded, long arrays as their size and range.

    Works on the bus's payload dataclasses (the simulation's own messages, before any ROS conversion), so
    a replay needs no rclpy. It stops at :data:`MAX_FIELDS` fields and four levels of nesting; a list of
    dataclasses (a scan's contacts, a trajectory's points) shows its first element and its count. Non-finite
    numbers are kept as text (``inf``, ``nan``): JSON has no such numbers, and a lidar's "no return" must
    still show."""
    out = {} if out is None else out
    if len(out) >= MAX_FIELDS:
        return out
    if dataclasses.is_dataclass(msg) and not isinstance(msg, type):
        for f in dataclasses.fields(msg):
            flatten(getattr(msg, f.name), f"{prefix}{f.name}.", out, depth + 1)
        return out
    key = prefix[:-1] or "value"
    if key.rsplit(".", 1)[-1] == "orientation" and isinstance(msg, tuple | list) and len(msg) == 4:
        # the bus's quaternions are w first (MuJoCo's order); the page shows ROS's fields, x, y, z, w, as
        # `ros2 topic echo` does, so that a value read off the replay reads the same as in the bag
        for name, v in zip(("x", "y", "z", "w"), (msg[1], msg[2], msg[3], msg[0])):
            out[f"{key}.{name}"] = round(float(v), 4) if math.isfinite(float(v)) else str(v)
        return out
    if isinstance(msg, bytes | bytearray):
        if key.rsplit(".", 1)[-1] in FLOAT32_FIELDS and len(msg) % 4 == 0 and msg:
            values = np.frombuffer(msg, dtype=np.float32)  # a scan's ranges: their count and span
            finite = values[np.isfinite(values)]
            span = f", {finite.min():.3g} .. {finite.max():.3g}" if len(finite) else ", none finite"
            out[key] = f"{len(values)} values{span}"
        else:
            out[key] = f"{len(msg)} bytes"
    elif isinstance(msg, enum.Enum):
        out[key] = msg.name
    elif isinstance(msg, bool | str):
        out[key] = msg if not isinstance(msg, str) else msg[:80]
    elif isinstance(msg, int | float | np.floating | np.integer):
        v = float(msg)
        out[key] = round(v, 4) if math.isfinite(v) else str(v)
    elif isinstance(msg, list | tuple | np.ndarray) and depth < 4 and len(msg):
        if dataclasses.is_dataclass(msg[0]):
            flatten(msg[0], f"{prefix}0.", out, depth + 1)
            out[f"{prefix}count"] = len(msg)
            return out
        try:
            values = np.asarray(msg, dtype=float).ravel()
        except (TypeError, ValueError):
            return out  # not numbers
        if len(values) <= 6:
            out[key] = [round(float(v), 4) if math.isfinite(v) else str(v) for v in values.tolist()]
        else:
            finite = values[np.isfinite(values)]
            span = f", {finite.min():.3g} .. {finite.max():.3g}" if len(finite) else ""
            out[key] = f"{len(values)} values{span}"
    return out


class ReplayRecorder:
    """Samples the world of ``sim`` from now on, and the messages of ``topics`` its systems publish."""

    def __init__(self, sim: Any, rate_hz: float = RATE_HZ, topics: tuple[str, ...] = ()) -> None:
        """Record the bodies' poses of ``sim`` at ``rate_hz`` of sim time for a replay page, and the fields of
        ``topics``' messages at no more than that rate. The recording is bounded: past :data:`MAX_SAMPLES` it
        keeps every other frame and halves its rate, so an hour-long run still makes a page a browser opens."""
        self._sim = sim
        self._lock = threading.Lock()
        self._shapes: dict[str, list[dict[str, Any]]] = {}
        self._models: dict[str, int] = {}
        self._index: tuple[int, tuple[str, ...], np.ndarray] | None = None
        self._frames: list[tuple[float, tuple[str, ...], np.ndarray, dict[str, list[float]]]] = []
        self._lidars: list[tuple[str, Lidar]] = []
        self._samples = 0
        self._rate_hz = rate_hz
        self._period = 1.0 / rate_hz
        self._next = -1.0
        self._topics = {t: [] for t in topics}
        self._topic_period = {t: self._period for t in topics}  # no more samples than frames
        self._sinks: list[tuple[Any, Any]] = []
        self._time = 0.0
        # at the frame rate: the runtime steps in blocks up to the next frame (a listener of every step
        # would have it step one at a time, 3 times slower); _next thins further when the recording does
        sim.add_step_listener(self._on_step, rate_hz)
        if topics:
            sim.call(self._attach)

    def close(self) -> None:
        """Stop sampling (what was recorded stays)."""
        self._sim.remove_step_listener(self._on_step)

        def detach() -> None:
            for endpoint, sink in self._sinks:
                endpoint.remove_sink(sink)
            self._sinks = []

        self._sim.call(detach)

    # ------------------------------------------------------------------ on the simulation thread
    def _attach(self) -> None:
        """Listen to the publishers of the topics asked for (those there are now, and at each new index)."""
        heard = {id(e) for e, _ in self._sinks}
        for endpoint in self._sim.bus.endpoints():
            if endpoint.topic in self._topics and endpoint.is_publisher and id(endpoint) not in heard:
                sink = self._sink(endpoint.topic)
                endpoint.add_sink(sink)
                self._sinks.append((endpoint, sink))

    def _sink(self, topic: str) -> Any:
        """A bus sink for ``topic``: a message's flattened fields at most once a frame period, thinned like the
        frames when there are too many."""
        samples = self._topics[topic]

        def on(msg: Any) -> None:
            t = self._time
            if samples and t - samples[-1][0] < self._topic_period[topic]:
                return
            fields = flatten(msg)
            with self._lock:
                samples.append((round(t, 4), fields))
                if len(samples) > MAX_TOPIC_SAMPLES:
                    samples[:] = samples[::2]
                    self._topic_period[topic] *= 2.0

        return on

    def _reindex(self) -> tuple[int, tuple[str, ...], np.ndarray]:
        """The bodies to record after the world changed (a spawn, a delete): every link with a body of its own,
        named ``entity::link``, with its shapes (kept once per model, for the page to draw)."""
        world = self._sim.world
        names, ids = [], []
        for entity_name, entity in list(world.entities.items()):
            shapes = link_shapes(entity.model)
            for link, link_shapes_ in shapes.items():
                try:
                    body = world.body_id(entity_name, link)
                except WorldError:  # a link without a body of its own
                    continue
                name = f"{entity_name}::{link}"
                names.append(name)
                ids.append(body)
                if name not in self._shapes or self._models.get(name) != id(entity.model):
                    with self._lock:
                        self._shapes[name] = [_shape(s) for s in link_shapes_]
                        self._models[name] = id(entity.model)
        self._lidars = [
            (f"{entity_name}::{system.sensor.name}", system)
            for entity_name, entity in list(world.entities.items())
            for system in entity.systems
            if isinstance(system, Lidar) and system.sensor is not None
        ]
        if self._topics:
            self._attach()
        return world.generation, tuple(names), np.asarray(ids, dtype=int)

    def _on_step(self, info: UpdateInfo) -> None:
        """At each frame time, the poses of every recorded body in one read. A clock that went back (a world reset)
        starts the recording again: the replay is of the run since."""
        t = info.sim_time_sec
        if t < self._time - 1e-9:  # the world was reset: the replay is of the run since (a test's own)
            with self._lock:
                self._frames = []
                self._samples = 0
                self._period = 1.0 / self._rate_hz
                for topic, samples in self._topics.items():
                    samples.clear()
                    self._topic_period[topic] = self._period
            self._next = -1.0
        self._time = t
        if t < self._next - info.dt_sec:  # the listener comes at step boundaries: a step early is on time
            return
        self._next = t + self._period
        world = self._sim.world
        if self._index is None or self._index[0] != world.generation:
            self._index = self._reindex()
        _, names, ids = self._index
        poses = world.body_poses(ids) if len(ids) else np.zeros((0, 7))
        rays = self._lidar_rays(world)
        with self._lock:
            self._frames.append((round(t, 4), names, poses, rays))
            self._samples += len(names) + sum(len(r) for r in rays.values()) // 7
            if self._samples > MAX_SAMPLES:  # thin out: every other frame, and half the rate from now on
                self._frames = self._frames[::2]
                self._samples = sum(len(n) + sum(len(r) for r in rays.values()) // 7 for _, n, _, rays in self._frames)
                self._period *= 2.0

    def _lidar_rays(self, world: Any) -> dict[str, list[float]]:
        """Each lidar's scan now, for the page to draw as rays: ``{entity::sensor: [ox, oy, x1, y1, ...]}``, the
        sensor's origin then at most :data:`MAX_RAYS` of its hits (noise-free, as the viewer's overlay draws
        them), in the world frame, to the centimetre."""
        out = {}
        for key, lidar in self._lidars:
            pts = lidar.world_points(world)
            if len(pts) > MAX_RAYS:
                pts = pts[:: math.ceil(len(pts) / MAX_RAYS)]
            origin = lidar.sensor_pose().position
            out[key] = [round(float(origin[0]), 2), round(float(origin[1]), 2)] + np.round(
                pts[:, :2], 2
            ).ravel().tolist()
        return out

    # ------------------------------------------------------------------ any thread
    def data(self) -> dict[str, Any]:
        """``{"shapes": {link: [shape]}, "frames": [[t, {link: [x, y, z, qw, qx, qy, qz]}, rays?]], "topics":
        {topic: [[t, {field: value}]]}}``, positions rounded to 0.1 mm; ``rays`` (in frames with a lidar) is
        ``{entity::sensor: [ox, oy, x1, y1, ...]}`` (see :meth:`_lidar_rays`)."""
        with self._lock:
            frames = list(self._frames)
            shapes = dict(self._shapes)
            topics = {t: [[s[0], dict(s[1])] for s in samples] for t, samples in self._topics.items()}
        out = []
        for t, names, poses, rays in frames:
            rounded = np.concatenate((np.round(poses[:, :3], 4), np.round(poses[:, 3:], 5)), axis=1).tolist()
            out.append([t, dict(zip(names, rounded)), rays] if rays else [t, dict(zip(names, rounded))])
        return {"shapes": shapes, "frames": out, "topics": topics}

    def write(self, path: str | os.PathLike[str], text: str | None = None, force: bool = False) -> Path:
        """Write ``text`` (default: :meth:`data` as JSON) to ``path``, whole or not at all.

        Written through :func:`gazelle._files.atomic_write` (a new file of a random name beside the target,
        renamed over it), so a run killed mid-write (a test's timeout, Ctrl-C) leaves the previous replay or
        none, never a page that fails to parse, and nothing planted beside the target is written through.

        Raises:
            FileExistsError: ``path`` is there and is not a replay (see :meth:`refusal`), unless ``force``.
        """
        out = Path(path)
        why = self.refusal(out, force)
        if why is not None:
            raise FileExistsError(why)
        return atomic_write(out, text if text is not None else json.dumps(self.data(), separators=(",", ":")))

    @staticmethod
    def refusal(path: str | os.PathLike[str], force: bool = False) -> str | None:
        """Why a replay must not be written to ``path`` (one line), or None when it may: nothing is there,
        or a replay is (a page or data a replay wrote, :data:`REPLAY_SIGNATURES`), or ``force``.

        Anything else is refused, as rosbag2 refuses an existing output: ``--replay "my world.sdf"`` once
        replaced the world. A link counts as something else, whatever it points to: a forced write replaces
        the link itself, never its target."""
        out = Path(path)
        if force:
            return None
        try:
            info = out.lstat()
        except FileNotFoundError:
            return None
        except OSError as err:
            return f"{out}: {err.strerror or err}"
        if stat.S_ISREG(info.st_mode) and _starts_like_a_replay(out):
            return None
        kind = "a link" if stat.S_ISLNK(info.st_mode) else "not a replay"
        return f"{out} exists and is {kind}: it is not overwritten (name another file, or pass --force)"
