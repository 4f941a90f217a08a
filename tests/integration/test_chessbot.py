"""The seed's chess robot: two arms at a table with the seed's board, moved by the seed's r2 aliases.

examples/chessbot: the dual-arm Panda macro of dual_arm_panda_moveit_config with its bases 60 cm apart
on a table, that config's SRDF, ros2_controllers.yaml, joint_limits.yaml and moveit_controllers.yaml
unchanged (its Ros2ControlManager: move_group finds the arms' controllers from the controller
manager), the hands' GripperActionControllers of examples/chessbot/hand_controllers.yaml, the seed's
board spawned by examples/chessboard/spawn_chessboard.py, `r2home` from examples/chessbot/r2.bash, and
examples/chessbot/pick_and_place.py. The table, the board and the pieces reach move_group's planning scene from
the simulation. The robot spawned is tests/data/chessbot_bumpers.urdf.xacro: the example unchanged, with
a gazebo_ros bumper on each of its 22 arm links, so the simulation's contacts are checked as a Gazebo
user checks them.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from _harness import RosClient, run_spawner, spawn_file, start, start_move_group, start_sim, wait_for
from _paths import REAL as FIXTURES
from _paths import REPO

pytestmark = pytest.mark.slow

PANDA = FIXTURES / "moveit_panda"
DUAL = PANDA / "dual_arm_panda_moveit_config" / "config"
CHESSBOT = REPO / "examples" / "chessbot"
R2_CLI = CHESSBOT / "r2_cli.py"
WITH_BUMPERS = REPO / "tests" / "data" / "chessbot_bumpers.urdf.xacro"
ARM_LINKS = [
    f"{arm}_panda_{link}"
    for arm in ("left", "right")
    for link in (*(f"link{i}" for i in range(8)), "hand", "leftfinger", "rightfinger")
]


class Contacts:
    """Every contact the arms' bumpers report: (sim time, the bumper's link, the other collision)."""

    def __init__(self, ros: RosClient) -> None:
        from gazebo_msgs.msg import ContactsState

        self.heard: set[str] = set()
        self.touches: list[tuple[float, str, str]] = []

        def hear(link: str):
            def on(msg: ContactsState) -> None:
                self.heard.add(link)
                t = msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9
                self.touches += [(t, link, st.collision2_name) for st in msg.states]

            return on

        for link in ARM_LINKS:
            ros.node.create_subscription(ContactsState, f"/contacts/{link}", hear(link), 100)

    def forbidden(self) -> list[tuple[float, str, str]]:
        """Touches of an arm with anything but itself: the other arm, the table, the board, a piece."""

        def arm(name: str) -> str:
            entity, _, rest = name.partition("::")
            return rest.split("_", 1)[0] if entity == "chessbot" else entity

        return [(t, link, other) for t, link, other in self.touches if arm(other) != link.split("_", 1)[0]]


@pytest.fixture(scope="module")
def chessbot(ros_env) -> Iterator[RosClient]:
    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    try:
        start_sim(4)  # four times real time
        spawn_file("table", CHESSBOT / "table.sdf")
        spawn_file("chessbot", WITH_BUMPERS)
        board = start([sys.executable, str(REPO / "examples" / "chessboard" / "spawn_chessboard.py")], "board")
        assert board.wait(120) == 0, board.output
        arms = ("joint_state_broadcaster", "left_arm_controller", "right_arm_controller")
        run_spawner(DUAL / "ros2_controllers.yaml", *arms)
        run_spawner(CHESSBOT / "hand_controllers.yaml", "left_hand_controller", "right_hand_controller")
        urdf = CHESSBOT / "chessbot.urdf.xacro"
        start_move_group(urdf, DUAL / "panda.srdf", DUAL, via_ros2=False)
        ros = RosClient("chessbot_test")
        try:
            ros.contacts = Contacts(ros)  # type: ignore[attr-defined]
            yield ros
        finally:
            ros.close()
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH", None)


def _pose(ros: RosClient, name: str) -> np.ndarray:
    p = ros.entity_state(name).state.pose
    return np.array(
        [p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w]
    )


def _pieces(ros: RosClient) -> dict[str, np.ndarray]:
    names = ["chess_board"] + [f"piece_r{r}_c{c}" for r in (0, 1, 6, 7) for c in range(8)]
    return {n: _pose(ros, n)[:3] for n in names}


def _r2(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(R2_CLI), *args], capture_output=True, text=True, timeout=120)


def _at(ros: RosClient, link: str, xyz: tuple[float, float, float]) -> float:
    return float(np.linalg.norm(_pose(ros, f"chessbot::{link}")[:3] - np.array(xyz)))


def test_the_table_board_and_pieces_are_in_the_planning_scene_and_the_robot_is_not(chessbot):
    from moveit_msgs.srv import GetPlanningScene

    def objects() -> dict:
        scene = chessbot.call(GetPlanningScene, "/get_planning_scene", GetPlanningScene.Request()).scene
        return {o.id: o for o in scene.world.collision_objects}

    # the ground, the table, the board and 32 pieces
    listed = wait_for(lambda: (lambda o: o if len(o) == 35 else None)(objects()), 20, "35 objects in the scene")
    assert "table::top" in listed and "chess_board::link" in listed and "ground_plane::link" in listed
    assert not [i for i in listed if i.startswith("chessbot::")]
    # as large as in the simulation: no padding unless the config asks (MoveIt's default_object_padding is 0;
    # gazelle padded every object by 1 cm a side, and fingers could not reach a 2 cm piece)
    (top,) = listed["table::top"].primitives
    assert list(top.dimensions) == pytest.approx([1.2, 1.0, 0.89])


def test_r2home_moves_both_arms_to_their_home_poses(chessbot):
    r2 = subprocess.run(
        ["bash", "-c", f"shopt -s expand_aliases\nsource {CHESSBOT / 'r2.bash'}\nr2home"],  # as typed, line by line
        capture_output=True,
        text=True,
        timeout=240,
        env={**os.environ, "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"},  # the venv, activated
    )
    assert r2.returncode == 0, r2.stdout + r2.stderr
    # the aliases' targets (r2.bash): both flanges 1 mm from them in the simulation
    assert _at(chessbot, "left_panda_link8", (0.05, 1.3, 1.15)) < 1e-3
    assert _at(chessbot, "right_panda_link8", (0.45, 1.3, 1.15)) < 1e-3


def test_the_arms_cross_over_the_board_around_each_other_and_touch_nothing(chessbot):
    contacts: Contacts = chessbot.contacts
    wait_for(lambda: contacts.heard == set(ARM_LINKS), 20, "every arm link's bumper")
    contacts.touches.clear()
    before = _pieces(chessbot)
    # each hand to the other's side: once the left arm is there, the right arm's straight way in joint
    # space from home to its goal runs through the left arm (25 of 41 points, checked with the planner)
    left_goal, right_goal = (0.4, 1.5, 1.1), (0.0, 1.25, 1.1)
    run = _r2("left", *map(str, left_goal), str(math.pi), "0", "-0.785")
    assert run.returncode == 0, run.stdout + run.stderr
    run = _r2("right", *map(str, right_goal), str(math.pi), "0", "-0.785")
    assert run.returncode == 0, run.stdout + run.stderr
    assert _at(chessbot, "left_panda_link8", left_goal) < 1e-3
    assert _at(chessbot, "right_panda_link8", right_goal) < 1e-3
    after = _pieces(chessbot)
    moved = {n: float(np.linalg.norm(after[n] - before[n])) for n in before}
    assert max(moved.values()) < 1e-3, {n: d for n, d in moved.items() if d >= 1e-3}
    # ...and by the simulation's contacts, all the way: no arm touched the other, the table or the board
    assert not contacts.forbidden(), contacts.forbidden()[:10]


def test_an_unknown_arm_and_an_unreachable_pose_are_refused_and_nothing_moves(chessbot):
    before = _pose(chessbot, "chessbot::left_panda_link8")
    run = _r2("middle", "0", "0", "1", "0", "0", "0")
    assert run.returncode == 1 and "unknown arm: 'middle'" in run.stderr
    run = _r2("left", "3.0", "1.3", "1.1", str(math.pi), "0", "0")
    assert run.returncode == 1 and "error -31" in run.stderr, run.stderr  # NO_IK_SOLUTION
    after = _pose(chessbot, "chessbot::left_panda_link8")
    assert np.linalg.norm(after[:3] - before[:3]) < 1e-3


def test_a_piece_is_picked_and_placed_on_another_square_and_back_upright(chessbot):
    """Issue 27, item 11: examples/chessbot/pick_and_place.py (a MoveIt client: GripperCommand,
    MoveGroup, compute_cartesian_path, execute_trajectory, the piece attached in the planning scene)
    moves piece_r1_c2 to row 3 and back, run by bench/bench_pick_place.py in its small mode on this
    robot. Each time within 5 mm of the square's centre and upright; no other piece moved."""
    home = subprocess.run(
        ["bash", "-c", f"shopt -s expand_aliases\nsource {CHESSBOT / 'r2.bash'}\nr2home"],
        capture_output=True,
        text=True,
        timeout=240,
        env={**os.environ, "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"},
    )
    assert home.returncode == 0, home.stdout + home.stderr
    before = _pieces(chessbot)
    bench = subprocess.run(
        [sys.executable, str(REPO / "bench" / "bench_pick_place.py"), "--running", "--picks", "2"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert bench.returncode == 0 and "2 of 2 moves done" in bench.stdout, bench.stdout + bench.stderr[-3000:]
    rows = [line.split() for line in bench.stdout.splitlines() if "->" in line]
    assert [r[:3] for r in rows] == [["1,2", "->", "3,2"], ["3,2", "->", "1,2"]], bench.stdout
    for row in rows:  # off mm, tilt °, others mm
        assert float(row[5]) < 5.0 and float(row[6]) < 2.0 and float(row[7]) < 1.0, bench.stdout
    after = _pieces(chessbot)
    moved = {n: float(np.linalg.norm(after[n] - before[n])) for n in before}
    assert moved.pop("piece_r1_c2") < 0.005  # back on its own square
    assert max(moved.values()) < 1e-3, {n: d for n, d in moved.items() if d >= 1e-3}
    p = _pose(chessbot, "piece_r1_c2")
    assert 1.0 - 2.0 * (p[3] ** 2 + p[4] ** 2) > math.cos(math.radians(2.0))  # upright


def test_the_bumpers_report_a_touch(chessbot):
    """The contact check above can fail: a box dropped on the left hand is reported by its bumpers."""
    from gazebo_msgs.srv import SpawnEntity

    contacts: Contacts = chessbot.contacts
    hand = _pose(chessbot, "chessbot::left_panda_hand")
    box = (
        '<sdf version="1.9"><model name="box"><link name="link"><inertial><mass>0.05</mass></inertial>'
        '<collision name="c"><geometry><box><size>0.04 0.04 0.04</size></box></geometry></collision>'
        "</link></model></sdf>"
    )
    req = SpawnEntity.Request(name="dropped", xml=box)
    req.initial_pose.position.x, req.initial_pose.position.y = float(hand[0]), float(hand[1])
    req.initial_pose.position.z = float(hand[2]) + 0.15
    contacts.touches.clear()
    assert chessbot.call(SpawnEntity, "/spawn_entity", req).success
    wait_for(lambda: [c for c in contacts.forbidden() if c[2].startswith("dropped::")], 20, "the box on the hand")
