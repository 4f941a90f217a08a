"""``gazelle snapshot`` and ``gazelle record-video``: a PNG, an MP4 or a GIF of the viewer, headless
(an in-process sim, or --attach to a running one)."""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ._browser import BrowserUnavailable, screenshot

if TYPE_CHECKING:
    from ..description import World
    from ..sim import Simulation


def snapshot_world(world: World, out: Path, *, settle_sec: float = 1.0, panel: bool = True) -> Path:
    """Simulate ``world`` in this process for a moment, serve it, and write a PNG of the viewer."""
    from ..sim import Simulation
    from ._viewer import Viewer

    sim = Simulation(world, rtf=1.0)
    sim.start()
    viewer = Viewer(sim, port=0)
    viewer.start()
    try:
        return screenshot(viewer.url, out, settle_sec=settle_sec, panel=panel)
    finally:
        viewer.stop()
        sim.stop()


def run_snapshot(world: World | None, out: Path, *, attach: str | None, settle_sec: float, panel: bool = True) -> int:
    """CLI body: returns the exit code."""
    try:
        if attach is not None:
            path = screenshot(attach, out, settle_sec=settle_sec, panel=panel)
        else:
            assert world is not None
            path = snapshot_world(world, out, settle_sec=settle_sec, panel=panel)
    except BrowserUnavailable as err:
        print(f"gazelle snapshot: {err}", file=sys.stderr)
        return 2
    except Exception as err:
        print(f"gazelle snapshot: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    print(f"gazelle: snapshot written to {path}")
    return 0


# --------------------------------------------------------------------------- videos
VIDEO_WIDTH = 640
"""GIF frames are scaled down to this width: GIFs of a full 1280 x 800 viewport get large (MP4s keep the viewport)."""
VIDEO_SUFFIXES = (".mp4", ".gif")
MP4_CRF = 23
"""x264's constant rate factor (0 lossless .. 51 worst; 23 is its default): 1280 x 800 views measured ~6-25 kB/s."""
MP4_PRESET = "fast"


def video_format(out: Path) -> str:
    """``"mp4"`` or ``"gif"``, from ``out``'s extension. Raises ValueError (one line) for any other."""
    suffix = out.suffix.lower()
    if suffix not in VIDEO_SUFFIXES:
        got = f"format {suffix!r}" if suffix else "format (no extension)"
        raise ValueError(f"unsupported video {got} in {out}: use .mp4 (H.264) or .gif (animated GIF)")
    return suffix[1:]


class _GifWriter:
    """Keeps the (quantised, scaled-down) frames and writes the GIF at the end: GIF needs them all to optimise."""

    def __init__(self, out: Path, width: int | None) -> None:
        self.out, self.width = out, width or VIDEO_WIDTH
        self.frames: list[Any] = []
        self.stamps: list[float] = []

    def add(self, img: Any, stamp: float) -> None:
        """Add a screenshot taken at wall time ``stamp``, scaled to the GIF's width and reduced to 128 colours."""
        from PIL import Image

        h = round(img.height * self.width / img.width)
        small = img.resize((self.width, h), Image.Resampling.BILINEAR)
        self.frames.append(small.quantize(colors=128, method=Image.Quantize.MEDIANCUT))
        self.stamps.append(stamp)

    def close(self, end: float) -> int:
        """Write the GIF, each frame lasting as long as it really did until the next (at least 20 ms), looping;
        the number of frames."""
        if not self.frames:
            return 0
        # each frame lasts as long as it really did: screenshots can fall behind ``fps`` on a busy machine
        stamps = [*self.stamps, end]
        durations = [max(20, int(1000 * (b - a))) for a, b in zip(stamps, stamps[1:])]
        first, rest = self.frames[0], self.frames[1:]
        first.save(self.out, save_all=True, append_images=rest, duration=durations, loop=0, optimize=True)
        return len(self.frames)


class _Mp4Writer:
    """H.264 (yuv420p) in MP4 through PyAV, each frame encoded as it arrives: memory stays bounded (the latest
    frame here, and x264's lookahead: at most a few dozen frames, whatever the length of the recording).

    Frames are stamped with their capture wall time (pts in milliseconds) and each lasts until the next
    one was captured, so the video plays in real time even when screenshots fall behind ``fps``.
    """

    TIME_BASE = Fraction(1, 1000)

    def __init__(self, out: Path, fps: float, width: int | None) -> None:
        """An H.264 MP4 writer whose frames keep their real timing (``fps`` is nominal: a screenshot that came late
        lasts longer), at ``width`` pixels (None: the page's)."""
        self.out, self.fps, self.width = out, fps, width
        self.container: Any = None
        self.stream: Any = None
        self.t0 = 0.0
        self.pending: Any = None  # the last frame: its duration is known once the next one (or the end) is
        self.durations: dict[int, int] = {}  # pts -> duration (ms) of the frames in the encoder
        self.count = 0

    def _open(self, w: int, h: int, stamp: float) -> None:
        """Open the file at the first frame, which fixes the video's size (H.264's yuv420p needs even sides)."""
        import av

        # +faststart: the index goes first, so a browser plays the file while it downloads;
        # no B-frames: packets leave in capture order, so each gets its frame's duration (below)
        self.container = av.open(str(self.out), mode="w", format="mp4", options={"movflags": "+faststart"})
        rate = Fraction(max(self.fps, 0.1)).limit_denominator(1000)  # nominal only: the pts carry the timing
        options = {"crf": str(MP4_CRF), "preset": MP4_PRESET, "bf": "0"}
        self.stream = self.container.add_stream("libx264", rate=rate, options=options)
        self.stream.width, self.stream.height, self.stream.pix_fmt = w, h, "yuv420p"
        self.stream.codec_context.time_base = self.TIME_BASE
        self.t0 = stamp

    def _pts(self, stamp: float) -> int:
        return round((stamp - self.t0) * 1000)

    def _mux(self, packets: Any) -> None:
        """Write encoded packets, each with its frame's real duration."""
        for packet in packets:
            # libx264 does not carry a frame's duration to its packet, and the muxer would give the
            # last frame 1/fps: each packet gets its frame's real duration
            packet.duration = self.durations.pop(packet.pts, 0)
            self.container.mux(packet)

    def _flush_pending(self, next_pts: int) -> None:
        """Encode the held frame now that the next frame's time (``next_pts``) says how long it lasts."""
        frame, self.pending = self.pending, None
        self.durations[frame.pts] = max(1, next_pts - frame.pts)
        self._mux(self.stream.encode(frame))
        self.count += 1

    def add(self, img: Any, stamp: float) -> None:
        """Add a screenshot taken at wall time ``stamp``: scaled (and cropped to even sides), resized to the video's
        size if the window changed, and held until the next frame gives it a duration."""
        import av
        from PIL import Image

        if self.width:
            img = img.resize((self.width, round(img.height * self.width / img.width)), Image.Resampling.BILINEAR)
        if img.width % 2 or img.height % 2:  # yuv420p halves the chroma planes: even sizes only
            img = img.crop((0, 0, img.width - img.width % 2, img.height - img.height % 2))
        if self.container is None:
            self._open(img.width, img.height, stamp)
        elif (img.width, img.height) != (self.stream.width, self.stream.height):
            img = img.resize(
                (self.stream.width, self.stream.height), Image.Resampling.BILINEAR
            )  # the window was resized
        pts = self._pts(stamp)
        if self.pending is not None:
            pts = max(pts, self.pending.pts + 1)
            self._flush_pending(pts)
        frame = av.VideoFrame.from_image(img)
        frame.pts, frame.time_base = pts, self.TIME_BASE
        self.pending = frame

    def close(self, end: float) -> int:
        """Encode the last frame, flush the encoder and write the index (the file is valid only after this)."""
        if self.container is None:
            return 0
        try:
            if self.pending is not None:
                self._flush_pending(self._pts(end))
            self._mux(self.stream.encode(None))
        finally:
            self.container.close()
            self.container = None
        return self.count


def record_video(
    url: str,
    out: Path,
    *,
    seconds: float,
    fps: float = 4.0,
    width: int | None = None,
    stop: threading.Event | None = None,
    settle_sec: float = 1.0,
    on_start: Callable[[], object] | None = None,
    panel: bool = True,
) -> tuple[Path, int]:
    """Screenshots of the viewer at ``url`` at ``fps`` for ``seconds`` (or until ``stop`` is set), as a video.

    The format follows ``out``'s extension: ``.mp4`` is H.264 (yuv420p, played by browsers and common
    players), encoded frame by frame; ``.gif`` is an animated GIF, whose frames are kept until the end.
    ``width`` scales the frames (default: the viewport for MP4, ``VIDEO_WIDTH`` for GIF).
    Headless chromium renders WebGL in software, so a frame costs ~0.1-0.3 s of CPU: keep ``fps`` modest.
    ``on_start`` is called once the page shows the scene, just before the first frame.
    ``panel=False`` minimizes the control panel, so the whole view shows the scene.
    If the recording fails half-way, what was captured is still written (a valid, shorter file).
    Returns (``out``, frame count).
    """
    import io as _io

    from PIL import Image

    from ._browser import open_viewer_page

    fmt = video_format(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    writer: _GifWriter | _Mp4Writer = _Mp4Writer(out, fps, width) if fmt == "mp4" else _GifWriter(out, width)
    period = 1.0 / max(fps, 0.1)
    with open_viewer_page(url, panel=panel) as page:
        page.wait_for_timeout(int(settle_sec * 1000))
        if on_start is not None:
            on_start()
        t_end = time.monotonic() + seconds
        next_t = time.monotonic()
        try:
            while time.monotonic() < t_end and not (stop is not None and stop.is_set()):
                stamp = time.monotonic()
                writer.add(Image.open(_io.BytesIO(page.screenshot())).convert("RGB"), stamp)
                next_t += period
                delay = next_t - time.monotonic()
                if delay > 0:
                    page.wait_for_timeout(int(delay * 1000))
                else:
                    next_t = time.monotonic()
        finally:  # the last frame lasts until now, or until ``seconds`` if its screenshot ran past them
            n = writer.close(min(time.monotonic(), t_end))
    if not n:
        raise RuntimeError("no frame was captured")
    return out, n


def drive_first_robot(sim: Simulation, linear: float, angular: float) -> str | None:
    """Send one Twist to the first entity with a cmd_vel subscription (as the viewer's Drive buttons do)."""
    from ..systems import MsgType, Twist

    eps = sorted(
        (ep for ep in sim.bus.endpoints() if not ep.is_publisher and ep.msg_type == MsgType.TWIST and ep.callback),
        key=lambda ep: ep.owner,
    )
    if not eps:
        return None
    owner = eps[0].owner
    for ep in eps:
        if ep.owner == owner and ep.callback is not None:
            ep.callback(Twist((linear, 0.0, 0.0), (0.0, 0.0, angular)))
    return owner


def run_record(
    world: World | None,
    out: Path,
    *,
    attach: str | None,
    seconds: float,
    fps: float,
    drive: tuple[float, float] | None,
    panel: bool = True,
) -> int:
    """CLI body of ``gazelle record-video`` (the CLI has checked ``out``'s format): returns the exit code."""
    from ..sim import Simulation
    from ._viewer import Viewer

    sim = viewer = None
    try:
        url = attach
        on_start: Callable[[], None] | None = None
        if url is None:
            assert world is not None
            sim = Simulation(world, rtf=1.0)
            sim.start()
            viewer = Viewer(sim, port=0)
            viewer.start()
            url = viewer.url
            if drive is not None:
                the_sim = sim

                def start_driving() -> None:  # drive once the browser shows the scene, so the video sees it start
                    who = drive_first_robot(the_sim, *drive)
                    print(f"gazelle: driving {who}" if who else "gazelle: no diff-drive robot to drive", flush=True)

                on_start = start_driving

        path, n = record_video(url, out, seconds=seconds, fps=fps, on_start=on_start, panel=panel)
    except BrowserUnavailable as err:
        print(f"gazelle record-video: {err}", file=sys.stderr)
        return 2
    except Exception as err:
        print(f"gazelle record-video: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    finally:
        if viewer is not None:
            viewer.stop()
        if sim is not None:
            sim.stop()
    print(f"gazelle: video written to {path} ({n} frames at {fps:g} fps, {path.stat().st_size / 1e3:.0f} kB)")
    return 0
