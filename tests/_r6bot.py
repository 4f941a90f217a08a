"""r6bot (ros2_control_demos example 7) under joint_trajectory_controller and joint_state_broadcaster at
1 kHz, as the ros2_control block tests and bench/bench_control.py set it up (one place for both)."""

from __future__ import annotations

from typing import Any

from _paths import REAL
from _sim import new_simulation

R6BOT = REAL / "ros2_control_r6bot"
URDF = R6BOT / "_xacro_expanded" / "r6bot.urdf"
JOINTS = tuple(f"joint_{i}" for i in range(1, 7))
YAML = """
controller_manager:
  ros__parameters:
    update_rate: 1000
jsb:
  ros__parameters:
    type: joint_state_broadcaster/JointStateBroadcaster
jtc:
  ros__parameters:
    type: joint_trajectory_controller/JointTrajectoryController
    joints: [joint_1, joint_2, joint_3, joint_4, joint_5, joint_6]
    command_interfaces: [position]
    state_interfaces: [position, velocity]
"""
"""The controllers (the demo's own controller is C++ of its own)."""


def manager_of(entity: Any, *, blocks: bool = True, controllers: tuple[str, ...] = ("jsb", "jtc")) -> Any:
    """The entity's controller manager at 1 kHz with :data:`YAML`, ``controllers`` loaded and active;
    ``blocks``: whether its cycles may run as planned blocks (False: a Python cycle per step)."""
    from gazelle.systems.ros2_control import ControllerManager, parse_params

    cm = next(s for s in entity.systems if isinstance(s, ControllerManager))
    cm.blocks_allowed = blocks
    cm.files.append(parse_params(YAML))
    cm.update_rate = 1000
    for name in controllers:
        cm.load_controller(name)
        cm.configure_controller(name)
    if controllers:
        cm.switch_controller(list(controllers), [])
    return cm


def arm(*, blocks: bool = True, controllers: tuple[str, ...] = ("jsb", "jtc")) -> tuple[Any, Any]:
    """A world (``rtf`` 0) with one r6bot named "r6bot" and its manager (see :func:`manager_of`)."""
    from gazelle.description import load

    sim = new_simulation()
    entity = sim.spawn(load(URDF).model, name="r6bot")
    return sim, manager_of(entity, blocks=blocks, controllers=controllers)
