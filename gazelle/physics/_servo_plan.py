"""Planned position-servo cycles: the per-step work of a ros2_control hardware component, run by MuJoCo.

A :class:`ServoPlan` holds, for one group of position servos (a hardware component's), the target
and velocity reference of each of the next ``M`` cycles, the servos' gains and integral state, and
room to record the joints' state at each cycle. :meth:`PhysicsWorld.step` runs the live plans' cycles
inside its step loop (:func:`gazelle.physics._native.run_servo_groups`: a servo cycle, then
``mj_step``, per step, in compiled code), so a 1 kHz controller costs Python once per block of steps
instead of once per step. The cycle is the one :class:`gazelle.systems._actuation.PositionServo`
computes (same formula, same rounding): a block and the Python cycles it replaces give bit-identical
states, which ``tests/systems/test_ros2_control_blocks.py`` holds.

The systems build plans (they know the controllers); this module knows only servos and joints.
"""

from __future__ import annotations

import ctypes
import math

import numpy as np

from . import _native
from ._handles import ActuatorGroup, CompiledWorld, JointGroup, PerGeneration


def _f64(values: object, n: int) -> np.ndarray:
    """``values`` as a fresh contiguous float64 vector of ``n`` (the native loop reads raw pointers: the
    plan must own arrays of exactly this type and layout)."""
    return np.array(values, dtype=np.float64).reshape(n)  # a copy: the plan owns its arrays


class ServoPlan:
    """The planned cycles of one group of position servos (see the module docstring).

    Build it once per group; :meth:`load` a block of cycles, then let the world step: each step
    consumes one cycle (:attr:`cursor`). After the steps, :attr:`records` and :attr:`times` hold the
    joints' state at each cycle taken, :attr:`integral`, :attr:`last` and :attr:`commands` the
    servos' state after the last one.
    """

    def __init__(
        self,
        actuators: ActuatorGroup,
        servo_joints: JointGroup,
        recorded: JointGroup,
        gains: dict[str, np.ndarray],
    ) -> None:
        """A planned block's servo state for one group of position actuators: per servo, the PID gains, integral and
        last time; per cycle, the targets, velocity references and path tolerances the controller planned; and
        what it records per cycle of the ``recorded`` joints (positions, velocities, forces before each step) for
        the controller to publish afterwards."""
        self.world = actuators.world
        self.entity = servo_joints.entity
        self.actuators = actuators
        self.servo_joints = servo_joints
        self.recorded = recorded
        n = len(actuators.actuators)
        self.nservo = n
        self.kp = _f64(gains["kp"], n)
        self.ki = _f64(gains["ki"], n)
        self.kd = _f64(gains["kd"], n)
        self.offset = _f64(gains["offset"], n)
        self.imin = _f64(gains["imin"], n)
        self.imax = _f64(gains["imax"], n)
        self.integral = np.zeros(n)
        self.last = np.full(n, math.nan)
        self.commands = np.zeros(n)
        self.steps = 0
        self.cursor = 0
        self.violated = -1
        """The cycle (index) whose state left a path tolerance; -1: none."""
        nrec = len(recorded.names)
        self.nrec = nrec
        self.target = np.zeros((0, n))
        self.velref = np.zeros((0, n))
        self.desp: np.ndarray | None = None
        self.desv: np.ndarray | None = None
        self.tol_p: np.ndarray | None = None
        self.tol_v: np.ndarray | None = None
        self.records = np.zeros((0, 3, nrec))
        """Per cycle: positions, velocities and actuator forces of :attr:`recorded` before its step."""
        self.times = np.zeros(0)
        self._ids = PerGeneration(self._resolve)
        self._struct: _native.ServoGroupStruct | None = None
        self._struct_key: tuple[int, ...] | None = None

    def _resolve(self, world: CompiledWorld) -> tuple[np.ndarray, ...]:
        """The actuators' and joints' addresses in the compiled model, as the native loop takes them."""
        act = self.actuators._ids.get(self.world).astype(np.int32)
        sq, sd = (a.astype(np.int32) for a in self.servo_joints._ids.get(self.world))
        rq, rd = (a.astype(np.int32) for a in self.recorded._ids.get(self.world))
        return act, sq, sd, rq, rd

    def load(
        self,
        target: np.ndarray,
        velref: np.ndarray,
        *,
        desp: np.ndarray | None = None,
        desv: np.ndarray | None = None,
        tol_p: np.ndarray | None = None,
        tol_v: np.ndarray | None = None,
    ) -> None:
        """Plan ``len(target)`` cycles: per cycle, each servo's target and velocity reference (rows);
        with ``tol_p``/``tol_v`` (per servo, 0: unchecked) the block stops after the first cycle whose
        state is farther than that from (``desp``, ``desv``); ``desp`` None: the targets (a trajectory
        controller commands the next cycle's set point and checks the path against this cycle's)."""
        # rows are cycles, columns the servos in the actuator group's order; C-contiguous float64, as the
        # native loop indexes them (row k at k * nservo)
        m = len(target)
        self.target = np.ascontiguousarray(target, dtype=np.float64).reshape(m, self.nservo)
        self.velref = np.ascontiguousarray(velref, dtype=np.float64).reshape(m, self.nservo)
        checked = tol_p is not None and tol_v is not None and desv is not None
        self.desv = np.ascontiguousarray(desv, dtype=np.float64).reshape(m, self.nservo) if checked else None
        self.desp = (
            np.ascontiguousarray(desp, dtype=np.float64).reshape(m, self.nservo)
            if checked and desp is not None
            else None
        )
        self.tol_p = _f64(tol_p, self.nservo) if checked else None
        self.tol_v = _f64(tol_v, self.nservo) if checked else None
        self.records = np.zeros((m, 3, self.nrec))  # per cycle: positions, velocities, actuator forces
        self.times = np.zeros(m)
        self.steps, self.cursor, self.violated = m, 0, -1

    @property
    def remaining(self) -> int:
        """Cycles planned and not yet taken (0 once a tolerance was left)."""
        return 0 if self.violated >= 0 else self.steps - self.cursor

    def struct(self) -> _native.ServoGroupStruct:
        """The C view of this plan (pointers into its arrays), made once per load and model generation."""
        # keyed by where the arrays are: a checkpoint's restore may replace them under a live plan
        key = (
            self.world.generation,
            *(a.__array_interface__["data"][0] if a is not None else 0 for a in self._arrays()),
        )
        if self._struct is None or self._struct_key != key:
            act, sq, sd, rq, rd = self._ids.get(self.world)
            self._keep = (act, sq, sd, rq, rd)  # the addresses below point into these
            p = _native.pointer
            self._struct = _native.ServoGroupStruct(
                self.nservo,
                p(act),
                p(sq),
                p(sd),
                p(self.target),
                p(self.velref),
                p(self.kp),
                p(self.ki),
                p(self.kd),
                p(self.offset),
                p(self.imin),
                p(self.imax),
                p(self.integral),
                p(self.last),
                p(self.tol_p),
                p(self.tol_v),
                p(self.desp),
                p(self.desv),
                self.nrec,
                p(rq),
                p(rd),
                p(self.records),
                p(self.times),
                p(self.commands),
                0,
                -1,
            )
            self._struct_key = key
        self._struct.cursor = self.cursor
        return self._struct

    def _arrays(self) -> tuple[np.ndarray | None, ...]:
        """The arrays the native servo loop reads and writes, in the order its struct holds them."""
        return (
            self.target,
            self.velref,
            self.kp,
            self.ki,
            self.kd,
            self.offset,
            self.imin,
            self.imax,
            self.integral,
            self.last,
            self.tol_p,
            self.tol_v,
            self.desp,
            self.desv,
            self.records,
            self.times,
            self.commands,
        )

    def __getstate__(self) -> dict[str, object]:
        """Pickled (a checkpoint) without its C view and index cache, which are made again."""
        state = dict(self.__dict__)
        for key in ("_ids", "_keep", "_struct", "_struct_key"):
            state.pop(key, None)
        return state

    def __setstate__(self, state: dict[str, object]) -> None:
        """Restore a plan from a checkpoint: the addresses and the native struct are made again in the rebuilt
        world."""
        self.desp = None  # a plan pickled before the path check had a position reference of its own
        self.__dict__.update(state)
        self._ids = PerGeneration(self._resolve)
        self._struct = None
        self._struct_key = None


def run_plans(world: CompiledWorld, plans: list[ServoPlan], nstep: int) -> tuple[int, str | None]:
    """Take up to ``nstep`` steps of ``world`` running ``plans``' cycles; the steps taken and, after a
    MuJoCo error, its message (the steps before it are taken)."""
    if len(plans) == 1:
        structs = ctypes.pointer(plans[0].struct())
        n = 1
    else:
        structs = (_native.ServoGroupStruct * len(plans))(*(p.struct() for p in plans))  # copies
        n = len(plans)
    taken = _native.run_servo_groups(world.model, world.data, nstep, structs, n)
    error = None
    if taken < 0:
        taken = -taken - 1
        error = _native.last_error().strip() or "MuJoCo error"
    for k, plan in enumerate(plans):
        violated = structs[k].violated
        if violated >= 0:
            plan.violated = violated
        plan.cursor += taken
    return taken, error
