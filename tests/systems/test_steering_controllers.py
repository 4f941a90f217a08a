"""ros2_controllers' tricycle_controller and ackermann_steering_controller (Jazzy), driven without a simulation:
their commands for a twist and their odometry from the wheels, as upstream's sources compute them
(tricycle_controller.cpp, steering_kinematics.cpp), and their parameter checks."""

from __future__ import annotations

import logging
import math
from typing import Any

import pytest

from gazelle.systems import Bus, TwistStamped
from gazelle.systems._payloads import Twist
from gazelle.systems.ros2_control import CONTROLLER_TYPES, ControlError
from gazelle.systems.ros2_control._controller import ControllerContext

TRICYCLE = {
    "traction_joint_name": "traction",
    "steering_joint_name": "steer",
    "wheel_radius": 0.3,
    "wheelbase": 1.7,
}
ACKERMANN = {
    "traction_joints_names": ["rr", "rl"],
    "steering_joints_names": ["sr", "sl"],
    "traction_wheels_radius": 0.3,
    "traction_track_width": 1.0,
    "wheelbase": 1.7,
}


def _controller(type_name: str, params: dict, joints: tuple[str, ...]) -> Any:
    states = tuple(f"{j}/{k}" for j in joints for k in ("position", "velocity"))
    commands = tuple(f"{j}/{k}" for j in joints for k in ("position", "velocity"))
    ctx = ControllerContext(Bus(), "r", "", logging.getLogger("test"), states, commands, joints)
    c = CONTROLLER_TYPES[type_name]("c", params, ctx)
    c.configure()
    return c


def test_both_are_registered_by_their_plugin_names():
    assert "tricycle_controller/TricycleController" in CONTROLLER_TYPES
    assert "ackermann_steering_controller/AckermannSteeringController" in CONTROLLER_TYPES


def test_the_tricycle_steers_atan_wl_over_v_and_drives_v_over_r_cos_alpha_and_its_odometry_follows_the_wheel():
    c = _controller("tricycle_controller/TricycleController", TRICYCLE, ("traction", "steer"))
    assert c.command_interfaces() == ["traction/velocity", "steer/position"]
    c._on_cmd_vel(TwistStamped(0.0, "", Twist((0.2, 0, 0), (0, 0, 0.1))))
    alpha = math.atan(0.1 * 1.7 / 0.2)
    states = {"traction/velocity": 0.0, "steer/position": alpha}
    commands: dict[str, float] = {}
    c.update(1.0, 0.02, states, commands)
    assert commands["steer/position"] == pytest.approx(alpha)
    assert commands["traction/velocity"] == pytest.approx(0.2 / (0.3 * math.cos(alpha)))
    # a wheel turning at that speed, steered at alpha, moves the base at 0.2 m/s and 0.1 rad/s
    for i in range(100):
        c._on_cmd_vel(TwistStamped(0.0, "", Twist((0.2, 0, 0), (0, 0, 0.1))))
        c.update(1.02 + 0.02 * i, 0.02, {**states, "traction/velocity": 0.2 / (0.3 * math.cos(alpha))}, commands)
    assert c.linear == pytest.approx(0.2) and c.angular == pytest.approx(0.1)
    assert c.pose[2] == pytest.approx(0.1 * 2.0)


def test_the_tricycle_stops_when_its_command_is_older_than_cmd_vel_timeout():
    c = _controller(
        "tricycle_controller/TricycleController", {**TRICYCLE, "cmd_vel_timeout": 100}, ("traction", "steer")
    )
    c._on_cmd_vel(TwistStamped(0.0, "", Twist((0.2, 0, 0), (0, 0, 0.0))))
    commands: dict[str, float] = {}
    states = {"traction/velocity": 0.0, "steer/position": 0.0}
    c.update(1.0, 0.02, states, commands)
    assert commands["traction/velocity"] > 0
    c.update(1.2, 0.02, states, commands)
    assert commands["traction/velocity"] == 0.0


def test_the_tricycle_refuses_a_negative_limit_and_a_min_above_its_max():
    with pytest.raises(ControlError, match="cannot be negative"):
        _controller(
            "tricycle_controller/TricycleController", {**TRICYCLE, "traction.max_velocity": -1.0}, ("traction", "steer")
        )
    with pytest.raises(ControlError, match="cannot be greater"):
        _controller(
            "tricycle_controller/TricycleController",
            {**TRICYCLE, "traction.min_acceleration": 2.0, "traction.max_acceleration": 1.0},
            ("traction", "steer"),
        )


def test_ackermann_steers_each_front_wheel_about_the_same_centre_and_splits_the_rear_wheels_speeds():
    c = _controller("ackermann_steering_controller/AckermannSteeringController", ACKERMANN, ("rr", "rl", "sr", "sl"))
    assert c.command_interfaces() == ["rr/velocity", "rl/velocity", "sr/position", "sl/position"]
    radius = 0.5 / 0.3  # v / w
    # the wheels are steered for that radius already: the odometry reads it back, and the speeds split by it
    c._on_reference(TwistStamped(0.0, "", Twist((0.5, 0, 0), (0, 0, 0.3))))
    commands: dict[str, float] = {}
    states = {
        "rr/velocity": 0.0,
        "rl/velocity": 0.0,
        "sr/position": math.atan(1.7 / (radius + 0.5)),
        "sl/position": math.atan(1.7 / (radius - 0.5)),
    }
    c.update(1.0, 0.1, states, commands)
    assert c.kin.steer_pos == pytest.approx(math.atan(1.7 / radius))
    assert commands["rr/velocity"] == pytest.approx(0.5 / 0.3 * (radius + 0.5) / radius)
    assert commands["rl/velocity"] == pytest.approx(0.5 / 0.3 * (radius - 0.5) / radius)
    assert commands["sr/position"] == pytest.approx(math.atan(1.7 / (radius + 0.5)))
    assert commands["sl/position"] == pytest.approx(math.atan(1.7 / (radius - 0.5)))


def test_ackermann_reads_the_deprecated_front_and_rear_names_and_stops_after_reference_timeout():
    params = {
        "rear_wheels_names": ["rr", "rl"],
        "front_wheels_names": ["sr", "sl"],
        "rear_wheels_radius": 0.3,
        "rear_wheel_track": 1.0,
        "front_wheel_track": 1.0,
        "wheelbase": 1.7,
        "reference_timeout": 0.5,
    }
    c = _controller("ackermann_steering_controller/AckermannSteeringController", params, ("rr", "rl", "sr", "sl"))
    assert c.traction == ["rr", "rl"] and c.steering == ["sr", "sl"]
    c._on_reference(TwistStamped(0.0, "", Twist((0.5, 0, 0), (0, 0, 0.0))))
    commands: dict[str, float] = {}
    states = {"rr/velocity": 0.0, "rl/velocity": 0.0, "sr/position": 0.0, "sl/position": 0.0}
    c.update(1.0, 0.1, states, commands)
    assert commands["rr/velocity"] == pytest.approx(0.5 / 0.3)
    c.update(1.6, 0.1, states, commands)
    assert commands["rr/velocity"] == 0.0


def test_ackermann_without_a_traction_radius_fails_its_configure_as_upstream_says():
    params = {k: v for k, v in ACKERMANN.items() if k != "traction_wheels_radius"}
    with pytest.raises(ControlError, match="traction_wheels_radius' is not set"):
        _controller("ackermann_steering_controller/AckermannSteeringController", params, ("rr", "rl", "sr", "sl"))
