"""Every robot and model of the real fixtures compiles into the physics world and behaves under gravity.

Each one is spawned into the default world (ground plane, Earth gravity) and stepped for 2 s of
sim time. Always: it builds, no NaN in qpos/qvel, no divergence reported. Wheeled robots and
objects must come to rest on the ground; arms (fixed to the world or with a free base that tips
over) must keep bounded velocities.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from _paths import REAL

from gazelle.description import Model, Pose, load

pytestmark = pytest.mark.skipif(not REAL.is_dir(), reason="shared real fixtures not available")

MOBILE, ARM, OBJECT = "mobile", "arm", "object"

# (id, GAZELLE_RESOURCE_PATH relative to REAL, file relative to REAL, kind, spawn height, xacro args)
CASES = [
    pytest.param(
        "turtlebot3/turtlebot3_gazebo/models",
        "turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model.sdf",
        MOBILE,
        0.02,
        id="turtlebot3_sdf",
    ),
    pytest.param(
        "turtlebot3",
        "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro",
        MOBILE,
        0.5,
        id="turtlebot3_xacro",
    ),
    pytest.param(
        "ros2_control_diffbot",
        "ros2_control_diffbot/ros2_control_demo_example_2/urdf/diffbot.urdf.xacro",
        MOBILE,
        0.5,
        id="diffbot_xacro",
    ),
    pytest.param(
        "moveit_panda",
        "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf",
        ARM,
        0.05,
        id="panda_urdf",
    ),
    pytest.param(
        "moveit_panda",
        "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf.xacro",
        ARM,
        0.05,
        id="panda_xacro",
    ),
    pytest.param(
        "moveit_panda",
        "moveit_panda/moveit_resources_panda_moveit_config/config/panda.urdf.xacro",
        ARM,
        0.05,
        id="panda_moveit_config_xacro",
    ),
    pytest.param(
        "moveit_panda",
        "moveit_panda/dual_arm_panda_moveit_config/config/panda.urdf.xacro",
        ARM,
        0.0,
        id="dual_arm_panda_xacro",
    ),
    pytest.param(
        "ros2_control_r6bot",
        "ros2_control_r6bot/ros2_control_demo_example_7/urdf/r6bot.urdf.xacro",
        ARM,
        0.0,
        id="r6bot_xacro",
    ),
    pytest.param("gazebo_models/models", "gazebo_models/models/table/model.sdf", OBJECT, 0.0, id="table"),
    pytest.param(
        "gazebo_models/models",
        "gazebo_models/models/coke_can/model.sdf",
        OBJECT,
        0.05,
        id="coke_can",
    ),
]

SECONDS = 2.0
REST_LINEAR = 0.01  # m/s
REST_ANGULAR = 0.05  # rad/s
ARM_MAX_QVEL = 50.0  # rad/s or m/s: a falling, undamped arm swings, an exploding one is far beyond


@pytest.mark.parametrize(("resource_dir", "rel", "kind", "z"), CASES)
def test_fixture_stands_under_gravity(
    resource_path, resource_dir: str, rel: str, kind: str, z: float, make_sim
) -> None:
    resource_path(resource_dir)
    model = load(REAL / rel).value
    assert isinstance(model, Model)

    sim = make_sim()
    entity = sim.spawn(model, name="subject", pose=Pose((0.0, 0.0, z)))
    # every link became a body (a link named "world" is the world frame itself)
    assert set(entity.built.bodies) == {lk.name for lk in model.links} - {"world"}

    x0, y0, _ = sim.world.entity_state("subject").pose.position
    steps = int(round(SECONDS / sim.world.timestep))
    sim.step(steps)
    data = sim.world.data
    assert np.all(np.isfinite(data.qpos)) and np.all(np.isfinite(data.qvel)), "NaN/inf in the state"
    assert sim.diverged == {}

    state = sim.world.entity_state("subject")
    x, y, zz = state.pose.position
    speed = math.hypot(*state.linear_velocity)
    spin = math.hypot(*state.angular_velocity)
    if kind in (MOBILE, OBJECT):
        assert speed < REST_LINEAR and spin < REST_ANGULAR, f"not at rest: v={speed:.3g} m/s, w={spin:.3g} rad/s"
        assert -0.05 < zz < z + 0.05, f"fell through or was launched: z={zz:.3f}"
        assert math.hypot(x - x0, y - y0) < 0.1, f"slid away: ({x:.3f}, {y:.3f})"
    else:
        assert float(np.abs(data.qvel).max(initial=0.0)) < ARM_MAX_QVEL
        assert math.hypot(x - x0, y - y0) < 1.5 and -0.1 < zz < z + 0.5, f"arm base flew off: {(x, y, zz)}"
    if model.static:
        assert speed == 0.0 and spin == 0.0
        assert zz == pytest.approx(z)


def test_fixed_arm_base_stays_put(resource_path, make_sim) -> None:
    """r6bot is fixed to the world by its URDF 'world' link: its base must not move at all."""
    resource_path("ros2_control_r6bot")
    model = load(REAL / "ros2_control_r6bot/ros2_control_demo_example_7/urdf/r6bot.urdf.xacro").model
    sim = make_sim()
    entity = sim.spawn(model, name="r6bot", pose=Pose((1.0, 2.0, 0.0)))
    assert entity.built.free_joint is None
    sim.step(500)
    state = sim.world.entity_state("r6bot")
    assert state.pose.position == pytest.approx((1.0, 2.0, 0.0), abs=1e-9)
    assert math.hypot(*state.linear_velocity) == pytest.approx(0.0, abs=1e-9)
