"""Issue 50, item 10: the viewer's panel hid a quarter of a 1200 x 800 view, and there was no way to bring a
robot that drove out of the picture back into it. Checked in chromium by pixels: the share of the view
that changes when the panel is minimized, and a robot spawned behind the initial camera seen (its blue
pixels) after "Fit all"."""

from __future__ import annotations

import time
from typing import Any

import numpy as np
import pytest
from _paths import SEED_XACRO
from _pixels import blue_mask, project, rgb_of

from gazelle.viewer._browser import find_chromium
from gazelle.viewer._framing import fit_view
from gazelle.viewer._viewer import CAMERA_FOV_RAD, CAMERA_LOOK_AT, CAMERA_POSITION

ROBOT_AT = (5.0, -5.0, 0.1)
"""Behind the initial camera (at 1.6, -1.6, 1.2, looking at the origin): not in its picture."""

pytestmark = pytest.mark.skipif(find_chromium() is None, reason="no system chromium (scripts/setup.sh installs it)")


def test_the_panel_covers_little_of_a_1200_by_800_view_and_fit_all_shows_a_robot_out_of_view(make_sim) -> None:
    from gazelle.description import Pose, load
    from gazelle.viewer import Viewer
    from gazelle.viewer._browser import minimize_panel, open_viewer_page

    sim = make_sim(rtf=1.0)
    sim.spawn(load(SEED_XACRO).model, name="far_robot", pose=Pose((ROBOT_AT[0], ROBOT_AT[1], 0.07)))
    sim.start()
    viewer = Viewer(sim, port=0)
    viewer.start()
    try:
        with open_viewer_page(viewer.url) as page:
            page.set_viewport_size({"width": 1200, "height": 800})
            page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
            page.mouse.move(2, 798)
            with_panel = rgb_of(page.screenshot())
            minimize_panel(page)
            page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
            covered = float((np.abs(rgb_of(page.screenshot()) - with_panel).max(axis=2) > 24).mean())
            assert covered < 0.2, f"the panel covers {covered:.0%} of the view"  # 24 % before, ~18 % now
            page.get_by_label("Expand panel").first.click()
            page.mouse.move(2, 798)
            assert _blue_near(page, ROBOT_AT) < 0.2, "the robot is in the initial view: the test shows nothing"
            page.get_by_role("button", name="Fit all", exact=True).click()
            page.mouse.move(2, 798)  # off the button: its tooltip would cover the view
            snap = viewer._last
            assert snap is not None
            points = [pos for links in snap.poses.values() for pos, _q in links.values()]
            eye, target = fit_view(points, CAMERA_POSITION, CAMERA_LOOK_AT, CAMERA_FOV_RAD)
            deadline = time.monotonic() + 20.0
            while (seen := _blue_near(page, ROBOT_AT, eye, target)) < 0.5:
                assert time.monotonic() < deadline, f"after Fit all, {seen:.0%} blue where the robot is"
    finally:
        viewer.stop()
        sim.stop()


def _blue_near(
    page: Any, point: tuple[float, float, float], eye: Any = CAMERA_POSITION, target: Any = CAMERA_LOOK_AT
) -> float:
    """The share of blue (the seed robot's) pixels within 6 px of where ``point`` is seen from ``eye``."""
    mask = blue_mask(page.screenshot())
    h, w = mask.shape
    x, y = project(point, w, h, eye, target)
    if not (0 <= x < w and 0 <= y < h):
        return 0.0
    return float(mask[max(int(y) - 6, 0) : int(y) + 7, max(int(x) - 6, 0) : int(x) + 7].mean())
