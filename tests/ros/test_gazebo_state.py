"""gazebo_ros's /get_entity_state in a reference frame (gazebo_ros_state.cpp GetEntityState), as arithmetic."""

from __future__ import annotations

import math

import pytest

from gazelle.description import Pose, quat_from_rpy
from gazelle.physics import EntityState
from gazelle.ros._gazebo_services import relative_state


def test_a_moving_reference_frame_s_velocity_is_taken_off_and_its_turn_applied() -> None:
    # the frame drives along world x at 1 m/s, turned 90 degrees left, spinning at 0.5 rad/s about z;
    # the entity drives along world x at 3 m/s, 2 m ahead of it, not spinning
    frame = EntityState(Pose((1.0, 0.0, 0.0), quat_from_rpy(0.0, 0.0, math.pi / 2)), (1.0, 0.0, 0.0), (0.0, 0.0, 0.5))
    entity = EntityState(Pose((3.0, 0.0, 0.0)), (3.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    pose, lin, ang = relative_state(entity, frame)
    # 2 m ahead in the world is 2 m to the frame's right (-y), and so is the 2 m/s it gains on the frame
    assert pose.position == pytest.approx((0.0, -2.0, 0.0), abs=1e-12)
    assert lin == pytest.approx((0.0, -2.0, 0.0), abs=1e-12)  # gazelle reported (0, -3, 0): the frame's own speed
    assert ang == pytest.approx((0.0, 0.0, -0.5), abs=1e-12)  # less the frame's spin
    # against the world nothing changes
    assert relative_state(entity, None) == (entity.pose, entity.linear_velocity, entity.angular_velocity)
