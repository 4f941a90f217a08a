"""A trajectory as the trajectory controller samples it: ros2_controllers Jazzy's ``trajectory.cpp``.

:class:`_Segmented` holds one trajectory in the controller's joint order, its times absolute, with the state
before it as its first point when that state comes first, and samples it as ``interpolation_method: splines``
does (``interpolate_between_points``): linear with positions only, cubic with velocities, quintic with
accelerations, efforts linear; one cycle at a time (:meth:`_Segmented.sample`) or every cycle of a planned
block at once (:meth:`_Segmented.sample_many`), the two bit-identical.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass
from typing import Any

import numpy as np

from ._goal import TrajectoryGoal
from ._tolerances import Tolerance


@dataclass
class _Segmented:
    """A trajectory in the controller's joint order, times absolute (sim seconds)."""

    times: list[float]
    pos: list[list[float]]
    vel: list[list[float]] | None
    acc: list[list[float]] | None
    goal: TrajectoryGoal | None
    path_tolerance: list[Tolerance] | None = None
    """Per joint (controller order), what the goal's path must keep to; None: nothing to check."""
    eff: list[list[float] | None] | None = None
    """Per point, the efforts (N·m or N) when every point of the trajectory has them (None for the state
    before it, which has none); None otherwise."""
    first: int = 0
    """Where the message's first point is in :attr:`times`: 1 when the state before the trajectory came first
    (the first segment runs from it), 0 when the trajectory was sampled between its own points from the start."""

    def on_first_segment(self, t: float) -> bool:
        """Whether sim time ``t`` is on the segment from the state before the trajectory to its first point
        (Jazzy's ``sample()`` interpolating from ``state_before_traj_msg_``): the controller is still on its
        way to, or waiting for, the trajectory's first point."""
        return self.first == 1 and t < self.times[1]

    def effort(self, t: float) -> list[float]:
        """The efforts at sim time ``t``, linear between two points as trajectory.cpp's
        ``interpolate_between_points`` makes them (``has_effort``): the last point's after the end, 0 on a
        segment whose start has none (the state before the trajectory), and 0 without efforts."""
        n = len(self.pos[0])
        eff, times = self.eff, self.times
        if eff is None or t < times[0]:
            return [0.0] * n
        if t >= times[-1]:
            return list(eff[-1] or [0.0] * n)
        k = bisect.bisect_right(times, t) - 1
        a, b = eff[k], eff[k + 1]
        if a is None or b is None:
            return [0.0] * n
        T, s = times[k + 1] - times[k], t - times[k]
        return [x + (y - x) / T * s for x, y in zip(a, b, strict=True)]

    def sample(self, t: float) -> tuple[list[float], list[float], list[float]]:
        """The desired (positions, velocities, accelerations) at sim time ``t``: before the first point, its
        position at rest (at it, the first segment's start: the state before the trajectory, moving as it
        was); after the last, the last position at rest; between two points, the segment's polynomial:
        linear with positions only, cubic with velocities, quintic with accelerations (ros2_controllers'
        spline interpolation)."""
        times = self.times
        n = len(self.pos[0])
        if t < times[0]:
            return list(self.pos[0]), [0.0] * n, [0.0] * n
        if t >= times[-1]:
            return list(self.pos[-1]), [0.0] * n, [0.0] * n
        k = bisect.bisect_right(times, t) - 1
        t0, t1 = times[k], times[k + 1]
        T, s = t1 - t0, t - t0
        p0, p1 = self.pos[k], self.pos[k + 1]
        if self.vel is None:
            v = [(b - a) / T for a, b in zip(p0, p1, strict=True)]
            return [a + vi * s for a, vi in zip(p0, v, strict=True)], v, [0.0] * n
        v0, v1 = self.vel[k], self.vel[k + 1]
        if self.acc is None:
            rows = [_cubic(a, b, va, vb, T, s) for a, b, va, vb in zip(p0, p1, v0, v1, strict=True)]
        else:
            a0s, a1s = self.acc[k], self.acc[k + 1]
            rows = [
                _quintic(a, b, va, vb, aa, ab, T, s)
                for a, b, va, vb, aa, ab in zip(p0, p1, v0, v1, a0s, a1s, strict=True)
            ]
        return [r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows]

    def sample_many(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`sample` at each of the times ``t`` at once (rows), with the same arithmetic in the same
        order, so each row is bit-identical to :meth:`sample` at that time."""
        times = np.asarray(self.times)
        P = np.asarray(self.pos, dtype=np.float64)
        m = len(t)
        n = P.shape[1]
        zeros = np.zeros((m, n))
        if len(times) < 2:
            return np.repeat(P[:1], m, axis=0), zeros, zeros.copy()
        k = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 2)
        t0 = times[k][:, None]
        T, s = times[k + 1][:, None] - t0, t[:, None] - t0
        p0, p1 = P[k], P[k + 1]
        if self.vel is None:
            v = (p1 - p0) / T
            pos, vel, acc = p0 + v * s, v, zeros.copy()
        else:
            V = np.asarray(self.vel, dtype=np.float64)
            if self.acc is None:
                pos, vel, acc = _cubic(p0, P[k + 1], V[k], V[k + 1], T, s)
            else:
                A = np.asarray(self.acc, dtype=np.float64)
                pos, vel, acc = _quintic(p0, P[k + 1], V[k], V[k + 1], A[k], A[k + 1], T, s)
        for rows, row in ((t < times[0], P[0]), (t >= times[-1], P[-1])):
            if rows.any():
                pos[rows], vel[rows], acc[rows] = row, 0.0, 0.0
        return pos, vel, acc


def _cubic(a: Any, b: Any, va: Any, vb: Any, T: Any, s: Any) -> tuple[Any, Any, Any]:
    """Position, velocity and acceleration at ``s`` into a segment of length ``T`` of the cubic with positions
    ``a``, ``b`` and velocities ``va``, ``vb`` at its ends. Floats (one joint) or numpy arrays (every joint at
    every cycle of a planned block): the same operations in the same order, so the same roundings."""
    T2, s3 = T * T, s * s * s
    c2 = (3 * (b - a) - (2 * va + vb) * T) / T2
    c3 = (2 * (a - b) + (va + vb) * T) / (T2 * T)
    return a + va * s + c2 * s * s + c3 * s3, va + 2 * c2 * s + 3 * c3 * s * s, 2 * c2 + 6 * c3 * s


def _quintic(a: Any, b: Any, va: Any, vb: Any, aa: Any, ab: Any, T: Any, s: Any) -> tuple[Any, Any, Any]:
    """As :func:`_cubic`, the quintic with position, velocity and acceleration given at both ends.

    Written in the offsets from the cubic-free part (``h``: the distance left after the start's own
    velocity and acceleration, ``dv``, ``da``): algebraically the coefficients of trajectory.cpp's quintic in
    ``interpolate_between_points``, arranged so that the float and the numpy forms round alike."""
    T3 = T * T * T
    T4, s2 = T3 * T, s * s
    T5, s3 = T4 * T, s2 * s
    s4 = s3 * s
    s5 = s4 * s
    c0, c1, c2 = a, va, aa / 2.0
    h = b - a - va * T - aa * T * T / 2.0
    dv = vb - va - aa * T
    da = ab - aa
    c3 = (10 * h - 4 * dv * T + da * T * T / 2.0) / T3
    c4 = (-15 * h + 7 * dv * T - da * T * T) / T4
    c5 = (6 * h - 3 * dv * T + da * T * T / 2.0) / T5
    return (
        c0 + c1 * s + c2 * s2 + c3 * s3 + c4 * s4 + c5 * s5,
        c1 + 2 * c2 * s + 3 * c3 * s2 + 4 * c4 * s3 + 5 * c5 * s4,
        2 * c2 + 6 * c3 * s + 12 * c4 * s2 + 20 * c5 * s3,
    )
