"""Anisotropic friction from a URDF's ``<gazebo reference>`` (issue 55 item 8): a skid-steer robot's wheels with
``mu2`` 0 across them slide sideways as it turns, so it turns as far as its wheel odometry says, on a plane, whatever
its heading (the ``<collision><surface>`` block read as tests/description/test_gazebo_files.py checks); the contacts
of the capsule that carries a wheel's anisotropic friction are the wheel's (see gazelle/physics/_contact_pairs.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from gazelle.description import Pose, load_string, quat_from_rpy
from gazelle.systems._payloads import Odometry
from gazelle.systems.diff_drive import DiffDrive

SEPARATION, RADIUS, WIDTH, WHEELBASE = 0.4, 0.08, 0.05, 0.34
BLOB = "<collision><surface><friction><ode><mu>1.0</mu><mu2>0.0</mu2><fdir1>1 0 0</fdir1></ode></friction></surface></collision>"
"""The friction skid-steer robots give their wheels: mu along the rolling direction (fdir1 across the axle, in the
wheel collision's frame), none across the wheel."""
SHORT = "<mu1>1.0</mu1><mu2>0.0</mu2><fdir1>1 0 0</fdir1>"
"""The same in the short forms sdformat also reads."""


def skid_steer_urdf(friction: str) -> str:
    """A four-wheel skid-steer robot as such robots are written for Gazebo Classic: a box chassis, four wheel
    cylinders (their axis turned onto the axle by the collision's rpy) on continuous joints, each wheel's
    ``friction`` in a ``<gazebo reference>`` block, and gazebo_ros_diff_drive with two wheel pairs and odometry
    from the wheel encoders."""
    inertia = '<inertia ixx="{i}" iyy="{i}" izz="{i}" ixy="0" ixz="0" iyz="0"/>'
    links = joints = gazebo = ""
    for name, (x, y) in {"fl": (1, 1), "fr": (1, -1), "rl": (-1, 1), "rr": (-1, -1)}.items():
        links += (
            f'<link name="{name}_wheel"><inertial><mass value="0.5"/>{inertia.format(i=0.001)}</inertial>'
            f'<collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="{RADIUS}" length="{WIDTH}"/>'
            "</geometry></collision></link>"
        )
        joints += (
            f'<joint name="{name}_joint" type="continuous"><parent link="base_link"/><child link="{name}_wheel"/>'
            f'<origin xyz="{x * WHEELBASE / 2} {y * SEPARATION / 2} 0"/><axis xyz="0 1 0"/></joint>'
        )
        gazebo += f'<gazebo reference="{name}_wheel">{friction}</gazebo>'
    pair = f"<wheel_separation>{SEPARATION}</wheel_separation><wheel_diameter>{2 * RADIUS}</wheel_diameter>"
    return f"""<?xml version="1.0"?>
<robot name="skid">
  <link name="base_link">
    <inertial><origin xyz="0 0 0.05"/><mass value="8"/>{inertia.format(i=0.15)}</inertial>
    <collision><origin xyz="0 0 0.06"/><geometry><box size="0.5 0.3 0.08"/></geometry></collision>
  </link>
  {links}{joints}{gazebo}
  <gazebo><plugin name="skid_steer" filename="libgazebo_ros_diff_drive.so">
    <num_wheel_pairs>2</num_wheel_pairs>
    <left_joint>fl_joint</left_joint><right_joint>fr_joint</right_joint>
    <left_joint>rl_joint</left_joint><right_joint>rr_joint</right_joint>
    {pair}{pair}
    <max_wheel_torque>20</max_wheel_torque>
    <odometry_source>0</odometry_source>
    <publish_odom>true</publish_odom>
    <robot_base_frame>base_link</robot_base_frame>
  </plugin></gazebo>
</robot>"""


def _yaw(q) -> float:
    return math.atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2))


def _turned(make_sim, friction: str, heading: float, steps: int = 2500) -> tuple[float, float]:
    """(what the wheel odometry says, what the robot did): the yaw change of each while the robot spawned at
    ``heading`` turns in place at 1 rad/s for ``steps`` ms (after 0.3 s of settling), unwrapped step by step."""
    model = load_string(skid_steer_urdf(friction)).model
    sim = make_sim()
    entity = sim.spawn(model, name="skid", pose=Pose((0.0, 0.0, RADIUS + 0.005), quat_from_rpy(0, 0, heading)))
    odometry: list[Odometry] = []
    next(e for e in sim.bus.endpoints() if e.topic == "/odom").add_sink(odometry.append)
    sim.step(300)
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    drive.command(0.0, 1.0)
    turned = {"odom": 0.0, "truth": 0.0}
    last = {"odom": _yaw(odometry[-1].pose.orientation), "truth": _yaw(sim.world.entity_state("skid").pose.orientation)}
    for _ in range(steps // 10):
        sim.step(10)
        now = {
            "odom": _yaw(odometry[-1].pose.orientation),
            "truth": _yaw(sim.world.entity_state("skid").pose.orientation),
        }
        for k in now:
            turned[k] += math.remainder(now[k] - last[k], 2 * math.pi)
        last = now
    return turned["odom"], turned["truth"]


@pytest.mark.parametrize("friction", [BLOB, SHORT], ids=["collision-block", "short-forms"])
@pytest.mark.parametrize("heading", [0.0, math.pi / 2, 0.7])
def test_a_skid_steer_robot_with_mu2_0_on_its_wheels_turns_as_far_as_its_odometry_says(make_sim, friction, heading):
    """Odometry (the wheels' travel over the separation) claims 2.3-2.5 rad; the robot turns within 5 % of it,
    spawned facing any way (the friction's directions follow the wheels, not the world's axes). With the
    collision block ignored (before issue 55) the wheels scrubbed with mu 1 sideways and the robot turned 29 %
    of the claim; with the short forms folded into one isotropic mu = min(1, 0) the wheels had no grip at all."""
    odom, truth = _turned(make_sim, friction, heading)
    assert odom == pytest.approx(2.5, rel=0.1)
    assert truth == pytest.approx(odom, rel=0.05)


def test_the_wheels_ground_contacts_are_the_wheels_and_carry_mu_along_the_rolling_direction_only(make_sim):
    """The plane contacts of a wheel go through its capsule, named as the wheel's collision, with the friction
    (across the axle 0, along the rolling direction 1) in a frame whose first tangent is the axle."""
    from gazelle.physics._contact_pairs import MIN_FRICTION_RATIO

    sim = make_sim()
    sim.spawn(load_string(skid_steer_urdf(BLOB)).model, name="skid", pose=Pose((0.0, 0.0, RADIUS + 0.005)))
    sim.step(300)
    geoms = sim.world.collision_geoms("skid", "fl_wheel")
    contacts = sim.world.contacts_of(geoms)
    assert contacts and {c.collision1 for c in contacts} == {"skid::fl_wheel::fl_wheel_collision_0"}
    assert sum(c.force[2] for c in contacts) == pytest.approx(9.81 * (8 + 4 * 0.5) / 4, rel=0.2)
    m, d = sim.world.model, sim.world.data
    mine = [c for c in d.contact[: d.ncon] if set(c.geom.tolist()) & set(geoms)]
    for c in mine:
        axle = np.asarray(c.frame[3:6])
        assert abs(axle[1]) == pytest.approx(1.0, abs=1e-3)  # the wheels' axle is the robot's (and world's) y
        # none across (kept at 1 % of the grip along: see MIN_FRICTION_RATIO), mu 1 along the rolling direction
        assert (c.friction[0], c.friction[1]) == pytest.approx((MIN_FRICTION_RATIO, 1.0))
    assert m.npair >= 8  # per wheel: its capsule with the ground, and its own contact with the ground replaced


def test_the_wheels_pairs_follow_the_planes_and_robots_that_come_and_go(make_sim, tmp_path):
    """The pairs are remade at every change of the world: none left naming a deleted plane or wheel (MuJoCo would
    refuse to compile), a plane spawned later gets the wheels' anisotropic contacts too, and a simulation restored
    from a checkpoint has them (it rebuilds the world, bit-identically: the pairs are part of the build)."""
    from gazelle.sim import Simulation

    sim = make_sim()
    sim.spawn(load_string(skid_steer_urdf(BLOB)).model, name="skid", pose=Pose((0.0, 0.0, RADIUS + 0.005)))
    assert sim.world.model.npair == 8
    sim.step(50)
    restored = Simulation.from_checkpoint(sim.checkpoint(tmp_path / "skid.ckpt"))
    try:
        assert restored.world.model.npair == 8
        sim.step(200)
        restored.step(200)
        assert restored.world.entity_state("skid").pose == sim.world.entity_state("skid").pose
    finally:
        restored.stop()
    sim.delete("ground_plane")
    assert sim.world.model.npair == 0
    sim.step(100)  # falls: nothing under it
    floor = """<?xml version="1.0"?><sdf version="1.9"><model name="floor"><static>true</static><link name="l">
      <collision name="c"><geometry><plane><normal>0 0 1</normal><size>10 10</size></plane></geometry>
      </collision></link></model></sdf>"""
    sim.spawn(load_string(floor).model, name="floor", pose=Pose((0.0, 0.0, -0.5)))
    assert sim.world.model.npair == 8
    sim.step(1000)
    assert sim.world.entity_state("skid").pose.position[2] == pytest.approx(-0.5 + RADIUS, abs=0.005)
    sim.delete("skid")
    assert sim.world.model.npair == 0


def test_past_the_pair_budget_the_remaining_wheels_keep_isotropic_ground_contacts_and_a_warning_says_so(
    make_sim, monkeypatch, caplog
):
    """MuJoCo tests every pair at every step: a world of thousands of planes or anisotropic wheels must not make
    millions. With a budget of 4 pairs, two wheels get theirs (2 each), the other two touch the ground as before."""
    import logging

    from gazelle.physics import _contact_pairs

    monkeypatch.setattr(_contact_pairs, "MAX_FRICTION_PAIRS", 4)
    sim = make_sim()
    with caplog.at_level(logging.WARNING, logger="gazelle.physics"):
        sim.spawn(load_string(skid_steer_urdf(BLOB)).model, name="skid", pose=Pose((0.0, 0.0, RADIUS + 0.005)))
    assert sim.world.model.npair == 4
    assert "2 collision(s) with anisotropic friction keep isotropic contacts with the planes" in caplog.text
    sim.step(300)
    assert sim.world.entity_state("skid").pose.position[2] == pytest.approx(RADIUS, abs=0.005)  # on all four
