"""The chess robot's pick-and-place: how long a user's MoveIt client takes to move a piece, and where it lands.

Run: ``.venv/bin/python bench/bench_pick_place.py [--picks 4] [--rtf 4] [--running]``.

Starts, in a private ROS domain, what a user starts: ``gazelle sim``, the table, the chess robot
(examples/chessbot), the seed's board and pieces, the arms' controllers (dual_arm_panda_moveit_config's
ros2_controllers.yaml) and the hands' (examples/chessbot/hand_controllers.yaml), and ``gazelle
move_group``. With ``--running`` it uses the simulation and move_group already on this ROS domain
instead (the suite runs it so on tests/integration/test_chessbot.py's robot: ``--running --picks 1``).

Then it runs examples/chessbot/pick_and_place.py ``--picks`` times, moving a piece from row 1 to row 3
and back, column by column, and prints for each move: the program's wall time, the simulated time it
took, the piece's distance from the target square's centre (mm), its tilt (degrees) and the most any
other piece moved (mm). Machine-dependent; nothing asserts timing.
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO / "tests"))
sys.path.insert(0, str(REPO / "examples" / "chessboard"))
from _paths import REAL  # noqa: E402 - the shared fixtures as the tests find them
from spawn_chessboard import COLS, ROWS, piece_name, piece_pose  # noqa: E402 - the board's layout

PANDA = REAL / "moveit_panda"
DUAL = PANDA / "dual_arm_panda_moveit_config" / "config"
CHESSBOT = REPO / "examples" / "chessbot"
GAZELLE = [sys.executable, "-m", "gazelle.cli"]


def moves(picks: int) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Row 1 to row 3 and back, in columns 2 to 5 (both arms reach them)."""
    out = []
    for k in range(picks):
        col = 2 + (k // 2) % 4
        out.append(((1, col), (3, col)) if k % 2 == 0 else ((3, col), (1, col)))
    return out


class Stack:
    """The processes a user starts, in this ROS domain; stopped with SIGINT, then killed."""

    def __init__(self, rtf: float) -> None:
        self.procs: list[subprocess.Popen] = []
        sim = self._start([*GAZELLE, "sim", "--no-viewer", "--rtf", str(rtf)])
        self._wait_line(sim, "gazelle: ready", 60)
        for name, path in (("table", CHESSBOT / "table.sdf"), ("chessbot", CHESSBOT / "chessbot.urdf.xacro")):
            self._run([*GAZELLE, "spawn", "-entity", name, "-file", str(path)])
        self._run([sys.executable, str(REPO / "examples" / "chessboard" / "spawn_chessboard.py")])
        arms = ["joint_state_broadcaster", "left_arm_controller", "right_arm_controller"]
        self._run([*GAZELLE, "spawner", *arms, "-p", str(DUAL / "ros2_controllers.yaml")])
        hands = ["left_hand_controller", "right_hand_controller"]
        self._run([*GAZELLE, "spawner", *hands, "-p", str(CHESSBOT / "hand_controllers.yaml")])
        mg = self._start(
            [*GAZELLE, "move_group", "--urdf", str(CHESSBOT / "chessbot.urdf.xacro")]
            + ["--srdf", str(DUAL / "panda.srdf"), "--config", str(DUAL)]
        )
        self._wait_line(mg, "You can start planning now!", 60)

    def _start(self, cmd: list[str]) -> subprocess.Popen:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        self.procs.append(p)
        return p

    @staticmethod
    def _wait_line(p: subprocess.Popen, text: str, timeout: float) -> None:
        found = threading.Event()

        def read() -> None:
            assert p.stdout is not None
            for line in p.stdout:
                if text in line:
                    found.set()

        threading.Thread(target=read, daemon=True).start()
        if not found.wait(timeout):
            raise SystemExit(f"bench: '{text}' did not come within {timeout} s from {p.args[:4]}")

    @staticmethod
    def _run(cmd: list[str]) -> None:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
        if out.returncode != 0:
            raise SystemExit(f"bench: {' '.join(cmd[2:5])} failed:\n{out.stdout[-1500:]}{out.stderr[-1500:]}")

    def stop(self) -> None:
        for p in reversed(self.procs):
            if p.poll() is None:
                os.killpg(p.pid, signal.SIGINT)
        for p in reversed(self.procs):
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)


class Observer:
    """Sim time (/clock) and the pieces' poses (/get_entity_state) from this process."""

    def __init__(self) -> None:
        import rclpy
        from gazebo_msgs.srv import GetEntityState
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.qos import QoSProfile, ReliabilityPolicy
        from rosgraph_msgs.msg import Clock

        rclpy.init()
        self.rclpy, self.GetEntityState = rclpy, GetEntityState
        self.node = rclpy.create_node("bench_pick_place")
        self.sim_time = math.nan

        def on_clock(msg: Clock) -> None:
            self.sim_time = msg.clock.sec + msg.clock.nanosec * 1e-9

        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
        self.node.create_subscription(Clock, "/clock", on_clock, qos)
        self.client = self.node.create_client(GetEntityState, "/get_entity_state")
        self.executor = SingleThreadedExecutor()
        self.executor.add_node(self.node)
        self._stop = threading.Event()

        def spin() -> None:
            while not self._stop.is_set():
                self.executor.spin_once(timeout_sec=0.05)

        self._spinner = threading.Thread(target=spin, daemon=True)
        self._spinner.start()
        if not self.client.wait_for_service(timeout_sec=30.0):
            raise SystemExit("bench: no /get_entity_state on this ROS domain")

    def pose(self, name: str) -> tuple[tuple[float, float, float], float]:
        """(x, y, z) and tilt from upright (degrees) of an entity."""
        future = self.client.call_async(self.GetEntityState.Request(name=name))
        done = threading.Event()
        future.add_done_callback(lambda _f: done.set())
        if not done.wait(10.0) or future.result() is None or not future.result().success:
            raise SystemExit(f"bench: no entity '{name}'")
        p = future.result().state.pose
        q = p.orientation
        tilt = math.degrees(math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (q.x * q.x + q.y * q.y)))))
        return (p.position.x, p.position.y, p.position.z), tilt

    def close(self) -> None:
        self._stop.set()  # the spinning thread ends before the node goes (else rclpy aborts the process)
        self._spinner.join(5.0)
        self.executor.shutdown()
        self.node.destroy_node()
        self.rclpy.shutdown()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--picks", type=int, default=4, help="moves of a piece (default 4)")
    ap.add_argument("--rtf", type=float, default=4.0, help="real-time factor of the simulation started (default 4)")
    ap.add_argument("--arm", choices=("left", "right"), default="left")
    ap.add_argument("--running", action="store_true", help="use the simulation and move_group on this ROS domain")
    args = ap.parse_args()
    if not args.running:
        from _domain import private_ros_domain

        private_ros_domain()
        os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    t_bench = time.monotonic()
    stack = None if args.running else Stack(args.rtf)
    try:
        if stack is not None:
            print(f"the chess robot and move_group up in {time.monotonic() - t_bench:.1f} s", flush=True)
        observer = Observer()
        try:
            names = [piece_name(r, c) for r in ROWS for c in COLS]
            print(f"{'move':<16s} {'wall s':>7s} {'sim s':>7s} {'off mm':>7s} {'tilt °':>7s} {'others mm':>9s}")
            failed = 0
            walls = []
            for source, target in moves(args.picks):
                piece = piece_name(*source) if source[0] in ROWS else None
                # a piece put on row 3 is still called by the square it started from
                piece = piece or piece_name(1, source[1])
                others = {n: observer.pose(n)[0] for n in names if n != piece}
                t0, s0 = time.monotonic(), observer.sim_time
                run = subprocess.run(
                    [sys.executable, str(CHESSBOT / "pick_and_place.py"), "--arm", args.arm]
                    + ["--from", f"{source[0]},{source[1]}", "--to", f"{target[0]},{target[1]}", "--piece", piece],
                    capture_output=True,
                    text=True,
                    timeout=300,
                )
                wall, sim = time.monotonic() - t0, observer.sim_time - s0
                (x, y, _z), tilt = observer.pose(piece)
                goal = piece_pose(*target).position
                off = math.hypot(x - goal.x, y - goal.y) * 1e3
                moved, most = max((math.dist(observer.pose(n)[0], p) * 1e3, n) for n, p in others.items())
                label = f"{source[0]},{source[1]} -> {target[0]},{target[1]}"
                if run.returncode != 0:
                    failed += 1
                    print(f"{label:<16s} failed: {run.stderr.strip()[-300:]}", flush=True)
                    continue
                walls.append(wall)
                print(f"{label:<16s} {wall:7.2f} {sim:7.2f} {off:7.2f} {tilt:7.2f} {moved:9.2f}", flush=True)
                if moved > 1.0:
                    print(f"    {most} moved {moved:.1f} mm", flush=True)
            if walls:
                print(f"{len(walls)} of {len(walls) + failed} moves done, {sum(walls) / len(walls):.2f} s each (wall)")
        finally:
            observer.close()
    finally:
        if stack is not None:
            stack.stop()
    print(f"bench took {time.monotonic() - t_bench:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
