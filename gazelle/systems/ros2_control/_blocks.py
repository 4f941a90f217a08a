"""ros2_control cycles run as planned blocks inside MuJoCo's steps (issue 29).

When a controller manager cycles at every physics step and only controllers that can plan their cycles
are active (joint_trajectory_controller on position, or position + velocity, interfaces; the
joint_state_broadcaster), :class:`PlannedBlocks` plans up to :data:`BLOCK_CYCLES` cycles at once and the
world's steps run them in compiled code (``gazelle.physics.ServoPlan``). Each planned cycle commands what
the manager's Python cycle would (``tests/systems/test_ros2_control_blocks.py`` holds them bit-identical); the
joint states recorded at each cycle are published as blocks of messages; the controllers and the hardware
take back their state when the block ends (:meth:`PlannedBlocks.settle`). docs/architecture.md follows one
goal through it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from ...physics import PhysicsWorld
from .._base import RateGate
from ._broadcasters import JointStateBroadcaster
from ._controller import ACTIVE
from ._hardware import SimHardware
from ._trajectory import JointTrajectoryController, TrajectoryBlock

BLOCK_CYCLES = 100
"""The most cycles planned at once (see :meth:`PlannedBlocks.plan`). A block is cut short where
something must act sooner: a new trajectory or a cancel is seen at the next boundary of the runtime's blocks
(at most ``gazelle.sim.MAX_BLOCK_SEC``, 10 ms, later), a service call at once."""


@dataclass
class _Block:
    """A planned block of cycles running: its controllers, with a trajectory controller's references and
    each controller's cycle count at the block's start, and the cycles already handed to the broadcasters."""

    members: list[tuple[Any, TrajectoryBlock | None, int]]
    """(the manager's loaded controller, a trajectory controller's references, its cycle count at the start)"""
    t0: float
    published: int = 0


class _Manager(Protocol):
    """What the planned blocks use of the controller manager that owns them (``_manager.ControllerManager``): its
    rate and rate gate, its hardware and loaded controllers, and its merged state and command values."""

    @property
    def update_rate(self) -> float: ...
    @property
    def hardware(self) -> Sequence[SimHardware]: ...
    @property
    def controllers(self) -> Mapping[str, Any]: ...
    @property
    def _gate(self) -> RateGate: ...
    def _merged(self) -> tuple[dict[str, float], dict[str, float]]: ...


class PlannedBlocks:
    """One controller manager's planned blocks of cycles (see the module docstring)."""

    def __init__(self, cm: _Manager) -> None:
        """The planned blocks of one controller manager; none runs yet."""
        self.cm = cm
        self.block: _Block | None = None
        """The planned block running, if any."""
        self.allowed = True
        """Whether cycles may run as planned blocks (False: every cycle in Python, as a reference)."""
        self.cycles = 0
        """Cycles run in planned blocks so far."""

    @property
    def active(self) -> bool:
        """Whether a block was planned and is not settled yet."""
        return self.block is not None

    @property
    def running(self) -> bool:
        """Whether the world's steps still have cycles of the block to run."""
        plan = self.cm.hardware[0].block if self.block is not None else None
        return plan is not None and plan.remaining > 0

    def members(self, world: PhysicsWorld) -> list[Any] | None:
        """The active controllers, when the next cycles can be planned as a block: one hardware component
        whose joints are all position servos (:meth:`SimHardware.block_ready`), a cycle every step, and only
        trajectory controllers (every cycle) and joint state broadcasters active."""
        if len(self.cm.hardware) != 1 or not self.cm.hardware[0].block_ready():
            return None
        if 1.0 / self.cm.update_rate > world.timestep * (1.0 + 1e-9) or not world.servo_plans_available():
            return None
        members: list[Any] = []
        for loaded in self.cm.controllers.values():
            c = loaded.controller
            if c.state != ACTIVE:
                continue
            if isinstance(c, JointTrajectoryController):
                if c.update_rate and c.update_rate < self.cm.update_rate:
                    return None
            elif not isinstance(c, JointStateBroadcaster) or not c.block_ready():
                return None
            members.append(loaded)
        return members

    def plan(self, t: float, world: PhysicsWorld) -> bool:
        """Plan the cycles from ``t`` on (at most :data:`BLOCK_CYCLES`) as one block the world's steps run in
        compiled code, instead of a Python cycle per step; False when the cycle at ``t`` must run in Python.

        Each cycle of a block commands what a Python cycle would (the trajectory controllers' samples, the
        hardware's servo law: bit-identical, see ``tests/systems/test_ros2_control_blocks.py``); the cycles' states are
        recorded, the broadcasters publish one message per cycle, stamped with its time, at each boundary of
        the runtime's blocks (as one :class:`~gazelle.systems.PayloadBlock`: the messages are built where they
        are published, off the simulation thread), and when the block ends (:meth:`settle`) the trajectory
        controllers take back their state."""
        members = self.members(world)
        if members is None:
            return False
        hw = self.cm.hardware[0]
        times = np.full(BLOCK_CYCLES, world.timestep)
        times[0] = t
        times = np.add.accumulate(times)  # the times MuJoCo's steps reach (time += timestep, one by one)
        states, _commands = self.cm._merged()
        chosen: list[tuple[Any, TrajectoryBlock | None, int]] = []
        targets: dict[str, np.ndarray] = {}
        velocities: dict[str, np.ndarray] = {}
        tolerances: dict[str, tuple[float, float, np.ndarray, np.ndarray]] = {}
        m = len(times)
        for loaded in members:
            c = loaded.controller
            blk = None
            if isinstance(c, JointTrajectoryController):
                blk = c.plan_block(times, states)
                if blk is None:
                    return False
                m = min(m, len(blk.times))
                for k, j in enumerate(c.joints):
                    targets[j] = blk.cmd_p[:, k]  # the next cycle's set point, as Jazzy's JTC commands
                    if c.cmd_kinds[1:2] == ("velocity",):
                        velocities[j] = blk.cmd_v[:, k]
                if blk.tolerances:
                    tolerances.update(blk.tolerances)
            chosen.append((loaded, blk, loaded.cycle))
        if m < len(times):
            targets = {j: v[:m] for j, v in targets.items()}
            velocities = {j: v[:m] for j, v in velocities.items()}
            tolerances = {j: (p, v, rp[:m], rv[:m]) for j, (p, v, rp, rv) in tolerances.items()}
        n = hw.plan_block(times[:m], targets, velocities, tolerances or None)
        if n == 0:
            return False
        self.block = _Block(chosen, t)
        return True

    def interrupted(self) -> bool:
        """Whether a trajectory controller of the running block has a new trajectory or a canceled goal."""
        assert self.block is not None
        for loaded, blk, _first in self.block.members:
            if blk is not None and isinstance(loaded.controller, JointTrajectoryController):
                if loaded.controller.interrupted():
                    return True
        return False

    def publish_so_far(self) -> None:
        """Hand the broadcasters the cycles the world ran since the last hand-over."""
        block = self.block
        plan = self.cm.hardware[0].block
        if block is None or plan is None or plan.cursor <= block.published:
            return
        self._publish(block, plan.cursor)

    def _publish(self, block: _Block, upto: int) -> None:
        """Publish the joint state broadcasters' messages of a block's cycles ``[block.published, upto)``, from the
        states the plan recorded before each step, at each broadcaster's own rate."""
        hw = self.cm.hardware[0]
        plan = hw.block
        assert plan is not None
        start = block.published
        block.published = upto
        for loaded, _blk, first in block.members:
            c = loaded.controller
            if not isinstance(c, JointStateBroadcaster):
                continue
            every = 1
            if c.update_rate and c.update_rate < self.cm.update_rate:
                every = max(1, round(self.cm.update_rate / c.update_rate))
            runs = [i for i in range(start, upto) if (first + i) % every == 0]
            if runs:
                rows = slice(runs[0], runs[-1] + 1) if every == 1 else runs
                c.publish_block(plan.times[rows], plan.records[rows], hw.joint_index, hw.states)
                loaded.last_update = float(plan.times[runs[-1]])

    def settle(self) -> None:
        """End the planned block at the cycles the world has run so far (all of them, or fewer when a
        service call, a new trajectory, a reset or a checkpoint comes between): the broadcasters publish the
        cycles not yet published, the hardware and the controllers take back their state as if each cycle
        had run in Python, and the next cycle is due at once. Nothing happens when no block runs."""
        block = self.block
        if block is None:
            return
        hw = self.cm.hardware[0]
        plan = hw.block
        n = plan.cursor if plan is not None else 0
        if plan is not None and n > block.published:
            self._publish(block, n)
        self.block = None
        n = hw.finish_block()
        if plan is None or n == 0:
            if plan is not None:
                plan.steps = plan.cursor = 0
            self.cm._gate._next = block.t0  # the first cycle did not run: due again
            return
        self.cycles += n
        times = plan.times[:n]
        records = plan.records[:n]
        column = hw.joint_index
        _states, commands = self.cm._merged()
        for loaded, blk, _first in block.members:
            c = loaded.controller
            loaded.cycle += n
            if isinstance(c, JointTrajectoryController) and blk is not None:
                idx = [column[j] for j in c.joints]
                c.finish_block(blk, n, records[:, 0, idx], records[:, 1, idx], commands)
                loaded.last_update = float(times[-1])
        self.cm._gate.due(float(times[-1]), self.cm.update_rate)
