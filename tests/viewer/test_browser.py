"""End to end: headless Debian chromium (Playwright) on the viewer of a real `gazelle sim`.

One server and one browser page for the module (kept under ~60 s); the tests run in order:
the robot is spawned and seen by pixels, the sim is paused and resumed from the GUI, the robot
is selected by clicking it in the 3D view, then driven from the GUI and its motion checked by
ground truth (/get_entity_state).
"""

from __future__ import annotations

import io
import math
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from gazelle.viewer._browser import find_chromium

pytest.importorskip("playwright")
if find_chromium() is None:
    pytest.skip("no system chromium (scripts/setup.sh installs Debian's chromium)", allow_module_level=True)

from _harness import GAZELLE, wait_for
from _paths import ARTIFACTS, REPO, SEED_XACRO
from _pixels import blue_mask, plan_mask, project

ROBOT = "simple_robot"
ROBOT_CENTRE = (0.0, 0.0, 0.07)
"""The base box centre once the robot rests on the ground (wheel radius 5 cm + 2 cm axle drop)."""
REGION_HALF_PX = 90
MIN_BLUE_PX = 3000
"""The 0.3 x 0.3 x 0.1 m blue box covers ~10 000 px at this camera; the blue world z axis alone ~800."""


def blue_in_region(page: Any, save: Path | None = None) -> tuple[int, tuple[float, float], tuple[float, float] | None]:
    """(strongly blue pixel count near the robot's projected position, that position, the blue centroid)."""
    png = page.screenshot()
    if save is not None:
        save.write_bytes(png)
        shutil.copy(save, ARTIFACTS / save.name)
    mask = blue_mask(png)
    h, w = mask.shape
    cx, cy = project(ROBOT_CENTRE, w, h)
    x0, x1 = int(cx - REGION_HALF_PX), int(cx + REGION_HALF_PX)
    y0, y1 = int(cy - REGION_HALF_PX), int(cy + REGION_HALF_PX)
    region = mask[max(y0, 0) : y1, max(x0, 0) : x1]
    ys, xs = np.nonzero(region)
    centroid = (float(xs.mean()) + max(x0, 0), float(ys.mean()) + max(y0, 0)) if len(xs) else None
    return int(region.sum()), (cx, cy), centroid


def gui_input(page: Any, label: str) -> Any:
    """The input next to a viser GUI label."""
    return page.locator(
        f"xpath=//label[normalize-space()='{label}']/ancestor::div[contains(@class,'mantine-Flex-root')][1]//input"
    ).first


def sim_time(page: Any) -> float:
    return float(gui_input(page, "Sim time").input_value().split()[0])


def test_blue_robot_appears_at_its_projected_position(page: Any, artifacts: Path) -> None:
    empty, (cx, cy), _ = blue_in_region(page, artifacts / "viewer_empty.png")
    assert empty < MIN_BLUE_PX / 2, f"{empty} blue pixels before anything was spawned"
    spawn = subprocess.run(
        [*GAZELLE, "spawn", "-file", str(SEED_XACRO), "-entity", ROBOT],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert spawn.returncode == 0, spawn.stdout + spawn.stderr
    seen: list[int] = []

    def enough_blue() -> bool:
        n, _, _ = blue_in_region(page)
        seen.append(n)
        return n >= MIN_BLUE_PX

    wait_for(
        enough_blue,
        timeout=15,
        what=f">= {MIN_BLUE_PX} blue pixels around ({cx:.0f}, {cy:.0f}) (last: {seen[-3:]})",
        interval=0.2,
    )
    n, _, centroid = blue_in_region(page, artifacts / "viewer_robot.png")
    assert n >= MIN_BLUE_PX
    assert centroid is not None and math.dist(centroid, (cx, cy)) < 40, (
        f"blue centroid {centroid} is far from the projected robot position ({cx:.0f}, {cy:.0f})"
    )


def test_pause_stops_sim_time_and_play_resumes(page: Any, ros_client_mod: Any) -> None:
    from rosgraph_msgs.msg import Clock

    last_clock: list[float] = []
    ros_client_mod.node.create_subscription(
        Clock, "/clock", lambda m: last_clock.append(m.clock.sec + m.clock.nanosec * 1e-9), 10
    )
    t0 = sim_time(page)
    wait_for(lambda: sim_time(page) > t0 + 0.2, timeout=10, what="sim time advancing in the GUI")
    wait_for(lambda: last_clock, timeout=10, what="/clock")

    page.get_by_role("button", name="Pause", exact=True).click()
    wait_for(
        lambda: page.get_by_role("button", name="Play", exact=True).count() == 1, timeout=5, what="the Play button"
    )
    # the GUI refreshes at 10 Hz: let a frame taken just before the click be overwritten
    reads: list[float] = []

    def settled() -> bool:
        reads.append(sim_time(page))
        page.wait_for_timeout(250)
        return sim_time(page) == reads[-1]

    wait_for(settled, timeout=5, what=f"the GUI sim time settling while paused (reads: {reads[-3:]})")
    paused_gui, paused_clock = sim_time(page), last_clock[-1]
    # an observation window: nothing may advance during it
    window_end = time.monotonic() + 1.0
    while time.monotonic() < window_end:
        assert sim_time(page) == paused_gui, "sim time advanced in the GUI while paused"
        page.wait_for_timeout(100)
    assert last_clock[-1] == pytest.approx(paused_clock, abs=1e-9), "/clock advanced while paused"
    assert abs(paused_clock - paused_gui) < 0.05, f"GUI time {paused_gui} vs /clock {paused_clock}"

    page.get_by_role("button", name="Play", exact=True).click()
    wait_for(lambda: sim_time(page) > paused_gui + 0.2, timeout=10, what="sim time advancing after Play")
    wait_for(lambda: last_clock[-1] > paused_clock + 0.2, timeout=10, what="/clock advancing after Play")


def entity_dropdown(page: Any) -> str:
    """The Entities dropdown's displayed value."""
    return gui_input(page, "Entity").input_value()


def choose_entity(page: Any, name: str) -> None:
    page.get_by_role("combobox").first.click()
    page.get_by_role("option", name=name, exact=True).click()
    wait_for(lambda: entity_dropdown(page) == name, timeout=5, what=f"the Entity dropdown showing {name!r}")


def canvas_at(page: Any, xy: tuple[float, float]) -> bool:
    """Whether the pixel is on the 3D canvas (inside the viewport, not under the control panel)."""
    return page.evaluate("([x, y]) => document.elementFromPoint(x, y)?.tagName === 'CANVAS'", list(xy))


def canvas_cursor(page: Any, xy: tuple[float, float]) -> str:
    """The CSS cursor viser sets on the 3D canvas at that pixel ('pointer' over clickable meshes)."""
    return page.evaluate("([x, y]) => document.elementFromPoint(x, y)?.style.cursor ?? ''", list(xy))


def test_clicking_the_robot_in_the_view_selects_it(page: Any, ros_client_mod: Any, artifacts: Path) -> None:
    """Wherever earlier tests drove it: empty ground selects nothing, the robot's body selects it, an orbit
    starting on the robot moves the camera and selects nothing."""
    choose_entity(page, "(none)")
    wait_for(lambda: gui_input(page, "Pose").input_value() == "", timeout=5, what="an empty Pose with nothing selected")
    size = page.viewport_size
    w, h = size["width"], size["height"]
    p = ros_client_mod.entity_state(ROBOT).state.pose.position  # base_link = the blue box's centre
    robot_xy = project((p.x, p.y, p.z), w, h)
    ground_xy = project((p.x - 0.6, p.y + 0.6, 0.0), w, h)  # behind the robot seen from the camera
    assert canvas_at(page, robot_xy), f"the robot at ({p.x:.2f}, {p.y:.2f}) projects to {robot_xy}, off the 3D canvas"
    assert canvas_at(page, ground_xy), f"{ground_xy} is off the 3D canvas"

    # hovering: the robot is clickable (pointer cursor; viser also outlines the mesh), the ground is not
    page.mouse.move(*robot_xy)
    wait_for(lambda: canvas_cursor(page, robot_xy) == "pointer", timeout=10, what="the pointer cursor over the robot")
    page.mouse.move(*ground_xy)
    wait_for(
        lambda: canvas_cursor(page, ground_xy) in ("", "auto"), timeout=10, what="the default cursor over the ground"
    )

    # clicking empty ground (the static ground plane) selects nothing: watch a window for any change
    page.mouse.click(*ground_xy)
    window_end = time.monotonic() + 1.0
    while time.monotonic() < window_end:
        assert entity_dropdown(page) == "(none)", "clicking empty ground selected something"
        assert gui_input(page, "Pose").input_value() == ""
        page.wait_for_timeout(100)

    page.mouse.click(*robot_xy)
    wait_for(lambda: entity_dropdown(page) == ROBOT, timeout=10, what=f"the Entity dropdown showing {ROBOT}")

    # what follows the dropdown follows the click: the Pose text shows the robot's ground-truth pose
    def pose_matches() -> bool:
        text = gui_input(page, "Pose").input_value().split()
        if len(text) < 6 or text[0] != "x":
            return False
        q = ros_client_mod.entity_state(ROBOT).state.pose.position
        return abs(float(text[1]) - q.x) < 0.05 and abs(float(text[3]) - q.y) < 0.05

    wait_for(pose_matches, timeout=5, what="the Pose text showing the robot's ground-truth position")
    page.screenshot(path=str(artifacts / "viewer_click_select.png"))
    shutil.copy(artifacts / "viewer_click_select.png", ARTIFACTS / "viewer_click_select.png")

    # a drag that starts on the robot orbits the camera and is not a click. The orbit pivots about the
    # look-at point next to the robot, so the robot stays put on screen while the grid turns around it.
    choose_entity(page, "(none)")
    page.mouse.move(*ground_xy)  # no hover outline in the reference image

    def view() -> np.ndarray:
        from PIL import Image

        rgb = np.asarray(Image.open(io.BytesIO(page.screenshot())).convert("RGB")).astype(int)
        return rgb[:, : int(0.7 * w)]  # the 3D view left of the control panel

    before = view()
    page.mouse.move(*robot_xy)
    page.mouse.down()
    page.mouse.move(robot_xy[0] + 150, robot_xy[1], steps=5)
    page.mouse.up()

    def orbited() -> bool:  # ~1% of the view changes (the grid lines); without an orbit, none
        return float((np.abs(view() - before).max(axis=-1) > 40).mean()) > 0.004

    wait_for(orbited, timeout=10, what="the view turning after a drag that starts on the robot", interval=0.2)
    assert entity_dropdown(page) == "(none)", "a drag starting on the robot selected it"
    # back to the initial camera (later tests project with it) with nothing selected
    page.reload()
    from gazelle.viewer._browser import wait_rendered

    wait_rendered(page, 30)
    wait_for(lambda: entity_dropdown(page) == "(none)", timeout=10, what="nothing selected after the reload")


def test_drive_buttons_move_the_robot(page: Any, ros_client_mod: Any) -> None:
    page.get_by_role("combobox").first.click()
    page.get_by_role("option", name=ROBOT, exact=True).click()
    wait_for(lambda: "x " in gui_input(page, "Pose").input_value(), timeout=5, what="the selected robot's pose")
    start = ros_client_mod.entity_state(ROBOT).state.pose.position
    page.get_by_role("button", name="Forward", exact=True).click()
    wait_for(lambda: "linear +0.50" in gui_input(page, "cmd_vel").input_value(), timeout=5, what="the cmd_vel echo")

    def moved() -> bool:
        p = ros_client_mod.entity_state(ROBOT).state.pose.position
        return p.x - start.x > 0.25 and abs(p.y - start.y) < 0.1

    wait_for(moved, timeout=10, what="the robot driving 0.25 m forward (+x) by ground truth", interval=0.1)
    page.get_by_role("button", name="Stop", exact=True).click()

    def stopped() -> bool:
        v = ros_client_mod.entity_state(ROBOT).state.twist.linear
        return math.hypot(v.x, v.y) < 0.02

    wait_for(stopped, timeout=10, what="the robot stopping after Stop", interval=0.1)

    # the path trail of the selected robot is drawn (magenta, on the ground)
    def trail_px() -> int:
        rgb = np.asarray(Image.open(io.BytesIO(page.screenshot())).convert("RGB")).astype(int)
        r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
        return int(((r > 170) & (g < 90) & (b > 90) & (b < 200)).sum())

    from PIL import Image

    counts: list[int] = []
    try:
        wait_for(
            lambda: counts.append(trail_px()) or counts[-1] > 150, timeout=5, what="the magenta path trail in the view"
        )
    finally:
        page.screenshot(path=str(ARTIFACTS / "viewer_trail.png"))


def test_keyboard_drive_presses_the_drive_buttons(page: Any, ros_client_mod: Any) -> None:
    page.get_by_text("Keyboard drive", exact=True).click()
    page.wait_for_selector("#gazelle-keyboard-drive", state="attached", timeout=5000)
    page.evaluate("() => document.activeElement && document.activeElement.blur()")
    start = ros_client_mod.entity_state(ROBOT).state.pose.position
    page.keyboard.down("w")
    wait_for(lambda: "linear +0.50" in gui_input(page, "cmd_vel").input_value(), timeout=5, what="W -> Forward")

    def moved() -> bool:
        p = ros_client_mod.entity_state(ROBOT).state.pose.position
        return math.hypot(p.x - start.x, p.y - start.y) > 0.15

    wait_for(moved, timeout=10, what="the robot driving while W is held", interval=0.1)
    page.keyboard.up("w")
    wait_for(lambda: "linear +0.00" in gui_input(page, "cmd_vel").input_value(), timeout=5, what="releasing W -> Stop")
    page.keyboard.down("ArrowLeft")
    wait_for(lambda: "angular +1.00" in gui_input(page, "cmd_vel").input_value(), timeout=5, what="Left arrow -> Left")
    page.keyboard.up("ArrowLeft")
    wait_for(lambda: "angular +0.00" in gui_input(page, "cmd_vel").input_value(), timeout=5, what="release -> Stop")


@pytest.mark.parametrize("panel", [True, False], ids=["panel", "no-panel"])
def test_snapshot_command_writes_a_png_with_the_robot(tmp_path: Path, panel: bool) -> None:
    """`gazelle snapshot` shows the robot; with --no-panel the control panel's area shows the scene instead."""
    from PIL import Image

    out = tmp_path / "snapshot.png"
    res = subprocess.run(
        [*GAZELLE, "snapshot", "--world", str(SEED_XACRO), "--out", str(out), *([] if panel else ["--no-panel"])],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=120,  # ~5 s normally; its page wait alone may take 30 s on a starved CPU
    )
    assert res.returncode == 0, res.stdout + res.stderr
    shutil.copy(out, ARTIFACTS / ("snapshot_seed.png" if panel else "snapshot_seed_no_panel.png"))
    mask = blue_mask(out.read_bytes())
    h, w = mask.shape
    cx, cy = project(ROBOT_CENTRE, w, h)
    region = mask[
        int(cy) - REGION_HALF_PX : int(cy) + REGION_HALF_PX, int(cx) - REGION_HALF_PX : int(cx) + REGION_HALF_PX
    ]
    assert region.sum() >= MIN_BLUE_PX, f"only {region.sum()} blue pixels where the robot should be"
    # the panel is white; the scene there is the grey ground (see viewer_robot.png)
    rgb = np.asarray(Image.open(io.BytesIO(out.read_bytes())).convert("RGB"))
    area = rgb[int(0.15 * h) : int(0.85 * h), int(0.78 * w) : int(0.96 * w)]
    white = float((area.min(axis=2) >= 245).mean())
    if panel:
        assert white > 0.3, f"the control panel should cover its area, but only {white:.0%} of it is white"
    else:
        assert white < 0.05, f"--no-panel: {white:.0%} of the panel's area is still white"


CHESS_EYE = (0.25, 0.85, 1.75)
CHESS_TARGET = (0.25, 1.39, 0.90)


def test_chessboard_world_renders_33_entities(page: Any, artifacts: Path, make_sim) -> None:
    """The board and 32 pieces (the grid of examples/chessboard/spawn_chessboard.py), seen from above."""
    from PIL import Image

    from gazelle.description import Pose, load
    from gazelle.viewer import Viewer
    from gazelle.viewer._browser import wait_rendered

    here = REPO / "examples" / "chessboard"
    bx, by, bz = CHESS_TARGET
    sim = make_sim(rtf=1.0)
    sim.start()
    sim.spawn(load(here / "chess_board.sdf").model, name="chess_board", pose=Pose((bx, by, bz)))
    piece = load(here / "chess_piece.sdf").model
    for row in (0, 1, 6, 7):
        for col in range(8):
            sim.spawn(
                piece,
                name=f"piece_r{row}_c{col}",
                pose=Pose((bx - 0.175 + 0.05 * col, by - 0.175 + 0.05 * row, bz + 0.02)),
            )
    viewer = Viewer(sim, port=0)
    cam = viewer.server.initial_camera
    cam.position, cam.look_at = CHESS_EYE, CHESS_TARGET
    out = artifacts / "chessboard.png"
    seen: list[tuple[float, int]] = []

    def board_and_pieces() -> bool:
        """The board's grey middle band and a dark piece at each of the 32 squares, in a fresh screenshot."""
        page.screenshot(path=str(out))
        rgb = np.asarray(Image.open(out).convert("RGB")).astype(int)
        h, w = rgb.shape[:2]
        # the board's middle rows (2..5) hold no pieces: its plain grey top must fill that band
        corners = [
            project((bx + dx, by + dy, bz + 0.01), w, h, CHESS_EYE, CHESS_TARGET)
            for dx in (-0.15, 0.15)
            for dy in (-0.07, 0.07)
        ]
        x0, x1 = int(min(c[0] for c in corners)), int(max(c[0] for c in corners))
        y0, y1 = int(min(c[1] for c in corners)), int(max(c[1] for c in corners))
        band = rgb[y0:y1, x0:x1]
        r, g, b = band[..., 0], band[..., 1], band[..., 2]
        grey = (np.abs(r - g) < 25) & (np.abs(g - b) < 25) & (r > 60) & (r < 240)
        # the 32 pieces (dark boxes) stand where the spawner's grid puts them
        dark = 0
        for row in (0, 1, 6, 7):
            for col in range(8):
                px, py = project(
                    (bx - 0.175 + 0.05 * col, by - 0.175 + 0.05 * row, bz + 0.03), w, h, CHESS_EYE, CHESS_TARGET
                )
                win = rgb[int(py) - 5 : int(py) + 6, int(px) - 5 : int(px) + 6].max(axis=-1)
                dark += (win < 100).mean() > 0.3
        seen.append((float(grey.mean()) if band.size else 0.0, int(dark)))
        return seen[-1][0] > 0.8 and dark == 32

    viewer.start()
    try:
        page.goto(viewer.url)  # the module's browser (Playwright's sync API allows one at a time)
        wait_rendered(page, 30)
        wait_for(lambda: len(viewer._nodes) == 34, timeout=10, what="34 entities in the scene")  # ground + board + 32
        deadline = time.monotonic() + 30
        while not board_and_pieces():  # the scene streams in over the first frames; on a slow CPU, seconds
            grey, dark = seen[-1]
            assert time.monotonic() < deadline, (
                f"board grey covers {grey:.0%} of its band (> 80 % expected); {dark} of 32 pieces seen"
            )
            page.wait_for_timeout(300)
    finally:
        viewer.stop()
        sim.stop()
    shutil.copy(out, ARTIFACTS / "chessboard.png")


LIDAR_EYE = (0.6, -2.6, 3.2)
LIDAR_TARGET = (1.4, 0.0, 0.0)


def test_lidar_overlay_points_appear_where_the_wall_is(page: Any, artifacts: Path, make_sim) -> None:
    """examples/sensor_bot's lidar facing a wall 2 m ahead: green overlay points along the wall's face
    in the browser's pixels, and none over the empty floor between robot and wall."""
    from PIL import Image

    from gazelle.description import Pose, load, load_string
    from gazelle.viewer import Viewer
    from gazelle.viewer._browser import wait_rendered

    wall = """<?xml version="1.0"?><sdf version="1.9"><model name="wall"><static>true</static>
      <pose>2.1 0 0.25 0 0 0</pose><link name="l">
      <collision name="c"><geometry><box><size>0.2 2 0.5</size></box></geometry></collision>
      <visual name="v"><geometry><box><size>0.2 2 0.5</size></box></geometry><material><diffuse>0.6 0.6 0.6 1</diffuse></material></visual>
      </link></model></sdf>"""
    sim = make_sim(rtf=1.0)
    sim.spawn(load_string(wall).model, name="wall")
    sim.spawn(load(REPO / "examples/sensor_bot/sensor_bot.urdf").model, name="bot", pose=Pose((0.0, 0.0, 0.07)))
    sim.start()
    viewer = Viewer(sim, port=0)
    cam = viewer.server.initial_camera
    cam.position, cam.look_at = LIDAR_EYE, LIDAR_TARGET
    out = artifacts / "lidar_overlay.png"
    seen: list[tuple[int, int]] = []
    scan_z = 0.07 + 0.075 + 0.03  # base height + scan joint + the sensor's pose

    def green_on_the_wall() -> bool:
        page.screenshot(path=str(out))
        rgb = np.asarray(Image.open(out).convert("RGB")).astype(int)
        h, w = rgb.shape[:2]
        green = (rgb[..., 1] > 150) & (rgb[..., 0] < 100) & (rgb[..., 2] < 130)

        def near(p: tuple[float, float, float]) -> bool:
            px, py = project(p, w, h, LIDAR_EYE, LIDAR_TARGET)
            return bool(green[int(py) - 6 : int(py) + 7, int(px) - 6 : int(px) + 7].any())

        on_wall = sum(near((2.0, y, scan_z)) for y in np.linspace(-0.8, 0.8, 9))
        on_floor = sum(near((x, y, scan_z)) for x in (0.8, 1.2) for y in (-0.3, 0.3))
        seen.append((on_wall, on_floor))
        return on_wall == 9 and on_floor == 0

    viewer.start()
    try:
        page.goto(viewer.url)
        wait_rendered(page, 30)
        deadline = time.monotonic() + 30
        while not green_on_the_wall():
            assert time.monotonic() < deadline, (
                f"green overlay at {seen[-1][0]}/9 wall spots, {seen[-1][1]}/4 floor spots"
            )
            page.wait_for_timeout(300)
    finally:
        viewer.stop()
        sim.stop()
    shutil.copy(out, ARTIFACTS / "lidar_overlay.png")


ARM_EYE = (1.2, -1.4, 1.9)
ARM_TARGET = (0.0, 1.0, 0.5)
ARM_BASE = (0.0, 1.0, 0.5)


def _tool_at(q1: float, q2: float) -> tuple[float, float, float]:
    """Where the two-link arm's tool is (links 0.5 m and 0.3 m, both joints about z)."""
    bx, by, bz = ARM_BASE
    return (bx + 0.5 * math.cos(q1) + 0.3 * math.cos(q1 + q2), by + 0.5 * math.sin(q1) + 0.3 * math.sin(q1 + q2), bz)


def test_a_plan_published_on_display_planned_path_is_drawn_where_the_tool_will_go(
    page: Any, ros_client_mod: Any, artifacts: Path, make_sim
) -> None:
    """A moveit_msgs/DisplayTrajectory published over ROS, as move_group publishes each plan, shows in the
    browser as a blue line through the places the arm's tool will pass, before the arm moves; the arm
    stays where it is."""
    from builtin_interfaces.msg import Duration
    from moveit_msgs.msg import DisplayTrajectory, RobotTrajectory
    from PIL import Image
    from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

    from gazelle.description import load_string
    from gazelle.ros import RosBridge
    from gazelle.viewer import Viewer
    from gazelle.viewer._browser import wait_rendered

    from .test_viewer import TWO_LINK_ARM

    urdf = TWO_LINK_ARM.replace('<origin xyz="0 0 1"/>', '<origin xyz="{} {} {}"/>'.format(*ARM_BASE))
    sim = make_sim(rtf=1.0)
    sim.spawn(load_string(urdf).model, name="arm")
    sim.start()
    viewer = Viewer(sim, port=0)
    bridge = RosBridge(sim)
    cam = viewer.server.initial_camera
    cam.position, cam.look_at = ARM_EYE, ARM_TARGET
    out = artifacts / "planned_path.png"
    # a quarter turn of the shoulder with the elbow bending: the tool sweeps an arc to (-0.3, 1.5, 0.5)
    qs = [(a, b) for a, b in zip(np.linspace(0.0, math.pi / 2, 30), np.linspace(0.0, math.pi / 2, 30))]
    samples = [_tool_at(*q) for q in qs[6:25:3]]  # along the way, away from the arm's own links at rest
    msg = DisplayTrajectory(model_id="arm2", trajectory=[RobotTrajectory()])
    jt = JointTrajectory(joint_names=["j1", "j2"])
    jt.points = [
        JointTrajectoryPoint(positions=[float(a), float(b)], time_from_start=Duration(sec=i))
        for i, (a, b) in enumerate(qs)
    ]
    msg.trajectory = [RobotTrajectory(joint_trajectory=jt)]
    publisher = ros_client_mod.node.create_publisher(DisplayTrajectory, "/display_planned_path", 10)
    hits: list[int] = []

    def blue_along_the_path() -> int:
        page.screenshot(path=str(out))
        rgb = np.asarray(Image.open(out).convert("RGB")).astype(int)
        h, w = rgb.shape[:2]
        mask = plan_mask(rgb)
        near = 0
        for p in samples:
            px, py = project(p, w, h, ARM_EYE, ARM_TARGET)
            near += bool(mask[int(py) - 5 : int(py) + 6, int(px) - 5 : int(px) + 6].any())
        hits.append(near)
        return near

    viewer.start()
    try:
        page.goto(viewer.url)
        wait_rendered(page, 30)
        assert blue_along_the_path() == 0, "blue along the path before any plan"
        deadline = time.monotonic() + 30
        while blue_along_the_path() < len(samples):
            assert time.monotonic() < deadline, f"the planned path covers {hits[-1]}/{len(samples)} of its places"
            publisher.publish(msg)  # again until the simulation's node has matched the publisher
            page.wait_for_timeout(300)
        tool = sim.call(lambda: sim.world.entity_state("arm", "tool").pose.position)
        assert math.dist(tool, _tool_at(0.0, 0.0)) < 1e-3, tool  # drawn, not moved
    finally:
        ros_client_mod.node.destroy_publisher(publisher)
        viewer.stop()
        bridge.shutdown()
        sim.stop()
    shutil.copy(out, ARTIFACTS / "planned_path.png")


_TRY_WS_JS = """(url) => new Promise((resolve) => {
    const ws = new WebSocket(url);
    ws.onopen = () => { ws.close(); resolve('open'); };
    ws.onerror = () => resolve('refused');
    setTimeout(() => resolve('timeout'), 10000);
})"""


def test_foreign_pages_cannot_open_the_viewer_websocket(page: Any, viewer_sim) -> None:
    """A page on another origin (any site the user visits) gets no websocket; the viewer's own page does."""
    import http.client
    import http.server
    import threading
    from urllib.parse import urlsplit

    url = viewer_sim[1]
    ws_url = "ws://" + urlsplit(url).netloc
    body = b"<html><body>another site</body></html>"

    class Page(http.server.BaseHTTPRequestHandler):
        def do_GET(self) -> None:
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, format: str, *args: Any) -> None:
            pass

    other = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Page)
    threading.Thread(target=other.serve_forever, daemon=True).start()
    foreign = page.context.new_page()
    try:
        foreign.goto(f"http://127.0.0.1:{other.server_address[1]}/")
        assert foreign.evaluate(_TRY_WS_JS, ws_url) == "refused"
        foreign.goto(f"http://localhost:{other.server_address[1]}/")
        assert foreign.evaluate(_TRY_WS_JS, ws_url.replace("127.0.0.1", "localhost")) == "refused"
    finally:
        foreign.close()
        other.shutdown()
    # the viewer's own page still connects (a test above took the module's page to another viewer)
    page.goto(url)
    assert page.evaluate(_TRY_WS_JS, ws_url) == "open"
    # DNS rebinding: a request naming another host is refused, even for the page itself
    netloc = urlsplit(url).netloc
    host, port = netloc.rsplit(":", 1)
    for host_header, want in ((f"evil.example:{port}", 403), (netloc, 200), (f"localhost:{port}", 200)):
        conn = http.client.HTTPConnection(host, int(port), timeout=10)
        conn.request("GET", "/", headers={"Host": host_header})
        assert conn.getresponse().status == want, host_header
        conn.close()
