"""Plans that keep a path constraint are shortcut within it (issue 51: "constrained plans are slow", a 0.5 m move
at 0.1 rad orientation tolerance took ~25 s). The RRT's path, each node projected onto the constraint, wanders; its
shortcut by roboplan's PathShortcutter leaves the constraint, and gazelle then kept the wandering path: 65 points,
6.1 rad of joint travel and a 25.8 s trajectory for the Panda's hand moved 0.5 m sideways within 0.1 rad of its
'ready' orientation (planned in 0.03 s). MoveIt's OMPL simplifies a constrained path with checks of the constraint
(ompl's PathSimplifier validates each shortcut with the constrained state validity checker): now each shortcut
gazelle takes is a straight line in joint space that keeps the constraint and is collision free."""

from __future__ import annotations

import numpy as np
import pytest
from _pose_goals import panda_arm

from gazelle.planning import PathConstraints


@pytest.fixture(scope="module")
def panda():
    pytest.importorskip("roboplan")
    return panda_arm()


@pytest.mark.parametrize("sideways", [0.5, -0.5])
def test_a_half_metre_move_within_a_tenth_of_a_radian_of_the_hands_orientation_is_shortcut_within_it(panda, sideways):
    p = panda.planner
    start = p.state(p.named_state("panda_arm", "ready"))
    hand = p.fk(start, "panda_link8")
    target = hand.copy()
    target[1, 3] += sideways
    target[2, 3] -= 0.1
    goal = p.ik("panda_arm", "panda_link8", target, start)
    region = np.eye(4)
    region[:3, :3] = hand[:3, :3]
    tol, inf = 0.1, np.inf
    keep = PathConstraints(
        poses=(
            ("panda_link8", region, np.array([-inf, -inf, -inf, -tol, -tol, -tol]), np.array([inf] * 3 + [tol] * 3)),
        )
    )
    trajectory = p.plan("panda_arm", goal, start, constraints=keep, timeout=5.0)
    travel = float(np.sum(np.abs(np.diff(trajectory.positions, axis=0))))
    assert trajectory.duration < 5.0, (trajectory.duration, travel)
    # every point keeps the constraint: the hand's rotation from 'ready' within 0.1 rad about each axis
    index = [p.joint_names.index(j) for j in trajectory.joint_names]
    q = start.copy()
    for point in trajectory.positions:
        q[index] = point
        r = hand[:3, :3].T @ p.fk(q, "panda_link8")[:3, :3]
        angle = float(np.arccos(np.clip((np.trace(r) - 1.0) / 2.0, -1.0, 1.0)))
        assert angle <= tol * np.sqrt(3) + 1e-3, angle
