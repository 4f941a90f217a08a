"""The replay page (issue 30): a run recorded in sim time, drawn from above in one self-contained HTML file
that a browser opens from disk; checked by its pixels in headless chromium.

The seed robot drives an arc beside a box for 4 s of sim time; the page, scrubbed to the last frame, shows
the robot (the first moving body: red) where the simulation ended it, and not where it started; at the
first frame, the other way round.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from _paths import BOX, SEED_XACRO
from _pixels import open_replay, share_near
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.sim import ReplayRecorder
from gazelle.systems import MsgType, Twist
from gazelle.viewer import replay_html
from gazelle.viewer._browser import find_chromium

RED = np.array([0xE6, 0x19, 0x4B])
"""The first moving body's colour on the page."""


@pytest.fixture(scope="module")
def run() -> tuple[dict, tuple[float, float], tuple[float, float]]:
    """The recording of a 4 s drive, and the robot's (x, y) at its start and end by ground truth."""
    sim = new_simulation()
    sim.spawn(load(SEED_XACRO).model, name="robot", pose=Pose((0.0, 0.0, 0.05)))
    sim.spawn(load_string(BOX).model, name="crate", pose=Pose((0.0, 1.2, 0.1)))
    recorder = ReplayRecorder(sim)
    sim.step(1)
    start = sim.world.entity_state("robot").pose.position[:2]
    assert sim.bus.inject("/cmd_vel", MsgType.TWIST, Twist((0.5, 0.0, 0.0), (0.0, 0.0, 0.4))) == 1
    sim.step(4000)
    end = sim.world.entity_state("robot").pose.position[:2]
    recorder.close()
    return recorder.data(), (float(start[0]), float(start[1])), (float(end[0]), float(end[1]))


def test_the_recording_has_each_bodys_shapes_once_and_a_frame_every_thirtieth_of_a_second(run) -> None:
    data, start, end = run
    assert {"robot::base_link", "crate::link"} <= set(data["shapes"])
    times = [t for t, _ in data["frames"]]
    assert len(times) == pytest.approx(4.0 * 30, abs=3) and times == sorted(times)
    assert np.diff(times).max() == pytest.approx(1 / 30, abs=2e-3)
    assert np.hypot(end[0] - start[0], end[1] - start[1]) > 1.0  # it did drive
    last = data["frames"][-1][1]["robot::base_link"]
    assert last[:2] == pytest.approx(end, abs=0.02)  # the last frame is where the simulation ended it


def test_a_long_recording_thins_itself_instead_of_growing(monkeypatch, make_sim) -> None:
    from gazelle.sim import _replay

    monkeypatch.setattr(_replay, "MAX_SAMPLES", 300)
    sim = make_sim()
    sim.spawn(load_string(BOX).model, name="crate", pose=Pose((0.0, 0.0, 1.0)))
    recorder = ReplayRecorder(sim)
    sim.step(20_000)  # 20 s: 600 frames at 30 Hz
    frames = recorder.data()["frames"]
    assert len(frames) <= 300 and frames[-1][0] > 19.0  # the whole run, fewer frames


def test_the_page_is_one_file_with_its_data_and_survives_hostile_names(tmp_path: Path, run) -> None:
    data, *_ = run
    topics = {"/odom": [[0.5, {"x": 0.1, "note": "</script><script>alert(1)</script>"}]]}
    page = replay_html(data, topics, title="<b>a test</b>")
    assert "<script src" not in page and "http" not in page.split("<script")[1]  # nothing fetched
    assert "</script><script>alert" not in page  # data cannot end its script element
    payload = page.split('type="application/json">')[1].split("</script>")[0]
    assert json.loads(payload)["topics"]["/odom"][0][1]["note"].startswith("</script>")
    assert len(page.encode()) < 2_000_000


@pytest.mark.skipif(find_chromium() is None, reason="no system chromium (scripts/setup.sh installs it)")
def test_chromium_opens_the_replay_from_disk_and_scrubbing_moves_the_robot(tmp_path: Path, run) -> None:
    pytest.importorskip("playwright")
    data, start, end = run
    path = tmp_path / "replay.html"
    path.write_text(replay_html(data, {"/odom": [[0.0, {"x": 0.0}], [2.0, {"x": 0.9}]]}, title="drive"))
    with open_replay(path) as replay:
        assert replay.frames() > 100
        assert replay.page.evaluate("() => window.gazelleReplay.moving") == ["robot"]
        red = replay.color_of("robot")
        assert list(red) == list(RED)  # the first body met
        replay.seek(replay.frames() - 1)  # scrubbed to the end
        at_end = replay.canvas()
        assert share_near(at_end, replay.to_screen(*end), red) > 0.9, "the robot is not drawn where it ended"
        assert share_near(at_end, replay.to_screen(*start), red) < 0.5, "the robot is still drawn where it started"
        assert "0.9" in replay.page.locator("#topics").inner_text()  # the topic's value at the cursor
        slider = replay.page.locator("#cursor").bounding_box()
        assert slider is not None
        replay.page.mouse.click(slider["x"] + 3, slider["y"] + slider["height"] / 2)  # the slider's start, clicked
        at_start = replay.canvas()
        assert share_near(at_start, replay.to_screen(*start), red) > 0.9
        assert share_near(at_start, replay.to_screen(*end), red) < 0.5
        assert "nothing yet" not in replay.page.locator("#topics").inner_text()


HOSTILE = "bot<!--<script>"
"""An entity name that blanked the page when only ``</`` was escaped (issue 48, item 9)."""


def _renamed(data: dict, old: str, new: str) -> dict:
    """A recording with entity ``old`` called ``new`` (its links' names, in shapes and frames)."""

    def rename(link: str) -> str:
        return new + link[len(old) :] if link.split("::")[0] == old else link

    return {
        "shapes": {rename(k): v for k, v in data["shapes"].items()},
        "frames": [[t, {rename(k): p for k, p in f.items()}] for t, f in data["frames"]],
        "topics": data.get("topics", {}),
    }


def test_no_name_can_open_an_escaped_section_in_the_pages_scripts(run) -> None:
    data, *_ = run
    page = replay_html(_renamed(data, "robot", HOSTILE), {"/odom": [[0.0, {"note": "<!--<script>&</script>"}]]})
    scripts = re.findall(r"<script[^>]*>(.*?)</script>", page, flags=re.S)
    assert len(scripts) == 2
    for body in scripts:
        assert not re.search(r"<!--|<script|</script", body, flags=re.I)
    payload = json.loads(scripts[0])
    assert f"{HOSTILE}::base_link" in payload["shapes"]  # the name itself reads back unchanged
    assert payload["topics"]["/odom"][0][1]["note"] == "<!--<script>&</script>"


@pytest.mark.skipif(find_chromium() is None, reason="no system chromium (scripts/setup.sh installs it)")
def test_an_entity_named_to_open_a_comment_does_not_blank_the_page(tmp_path: Path, run) -> None:
    """The issue's page: an entity named ``bot<!--<script>`` made chromium read the rest of the page as
    script data, so the page's code never ran (no drawing, no key, no timeline). Now the code runs, the key
    shows the name as text, and the renamed robot is drawn where the simulation ended it."""
    pytest.importorskip("playwright")
    data, _start, end = run
    path = tmp_path / "replay.html"
    path.write_text(replay_html(_renamed(data, "robot", HOSTILE), title=HOSTILE))
    with open_replay(path, timeout_ms=10_000) as replay:
        assert replay.page.evaluate("() => window.gazelleReplay.moving") == [HOSTILE]
        assert HOSTILE in replay.page.locator("#key").inner_text()
        assert replay.page.title() == HOSTILE
        replay.seek(replay.frames() - 1)
        assert share_near(replay.canvas(), replay.to_screen(*end), replay.color_of(HOSTILE)) > 0.9


def test_a_60_s_turtlebot3_world_run_makes_a_page_under_20_mb(resource_path, make_sim) -> None:
    """The issue's size bound: TurtleBot3 in its world for 60 s of sim time, /odom and /scan at the
    cursor (measured 1.4 MB: 1,801 frames)."""
    from _paths import REAL

    resource_path("turtlebot3/turtlebot3_gazebo/models", "turtlebot3")
    tb3 = REAL / "turtlebot3" / "turtlebot3_gazebo"
    sim = make_sim(load(tb3 / "worlds" / "turtlebot3_world.world").world)
    sim.spawn(
        load(tb3 / "models" / "turtlebot3_burger" / "model.sdf").model, name="burger", pose=Pose((-2.0, -0.5, 0.01))
    )
    recorder = ReplayRecorder(sim, topics=("/odom", "/scan"))
    assert sim.bus.inject("/cmd_vel", MsgType.TWIST, Twist((0.15, 0.0, 0.0), (0.0, 0.0, 0.1))) == 1
    sim.step(60_000)
    data = recorder.data()
    page = replay_html(data, title="turtlebot3_world")
    assert len(page.encode()) < 20_000_000
    assert len(data["frames"]) == pytest.approx(1800, abs=5)
    assert len(data["topics"]["/odom"]) > 1000 and "ranges" in data["topics"]["/scan"][-1][1]
