"""robot_localization's EKF on its 15-variable state (``src/ekf.cpp`` and ``src/filter_base.cpp``, ros2 branch,
read for their behaviour; the formulation below is gazelle's own).

The motion model is omnidirectional and kinematic: the pose moves by the body-frame velocity and
acceleration rotated into the world (``R = Rz(yaw) Ry(pitch) Rx(roll)``, over ``dt``: ``R (v dt + a dt^2/2)``),
the Euler angles by the body rates through the Euler-rate matrix, the velocity by the acceleration; rates and
accelerations are held. The covariance is propagated through the model's Jacobian, with the process noise
``dt * Q`` added (Q's pose block scaled by the squared speed with ``dynamic_process_noise_covariance``).

A measurement updates only the variables its update vector selects (a non-finite value is left out): the
Kalman gain from the selected block of its covariance (a negative variance taken as its magnitude, a
variance under 1e-9 raised to 1e-9), the angular innovations wrapped, a Mahalanobis gate, and the covariance
updated in Joseph form. The first measurement initializes the selected variables and their covariance
instead. Before each measurement the state is predicted to its stamp; a measurement older than the last one
is fused without prediction.

Where gazelle differs: a measurement whose covariance is not finite, or whose update would make the state or
covariance non-finite, is not fused (upstream's filter would stay NaN for good).
"""

from __future__ import annotations

import math

import numpy as np

from ._control import ControlSettings
from ._measurement import ACCELERATION, ANGLES, PITCH, ROLL, STATE_SIZE, TWIST, YAW, Measurement
from ._rigid import normalize_angle, rotation_x, rotation_y, rotation_z

MIN_VARIANCE = 1e-9
"""A measured variance below this is raised to it (a measurement without error would make the gain blow up)."""
DEFAULT_PROCESS_NOISE = (0.05, 0.05, 0.06, 0.03, 0.03, 0.06, 0.025, 0.025, 0.04, 0.01, 0.01, 0.02, 0.01, 0.01, 0.015)
"""robot_localization's default process noise variances, per second (``FilterBase::reset``)."""
DEFAULT_INITIAL_COVARIANCE = 1e-9
"""The default initial variance of every variable (``FilterBase::reset``)."""


def _euler_rates(roll: float, pitch: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """E with (roll, pitch, yaw)' = E @ body rates, and its derivatives by roll and by pitch."""
    sr, cr = math.sin(roll), math.cos(roll)
    sp, cp = math.sin(pitch), math.cos(pitch)
    tp, sec = sp / cp, 1.0 / cp
    e = np.array([[1.0, sr * tp, cr * tp], [0.0, cr, -sr], [0.0, sr * sec, cr * sec]])
    de_droll = np.array([[0.0, cr * tp, -sr * tp], [0.0, -sr, -cr], [0.0, cr * sec, -sr * sec]])
    sec2 = sec * sec
    de_dpitch = np.array([[0.0, sr * sec2, cr * sec2], [0.0, 0.0, 0.0], [0.0, sr * tp * sec, cr * tp * sec]])
    return e, de_droll, de_dpitch


def _rotation_and_derivatives(roll: float, pitch: float, yaw: float) -> tuple[np.ndarray, list[np.ndarray]]:
    """R = Rz(yaw) Ry(pitch) Rx(roll), and [dR/droll, dR/dpitch, dR/dyaw]."""
    rx, ry, rz = rotation_x(roll), rotation_y(pitch), rotation_z(yaw)
    # the derivative of a rotation about an axis by its angle is the rotation by a further quarter turn,
    # with the axis' own row and column zeroed
    drx = rotation_x(roll + math.pi / 2) - np.diag([1.0, 0.0, 0.0])
    dry = rotation_y(pitch + math.pi / 2) - np.diag([0.0, 1.0, 0.0])
    drz = rotation_z(yaw + math.pi / 2) - np.diag([0.0, 0.0, 1.0])
    return rz @ ry @ rx, [rz @ ry @ drx, rz @ dry @ rx, drz @ ry @ rx]


def motion_model(state: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """The state ``dt`` seconds on (angles not wrapped), and the model's Jacobian at ``state``."""
    roll, pitch, yaw = (float(state[i]) for i in ANGLES)
    rot, drot = _rotation_and_derivatives(roll, pitch, yaw)
    e, de_droll, de_dpitch = _euler_rates(roll, pitch)
    v, w, a = state[6:9], state[9:12], state[12:15]
    travel = v * dt + a * (0.5 * dt * dt)  # in the body frame
    out = state.copy()
    out[0:3] += rot @ travel
    out[3:6] += (e @ w) * dt
    out[6:9] += a * dt
    jac = np.eye(STATE_SIZE)
    jac[0:3, 6:9] = rot * dt
    jac[0:3, 12:15] = rot * (0.5 * dt * dt)
    for k, d in enumerate(drot):
        jac[0:3, 3 + k] = d @ travel
    jac[3:6, 9:12] = e * dt
    jac[3:6, ROLL] += (de_droll @ w) * dt
    jac[3:6, PITCH] += (de_dpitch @ w) * dt
    jac[6:9, 12:15] = np.eye(3) * dt
    return out, jac


class Ekf:
    """The filter: state, covariance and their time (see the module docstring)."""

    def __init__(self) -> None:
        self.process_noise = np.diag(DEFAULT_PROCESS_NOISE)
        self.dynamic_process_noise = False
        self.control: ControlSettings | None = None
        self.reset()

    def reset(self) -> None:
        """Uninitialized, at rest at the origin, with the default initial covariance (``FilterBase::reset``)."""
        self.initialized = False
        self.state = np.zeros(STATE_SIZE)
        self.covariance = np.eye(STATE_SIZE) * DEFAULT_INITIAL_COVARIANCE
        self.last_measurement_ns = 0

    # ------------------------------------------------------------------ prediction
    def predict(self, now_ns: int, dt: float) -> None:
        """Project the state and covariance ``dt`` seconds forward (to ``now_ns``, the control's reference)."""
        _, jac = motion_model(self.state, dt)  # the Jacobian at the state before the control term
        if self.control is not None:
            self._apply_control(now_ns, dt)
        self.state, _ = motion_model(self.state, dt)
        self._wrap_angles()
        noise = self.process_noise
        if self.dynamic_process_noise:
            noise = noise.copy()
            speed2 = float(np.dot(self.state[TWIST], self.state[TWIST]))
            noise[0:6, 0:6] *= speed2
        self.covariance = jac @ self.covariance @ jac.T + dt * noise

    def _apply_control(self, now_ns: int, dt: float) -> None:
        """The control term: commanded angular accelerations change the rates now; a commanded linear axis
        sets that acceleration (upstream's order, before the projection)."""
        assert self.control is not None
        accel = self.control.accelerations(self.state[TWIST], now_ns)
        self.state[9:12] += accel[3:6] * dt
        for i in range(3):
            if self.control.update[i]:
                self.state[ACCELERATION.start + i] = accel[i]

    # ------------------------------------------------------------------ correction
    def correct(self, m: Measurement) -> bool:
        """Fuse the selected, finite variables of ``m``; False when it was gated out (or selected nothing)."""
        idx = np.flatnonzero(m.update & np.isfinite(m.values))
        if idx.size == 0:
            return False
        r = m.covariance[np.ix_(idx, idx)].copy()
        if not np.isfinite(r).all():
            return False  # gazelle's guard: upstream's filter would be NaN from here on
        diag = np.abs(np.diag(r))
        np.fill_diagonal(r, np.maximum(diag, MIN_VARIANCE))
        pht = self.covariance[:, idx]  # P H' (H selects the rows idx)
        try:
            s_inv = np.linalg.inv(self.covariance[np.ix_(idx, idx)] + r)
        except np.linalg.LinAlgError:
            return False
        gain = pht @ s_inv
        innovation = m.values[idx] - self.state[idx]
        for k, i in enumerate(idx):
            if i in ANGLES:
                innovation[k] = normalize_angle(float(innovation[k]))
        threshold = m.rejection_threshold
        # written so that a NaN distance (a NaN in the reading's covariance) fails the gate: upstream's
        # ``>= threshold`` test lets it through, and its filter is NaN from then on
        if not float(innovation @ s_inv @ innovation) < threshold * threshold:
            return False
        state = self.state + gain @ innovation
        residual = np.eye(STATE_SIZE)
        residual[:, idx] -= gain
        covariance = residual @ self.covariance @ residual.T + gain @ r @ gain.T
        if not (np.isfinite(state).all() and np.isfinite(covariance).all()):
            return False  # gazelle's guard (values so large they overflow): the filter stays as it was
        self.state, self.covariance = state, covariance
        self._wrap_angles()
        return True

    def process(self, m: Measurement) -> None:
        """Predict to the measurement's time (when it is later than the last one) and fuse it; the first
        measurement initializes the variables it selects (``FilterBase::processMeasurement``)."""
        delta_ns = 0
        if self.initialized:
            delta_ns = m.time_ns - self.last_measurement_ns
            if delta_ns > 0:
                self.predict(m.time_ns, delta_ns * 1e-9)
            self.correct(m)
        else:
            sel = m.update
            self.state[sel] = m.values[sel]
            both = np.ix_(sel, sel)
            self.covariance[both] = m.covariance[both]
            self.initialized = True
        if delta_ns >= 0:
            self.last_measurement_ns = m.time_ns

    def _wrap_angles(self) -> None:
        for i in (ROLL, PITCH, YAW):
            self.state[i] = normalize_angle(float(self.state[i]))
