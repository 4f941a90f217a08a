"""`gazelle record-video` to MP4 (H.264 through PyAV): the format follows --out, real-time frame timing,
a valid file when stopped early. The browser tests skip, as test_browser.py does, without chromium."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest
from _harness import GAZELLE
from _paths import ARTIFACTS, REPO, SEED_XACRO
from _pixels import blue_mask

from gazelle.viewer._browser import find_chromium
from gazelle.viewer._snapshot import video_format

needs_browser = pytest.mark.skipif(
    importlib.util.find_spec("playwright") is None or find_chromium() is None,
    reason="no playwright or no system chromium (scripts/setup.sh installs Debian's chromium)",
)


pytestmark = pytest.mark.serial  # real time: run alone (./test.sh)


def decode_mp4(path: Path) -> tuple[object, float, list[np.ndarray]]:
    """(the video stream, its duration in seconds, every decoded frame as RGB), checking it is H.264 yuv420p."""
    import av

    with av.open(str(path)) as container:
        stream = container.streams.video[0]
        assert stream.codec_context.name == "h264"
        assert stream.codec_context.pix_fmt == "yuv420p"
        assert stream.width % 2 == 0 and stream.height % 2 == 0
        assert stream.duration is not None and stream.time_base is not None
        duration = float(stream.duration * stream.time_base)
        frames = [f.to_ndarray(format="rgb24").astype(int) for f in container.decode(stream)]
    assert len(frames) == stream.frames
    return stream, duration, frames


def blue_centroid(rgb: np.ndarray) -> tuple[float, float]:
    """Centroid (x, y) of the strongly blue pixels (the seed robot's box) left of the control panel."""
    rgb = rgb[:, : int(0.7 * rgb.shape[1])]  # the control panel (blue buttons) is on the right
    ys, xs = np.nonzero(blue_mask(rgb))
    # the robot alone is ~10 000 px of a 1280 x 800 view (GIF frames are scaled down)
    least = 3000 * rgb.shape[0] * rgb.shape[1] / (0.7 * 1280 * 800)
    assert len(xs) > least, f"no blue robot in a frame ({len(xs)} blue pixels)"
    return float(xs.mean()), float(ys.mean())


def record(out: Path, *, drive: str, seconds: float, fps: float) -> None:
    """Run `gazelle record-video` on the seed robot driving ``drive`` (V,W) and check it succeeded."""
    res = subprocess.run(
        [*GAZELLE, "record-video", "--world", str(SEED_XACRO), "--drive", drive, "--seconds", str(seconds)]
        + ["--fps", str(fps), "--out", str(out)],
        check=False,
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert res.returncode == 0, res.stdout + res.stderr
    assert "driving simple_robot" in res.stdout
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    shutil.copy(out, ARTIFACTS / f"record_video_seed{out.suffix}")


@pytest.mark.parametrize("name", ["x.avi", "x", "x.mp4.txt"])
def test_an_unsupported_extension_is_a_one_line_error(tmp_path: Path, name: str) -> None:
    out = tmp_path / name
    t0 = time.monotonic()
    res = subprocess.run(
        [*GAZELLE, "record-video", "--out", str(out)], check=False, cwd=REPO, capture_output=True, text=True, timeout=60
    )
    lines = [ln for ln in res.stderr.splitlines() if ln.strip()]
    assert res.returncode == 2, res.stdout + res.stderr
    assert len(lines) == 1 and "Traceback" not in res.stderr, res.stderr
    assert name in lines[0] and ".mp4" in lines[0] and ".gif" in lines[0], lines[0]
    assert not out.exists()
    assert time.monotonic() - t0 < 30, "it should fail before starting a sim or a browser"


def test_video_format_follows_the_extension() -> None:
    assert video_format(Path("a/run.mp4")) == "mp4"
    assert video_format(Path("RUN.MP4")) == "mp4"
    assert video_format(Path("run.gif")) == "gif"
    with pytest.raises(ValueError, match=r"\.webm"):
        video_format(Path("run.webm"))


@needs_browser
def test_record_video_writes_an_h264_mp4_of_the_robot_driving_in_real_time(tmp_path: Path) -> None:
    seconds = 6.0  # beside a CPU hog a screenshot took ~2 s: 4 s gave 2 frames once, the fewest the checks need
    out = tmp_path / "drive.mp4"
    record(out, drive="0.1,0", seconds=seconds, fps=4)
    _, duration, frames = decode_mp4(out)
    # at 4 fps a frame every 0.25 s; software WebGL takes ~1 s a screenshot on a busy machine and ~2 s
    # beside a CPU hog (a fresh clone's run got 2): a first and a last frame are what the checks below need
    assert len(frames) >= 2, f"only {len(frames)} frames in {seconds} s"
    # the frames carry their capture times: the video lasts as long as the recording, however many frames
    assert abs(duration - seconds) <= 0.5 * seconds, f"the video lasts {duration:.2f} s for {seconds} s recorded"
    (x0, y0), (x1, y1) = blue_centroid(frames[0]), blue_centroid(frames[-1])
    # driving +x moves the robot right and towards the camera at (1.6, -1.6): its blue shifts right and down
    # (slowly: at 0.3 m/s it would be under the control panel after ~4 s)
    assert x1 > x0 + 20, f"the robot's blue centroid went from ({x0:.0f}, {y0:.0f}) to ({x1:.0f}, {y1:.0f})"


@needs_browser
def test_record_video_writes_an_animated_gif_of_the_robot_driving(tmp_path: Path) -> None:
    from PIL import Image, ImageSequence

    out = tmp_path / "drive.gif"
    # 5 s: beside a CPU hog the first screenshot once took the whole of 3 s (a one-frame GIF)
    record(out, drive="0.1,0", seconds=5.0, fps=2)
    frames = [np.asarray(f.convert("RGB")).astype(int) for f in ImageSequence.Iterator(Image.open(out))]
    assert len(frames) >= 2
    (x0, _), (x1, _) = blue_centroid(frames[0]), blue_centroid(frames[-1])
    # driving +x moves the robot right and towards the camera: its blue shifts right (GIFs are 640 wide)
    assert x1 > x0 + 5, f"the robot's blue centroid went from x {x0:.0f} to {x1:.0f}"


@needs_browser
def test_a_recording_stopped_early_is_a_valid_mp4(tmp_path: Path, make_sim) -> None:
    from gazelle.cli._sim import load_world
    from gazelle.viewer import Viewer
    from gazelle.viewer._snapshot import record_video

    class StopAfter:
        """A stop event that is set once ``frames`` frames were captured (record_video asks before each one)."""

        def __init__(self, frames: int) -> None:
            self.calls, self.frames = 0, frames

        def is_set(self) -> bool:
            self.calls += 1
            return self.calls > self.frames

    sim = make_sim(load_world(None, {}), rtf=1.0)
    sim.start()
    viewer = Viewer(sim, port=0)
    viewer.start()
    try:
        out = tmp_path / "stopped.mp4"
        t0 = time.monotonic()
        stop = StopAfter(3)
        path, n = record_video(viewer.url, out, seconds=600, fps=4, stop=stop, settle_sec=0.2)  # type: ignore[arg-type]
        elapsed = time.monotonic() - t0
    finally:
        viewer.stop()
        sim.stop()
    assert (path, n) == (out, 3)
    _, duration, frames = decode_mp4(out)
    assert len(frames) == 3
    assert 0.45 <= duration < elapsed, f"{duration:.2f} s of video for 3 frames at 4 fps captured in {elapsed:.2f} s"
