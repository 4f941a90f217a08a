"""50 random reachable pose goals on the Panda and on the UR5e (issue 51, "must show": at least 49 succeed, median
position error at most 0.5 mm), planned as move_group plans a MoveGroup pose goal: IK of the tip from the start
state, then a plan within allowed_planning_time (5 s), each goal from where the last one ended (tests/_pose_goals.py).
The robots are MoveIt's Panda config and UR's own UR5e files (ur_simulation_gz's URDF, ur_moveit_config's SRDF and
joint limits). One goal of each robot through the whole MoveGroup action, executed in a simulation, is in
tests/integration/test_ur5e_moveit.py and test_move_group.py; bench/bench_planning.py runs the 50 that way.

Before, the UR5e planned 8 of 10: IK restarts from random joint values answered, for joints whose limits span two
turns (UR's +-2 pi), the value a whole turn away from the start (shoulder_lift 3.16 for -3.12 beside a start of
-2.95), a configuration RRT-Connect could not reach in 20 s without the upper arm sweeping through the base."""

from __future__ import annotations

import math
import statistics

import numpy as np
import pytest
from _pose_goals import Arm, panda_arm, plan_goals, reachable_goals, ur5e_arm

GOALS = 50
SEED = 51


@pytest.fixture(scope="module", params=["panda", "ur5e"])
def arm(request, tmp_path_factory) -> Arm:
    pytest.importorskip("roboplan")
    return panda_arm() if request.param == "panda" else ur5e_arm(tmp_path_factory.mktemp("ur") / "install")


def test_50_random_reachable_pose_goals_at_least_49_planned_median_error_within_half_a_millimetre(arm):
    goals = reachable_goals(arm, GOALS, SEED)
    out = plan_goals(arm, goals)
    print(arm.name, out.summary(GOALS))
    assert len(out.failures) <= 1, (arm.name, out.failures)
    assert statistics.median(out.position_mm) <= 0.5, out.summary(GOALS)
    assert statistics.median(out.angle_rad) <= 0.01, out.summary(GOALS)


def test_ik_answers_each_revolute_joint_at_the_turn_nearest_its_seed(arm):
    """A revolute joint whose limits span more than a turn has several values for one pose; MoveIt's IK plugins
    search from the seed (KDL's Newton iterations, restarts only when that fails), so a client gets the one near
    the seed. gazelle's IK restarts from random joint values: whatever it converges to is brought to the value a
    whole number of turns away that is nearest the seed and within the limits (the same pose, the same geometry)."""
    planner = arm.planner
    joints = planner.group_joints(arm.group)
    idx = [planner.joint_names.index(j) for j in joints]
    lo, hi = (np.array(v) for v in planner.scene.getPositionLimitVectors(""))
    start = planner.state(planner.named_state(arm.group, arm.start))
    for k, target in enumerate(reachable_goals(arm, 20, SEED + 1)):
        q = planner.ik(arm.group, arm.tip, target, start)
        for i in idx:
            for turn in (-2 * math.pi, 2 * math.pi):
                other = q[i] + turn
                if lo[i] <= other <= hi[i]:
                    assert abs(q[i] - start[i]) <= abs(other - start[i]), (k, planner.joint_names[i], q[i], start[i])
        start = q


def test_an_ik_request_answers_the_same_whatever_was_asked_before(arm):
    """roboplan's own IK restarts draw from a generator each solver seeds anew, so a goal that needed restarts got
    another branch on each call, and the random goals above took other paths on a CI machine than here (two UR5e
    goals found no path in 5 s there). gazelle draws the restarts itself from the planner's seed: one request,
    one answer, on any machine and after any other request."""
    planner = arm.planner
    start = planner.state(planner.named_state(arm.group, arm.start))
    goals = reachable_goals(arm, 8, SEED + 2)
    first = [planner.ik(arm.group, arm.tip, target, start) for target in goals]
    again = [planner.ik(arm.group, arm.tip, target, start) for target in reversed(goals)][::-1]
    for k, (a, b) in enumerate(zip(first, again)):
        np.testing.assert_array_equal(a, b, err_msg=f"goal {k}")
