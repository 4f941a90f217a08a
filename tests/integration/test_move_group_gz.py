"""move_group executing on a Panda driven the gz-sim way, without ros2_control: a JointPositionController
per joint (examples/arms/panda_gz_position.urdf.xacro). The config's moveit_controllers.yaml names a
FollowJointTrajectory controller that does not exist here, so move_group streams each plan to the
joints' command topics (/model/panda/joint/<joint>/n0/cmd_pos on ROS) and checks the end by /joint_states."""

from __future__ import annotations

import os
from collections.abc import Iterator

import pytest
from _harness import RosClient, spawn_file, start_sim, wait_for
from _paths import REPO
from moveit_msgs.msg import MoveItErrorCodes

from .test_move_group import PANDA, Panda, _group_states, start_panda_move_group

pytestmark = pytest.mark.slow

GZ_PANDA = REPO / "examples" / "arms" / "panda_gz_position.urdf.xacro"


@pytest.fixture(scope="module")
def gz_panda(ros_env) -> Iterator[Panda]:
    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    try:
        sim = start_sim(2)
        spawn_file("panda", GZ_PANDA)
        move_group = start_panda_move_group()
        ros = RosClient("move_group_gz_test")
        try:
            yield Panda(ros, sim, move_group)
        finally:
            ros.close()
    finally:
        os.environ.pop("GAZELLE_RESOURCE_PATH", None)


def _within(panda: Panda, target: dict[str, float], tol: float) -> dict[str, float] | None:
    js = panda.joints()
    return js if max(abs(js[j] - v) for j, v in target.items()) < tol else None


def test_named_states_are_reached_through_the_joints_position_controllers(gz_panda):
    states = _group_states("panda_arm")
    # the plugins' <initial_position>s: the arm holds 'ready' before anything is sent
    wait_for(lambda: _within(gz_panda, states["ready"], 0.01), 20, "the arm at its initial 'ready'")
    # 'extended' puts joint 4 at 0, beyond its URDF limit (-0.07): a servo against the limit is not a test
    # of execution; a bent arm within the limits is
    bent = {**states["ready"], "panda_joint1": 0.8, "panda_joint4": -1.6, "panda_joint6": 2.2}
    for name, target in (("bent", bent), ("ready", states["ready"])):
        result = gz_panda.action(gz_panda.move, gz_panda.joint_goal(target))
        assert result.error_code.val == MoveItErrorCodes.SUCCESS, (name, result.error_code.message, gz_panda.said())
        # move_group reports success once every joint has stayed within 0.01 rad of the end for 0.1 s
        wait_for(lambda target=target: _within(gz_panda, target, 0.01), 5, f"the arm at '{name}'")


def test_cancelling_a_streamed_motion_stops_the_arm_short_of_its_goal(gz_panda):
    far = {**_group_states("panda_arm")["ready"], "panda_joint1": 2.5}
    response, stopped, held = gz_panda.cancel_midway(far, "panda_joint1", 0.3)
    assert response.result.error_code.val == MoveItErrorCodes.PREEMPTED, response.result.error_code
    assert stopped < 2.0, stopped
    # it stays where it stopped, a second of sim time later: nothing streams the rest of the plan
    assert abs(held - stopped) < 0.05, (stopped, held)
