"""Issue 51 item 6: move_group's services and actions were up before its robot model was built; a client that
waited for /plan_kinematic_path (as pymoveit2 does) and called at once got FAILURE "move_group has no robot
yet". MoveIt makes its capabilities once the model is loaded (move_group.cpp): nothing is served before."""

from __future__ import annotations

import time

from _harness import GAZELLE, RosClient, start, wait_for
from _paths import REAL as FIXTURES
from moveit_msgs.msg import Constraints, JointConstraint, MoveItErrorCodes
from moveit_msgs.srv import GetMotionPlan
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from gazelle.description import read_description_file

PANDA = FIXTURES / "moveit_panda"
CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]
"""The SRDF's 'ready' state of panda_arm (no /joint_states here: the start state is given)."""
NS = "/startup_test"
SERVED_BY_CAPABILITIES = tuple(
    f"{NS}/{name}" for name in ("plan_kinematic_path", "compute_fk", "get_planning_scene", "move_action")
)


def _names(ros: RosClient) -> set[str]:
    """Every service name in the graph, and every action's (by its send_goal service)."""
    names = {name for name, _ in ros.node.get_service_names_and_types()}
    return names | {n.removesuffix("/_action/send_goal") for n in names if n.endswith("/_action/send_goal")}


def test_move_group_serves_nothing_until_its_robot_is_known_then_answers_at_once(ros_env, monkeypatch) -> None:
    """Waits 3 s on purpose for services that must not appear (they came with the node's own parameter
    services before)."""
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(PANDA))
    ros = RosClient("move_group_startup_test")
    # in a namespace of its own: a move_group an earlier test module stopped may linger in the graph
    move_group = start([*GAZELLE, "move_group", "--ros-args", "-r", f"__ns:={NS}"], "move_group")
    try:
        wait_for(lambda: f"{NS}/move_group/get_parameters" in _names(ros), 30, "move_group's parameter services")
        deadline = time.monotonic() + 3.0
        while time.monotonic() < deadline:  # polled as wait_for polls: nothing may appear in these 3 s
            early = _names(ros) & set(SERVED_BY_CAPABILITIES)
            assert not early, f"served before the robot is known: {sorted(early)}"
            time.sleep(0.05)
        publishers = []
        for topic, text in (
            (f"{NS}/robot_description", read_description_file(str(CONFIG / "panda.urdf.xacro"))),
            (f"{NS}/robot_description_semantic", (CONFIG / "panda.srdf").read_text()),
        ):
            pub = ros.node.create_publisher(String, topic, LATCHED)
            pub.publish(String(data=text))
            publishers.append(pub)
        wait_for(lambda: f"{NS}/plan_kinematic_path" in _names(ros), 60, "plan_kinematic_path once the robot is known")
        request = GetMotionPlan.Request()
        mpr = request.motion_plan_request
        mpr.group_name = "panda_arm"
        mpr.start_state.joint_state.name = [f"panda_joint{i}" for i in range(1, 8)]
        mpr.start_state.joint_state.position = READY
        mpr.goal_constraints = [
            Constraints(joint_constraints=[JointConstraint(joint_name="panda_joint1", position=0.3, weight=1.0)])
        ]
        reply = ros.call(GetMotionPlan, f"{NS}/plan_kinematic_path", request, timeout=30)
        code = reply.motion_plan_response.error_code
        assert code.val == MoveItErrorCodes.SUCCESS, (code.val, code.message, move_group.output)
        move_group.wait_line("You can start planning now!", 5)
    finally:
        ros.close()
        assert move_group.interrupt() == 0, move_group.output
