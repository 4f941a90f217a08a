"""What writes the world's state outside its steps (:class:`WorldState`, a part :class:`~gazelle.physics.PhysicsWorld`
owns, ``world.state``, whose public methods the world hands on to it): an entity's pose and twist, a joint's
position and velocity, resets,
the repair of a diverged state, and checkpoints (the whole of MuJoCo's data and the model's run-time
parameters, for ``gazelle.sim``'s checkpoint and branch). The part sees the world as a :class:`StatefulWorld`, so
it imports nothing of the module that builds it."""

from __future__ import annotations

import hashlib
import math
import pickle
from typing import Any, Protocol

import mujoco
import numpy as np

from ..description import Pose, quat_conj, quat_rotate
from ._builder import scoped
from ._entities import Entity, ErrorKind, WorldError, pose_out_of_range
from ._queries import ONE_DOF_JOINTS, WorldQueries
from ._world_part import WorldPart, WorldView


class StatefulWorld(WorldView, Protocol):
    """What the state part uses of the world (:class:`~gazelle.physics.PhysicsWorld` is one): its spec, model, data
    and entities, and its own stepping state, which a checkpoint keeps."""

    _overlap_steps: int
    """Steps left in which deep overlaps are limited."""
    _deep: bool
    """Whether the last overlap check found a deep one."""
    _actuator_gains: dict[str, tuple[np.ndarray, np.ndarray]]
    """Actuator name -> its gain and bias parameters as added."""

    @property
    def spec(self) -> mujoco.MjSpec: ...

    def _forward(self) -> None:
        """``mj_forward`` with the arena grown when contacts need it."""
        ...

    def _watch_overlaps(self) -> None:
        """Watch for deep overlaps after something was placed."""
        ...


class WorldState(WorldPart[StatefulWorld]):
    """The state-writing part of a world (see the module docstring); ``queries`` is the world's query part (its
    kinematics are current after a write)."""

    def __init__(self, world: StatefulWorld, queries: WorldQueries) -> None:
        super().__init__(world)
        self._queries = queries
        self._state_views: tuple[Any, np.ndarray, np.ndarray] = (None, np.zeros(0), np.zeros(0))
        """(MjData, its qpos, its qvel): array views kept for the divergence check before every block of steps."""

    @property
    def spec(self) -> mujoco.MjSpec:
        return self._world.spec

    def state_digest(self) -> str:
        """SHA-256 of the whole physics state (time, positions, velocities, actuator states, controls,
        warm start: MuJoCo's ``mjSTATE_INTEGRATION``): equal digests, bit-identical worlds."""
        spec = mujoco.mjtState.mjSTATE_INTEGRATION
        state = np.empty(mujoco.mj_stateSize(self.model, spec))
        mujoco.mj_getState(self.model, self.data, state, spec)
        return hashlib.sha256(state.tobytes()).hexdigest()

    def checkpoint_extras(self) -> dict[str, object]:
        """Everything of the world a checkpoint keeps: MuJoCo's whole data (state, warm start, contacts,
        every derived quantity) and model (parameters changed at run time), and the world's own run-time
        state (see ``gazelle.sim`` checkpoints). Picklable."""
        return {
            "data": pickle.dumps(self.data, protocol=pickle.HIGHEST_PROTOCOL),
            "overlap_steps": self._world._overlap_steps,
            "deep": self._world._deep,
            "kinematics_stale": self._queries.kinematics_stale,
            "actuator_gains": {k: (g.copy(), b.copy()) for k, (g, b) in self._world._actuator_gains.items()},
            "model": self.model,
        }

    def restore_checkpoint_extras(self, extras: dict[str, Any]) -> None:
        """Take back what :meth:`checkpoint_extras` gave, into a world rebuilt with the same entities:
        the model's parameters as they were at the checkpoint (gains changed at run time, static bodies
        moved), in the model and in its description (a later recompile keeps them)."""
        saved: mujoco.MjModel = extras["model"]
        # every parameter array of the saved model over the rebuilt one's (same sizes: same_structure said so),
        # then the option, visual and statistic structs field by field; the sizes and names stay the rebuilt's
        for name in dir(saved):
            if name.startswith("_"):
                continue
            value = getattr(saved, name, None)
            if isinstance(value, np.ndarray):
                live = getattr(self.model, name)
                if isinstance(live, np.ndarray) and live.shape == value.shape and live.flags.writeable:
                    live[...] = value
        for struct in ("opt", "vis", "stat"):
            src, dst = getattr(saved, struct), getattr(self.model, struct)
            for field_name in dir(src):
                if field_name.startswith("_"):
                    continue
                try:
                    setattr(dst, field_name, getattr(src, field_name))
                except (AttributeError, TypeError):
                    pass  # read-only or a nested struct
        # MjData whole: the state, the warm start and every derived quantity, so the next step is the one the
        # saved run would have taken (bit for bit)
        data = pickle.loads(extras["data"])
        mujoco.mj_copyData(self.data, self.model, data)
        self._world._overlap_steps = int(extras["overlap_steps"])
        self._world._deep = bool(extras["deep"])
        self._queries.kinematics_stale = bool(extras["kinematics_stale"])
        self._world._actuator_gains = dict(extras["actuator_gains"])
        # the gains written into the model at run time go into the spec too: the next recompile (a spawn) builds
        # the model from the spec, and would otherwise put the spawn-time gains back
        n_g, n_b = self.model.actuator_gainprm.shape[1], self.model.actuator_biasprm.shape[1]
        for aid in range(self.model.nu):
            act = self.spec.actuator(mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, aid))
            if act is not None:
                gain, bias = np.array(act.gainprm), np.array(act.biasprm)
                gain[:n_g], bias[:n_b] = self.model.actuator_gainprm[aid], self.model.actuator_biasprm[aid]
                act.gainprm, act.biasprm = gain, bias

    def same_structure(self, extras: dict[str, Any]) -> bool:
        """Whether the model in ``extras`` (:meth:`checkpoint_extras`) has this model's sizes and names:
        the same world, its parameters aside (so its data can be copied in)."""
        other = extras.get("model")
        if not isinstance(other, mujoco.MjModel):
            return False
        sizes = [n for n in dir(other) if n.startswith("n") and isinstance(getattr(other, n, None), int)]
        return all(getattr(other, n) == getattr(self.model, n) for n in sizes) and bytes(other.names) == bytes(
            self.model.names
        )

    def recover_divergence(self) -> list[str] | None:
        """Find a diverged state (NaN, inf or runaway velocity) and repair it.

        Returns None when the state is sound (the usual case, ~0.6 µs); else the names of the
        entities that diverged (``["<world>"]`` when none can be blamed), after putting each back
        at its spawn pose, at rest, and zeroing every non-finite value.
        """
        d = self.data
        cache = self._state_views
        if cache[0] is not d:  # a recompile made a new MjData; `d.qpos` builds a new array object per access
            cache = self._state_views = (d, d.qpos, d.qvel)
        _, qpos, qvel = cache
        # fast path: a NaN/inf makes these dot products non-finite (NaN < x is False),
        # a |qvel| >= 1e4 makes the first >= 1e8
        if qvel.dot(qvel) < 1e8 and math.isfinite(qpos.dot(qpos)):
            return None
        if np.all(np.isfinite(d.qpos)) and np.all(np.isfinite(d.qvel)) and np.all(np.abs(d.qvel) < 1e4):
            return None
        # repair: non-finite values zeroed, each diverged free-floating entity back at its spawn pose at rest,
        # the accelerations and MuJoCo's warm start cleared (they would carry the blow-up into the next step)
        names = self.diverged_entities() or ["<world>"]
        for name in names:
            e = self.entities.get(name)
            if e is None:
                continue
            d.qpos[~np.isfinite(d.qpos)] = 0.0
            d.qvel[~np.isfinite(d.qvel)] = 0.0
            if e.built.free_joint:
                self.set_entity_state(name, self._spawn_root_pose(e))
        d.qacc[:] = 0.0
        d.qacc_warmstart[:] = 0.0
        d.qvel[~np.isfinite(d.qvel)] = 0.0
        mujoco.mj_forward(self.model, d)
        return names

    def diverged_entities(self) -> list[str]:
        """Entities whose state holds NaN/inf or absurd velocities (|qvel| > 1e4)."""
        nq = {int(mujoco.mjtJoint.mjJNT_FREE): (7, 6), int(mujoco.mjtJoint.mjJNT_BALL): (4, 3)}
        bad: list[str] = []
        for e in self.entities.values():
            names = [mj for jn in e.built.joints.values() for mj in jn]
            if e.built.free_joint:
                names.append(e.built.free_joint)
            for mj in names:
                jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj)
                if jid < 0:
                    continue
                a, v = self.model.jnt_qposadr[jid], self.model.jnt_dofadr[jid]
                na, nv = nq.get(int(self.model.jnt_type[jid]), (1, 1))
                qvel = np.abs(self.data.qvel[v : v + nv])
                # written so that NaN fails the test (NaN <= x is False)
                if not (np.all(np.isfinite(self.data.qpos[a : a + na])) and np.all(qvel <= 1e4)):
                    bad.append(e.name)
                    break
        return sorted(set(bad))

    def set_entity_state(
        self,
        entity: str,
        pose: Pose,
        linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
        angular: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        """Teleport an entity's free root and set its twist (world frame)."""
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        vals = (*pose.position, *pose.orientation, *linear, *angular)
        if not all(math.isfinite(v) for v in vals):
            raise WorldError(ErrorKind.INVALID_POSE, f"state for '{entity}' is not finite")
        far = pose_out_of_range(pose, "pose.position")
        if far is not None:
            raise WorldError(ErrorKind.INVALID_POSE, f"state for '{entity}': {far}")
        qn = math.sqrt(sum(v * v for v in pose.orientation))
        if qn < 1e-9:
            raise WorldError(ErrorKind.INVALID_POSE, "orientation is a zero quaternion")
        if e.built.free_joint is None:
            # a static or welded entity has no degrees of freedom to set: its root body is moved in the model
            # itself (body_pos/body_quat), and it cannot move, so a twist is refused
            if any(linear) or any(angular):
                raise WorldError(ErrorKind.INCORRECT_STATE, f"entity '{entity}' is static; it cannot have a twist")
            bid = self._queries.body_id(entity)
            self.model.body_pos[bid] = pose.position
            self.model.body_quat[bid] = [v / qn for v in pose.orientation]
            self._world._forward()
            return
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, e.built.free_joint)
        a, v = self.model.jnt_qposadr[jid], self.model.jnt_dofadr[jid]
        # a free joint's qpos is position then a unit quaternion (wxyz), its qvel linear velocity in the world
        # frame then angular velocity in the body frame
        self.data.qpos[a : a + 3] = pose.position
        w, x, y, z = pose.orientation
        q = (w / qn, x / qn, y / qn, z / qn)
        self.data.qpos[a + 3 : a + 7] = q
        self.data.qvel[v : v + 3] = linear
        # free joint angular velocity is in the body frame
        self.data.qvel[v + 3 : v + 6] = quat_rotate(quat_conj(q), angular)
        self._world._watch_overlaps()
        self._world._forward()

    def joint_address(self, entity: str, mj_joint: str) -> tuple[int, int]:
        """(qposadr, dofadr) of a MuJoCo joint of an entity."""
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, scoped(entity, mj_joint))
        if jid < 0:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no joint '{mj_joint}'")
        return int(self.model.jnt_qposadr[jid]), int(self.model.jnt_dofadr[jid])

    def set_joint_state(
        self, entity: str, joint: str, position: float | None = None, velocity: float | None = None
    ) -> None:
        """Set the position and/or velocity of a 1-dof (hinge or slide) joint of an entity, by its
        description name; the way to move a kinematic joint, which no force moves.

        Used for a ros2_control ``initial_value`` and for kinematic joints: the value is written into the
        state and the kinematics recomputed at once (``mj_forward``), so a pose read, a sensor or a contact
        check before the next step already sees it. Units are the joint's (rad
        or m, per second for the velocity); a value that is not finite is refused before anything changes.

        Raises:
            WorldError: no such entity or joint (NOT_FOUND), a value that is not finite (INVALID_POSE), or a
                joint with more than one degree of freedom (INCORRECT_STATE).
        """
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        mj = e.built.joints.get(joint)
        if not mj:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no movable joint '{joint}'")
        if any(v is not None and not math.isfinite(v) for v in (position, velocity)):
            raise WorldError(ErrorKind.INVALID_POSE, f"state for joint '{joint}' of '{entity}' is not finite")
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj[0])
        if int(self.model.jnt_type[jid]) not in ONE_DOF_JOINTS:
            raise WorldError(ErrorKind.INCORRECT_STATE, f"joint '{joint}' of '{entity}' is not a 1-dof joint")
        if position is not None:
            self.data.qpos[self.model.jnt_qposadr[jid]] = position
        if velocity is not None:
            self.data.qvel[self.model.jnt_dofadr[jid]] = velocity
        self._world._forward()
        self._queries.kinematics_stale = False

    def actuator_id(self, name: str) -> int:
        """MuJoCo id of an actuator by its name (-1 when absent)."""
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, name)

    def reset_time(self) -> None:
        """Set sim time to zero (the state is kept)."""
        self.data.time = 0.0

    def reset_state(self) -> None:
        """Put every entity back where it was spawned, at rest."""
        mujoco.mj_resetData(self.model, self.data)
        for e in self.entities.values():
            if e.built.free_joint:
                self.set_entity_state(e.name, self._spawn_root_pose(e))
        self._world._watch_overlaps()
        self._world._forward()

    def _spawn_root_pose(self, e: Entity) -> Pose:
        """Where the entity's root link was placed when it was added: its model's world pose times the
        link's pose in the model (SDF gives one; URDF's root is at the model frame)."""
        root = e.model.root_link
        link = e.model.link(root)
        return e.X_WM * (link.pose or Pose())
