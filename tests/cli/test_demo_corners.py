"""The demo's corner finder: one corner per turn in place, however the samples fall."""

import math

from gazelle.cli._demo import Sample, find_corners


def _square(period: float = 0.02, repeat_every: int = 0) -> list[Sample]:
    """Ground truth of one square (5 s forward at 0.2 m/s, pi/2 turn at 0.5 rad/s), sampled every period.

    With repeat_every=n, every n-th sample is asked twice while the simulation has not stepped:
    the same stamp and pose again (what a loaded machine gives the demo's sampler).
    """
    out: list[Sample] = []
    t, x, y, yaw = 0.0, 0.0, 0.0, 0.0
    k = 0
    for _side in range(4):
        for v, w, dur in ((0.2, 0.0, 5.0), (0.0, 0.5, math.pi)):
            end = t + dur
            while t < end:
                out.append(Sample(t, x, y, yaw))
                k += 1
                if repeat_every and k % repeat_every == 0:
                    out.append(Sample(t, x, y, yaw))
                x += v * period * math.cos(yaw)
                y += v * period * math.sin(yaw)
                yaw += w * period
                t += period
    out.append(Sample(t, x, y, yaw))
    return out


def test_one_corner_per_turn():
    truth = _square()
    corners = [truth[i] for i in find_corners(truth)]
    assert len(corners) == 4
    assert [(round(c.x), round(c.y)) for c in corners] == [(1, 0), (1, 1), (0, 1), (0, 0)]


def test_repeated_stamps_inside_a_turn_do_not_split_it():
    truth = _square(repeat_every=7)
    corners = [truth[i] for i in find_corners(truth)]
    assert len(corners) == 4, [(round(c.x, 3), round(c.y, 3)) for c in corners]
    assert [(round(c.x), round(c.y)) for c in corners] == [(1, 0), (1, 1), (0, 1), (0, 0)]
