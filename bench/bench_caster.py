"""Why the example robot has casters: the seed's geometry vs one caster vs the two shipped.

Run: ``.venv/bin/python bench/bench_caster.py``. Three variants of
examples/simple_robot/simple_robot/robot.urdf.xacro, made by editing its xacro text:

* (a) the seed as written: no casters, wheel axles at the base centre (the box bottom is level with the
  wheel bottoms) and the box with default friction (the seed gives it none);
* (b) one frictionless caster at the back only, wheels dropped 2 cm;
* (c) the example as shipped: two frictionless casters, front and back, wheels dropped 2 cm.

All keep the example's wheel-axis fix (-PI/2), so a positive cmd_vel drives forward in each.
Each runs in-process (no ROS) on ``default_world()``: 1 s to settle, then the seed's square
pattern once: forward 0.2 m/s for 5 s, then turn 0.5 rad/s for 3.14 s (commanded 1.0 m and 90 deg).
Printed: the side's length, the turn angle, the max |pitch| and |roll| while driving and the final
height of base_link (spawn height = wheel radius + drop).
"""

from __future__ import annotations

import logging
import math
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, SIDE_SEC, W, TURN_SEC = 0.2, 5.0, 0.5, 3.14
SETTLE_SEC = 1.0

FRONT_CASTER = '    <xacro:caster x="${robot_length/2 - caster_radius}"/>\n'
BACK_CASTER = '    <xacro:caster x="${-(robot_length/2 - caster_radius)}"/>\n'
DROP = '<xacro:property name="wheel_drop" value="0.02"/>'
BASE_FRICTION = "    <mu1>0.0</mu1>\n    <mu2>0.0</mu2>\n"


def variants(text: str) -> list[tuple[str, str, float]]:
    """(label, xacro text, wheel drop in metres)."""
    for needle in (FRONT_CASTER, BACK_CASTER, DROP, BASE_FRICTION):
        if needle not in text:
            raise SystemExit(f"{ROBOT} changed: cannot find {needle.strip()!r} to build the variants")
    seed = text.replace(FRONT_CASTER, "").replace(BACK_CASTER, "").replace(DROP, DROP.replace("0.02", "0.0"))
    seed = seed.replace(BASE_FRICTION, "")
    return [
        ("(a) seed: no caster, axle at centre", seed, 0.0),
        ("(b) back caster only, drop 2 cm", text.replace(FRONT_CASTER, ""), 0.02),
        ("(c) shipped: 2 casters, drop 2 cm", text, 0.02),
    ]


def run(text: str, drop: float) -> dict[str, float]:
    from gazelle.description import (
        DiagnosticSink,
        ModelLoadError,
        Pose,
        ResourceResolver,
        expand_xacro_bounded,
        load_string,
        quat_to_rpy,
    )
    from gazelle.sim import Simulation
    from gazelle.systems.diff_drive import DiffDrive
    from gazelle.worlds import default_world

    # the variant is the user's own file edited here: expanded as `gazelle spawn -file` expands a file
    # (a description given as a string is data and never expanded)
    sink = DiagnosticSink()
    urdf = expand_xacro_bounded(text, source=str(ROBOT), sink=sink, resolver=ResourceResolver().trusting(ROBOT.parent))
    if urdf is None:
        raise ModelLoadError(sink.items)
    model = load_string(urdf, format="urdf", source=str(ROBOT)).model
    sim = Simulation(default_world(), rtf=0)
    z0 = 0.05 + drop  # wheel radius + drop: the wheels just touch the ground
    entity = sim.spawn(model, name="robot", pose=Pose((0.0, 0.0, z0)))
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    dt = sim.world.timestep
    world = sim.world
    max_pitch = max_roll = 0.0
    yaw_track = 0.0  # unwrapped yaw

    def advance(seconds: float, track: bool) -> None:
        nonlocal max_pitch, max_roll, yaw_track
        prev = quat_to_rpy(world.entity_state("robot").pose.orientation)[2]
        for _ in range(round(seconds / dt)):
            sim.step()
            roll, pitch, yaw = quat_to_rpy(world.entity_state("robot").pose.orientation)
            yaw_track += math.remainder(yaw - prev, 2 * math.pi)
            prev = yaw
            if track:
                if abs(pitch) > abs(max_pitch):
                    max_pitch = pitch  # signed: + is nose down (rotation about +y)
                if abs(roll) > abs(max_roll):
                    max_roll = roll

    advance(SETTLE_SEC, track=False)
    p0 = world.entity_state("robot").pose.position
    yaw0 = yaw_track
    drive.command(V, 0.0)
    advance(SIDE_SEC, track=True)
    p1 = world.entity_state("robot").pose.position
    yaw1 = yaw_track
    drive.command(0.0, W)
    advance(TURN_SEC, track=True)
    drive.command(0.0, 0.0)
    p2 = world.entity_state("robot").pose.position
    heading = quat_to_rpy(world.entity_state("robot").pose.orientation)[2]
    # signed distance along the heading at the start of the side
    along = (p1[0] - p0[0]) * math.cos(yaw0) + (p1[1] - p0[1]) * math.sin(yaw0)
    return {
        "side": along,
        "drift_yaw": math.degrees(yaw1 - yaw0),
        "turn": math.degrees(yaw_track - yaw1),
        "turn_shift": math.hypot(p2[0] - p1[0], p2[1] - p1[1]),
        "pitch": math.degrees(max_pitch),
        "roll": math.degrees(max_roll),
        "z_settled": p0[2],
        "z_final": p2[2],
        "z0": z0,
        "heading": math.degrees(heading),
    }


def main() -> int:
    global SETTLE_SEC, SIDE_SEC, TURN_SEC
    if "--smoke" in sys.argv[1:]:  # ./test.sh: the same code at a tenth of the times (the figures mean nothing)
        SETTLE_SEC, SIDE_SEC, TURN_SEC = SETTLE_SEC / 10, SIDE_SEC / 10, TURN_SEC / 10
    logging.disable(logging.CRITICAL)
    t_all = time.perf_counter()
    text = ROBOT.read_text()
    want_side, want_turn = V * SIDE_SEC, math.degrees(W * TURN_SEC)
    print(f"{ROBOT.relative_to(REPO)} variants on default_world(), in-process (no ROS), dt 1 ms")
    print(
        f"forward {V} m/s for {SIDE_SEC} s (commanded {want_side:.2f} m), then turn {W} rad/s for {TURN_SEC} s"
        f" (commanded {want_turn:.1f} deg)\n"
    )
    header = (
        f"{'variant':<37} {'side m':>7} {'% cmd':>6} {'yaw drift':>9} {'turn deg':>9} {'% cmd':>6}"
        f" {'turn xy':>8} {'max pitch':>9} {'max roll':>8} {'z spawn':>8} {'z final':>8}"
    )
    print(header)
    print("-" * len(header))
    results: list[tuple[str, dict[str, float]]] = []
    for label, xacro, drop in variants(text):
        r = run(xacro, drop)
        results.append((label, r))
        print(
            f"{label:<37} {r['side']:>7.3f} {100 * r['side'] / want_side:>5.0f}% {r['drift_yaw']:>8.1f}°"
            f" {r['turn']:>8.1f}° {100 * r['turn'] / want_turn:>5.0f}% {r['turn_shift']:>7.3f}m"
            f" {r['pitch']:>8.1f}° {r['roll']:>7.1f}° {r['z0']:>7.3f}m {r['z_final']:>7.3f}m"
        )
    print("-" * len(header))
    print(
        "yaw drift: heading change during the straight side; turn xy: how far base_link moved while turning in place;"
        " pitch/roll: largest while driving, signed (+pitch = nose down)"
    )

    # conclusion from the numbers: a variant "tracks" if side and turn are within 5 % and it stays level (< 3 deg)
    def tilt(r: dict[str, float]) -> float:
        return max(abs(r["pitch"]), abs(r["roll"]))

    def error(r: dict[str, float]) -> float:
        return max(abs(r["side"] / want_side - 1), abs(r["turn"] / want_turn - 1))

    def verdict(r: dict[str, float]) -> str:
        parts = []
        if tilt(r) >= 3.0:
            parts.append(
                f"tilts {tilt(r):.0f} deg"
                + (" nose down" if abs(r["pitch"]) >= abs(r["roll"]) and r["pitch"] > 0 else "")
            )
        if abs(r["side"] / want_side - 1) > 0.05:
            parts.append(f"side {100 * r['side'] / want_side:.0f}%")
        if abs(r["turn"] / want_turn - 1) > 0.05:
            parts.append(f"turn {100 * r['turn'] / want_turn:.0f}%")
        return ", ".join(parts) or "tracks the command"

    best_label, best = min(results, key=lambda lr: (tilt(lr[1]) >= 3.0, error(lr[1])))
    others = "; ".join(f"{lbl.split(')')[0]})" + f" {verdict(r)}" for lbl, r in results if lbl != best_label)
    print(
        f"conclusion: {best_label.split(')')[0]}) is best ({verdict(best)}: side {100 * best['side'] / want_side:.0f}%,"
        f" turn {100 * best['turn'] / want_turn:.0f}%, max tilt {tilt(best):.1f} deg); {others}"
    )
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
