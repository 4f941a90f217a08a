"""A world's ``<frame>``s attached to the world are its named poses, with gazelle's custom elements for their
description, tags and free space (simulation_interfaces' GetNamedPoses and GetNamedPoseBounds; issue 52)."""

from __future__ import annotations

import math

import pytest

from gazelle.description import ModelLoadError, load_string

WORLD = """<sdf version="1.9" xmlns:gazelle="https://gazelle.dev/sdf"><world name="w">
  <model name="table"><static>true</static><pose>1 0 0 0 0 0</pose><link name="l"/></model>
  <frame name="dock">
    <pose>1 2 0 0 0 1.5707963</pose>
    <gazelle:description>charging dock</gazelle:description>
    <gazelle:tag>spawn</gazelle:tag><gazelle:tag>dock</gazelle:tag>
    <gazelle:box>-0.5 -0.5 0 0.5 0.5 1</gazelle:box>
  </frame>
  <frame name="above_table" attached_to="world">
    <pose relative_to="table">0 0 1 0 0 0</pose>
    <gazelle:sphere>0.3</gazelle:sphere>
  </frame>
  <frame name="on_table" attached_to="table"><pose>0 0 1 0 0 0</pose></frame>
</world></sdf>"""


def test_frames_attached_to_the_world_are_named_poses_in_the_world_frame() -> None:
    poses = {p.name: p for p in load_string(WORLD).world.named_poses}
    assert list(poses) == ["dock", "above_table"]  # on_table moves with the table: not a named pose
    dock = poses["dock"]
    assert dock.pose.position == (1.0, 2.0, 0.0)
    assert math.isclose(dock.pose.orientation[3], math.sqrt(0.5), abs_tol=1e-6)
    assert dock.description == "charging dock" and dock.tags == ("spawn", "dock")
    assert dock.box == ((-0.5, -0.5, 0.0), (0.5, 0.5, 1.0)) and dock.sphere_radius is None
    above = poses["above_table"]  # relative_to a model, resolved into the world frame
    assert above.pose.position == (1.0, 0.0, 1.0) and above.sphere_radius == 0.3 and above.tags == ()
    assert dock.location is not None and dock.location.line == 3


@pytest.mark.parametrize(
    ("element", "message"),
    [
        ("<gazelle:sphere>-1</gazelle:sphere>", "<gazelle:sphere> must be > 0"),
        ("<gazelle:box>1 2 3</gazelle:box>", "<gazelle:box> must be 6 numbers"),
    ],
)
def test_bad_bounds_are_errors_at_their_line(element: str, message: str) -> None:
    text = f'<sdf version="1.9"><world name="w">\n<frame name="f">{element}</frame></world></sdf>'
    with pytest.raises(ModelLoadError) as err:
        load_string(text)
    assert message in str(err.value) and ":2:" in str(err.value)
