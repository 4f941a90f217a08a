"""Spawn timing of the seed's chessboard (1 board + 32 pieces) from a separate process, vs Gazebo.

Run: ``.venv/bin/python bench/bench_spawn.py [--reps 5] [--rtf 1]``. It starts its own ``gazelle sim``
(a private ROS_DOMAIN_ID, discovery on this host only) and, from this process over DDS, times:

* classic: the whole board as 33 sequential ``/spawn_entity`` (gazebo_msgs) calls; target < 1.5 s;
* batch: the whole board as one ``/gazelle/spawn_entities`` (simulation_interfaces) call; target < 0.3 s;

each ``--reps`` times (the board and pieces are deleted, untimed, before each run), and compares
with Gazebo's 0.145-0.38 s per spawn (log timestamps, ../shared/docs/anchors_and_user_needs.md §1.4).

Where the time goes: the server logs its own time per classic spawn (parse + build + recompile on the
sim thread), so ``client - server`` is the service round trip (DDS, serialisation, executor hand-off).
In-process, without ROS, it also measures parsing a piece's SDF, one spawn (= one MuJoCo recompile)
into a world holding the board and k pieces, and ``spawn_many`` of the whole board (one recompile).
Figures depend on the machine and its load; nothing here asserts timing.
"""

from __future__ import annotations

import argparse
import re
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

# a private ROS graph on this host only, before anything imports rclpy
from _domain import private_ros_domain

private_ros_domain()

REPO = Path(__file__).resolve().parent.parent
EXAMPLE = REPO / "examples" / "chessboard"
BOARD_XYZ = (0.25, 1.39, 0.90)
UNIT = 0.05
NAMES = ["chess_board"] + [f"piece_r{r}_c{c}" for r in (0, 1, 6, 7) for c in range(8)]
GAZEBO_PER_SPAWN = (0.145, 0.38)
TARGET_CLASSIC, TARGET_BATCH = 1.5, 0.3


def poses() -> list[tuple[float, float, float]]:
    bx, by, bz = BOARD_XYZ
    out = [BOARD_XYZ]
    for r in (0, 1, 6, 7):
        for c in range(8):
            out.append((bx - 3.5 * UNIT + c * UNIT, by - 3.5 * UNIT + r * UNIT, bz + 0.02))
    return out


class Server:
    """``gazelle sim`` as a subprocess; its output is kept for the per-spawn server times."""

    def __init__(self, rtf: float):
        self.lines: list[str] = []
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "gazelle.cli", "sim", "--rtf", str(rtf)],
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            cwd=REPO,
        )
        self.ready = threading.Event()
        threading.Thread(target=self._read, daemon=True).start()
        if not self.ready.wait(60):
            self.stop()
            sys.exit("gazelle sim did not get ready within 60 s:\n" + "\n".join(self.lines[-30:]))

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.lines.append(line.rstrip("\n"))
            if "gazelle: ready" in line:
                self.ready.set()

    def server_ms(self, since: int) -> list[float]:
        pattern = re.compile(r"spawned entity \[.*\] in ([\d.]+) ms")
        return [float(m.group(1)) for ln in self.lines[since:] if (m := pattern.search(ln))]

    def stop(self) -> None:
        if self.proc.poll() is None:
            self.proc.send_signal(2)
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                self.proc.kill()


def over_dds(reps: int, rtf: float) -> tuple[list[float], list[float], list[float]]:
    import rclpy
    from gazebo_msgs.srv import DeleteEntity, SpawnEntity
    from geometry_msgs.msg import Pose, PoseStamped
    from simulation_interfaces.msg import Resource, Result
    from simulation_interfaces.msg import SpawnEntity as SpawnRequest
    from simulation_interfaces.srv import SpawnEntities

    board_xml = (EXAMPLE / "chess_board.sdf").read_text()
    piece_xml = (EXAMPLE / "chess_piece.sdf").read_text()
    server = Server(rtf)
    rclpy.init()
    node = rclpy.create_node("bench_spawn")
    try:
        spawn = node.create_client(SpawnEntity, "/spawn_entity")
        delete = node.create_client(DeleteEntity, "/delete_entity")
        batch = node.create_client(SpawnEntities, "/gazelle/spawn_entities")
        for c in (spawn, delete, batch):
            if not c.wait_for_service(timeout_sec=20):
                sys.exit(f"{c.srv_name} not available")

        def call(client, req):
            fut = client.call_async(req)
            rclpy.spin_until_future_complete(node, fut, timeout_sec=30)
            if not fut.done():
                sys.exit(f"{client.srv_name} did not answer within 30 s")
            return fut.result()

        def clear() -> None:
            for n in NAMES:
                call(delete, DeleteEntity.Request(name=n))

        classic, batch_t, server_total = [], [], []
        for _ in range(reps):
            clear()
            mark = len(server.lines)
            t0 = time.perf_counter()
            for name, (x, y, z) in zip(NAMES, poses()):
                p = Pose()
                p.position.x, p.position.y, p.position.z = x, y, z
                p.orientation.w = 1.0
                xml = board_xml if name == "chess_board" else piece_xml
                res = call(spawn, SpawnEntity.Request(name=name, xml=xml, initial_pose=p, reference_frame="world"))
                if not res.success:
                    sys.exit(res.status_message)
            classic.append(time.perf_counter() - t0)
            time.sleep(0.3)  # let the server's log lines arrive
            server_total.append(sum(server.server_ms(mark)) / 1000)

            clear()
            reqs = []
            for name, (x, y, z) in zip(NAMES, poses()):
                ps = PoseStamped()
                ps.header.frame_id = "world"
                ps.pose.position.x, ps.pose.position.y, ps.pose.position.z = x, y, z
                ps.pose.orientation.w = 1.0
                xml = board_xml if name == "chess_board" else piece_xml
                reqs.append(SpawnRequest(name=name, entity_resource=Resource(resource_string=xml), initial_pose=ps))
            t0 = time.perf_counter()
            res = call(batch, SpawnEntities.Request(spawn_requests=reqs))
            batch_t.append(time.perf_counter() - t0)
            if res.result.result != Result.RESULT_OK:
                sys.exit(res.result.error_message)
        return classic, batch_t, server_total
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
        server.stop()


def in_process() -> dict[str, float]:
    """Parse, one spawn (recompile) at growing world size, and one spawn_many, without ROS (ms)."""
    from gazelle.description import Pose, load_string
    from gazelle.sim import Simulation, SpawnRequest
    from gazelle.worlds import default_world

    board_xml = (EXAMPLE / "chess_board.sdf").read_text()
    piece_xml = (EXAMPLE / "chess_piece.sdf").read_text()
    out: dict[str, float] = {}
    t0 = time.perf_counter()
    for _ in range(20):
        piece = load_string(piece_xml).value
    out["parse a piece SDF"] = (time.perf_counter() - t0) / 20 * 1000
    board = load_string(board_xml).model
    sim = Simulation(default_world(), rtf=0)
    per = []
    for name, (x, y, z) in zip(NAMES, poses()):
        t0 = time.perf_counter()
        sim.spawn(board if name == "chess_board" else piece, name=name, pose=Pose((x, y, z), (1, 0, 0, 0)))
        per.append((time.perf_counter() - t0) * 1000)
    out["spawn #1 (board, one recompile)"] = per[0]
    out["spawn #33 (32nd piece, one recompile)"] = per[-1]
    out["33 single spawns, total"] = sum(per)
    sim2 = Simulation(default_world(), rtf=0)
    t0 = time.perf_counter()
    sim2.spawn_many(
        [SpawnRequest(board if n == "chess_board" else piece, n, Pose(p, (1, 0, 0, 0))) for n, p in zip(NAMES, poses())]
    )
    out["spawn_many of 33 (one recompile)"] = (time.perf_counter() - t0) * 1000
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--rtf", type=float, default=1.0, help="the server's --rtf (1 = real time, as Gazebo)")
    args = ap.parse_args()
    classic, batch, server = over_dds(args.reps, args.rtf)
    lo, hi = GAZEBO_PER_SPAWN
    n = len(NAMES)
    med_c, med_b, med_s = statistics.median(classic), statistics.median(batch), statistics.median(server)
    print(f"chessboard: {n} entities, {args.reps} runs, gazelle sim --rtf {args.rtf:g}, client in a separate process")
    print(
        f"  classic, {n} x /spawn_entity : median {med_c:.3f} s (min {min(classic):.3f}, max {max(classic):.3f}),"
        f" {1000 * med_c / n:.1f} ms per spawn;"
        f" target < {TARGET_CLASSIC} s: {'met' if med_c < TARGET_CLASSIC else 'MISSED'}"
    )
    print(
        f"     of which on the server (parse + build + recompile): {med_s:.3f} s;"
        f" service round trips: {med_c - med_s:.3f} s ({1000 * (med_c - med_s) / n:.1f} ms per call)"
    )
    print(
        f"  batch, 1 x spawn_entities      : median {med_b:.3f} s (min {min(batch):.3f}, max {max(batch):.3f});"
        f" target < {TARGET_BATCH} s: {'met' if med_b < TARGET_BATCH else 'MISSED'}"
    )
    print(
        f"  Gazebo 11 (anchors §1.4): {lo:.3f}-{hi:.2f} s per spawn -> {n * lo:.1f}-{n * hi:.1f} s for the board;"
        f" gazelle classic is {n * lo / med_c:.0f}-{n * hi / med_c:.0f}x faster,"
        f" batch {n * lo / med_b:.0f}-{n * hi / med_b:.0f}x"
    )
    print("in-process profile (no ROS):")
    for k, v in in_process().items():
        print(f"  {k:40s} {v:8.2f} ms")


if __name__ == "__main__":
    main()
