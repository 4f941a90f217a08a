"""A controllers YAML written under ``/**/`` (any namespace, zero levels included, as rcl reads it) through
every way gazelle reads one: the robot's gz_ros2_control ``<parameters>``, ``spawn --ros-args --params-file``
and ``spawner -p``, on a `gazelle sim` server with real spawner processes."""

from __future__ import annotations

from pathlib import Path

import pytest
from _harness import GAZELLE, start
from _paths import REAL, REPO
from controller_manager_msgs.srv import ListControllers

DIFFBOT_URDF = REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf"
WILDCARD_YAML = REPO / "tests" / "data" / "ros2_control" / "diffbot_wildcard_controllers.yaml"
TYPES = {
    "joint_state_broadcaster": ("active", "joint_state_broadcaster/JointStateBroadcaster"),
    "diffbot_base_controller": ("active", "diff_drive_controller/DiffDriveController"),
}


def _run(*args: str) -> str:
    proc = start([*GAZELLE, *args], args[0])
    assert proc.wait(60) == 0, proc.output
    return proc.output


@pytest.mark.slow
def test_double_star_sections_reach_the_manager_the_spawn_and_the_spawner(
    sim_factory, ros_client, tmp_path: Path, monkeypatch
):
    """Three diffbots, one per reader; each runs its two controllers with the types only the file's
    ``/**/controller_manager`` gives (before, the manager stayed at 100 Hz and every spawner failed with
    "the 'type' of controller ... is not set"). About 8 s: a server, three spawns and three spawners, each
    a process that starts rclpy."""
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(tmp_path))  # the server may read the robot's file there
    sim = sim_factory("--no-viewer")
    (tmp_path / "controllers.yaml").write_text(WILDCARD_YAML.read_text())
    plugin = (
        '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
        f"<parameters>{tmp_path / 'controllers.yaml'}</parameters></plugin></gazebo></robot>"
    )
    robot = tmp_path / "diffbot.urdf"
    robot.write_text(DIFFBOT_URDF.read_text().replace("</robot>", plugin))
    # the manager's own file, no namespace: /**/controller_manager is /controller_manager
    _run("spawn", "-entity", "a", "-file", str(robot), "-z", "0.05")
    sim.wait_line("controller manager '/controller_manager' at 20 Hz", 10)
    # the file given to the spawn (--ros-args --params-file), in a namespace
    _run("spawn", "-entity", "b", "-robot_namespace", "b", "-file", str(DIFFBOT_URDF), "-y", "1", "-z", "0.05",
         "--ros-args", "--params-file", str(WILDCARD_YAML))  # fmt: skip
    # the file given to the spawner (-p)
    _run("spawn", "-entity", "c", "-robot_namespace", "c", "-file", str(DIFFBOT_URDF), "-y", "2", "-z", "0.05")
    names = ["joint_state_broadcaster", "diffbot_base_controller"]
    _run("spawner", *names)
    _run("spawner", *names, "-c", "/b/controller_manager")
    _run("spawner", *names, "-c", "/c/controller_manager", "-p", str(WILDCARD_YAML))
    for manager in ("/controller_manager", "/b/controller_manager", "/c/controller_manager"):
        listed = ros_client.call(ListControllers, f"{manager}/list_controllers", ListControllers.Request())
        assert {c.name: (c.state, c.type) for c in listed.controller} == TYPES, manager
