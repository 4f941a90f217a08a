"""move_group started from a launch file written as MoveIt's demo launch files are (no gazelle in it):
`moveit_ros_move_group move_group` with the URDF from xacro, the SRDF, kinematics.yaml,
joint_limits.yaml and moveit_controllers.yaml as parameters (launch_ros passes them as a params file).
The Panda config's packages are installed into a prefix on AMENT_PREFIX_PATH, as a workspace would."""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from _harness import RosClient, start
from _paths import REAL, REPO
from builtin_interfaces.msg import Duration
from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetMotionPlan, GetPositionIK

pytestmark = pytest.mark.slow

LAUNCH = REPO / "examples" / "arms" / "panda_move_group.launch.py"
PACKAGES = ("moveit_resources_panda_moveit_config", "moveit_resources_panda_description")
READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]


@pytest.fixture(scope="module")
def launched(ros_env, tmp_path_factory) -> Iterator[tuple[RosClient, object]]:
    prefix = tmp_path_factory.mktemp("install")
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    for package in PACKAGES:
        (index / package).write_text("")
        (prefix / "share" / package).symlink_to(REAL / "moveit_panda" / package)
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",  # the venv, activated: xacro
    }
    launch = start([str(Path(sys.prefix) / "bin" / "ros2"), "launch", str(LAUNCH)], "ros2 launch", env=env)
    launch.wait_line("You can start planning now!", timeout=90)
    ros = RosClient("move_group_launch_test")
    try:
        yield ros, launch
    finally:
        ros.close()
        assert launch.interrupt(20) == 0, launch.output


def test_a_moveit_style_launch_file_starts_move_group_with_the_configs_parameters(launched):
    ros, launch = launched
    said = "\n".join(launch.lines)
    # kinematics.yaml came through launch_ros's params file: its solver is named, its timeout used
    assert "panda_arm's kinematics_solver kdl_kinematics_plugin/KDLKinematicsPlugin" in said, said
    assert "kinematics_solver_timeout (0.05 s)" in said, said
    # a plan from a given start state (no simulation here): joint_limits.yaml bounds its speed
    req = GetMotionPlan.Request()
    mp = req.motion_plan_request
    mp.group_name = "panda_arm"
    mp.start_state.joint_state.name = [f"panda_joint{i}" for i in range(1, 8)]
    mp.start_state.joint_state.position = READY
    mp.max_velocity_scaling_factor = mp.max_acceleration_scaling_factor = 1.0
    from moveit_msgs.msg import Constraints, JointConstraint

    goal = [*READY[:3], -1.8, *READY[4:]]
    mp.goal_constraints = [
        Constraints(
            joint_constraints=[
                JointConstraint(
                    joint_name=f"panda_joint{i + 1}", position=v, tolerance_above=1e-4, tolerance_below=1e-4
                )
                for i, v in enumerate(goal)
            ]
        )
    ]
    res = ros.call(GetMotionPlan, "/plan_kinematic_path", req, timeout=30).motion_plan_response
    assert res.error_code.val == MoveItErrorCodes.SUCCESS, res.error_code.message
    points = res.trajectory.joint_trajectory.points
    assert abs(points[-1].positions[3] - (-1.8)) < 1e-3
    # IK without a timeout in the request: kinematics.yaml's budget
    ik = GetPositionIK.Request()
    ik.ik_request.group_name = "panda_arm"
    ik.ik_request.robot_state.joint_state = mp.start_state.joint_state
    ik.ik_request.pose_stamped.header.frame_id = "panda_link0"
    p = ik.ik_request.pose_stamped.pose
    p.position.x, p.position.y, p.position.z = 0.4, 0.1, 0.5
    p.orientation.x, p.orientation.w = 1.0, 0.0
    ik.ik_request.timeout = Duration()
    assert ros.call(GetPositionIK, "/compute_ik", ik).error_code.val == MoveItErrorCodes.SUCCESS
