"""A stream of trajectories stamped in the future on ``~/joint_trajectory``, over ROS (issue 51 item 1).

MoveIt Servo run without ``use_sim_time`` stamps its trajectories with the wall clock while the controller runs
on the simulation's clock: each is 1.7e9 s ahead. Jazzy's joint_trajectory_controller waits for them, holding
the arm; gazelle's threw the Panda past its joint limits. A `gazelle sim` at real time, the Panda of
moveit_resources_panda_moveit_config bolted down (examples/arms/panda_on_table.urdf.xacro), its arm controller
from its ros2_controllers.yaml through the spawner, and a plain rclpy publisher."""

from __future__ import annotations

import time

import pytest
from _harness import RosClient, run_spawner, spawn_file, start_sim, wait_for
from _paths import REAL, REPO
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

pytestmark = pytest.mark.slow

PANDA = REAL / "moveit_panda"
CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"
ARM = [f"panda_joint{i}" for i in range(1, 8)]
JOINT4_LIMITS = (-3.1416, 0.0873)  # panda_joint4's <limit> in moveit_resources_panda_description


def test_a_wall_clock_stamped_stream_leaves_the_panda_where_it_was(ros_env, monkeypatch):
    """100 two-point trajectories (positions and zero velocities) at 100 Hz, stamped with the wall clock, each
    1 mrad further on joint 4: the arm holds where it was within 1 mrad, joint 4 never past its limits. Before,
    the arm went unstable within 0.6 s and joint 4 ended past its lower limit."""
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(PANDA))
    start_sim(1)  # real time: the stream's 100 Hz is the controller's
    spawn_file("panda", REPO / "examples" / "arms" / "panda_on_table.urdf.xacro")
    run_spawner(CONFIG / "ros2_controllers.yaml", "joint_state_broadcaster", "panda_arm_controller")
    ros = RosClient("trajectory_stream_test")
    try:
        states: list[JointState] = []
        ros.node.create_subscription(JointState, "/joint_states", states.append, 100)
        pub = ros.node.create_publisher(JointTrajectory, "/panda_arm_controller/joint_trajectory", 10)
        wait_for(lambda: pub.get_subscription_count() > 0 and states, 15, "the controller's topic and /joint_states")

        def arm() -> list[float]:
            msg = states[-1]
            return [msg.position[list(msg.name).index(n)] for n in ARM]

        time.sleep(1.0)  # the arm settles where initial_positions.yaml put it (sim time runs at wall time)
        q0 = arm()
        heard = len(states)
        for k in range(100):
            msg = JointTrajectory(joint_names=ARM)
            msg.header.stamp = ros.node.get_clock().now().to_msg()  # the wall clock: this node has no use_sim_time
            target = list(q0)
            target[3] += 0.001 * (k + 1)
            first = JointTrajectoryPoint(positions=target, velocities=[0.0] * 7)
            second = JointTrajectoryPoint(positions=target, velocities=[0.0] * 7)
            second.time_from_start.nanosec = 10_000_000
            msg.points = [first, second]
            pub.publish(msg)
            time.sleep(0.01)
        time.sleep(1.0)
        during = states[heard:]
        assert len(during) > 100, len(during)
        joint4 = [m.position[list(m.name).index("panda_joint4")] for m in during]
        assert JOINT4_LIMITS[0] <= min(joint4) and max(joint4) <= JOINT4_LIMITS[1], (min(joint4), max(joint4))
        end = arm()
        assert max(abs(a - b) for a, b in zip(end, q0, strict=True)) < 1e-3, (q0, end)
    finally:
        ros.close()
