"""An arm test of this package, on gazelle's pytest fixtures: MoveIt's own Panda moves its flange to a pose
through MoveIt's interfaces (a MoveGroup action goal, as MoveGroupInterface sends it). It never imports
gazelle.

The Panda is moveit_resources' (its panda_moveit_config: URDF, SRDF, ros2_controllers.yaml and the
planning configs, unchanged), bolted to the world as gazelle's examples/arms/panda_on_table.urdf.xacro
does, with its controllers started by ros2_control's spawner and a move_group (gazelle's). Time: the
simulation moves only while the test steps it; move_group plans in wall time meanwhile.
"""

import math
import os
import sys
import threading
from pathlib import Path

import pytest
from geometry_msgs.msg import Pose
from moveit_msgs.action import MoveGroup
from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint, PositionConstraint
from rclpy.action import ActionClient
from sensor_msgs.msg import JointState
from shape_msgs.msg import SolidPrimitive

HERE = Path(__file__).resolve().parent
BIN = Path(sys.executable).parent  # this venv's commands: ros2, gazelle
# MoveIt's Panda where the user has it: a folder holding moveit_resources_panda_moveit_config and
# moveit_resources_panda_description (a moveit_resources clone)
MOVEIT_RESOURCES = os.environ.get("MOVEIT_RESOURCES", "")
if MOVEIT_RESOURCES:  # where package://moveit_resources_panda_description/... is found
    os.environ.setdefault("GAZELLE_RESOURCE_PATH", MOVEIT_RESOURCES)
CONFIG = Path(MOVEIT_RESOURCES) / "moveit_resources_panda_moveit_config" / "config"
PANDA = HERE.parents[1] / "arms" / "panda_on_table.urdf.xacro"
GOAL = (0.4, 0.2, 0.5)
"""panda_link8's goal in panda_link0, pointing down."""


def pose_goal(xyz, quat=(1.0, 0.0, 0.0, 0.0)):
    """A MoveGroup goal: panda_link8 within 1 mm of ``xyz`` and 0.01 rad of ``quat`` (x, y, z, w)."""
    goal = MoveGroup.Goal()
    goal.request.group_name = "panda_arm"
    goal.request.allowed_planning_time = 5.0
    goal.request.max_velocity_scaling_factor = goal.request.max_acceleration_scaling_factor = 0.5
    position = PositionConstraint(link_name="panda_link8", weight=1.0)
    position.header.frame_id = "panda_link0"
    position.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001])]
    target = Pose()
    target.position.x, target.position.y, target.position.z = xyz
    target.orientation.w = 1.0
    position.constraint_region.primitive_poses = [target]
    orientation = OrientationConstraint(link_name="panda_link8", weight=1.0)
    orientation.header.frame_id = "panda_link0"
    o = orientation.orientation
    o.x, o.y, o.z, o.w = quat
    orientation.absolute_x_axis_tolerance = orientation.absolute_y_axis_tolerance = 0.01
    orientation.absolute_z_axis_tolerance = 0.01
    constraints = Constraints(position_constraints=[position], orientation_constraints=[orientation])
    goal.request.goal_constraints = [constraints]
    return goal


@pytest.mark.skipif(not MOVEIT_RESOURCES, reason="set MOVEIT_RESOURCES to a folder with MoveIt's Panda packages")
@pytest.mark.gazelle(record=["/joint_states"])
def test_the_panda_moves_its_flange_to_a_pose_through_move_group(gazelle_sim, ros, record_property):
    gazelle_sim.spawn(PANDA, "panda")
    spawner = gazelle_sim.run(
        [str(BIN / "ros2"), "run", "controller_manager", "spawner", "joint_state_broadcaster", "panda_arm_controller"]
        + ["--param-file", str(CONFIG / "ros2_controllers.yaml")],
        name="spawner",
    )
    gazelle_sim.run_until(lambda: spawner.popen.poll() is not None, timeout=30.0, what="the spawner to finish")
    assert spawner.popen.returncode == 0, spawner.tail()
    gazelle_sim.run(
        [str(BIN / "gazelle"), "move_group", "--urdf", str(CONFIG / "panda.urdf.xacro")]
        + ["--srdf", str(CONFIG / "panda.srdf"), "--config", str(CONFIG)],
        name="move_group",
    )
    joints = ros.subscribe("/joint_states", JointState)
    client = ActionClient(ros.node, MoveGroup, "move_action")
    ros.wait_until(client.server_is_ready, 60.0, "move_group's MoveGroup action")  # wall clock: it starts
    gazelle_sim.run_for(0.5)  # move_group hears where the arm is
    done = threading.Event()
    box = {}

    def on_goal(future):
        handle = future.result()
        box["accepted"] = handle.accepted
        if handle.accepted:
            handle.get_result_async().add_done_callback(lambda r: (box.update(result=r.result().result), done.set()))
        else:
            done.set()

    # sent from the node's spinning thread: sent from this one, an answer that came back before rclpy filed
    # the request could be lost (ros2/rclpy#1123)
    ros.node.executor.create_task(lambda: client.send_goal_async(pose_goal(GOAL)).add_done_callback(on_goal))
    # planning takes wall time, executing sim time: step the world until move_group says it is done
    gazelle_sim.run_until(done.is_set, timeout=60.0, what="the MoveGroup result")
    assert box["accepted"] and box["result"].error_code.val == MoveItErrorCodes.SUCCESS, box
    # the arm is where the plan ended, by the simulation's joint states
    trajectory = box["result"].planned_trajectory.joint_trajectory
    reached = dict(zip(joints.last.name, joints.last.position))
    off = max(abs(reached[n] - q) for n, q in zip(trajectory.joint_names, trajectory.points[-1].positions))
    record_property("joint_error_rad", round(off, 5))
    assert off < math.radians(0.5), f"{math.degrees(off):.2f} degrees from the plan's end"
