"""A MoveIt Setup Assistant–style config package launched as its users launch it (issue 51 item 2):
``ros2 launch panda_moveit_config move_group.launch.py``, whose three lines are
``generate_move_group_launch(MoveItConfigsBuilder("panda", package_name=...).to_moveit_configs())``. Before
moveit_configs_utils existed in gazelle, the launch stopped at its import. move_group (gazelle's) comes up with the
parameters the builder gathered: the SRDF's groups, kinematics.yaml's solver, and /compute_fk answers for the URDF
the builder expanded (config/panda.urdf.xacro)."""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from _harness import RosClient, start
from _msa_package import PACKAGE, install_panda_config
from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetPositionFK

pytestmark = pytest.mark.slow

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]


@pytest.fixture(scope="module")
def launched(ros_env, tmp_path_factory) -> Iterator[tuple[RosClient, object]]:
    prefix = tmp_path_factory.mktemp("install")
    install_panda_config(prefix)
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    launch = start(
        [str(Path(sys.prefix) / "bin" / "ros2"), "launch", PACKAGE, "move_group.launch.py"], "ros2 launch", env=env
    )
    launch.wait_line("You can start planning now!", timeout=90)
    ros = RosClient("moveit_config_package_test")
    try:
        yield ros, launch
    finally:
        ros.close()
        assert launch.interrupt(20) == 0, launch.output


def test_setup_assistants_move_group_launch_starts_move_group_with_the_builders_parameters(launched):
    ros, launch = launched
    said = "\n".join(launch.lines)
    assert "groups: panda_arm, hand, panda_arm_hand" in said, said  # the SRDF the builder read
    assert "panda_arm's kinematics_solver kdl_kinematics_plugin/KDLKinematicsPlugin" in said, said
    req = GetPositionFK.Request()
    req.header.frame_id = "panda_link0"
    req.fk_link_names = ["panda_link8"]
    req.robot_state.joint_state.name = [f"panda_joint{i}" for i in range(1, 8)]
    req.robot_state.joint_state.position = READY
    res = ros.call(GetPositionFK, "/compute_fk", req, timeout=30)
    assert res.error_code.val == MoveItErrorCodes.SUCCESS, res.error_code.message
    p = res.pose_stamped[0].pose.position
    assert 0.25 < p.x < 0.4 and abs(p.y) < 1e-3 and 0.5 < p.z < 0.7, p  # the Panda's ready pose: flange ahead, up
