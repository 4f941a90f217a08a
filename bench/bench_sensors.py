#!/usr/bin/env python3
"""Sensor costs, as ratios measured in one run (issue 12's targets).

* TurtleBot3 burger (its gz ``model.sdf``) driving, with its lidar (360 rays, 5 Hz) and IMU (200 Hz)
  listened to, against the same robot with its sensors taken out: the loss of real-time factor
  (goal: at most 5 %).
* One 360-ray scan through the lidar system against a raw ``mj_multiRay`` call with the same rays on
  the same scene: throughput ratio (goal: at least 0.8).
* A 16 x 1800 3-D lidar (PointCloud2) at 10 Hz, listened to: the real-time factor (goal: at least 1).
* A 640 x 480 RGB camera at 30 Hz, listened to: the real-time factor and the images per wall second
  (goal: 30 Hz at real time, on the CPU).
* The floor of the first ratio: the sensorless robot with the least a sensor read from Python does per
  reading added (the IMU's ten floats from MuJoCo and its message at 200 Hz, one raw 360-ray
  ``mj_multiRay`` and its LaserScan at 5 Hz; no noise, no configuration, no checks). Its loss is
  what no sensor that reads MuJoCo from Python at its rate, on the simulation thread, goes below.
  Beside it, what MuJoCo's own IMU sensors (accelerometer, gyro, frame orientation, computed in C inside
  every step) add to a raw step of the same world: the price of the other way, before any message.

Every system runs in-process on ``sim.step`` (``rtf`` 0); "listened to" means a sink on each
sensor's endpoint, as the ROS bridge adds one for a subscriber, so every message is built.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))
from _paths import REAL as FIXTURES  # noqa: E402 - the shared fixtures as the tests find them

TB3 = FIXTURES / "turtlebot3" / "turtlebot3_gazebo" / "models" / "turtlebot3_burger" / "model.sdf"


def listen(sim) -> list[int]:
    """A counting sink on every sensor topic (so each message is built); returns the counter."""
    from gazelle.systems import MsgType

    count = [0]
    kinds = {MsgType.LASER_SCAN, MsgType.IMU, MsgType.POINT_CLOUD2, MsgType.IMAGE}
    for ep in sim.bus.endpoints():
        if ep.is_publisher and ep.msg_type in kinds:
            ep.add_sink(lambda _p: count.__setitem__(0, count[0] + 1))
    return count


def rtf_of(sim, sim_seconds: float) -> tuple[float, float]:
    """(real-time factor, wall seconds) of ``sim.step`` over ``sim_seconds``."""
    n = round(sim_seconds / sim.world.timestep)
    t0 = time.perf_counter()
    sim.step(n)
    wall = time.perf_counter() - t0
    return sim_seconds / wall, wall


def tb3_sim(with_sensors: bool):
    from gazelle.description import Pose, load
    from gazelle.sim import Simulation
    from gazelle.systems.gz_diff_drive import GzDiffDrive
    from gazelle.worlds import default_world

    model = load(TB3).value
    if not with_sensors:
        model = dataclasses.replace(model, links=tuple(dataclasses.replace(lk, sensors=()) for lk in model.links))
    sim = Simulation(default_world(), rtf=0)
    entity = sim.spawn(model, name="burger", pose=Pose((0.0, 0.0, 0.01)))
    drive = next(s for s in entity.systems if isinstance(s, GzDiffDrive))
    drive.command(0.1, 0.2)
    sim.step(500)
    return sim, entity


def floor_sensors(sim, entity):
    """The floor system (see the module's docstring) on TurtleBot3's IMU and lidar links, listened to."""
    from gazelle.description import Pose
    from gazelle.systems import Imu, LaserScan, MsgType, RateGate, System

    world = sim.world
    imu_body = world.body_id(entity.name, "imu_link")
    scan_body = world.body_id(entity.name, "base_scan")
    angles = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    dirs = np.stack([np.cos(angles), np.sin(angles), np.zeros(360)], axis=1)
    imu_ep = sim.bus.advertise(entity.name, "/floor/imu", MsgType.IMU)
    scan_ep = sim.bus.advertise(entity.name, "/floor/scan", MsgType.LASER_SCAN)
    at = Pose()

    class Floor(System):
        def __init__(self) -> None:
            self.imu_gate, self.scan_gate = RateGate(), RateGate()
            self.phase_gate = self.imu_gate

        def post_update(self, info, world) -> None:
            t = info.sim_time_sec
            if not self.imu_gate.due(t, 200.0):
                return
            r = world.imu_reading(imu_body, at)
            imu_ep.publish(Imu(t, "imu_link", (r[0], r[1], r[2], r[3]), (r[4], r[5], r[6]), (r[7], r[8], r[9])))
            if self.scan_gate.due(t, 5.0):
                dist, _ = world.cast_rays_from(scan_body, at, dirs, 3.5)
                ranges = np.where(dist >= 0, dist, np.inf).astype(np.float32).tobytes()
                scan_ep.publish(LaserScan(t, "base_scan", 0.0, 2 * math.pi, 2 * math.pi / 360, 0.12, 3.5, ranges, b""))

    sim.systems.add(entity.name, Floor())


def lidar_model(vertical: int, horizontal: int, rate: float) -> str:
    return f"""<?xml version="1.0"?><sdf version="1.9"><model name="lidar3d"><static>true</static><link name="l">
      <sensor name="vlp" type="gpu_lidar"><pose>0 0 1 0 0 0</pose><update_rate>{rate}</update_rate>
        <lidar><scan><horizontal><samples>{horizontal}</samples><min_angle>-3.14159</min_angle><max_angle>3.14159</max_angle></horizontal>
          <vertical><samples>{vertical}</samples><min_angle>-0.2618</min_angle><max_angle>0.2618</max_angle></vertical></scan>
          <range><min>0.3</min><max>100</max></range></lidar>
        <plugin name="vlp" filename="libgazebo_ros_ray_sensor.so">
          <output_type>sensor_msgs/PointCloud2</output_type></plugin>
      </sensor></link></model></sdf>"""


def camera_model(width: int, height: int, rate: float) -> str:
    return f"""<?xml version="1.0"?><sdf version="1.9"><model name="cam"><static>true</static><link name="l">
      <sensor name="rgb" type="camera"><pose>0 0 0.5 0 0.2 0</pose><update_rate>{rate}</update_rate>
        <camera><horizontal_fov>1.047</horizontal_fov><image><width>{width}</width><height>{height}</height></image>
          <clip><near>0.05</near><far>50</far></clip></camera>
        <plugin name="rgb" filename="libgazebo_ros_camera.so"/>
      </sensor></link></model></sdf>"""


def props(sim, n: int = 20) -> None:
    """A few boxes around the origin, so rays and pixels hit something."""
    from gazelle.description import Pose, load_string

    rng = np.random.default_rng(0)
    for i in range(n):
        a, r = rng.uniform(0, 2 * math.pi), rng.uniform(2, 8)
        xml = f"""<?xml version="1.0"?><sdf version="1.9"><model name="b{i}"><static>true</static><link name="l">
          <collision name="c"><geometry><box><size>0.5 0.5 {rng.uniform(0.5, 2):.2f}</size></box></geometry></collision>
          <visual name="v"><geometry><box><size>0.5 0.5 1</size></box></geometry>
            <material><diffuse>{rng.uniform(0.2, 1):.2f} {rng.uniform(0.2, 1):.2f} 0.3 1</diffuse></material></visual>
          </link></model></sdf>"""
        sim.spawn(load_string(xml).value, name=f"box{i}", pose=Pose((r * math.cos(a), r * math.sin(a), 0.5)))


SMOKE = "--smoke" in sys.argv[1:]
"""./test.sh's mode: every case on the same code path, for a sliver of the time (the figures mean nothing)."""
SPAN = 0.2 if SMOKE else 5.0
"""Sim seconds per measured run."""
REPEATS = 1 if SMOKE else 5


def main() -> int:
    logging.disable(logging.WARNING)
    os.environ.setdefault("GAZELLE_RESOURCE_PATH", str(TB3.parents[1]))
    t_all = time.perf_counter()
    import mujoco

    from gazelle.description import load_string
    from gazelle.sim import Simulation
    from gazelle.systems.sensors import Camera, Lidar
    from gazelle.worlds import default_world

    rows: list[tuple[str, str, str]] = []

    # 1. TurtleBot3 with and without its sensors, and the floor (best of 5 alternating runs each: one
    #    disturbed baseline run would move every ratio)
    with_s, without_s, floor_s = tb3_sim(True), tb3_sim(False), tb3_sim(False)
    floor_sensors(*floor_s)
    heard = listen(with_s[0])
    listen(without_s[0])
    floor_heard = listen(floor_s[0])
    best_with, best_without, best_floor = 0.0, 0.0, 0.0
    for _ in range(REPEATS):
        best_with = max(best_with, rtf_of(with_s[0], SPAN)[0])
        best_without = max(best_without, rtf_of(without_s[0], SPAN)[0])
        best_floor = max(best_floor, rtf_of(floor_s[0], SPAN)[0])
    loss = 1.0 - best_with / best_without
    floor_loss = 1.0 - best_floor / best_without
    rows.append(("TurtleBot3 burger, no sensors", f"RTF {best_without:.1f}x", ""))
    rows.append(
        ("TurtleBot3 burger, lidar 5 Hz + IMU 200 Hz heard", f"RTF {best_with:.1f}x", f"loss {loss:.1%} (goal <= 5 %)")
    )
    rows.append(
        (
            "  floor: bare readings + messages, no noise",
            f"RTF {best_floor:.1f}x",
            f"loss {floor_loss:.1%} ({floor_heard[0]} messages: the least a sensor read from Python costs)",
        )
    )

    # 1b. MuJoCo's own IMU sensors, computed inside every step, on the sensorless world (raw mj_step)
    w = without_s[0].world
    native = w.spec.copy()
    native.body(f"{without_s[1].name}::imu_link").add_site(name="bench_imu")
    for kind in ("ACCELEROMETER", "GYRO", "FRAMEQUAT"):
        native.add_sensor(
            type=getattr(mujoco.mjtSensor, f"mjSENS_{kind}"), objtype=mujoco.mjtObj.mjOBJ_SITE, objname="bench_imu"
        )
    costs = []
    for m in (w.model, native.compile()):
        d = mujoco.MjData(m)
        d.qpos[:], d.qvel[:], d.ctrl[:] = w.data.qpos, w.data.qvel, w.data.ctrl
        best = math.inf
        steps = 100 if SMOKE else 5000
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            mujoco.mj_step(m, d, nstep=steps)
            best = min(best, (time.perf_counter() - t0) / steps)
        costs.append(best)
    rows.append(
        (
            "  MuJoCo's own IMU sensors in every raw step",
            f"+{(costs[1] - costs[0]) * 1e6:.2f} us a step",
            f"{(costs[1] - costs[0]) * best_without / w.timestep:.1%} of the sensorless robot's step "
            "(its wall time per step), before any message",
        )
    )

    # 2. one 360-ray scan through the system vs raw mj_multiRay on the same scene
    sim = Simulation(default_world(), rtf=0)
    props(sim)
    lidar_xml = lidar_model(1, 360, 10).replace("PointCloud2", "LaserScan")
    lidar = next(s for s in sim.spawn(load_string(lidar_xml).model, name="scan").systems if isinstance(s, Lidar))
    sim.step(1)
    N = 20 if SMOKE else 2000
    t0 = time.perf_counter()
    for _ in range(N):
        lidar.scan(sim.world)
    ours = N * 360 / (time.perf_counter() - t0)
    m, d = sim.world.model, sim.world.data
    X = lidar.sensor_pose()
    dirs = np.ascontiguousarray(lidar.spec.directions()).reshape(-1)
    geom, dist = np.empty(360, np.int32), np.empty(360)
    pnt, groups = np.asarray(X.position, dtype=float), np.array([0, 0, 1, 1, 0, 0], np.uint8)
    body = sim.world.body_id("scan", "l")
    t0 = time.perf_counter()
    for _ in range(N):
        mujoco.mj_multiRay(m, d, pnt, dirs, groups, 1, body, geom, dist, None, 360, 100.0)
    raw = N * 360 / (time.perf_counter() - t0)
    rows.append(
        (
            "360-ray scan: lidar system vs raw mj_multiRay",
            f"{ours / 1e6:.2f} vs {raw / 1e6:.2f} M rays/s",
            f"ratio {ours / raw:.2f} (goal >= 0.8)",
        )
    )

    # 3. a 16 x 1800 3-D lidar at 10 Hz, point clouds built
    sim = Simulation(default_world(), rtf=0)
    props(sim)
    sim.spawn(load_string(lidar_model(16, 1800, 10)).model, name="vlp")
    clouds = listen(sim)
    rtf, wall = rtf_of(sim, SPAN)
    rows.append(
        (
            "16 x 1800 lidar at 10 Hz (PointCloud2)",
            f"RTF {rtf:.1f}x",
            f"{clouds[0]} clouds in {wall:.2f} s (goal RTF >= 1)",
        )
    )

    # 4. a 640 x 480 RGB camera at 30 Hz
    sim = Simulation(default_world(), rtf=0)
    props(sim)
    entity = sim.spawn(load_string(camera_model(640, 480, 30)).model, name="cam")
    cam = next(s for s in entity.systems if isinstance(s, Camera))
    images = listen(sim)
    sim.step(1)  # the first image makes the GL context
    images[0] = 0
    rtf, wall = rtf_of(sim, SPAN)
    rows.append(
        (
            "640 x 480 RGB camera at 30 Hz",
            f"RTF {rtf:.1f}x",
            f"{images[0]} images in {wall:.2f} s = {images[0] / wall:.0f} per wall s (goal: 30 Hz at RTF 1)",
        )
    )
    t0 = time.perf_counter()
    renders = 3 if SMOKE else 30
    for _ in range(renders):
        cam.render(sim.world, depth=False)
    per = (time.perf_counter() - t0) / renders
    rows.append(("  one 640 x 480 render + readback", f"{per * 1000:.1f} ms", f"{1 / per:.0f} images/s at most"))

    print(f"sensors on {os.cpu_count()} CPUs, MuJoCo {mujoco.__version__}, GL {os.environ.get('MUJOCO_GL', 'egl')}\n")
    width = max(len(r[0]) for r in rows)
    for label, figure, note in rows:
        print(f"{label:<{width}}  {figure:<28} {note}")
    print(f"\nheard {heard[0]} TurtleBot3 sensor messages; bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
