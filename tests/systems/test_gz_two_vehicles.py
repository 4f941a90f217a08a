"""gz-sim DiffDrive with several robots (issue 10), on a world shaped like gz-sim's diff_drive.sdf:
two vehicles with sphere wheels (r 0.3 m, 2 kg), a ball-jointed sphere caster (1 kg, I = 0.1 kg·m²)
and default DiffDrive frames.

Found: both vehicles published `chassis -> left_wheel` (duplicate TF names), and odometry was
11-15 % off ground truth (87.0° against 75.5°). The second is physics, not a bug: the wheels are
commanded to full speed at once, and until friction has spun the vehicle up (its yaw inertia is
doubled by the caster ball, whose inertia is 6x a solid sphere's and must be spun to 7.5 rad/s for
each rad/s of turn) they slip, while odometry integrates the wheels. Once up to speed, odometry and
ground truth agree; with an acceleration limit (``<max_angular_acceleration>``) they agree throughout.
"""

from __future__ import annotations

import math

import pytest
from _sim import new_simulation

from gazelle.description import load_string
from gazelle.sim import Simulation
from gazelle.systems._bus import Endpoint
from gazelle.systems._payloads import Twist


def _inertial(m: float, ixx: float, iyy: float, izz: float) -> str:
    return f"<inertial><mass>{m}</mass><inertia><ixx>{ixx}</ixx><iyy>{iyy}</iyy><izz>{izz}</izz></inertia></inertial>"


WHEEL_SURFACE = (
    "<surface><friction><ode><mu>1</mu><mu2>1</mu2><slip1>0.035</slip1><slip2>0</slip2><fdir1>0 0 1</fdir1></ode>"
    "<bullet><friction>1</friction><friction2>1</friction2><rolling_friction>0.1</rolling_friction></bullet>"
    "</friction></surface>"
)
"""The wheels' surface in gz-sim's examples/worlds/diff_drive.sdf."""


def vehicle(name: str, y: float, limits: str = "", wheel_surface: str = "") -> str:
    wheel = lambda n, wy: (
        f"<link name='{n}'><pose>0.554 {wy} -0.025 -1.5707 0 0</pose>{_inertial(2, 0.145833, 0.145833, 0.125)}"
        f"<collision name='c'><geometry><sphere><radius>0.3</radius></sphere></geometry>{wheel_surface}</collision>"
        "</link>"
    )
    hinge = lambda n, c: (
        f"<joint name='{n}' type='revolute'><parent>chassis</parent><child>{c}</child><axis><xyz>0 0 1</xyz>"
        "<limit><lower>-1.79769e+308</lower><upper>1.79769e+308</upper></limit></axis></joint>"
    )
    return (
        f"<model name='{name}'><pose>0 {y} 0.325 0 0 0</pose>"
        f"<link name='chassis'><pose>-0.151 0 0.175 0 0 0</pose>{_inertial(1.14, 0.126, 0.417, 0.481)}"
        "<collision name='c'><geometry><box><size>2.0 1 0.57</size></box></geometry></collision></link>"
        f"{wheel('left_wheel', 0.625)}{wheel('right_wheel', -0.625)}"
        f"<link name='caster'><pose>-0.957 0 -0.125 0 0 0</pose>{_inertial(1, 0.1, 0.1, 0.1)}"
        "<collision name='c'><geometry><sphere><radius>0.2</radius></sphere></geometry></collision></link>"
        f"{hinge('left_wheel_joint', 'left_wheel')}{hinge('right_wheel_joint', 'right_wheel')}"
        "<joint name='caster_wheel' type='ball'><parent>chassis</parent><child>caster</child></joint>"
        "<plugin filename='gz-sim-diff-drive-system' name='gz::sim::systems::DiffDrive'>"
        "<left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>"
        f"<wheel_separation>1.25</wheel_separation><wheel_radius>0.3</wheel_radius>{limits}</plugin></model>"
    )


def world(limits: str = "", wheel_surface: str = "") -> str:
    return (
        "<sdf version='1.6'><world name='diff_drive'><physics name='1ms' type='ode'><max_step_size>0.001</max_step_size>"
        "</physics><model name='ground_plane'><static>true</static><link name='link'><collision name='c'><geometry>"
        f"<plane><normal>0 0 1</normal></plane></geometry></collision></link></model>"
        f"{vehicle('vehicle_blue', 2, limits, wheel_surface)}{vehicle('vehicle_green', -2, limits, wheel_surface)}"
        "</world></sdf>"
    )


def _endpoints(sim: Simulation) -> dict[tuple[str, bool], Endpoint]:
    return {(e.topic, e.is_publisher): e for e in sim.bus.endpoints() if e.owner == "vehicle_blue"}


def _yaw(q) -> float:
    return math.atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2))


def test_each_vehicles_frames_are_scoped_by_its_model(make_sim) -> None:
    sim = make_sim(load_string(world()).world)
    for ep in sim.bus.endpoints():  # listen, as the ROS bridge or a recorder does (nothing is built for nobody)
        if ep.topic == "/tf":
            ep.add_sink(lambda _payload: None)
    sim.step(30)
    edges: list[tuple[str, str]] = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/tf" and ep.last is not None:
            edges += [(t.parent, t.child) for t in ep.last.transforms]
    children = [c for _, c in edges]
    assert len(children) == len(set(children)), f"a frame has two parents: {sorted(edges)}"
    for v in ("vehicle_blue", "vehicle_green"):
        assert (f"{v}/odom", f"{v}/chassis") in edges  # the DiffDrive's odometry
        assert (f"{v}/chassis", f"{v}/left_wheel") in edges  # the links hang below it: one tree per vehicle


def _turn(limits: str, seconds: float) -> tuple[float, float, float, float]:
    """Turn vehicle_blue in place at 1 rad/s: (truth yaw, odom yaw) over the whole turn, in degrees, and
    the same over its last second."""
    sim = new_simulation(load_string(world(limits)).world)
    eps = _endpoints(sim)
    cmd, odom = eps[("/model/vehicle_blue/cmd_vel", False)], eps[("/model/vehicle_blue/odometry", True)]
    deliver = cmd.callback
    assert deliver is not None
    odom.add_sink(lambda _payload: None)  # listen to the odometry (nothing is built for nobody)
    sim.step(1000)
    marks = []
    steps = int(seconds * 1000)
    for i in range(steps + 1):
        if i in (0, steps - 1000, steps):
            marks.append(
                (_yaw(sim.world.entity_state("vehicle_blue").pose.orientation), _yaw(odom.last.pose.orientation))
            )
        if i % 100 == 0:
            deliver(Twist(linear=(0.0, 0.0, 0.0), angular=(0.0, 0.0, 1.0)))
        if i < steps:
            sim.step()

    def d(a: float, b: float) -> float:
        return math.degrees(math.remainder(b - a, 2 * math.pi))

    (t0, o0), (t1, o1), (t2, o2) = marks
    return d(t0, t2), d(o0, o2), d(t1, t2), d(o1, o2)


def test_odometry_slips_only_while_the_vehicle_spins_up() -> None:
    truth, odom, truth_last, odom_last = _turn("", 2.5)
    assert odom == pytest.approx(143.2, abs=2.0)  # the wheels turned as commanded (2.5 s at 1 rad/s)
    assert 0.05 < (odom - truth) / odom < 0.15  # the spin-up slip the attacker measured
    assert odom_last == pytest.approx(truth_last, rel=0.01)  # up to speed: no slip


def test_with_an_acceleration_limit_odometry_follows_ground_truth() -> None:
    truth, odom, _, _ = _turn("<max_angular_acceleration>1.0</max_angular_acceleration>", 2.5)
    assert odom == pytest.approx(truth, rel=0.02)


def test_the_examples_wheel_surface_drives_at_the_speed_its_odometry_reports(caplog, make_sim) -> None:
    """Issue 26 item 12: gz-sim's diff_drive.sdf gives its wheels Bullet's <rolling_friction> 0.1, which
    gazelle applied (MuJoCo condim 6): vehicle_blue ran at 0.43 m/s for the file's own 0.5 command while
    its odometry said 0.50. gz-sim's default engine (DART) ignores it, with a warning
    (gz-physics dartsim/src/SimulationFeatures.cc); so does gazelle, and the spawn's warning names it."""
    with caplog.at_level("WARNING"):
        sim = make_sim(load_string(world(wheel_surface=WHEEL_SURFACE)).world)
    assert "<rolling_friction>" in caplog.text
    eps = _endpoints(sim)
    cmd, odom = eps[("/model/vehicle_blue/cmd_vel", False)], eps[("/model/vehicle_blue/odometry", True)]
    deliver = cmd.callback
    assert deliver is not None
    odom.add_sink(lambda _payload: None)
    track: list[tuple[float, float]] = []
    for _ in range(100):  # 10 s of the command in the file's header
        deliver(Twist(linear=(0.5, 0.0, 0.0), angular=(0.0, 0.0, 0.05)))
        sim.step(100)
        track.append(sim.world.entity_state("vehicle_blue").pose.position[:2])
    last = track[-40:]  # the last 4 s, up to speed
    true_speed = sum(math.dist(a, b) for a, b in zip(last, last[1:])) / 3.9
    assert odom.last.twist.linear[0] == pytest.approx(0.5, rel=0.01)
    assert true_speed == pytest.approx(odom.last.twist.linear[0], rel=0.02)
