"""The simulated world: a MuJoCo model and data built from description objects.

``PhysicsWorld`` is not thread-safe by itself; :class:`gazelle.sim.Simulation` owns one and serialises
every access through its command queue. It owns two parts, and hands their public methods on to them (one line
each, at the end of the class), so a caller asks the world:

* ``_queries.py`` (:class:`WorldQueries`, ``world.queries``): what it answers without changing anything: poses,
  rays, IMU, the wrench through a joint, contacts;
* ``_state.py`` (:class:`WorldState`, ``world.state``): what writes the state outside the steps: set-state,
  resets, the repair of a diverged state, checkpoints;
* here: building (spawn in two steps, remove, actuators, contact tweaks) and stepping (blocks of steps,
  servo plans, deep overlaps). What it says of a compiled entity is in ``_reports.py``, its lights and
  background in ``_lights.py``.

The entities, the errors and the rules of a name and a pose are in ``_entities.py``.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Container, Sequence
from typing import Any

import mujoco
import numpy as np

from ..description import Model, Pose, World
from ._bodies import add_model, add_visuals
from ._builder import (
    JOINT_ARMATURE,
    SEP,
    SHARED_MESH,
    friction_priority,
    scoped,
)
from ._contact_pairs import POINT_HALF_LENGTH, PROXY_SUFFIX, ContactProxy, sync_contact_pairs
from ._entities import (
    Entity,
    EntityState,
    ErrorKind,
    PhysicsOverload,
    StagedRequest,
    WorldError,
    build_failed,
    has_camera,
)
from ._entities import checked_placement as _checked_placement
from ._entities import no_joint_message as _no_joint_message
from ._handles import ActuatorGroup, ActuatorHandle, ActuatorKind, BodyHandle, JointGroup, JointHandle
from ._lights import add_light, background_of
from ._queries import ONE_DOF_JOINTS, ContactPoint, WorldQueries
from ._render import OffscreenRenderer
from ._reports import report_decomposed, report_unsimulated
from ._servo_plan import ServoPlan, run_plans
from ._state import WorldState

_log = logging.getLogger("gazelle.physics")
DEEP_PENETRATION_M = 0.01
"""A contact deeper than this is a start-up overlap (or a teleport), not a resting contact (~0.3 mm)."""
MAX_CORRECTING_VEL = 0.5
"""m/s: the fastest a body deep in penetration is pushed out (ODE's ``max_correcting_vel`` idea); it then
rises at most v²/2g ≈ 1.3 cm above its resting height."""
OVERLAP_CHECK_EVERY = 16
"""Steps between two overlap checks while nothing is deep in (a new overlap waits at most 16 ms)."""
OVERLAP_WATCH_SEC = 5.0
"""How long after a body is placed deep overlaps are watched for (1 m of overlap clears in 2 s)."""
MAX_CORRECTING_SPIN = 2.0
"""rad/s: the fastest such a body may spin while it is pushed out (uneven overlaps flipped it over)."""

_ACTUATOR_SUFFIX = {ActuatorKind.POSITION: "pos", ActuatorKind.VELOCITY: "vel", ActuatorKind.EFFORT: "eff"}
MAX_ARENA_BYTES = 1 << 30
"""The most MuJoCo arena (contacts, constraints, solver scratch) the world may grow to: 1 GiB."""


class PhysicsWorld:
    """MuJoCo model + data, with spawn and delete while running; its queries and state writes are its parts'
    (:attr:`queries`, :attr:`state`)."""

    def __init__(self, world: World, *, timestep_sec: float | None = None, visual_geoms: bool = False):
        """
        Args:
            world: the world description (its models are added by the runtime).
            timestep_sec: the physics step; default the world's ``max_step_size``.
            visual_geoms: put every entity's visuals in the MuJoCo model too (non-colliding, massless),
                so an offscreen camera renders what users see. Off unless something renders: the Panda's
                DAE visuals cost 0.85 s at spawn and ~20 % more time per step.
        """
        self.visual_geoms = visual_geoms
        self.description = world
        self.spec = mujoco.MjSpec()
        self.spec.modelname = world.name or "world"
        opt = self.spec.option
        opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        opt.timestep = timestep_sec or world.physics.max_step_size_sec
        opt.gravity = np.array(world.gravity, dtype=np.float64)
        opt.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        # a diverging state is found, reported and repaired per entity (recover_divergence),
        # never silently reset for the whole world as MuJoCo would
        opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_AUTORESET)
        self.spec.compiler.degree = False
        for light in world.lights:
            add_light(self.spec, light)
        self.background = background_of(world)
        """The cameras' background, 8-bit RGB."""
        self.entities: dict[str, Entity] = {}
        self.generation = 0
        """Bumped at every recompile: indices cached against an older generation are stale."""
        self._before_compile: list[Callable[[], None]] = []
        self.queries = WorldQueries(self)
        """What the world answers without changing it (poses, rays, IMU, wrenches, contacts)."""
        self.state = WorldState(self, self.queries)
        """What writes the world's state outside its steps (set-state, resets, divergence, checkpoints)."""
        self._actuator_gains: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        """Actuator name -> its gain and bias parameters as added (see :meth:`set_actuator_enabled`)."""
        self._overlap_steps = 0
        """Steps left in which deep overlaps are limited (see :meth:`_limit_correcting_velocity`)."""
        self._deep = False
        """Whether the last check found a deep overlap (then every step is checked)."""
        self._reported: dict[tuple[str, tuple[str, ...]], int] = {}
        """(model source, unsimulated parameters) -> how many entities had them (reported at the first)."""
        self._held: tuple[np.ndarray, np.ndarray] | None | bool = False
        """(qpos addresses, dof addresses) of the hinge/slide dofs above kinematic links; False = not indexed yet."""
        self._servo_plans: list[ServoPlan] = []
        """Planned servo cycles the steps run (see :meth:`add_servo_plan`)."""
        self._contact_proxies: dict[str, ContactProxy] = {}
        """Proxy geom -> the collision with anisotropic friction it stands for on planes (see ``_contact_pairs``)."""
        self.model: mujoco.MjModel = self.spec.compile()
        self._timestep = float(self.model.opt.timestep)
        self.data = mujoco.MjData(self.model)

    # ------------------------------------------------------------------ building
    def _forward(self) -> None:
        """``mj_forward``, growing the arena if the contacts need more memory (see :meth:`_guarded`)."""
        self._guarded(mujoco.mj_forward)

    def _guarded(self, fn: Callable[[mujoco.MjModel, mujoco.MjData], None]) -> None:
        """Run a MuJoCo pipeline call; when its arena (contacts, constraints) runs out, grow it and retry.

        Overlapping bodies make contacts by the thousand (8 clients spawning boxes at one spot ran
        MuJoCo's arena out and killed the simulation thread with ``mj_stackAlloc: out of memory``).
        The arena doubles, keeping the state, up to :data:`MAX_ARENA_BYTES`; past that,
        :class:`PhysicsOverload` says so, and the simulation pauses instead of dying.
        """
        try:
            fn(self.model, self.data)
            return
        except mujoco.FatalError as err:
            if "memory" not in str(err).lower() and "stack" not in str(err).lower():
                raise
            self._grow_arena(fn, str(err).strip().splitlines()[0])

    def _grow_arena(self, fn: Callable[[mujoco.MjModel, mujoco.MjData], None], reason: str) -> None:
        """After ``fn`` ran MuJoCo's arena out: grow it (see :meth:`_guarded`) and run ``fn`` again."""
        while True:
            # the interrupted pipeline left its stack frames and a partial arena in mjData: release them,
            # or copying the data (the recompile) is a fatal MuJoCo error that ends the process
            d = self.data
            d.pstack, d.pbase, d.parena, d.ncon = 0, 0, 0, 0
            current = int(self.model.narena)
            if current >= MAX_ARENA_BYTES:
                raise PhysicsOverload(
                    f"the contacts and constraints need more than {MAX_ARENA_BYTES >> 20} MiB of MuJoCo arena "
                    f"({reason}); overlapping bodies? delete some, or reset"
                )
            self.spec.memory = min(MAX_ARENA_BYTES, max(2 * current, 64 << 20))
            self._recompile()
            _log.warning(f"MuJoCo's arena ran out ({reason}): grown to {self.spec.memory >> 20} MiB")
            try:
                fn(self.model, self.data)
                return
            except mujoco.FatalError as err:
                reason = str(err).strip().splitlines()[0]

    def _recompile(self) -> None:
        sync_contact_pairs(self.spec, self._contact_proxies)  # the anisotropic wheels' pairs with today's planes
        self.model, self.data = self.spec.recompile(self.model, self.data)
        self.generation += 1
        self._held = False  # re-indexed at the next step, once ``entities`` matches the model

    def stage(self, model: Model, *, name: str, X_WM: Pose, namespace: str = "", spawned: bool = True) -> Entity:
        """Add a model's bodies to the world's spec, not yet to the running model.

        The caller (the runtime) then lets the entity's systems add actuators and set joint
        properties (:meth:`add_actuator`, :meth:`set_joint_armature`, ...), and finally
        :meth:`commit` s it, or :meth:`discard` s it. Until then the running model is unchanged.

        Raises:
            WorldError: a taken or invalid name, a bad pose (nothing was added), or the
                description cannot be built (``BUILD_FAILED``; what was added is removed again).
        """
        return self._stage(model, name, X_WM, namespace, spawned, self.entities)

    def _stage(
        self, model: Model, name: str, X_WM: Pose, namespace: str, spawned: bool, taken: Container[str]
    ) -> Entity:
        """Add ``model``'s bodies, joints and geoms to the spec under ``name`` at ``X_WM`` (checked: a finite pose,
        a free name) without compiling. The first camera to come into the world turns on visual geoms for every
        entity, so cameras see what users see; a model that fails to build leaves nothing of itself in the spec."""
        X_WM = _checked_placement(name, X_WM, taken)
        if has_camera(model) and not self.visual_geoms:
            # a camera comes into the world: from now on every entity's visuals are in the model, so it
            # sees the world as users do (its textures, not the collision shapes in a flat colour)
            self.visual_geoms = True
            for other in self.entities.values():
                add_visuals(self.spec, other.model, other.built)
        try:
            built = add_model(self.spec, model, name, X_WM, visuals=self.visual_geoms)
        except Exception as err:
            self._remove_elements(name)
            raise build_failed(name, err) from None
        self._contact_proxies.update((p.proxy, p) for p in built.contact_proxies)
        return Entity(name, model, namespace, X_WM, built, spawned)

    def discard(self, entity: Entity) -> None:
        """Take a staged entity's elements out of the spec again (the running model never had them)."""
        self._remove_elements(entity.name)

    def commit(self, staged: list[Entity]) -> None:
        """Recompile with the staged entities, keeping every existing entity's state.

        Raises:
            WorldError: (``BUILD_FAILED``) MuJoCo refused the model: the staged entities are
                discarded and the world is as it was. (``OVERLOAD``) the new contacts need more
                memory than the world may have: they are removed again.
        """
        if not staged:
            return
        try:
            self._recompile()
        except Exception as err:
            # the recompile failed, so model/data are the old ones; removing what was staged
            # makes the spec match them again
            for e in staged:
                self._remove_elements(e.name)
            what = staged[0].name if len(staged) == 1 else "the batch"
            raise build_failed(what, err) from None
        for e in staged:
            e.generation_added = self.generation
            self.entities[e.name] = e
            report_unsimulated(e, self._reported)
            report_decomposed(e, self._reported)
        self._watch_overlaps()
        try:
            self._forward()
        except PhysicsOverload:
            for e in staged:
                self.remove_entity(e.name)  # the world as it was; the reply says why
            raise

    def add_entity(self, model: Model, *, name: str, X_WM: Pose, namespace: str = "", spawned: bool = True) -> Entity:
        """Add a model as a new entity (no systems) while keeping every other entity's state.

        Raises:
            WorldError: duplicate or invalid name, NaN pose, or the model cannot be built;
                the world is then unchanged.
        """
        entity = self.stage(model, name=name, X_WM=X_WM, namespace=namespace, spawned=spawned)
        self.commit([entity])
        return entity

    def _remove_elements(self, name: str) -> None:
        """Delete every spec element of entity ``name`` (by its name prefix): actuators, equalities, contact
        exclusions, bodies, its own meshes, materials and textures; a mesh shared by content goes when no geom
        uses it any more."""
        prefix = name + SEP
        for act in list(self.spec.actuators):
            if act.name.startswith(prefix):
                self.spec.delete(act)
        for eq in list(self.spec.equalities):
            if eq.name.startswith(prefix):
                self.spec.delete(eq)
        for ex in list(self.spec.excludes):
            if ex.name.startswith(prefix):
                self.spec.delete(ex)
        for body in list(self.spec.worldbody.bodies):
            if body.name.startswith(prefix):
                self.spec.delete(body)
        for mesh in list(self.spec.meshes):
            if mesh.name.startswith(prefix) and not mesh.name.startswith(SHARED_MESH):
                self.spec.delete(mesh)
        # a mesh shared by content goes with the last geom that used it (see the builder's _shared_mesh)
        used = {g.meshname for g in self.spec.geoms if g.meshname}
        for mesh in list(self.spec.meshes):
            if mesh.name.startswith(SHARED_MESH) and mesh.name not in used:
                self.spec.delete(mesh)
        for material in list(self.spec.materials):  # a visual mesh's own texture (see the builder)
            if material.name.startswith(prefix):
                self.spec.delete(material)
        for texture in list(self.spec.textures):
            if texture.name.startswith(prefix):
                self.spec.delete(texture)

    def remove_entity(self, name: str) -> Entity:
        """Delete an entity; every other entity keeps its state.

        Raises:
            WorldError: no such entity.
        """
        entity = self.entities.get(name)
        if entity is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{name}' does not exist")
        self._remove_elements(name)
        self._recompile()
        del self.entities[name]
        self._servo_plans = [p for p in self._servo_plans if p.entity != name]
        self._forward()
        return entity

    def add_actuator(
        self,
        entity: Entity,
        joint: str,
        kind: ActuatorKind,
        *,
        kp: float = 0.0,
        kv: float = 0.0,
        force_limit: tuple[float, float] | None = None,
    ) -> ActuatorHandle:
        """Add an actuator on a 1-dof joint of a staged ``entity`` (between :meth:`stage` and :meth:`commit`).

        ``POSITION``: force = kp·(command − q) − kv·q̇; ``VELOCITY``: force = kv·(command − q̇);
        ``EFFORT``: force = command. MuJoCo integrates the kv terms implicitly (``implicitfast``), so a
        stiff servo stays stable at any gain. ``force_limit`` (lo, hi) clamps the force.

        Raises:
            WorldError: (``NOT_FOUND``) the entity has no such joint.
        """
        target = scoped(entity.name, joint)
        if self.spec.joint(target) is None:
            raise WorldError(ErrorKind.NOT_FOUND, _no_joint_message(entity, joint))
        name = scoped(entity.name, f"{joint}#{_ACTUATOR_SUFFIX[kind]}")
        act = self.spec.add_actuator(name=name, target=target, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        if kind is ActuatorKind.POSITION:
            act.set_to_position(kp=kp, kv=kv)
        elif kind is ActuatorKind.VELOCITY:
            act.set_to_velocity(kv=kv)
        else:
            act.set_to_motor()
        if force_limit is not None and (math.isfinite(force_limit[0]) or math.isfinite(force_limit[1])):
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            act.forcerange = np.array([max(force_limit[0], -1e30), min(force_limit[1], 1e30)])
        return ActuatorHandle(JointHandle(self, entity.name, joint), kind, name)

    def joint_group(self, entity: str, joints: tuple[str, ...]) -> JointGroup:
        """A handle reading several 1-dof joints of an entity at once (see :class:`JointGroup`)."""
        return JointGroup(self, entity, joints)

    def actuator_group(self, actuators: tuple[ActuatorHandle, ...]) -> ActuatorGroup:
        """A handle setting several actuators at once (see :class:`ActuatorGroup`)."""
        return ActuatorGroup(self, actuators)

    def set_actuator_gains(self, handle: ActuatorHandle, kp: float, kv: float) -> None:
        """Change a position (``kp``, ``kv``) or velocity (``kv``) actuator's gains, e.g. once the
        joint's inertia is known; kept in the model description, and applied when the actuator is on."""
        act = self.spec.actuator(handle.name)
        if act is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"no actuator '{handle.name}'")
        gain, bias = np.array(act.gainprm), np.array(act.biasprm)
        saved = self._actuator_gains.get(handle.name)
        if saved is not None:
            gain, bias = saved[0].copy(), saved[1].copy()
        if handle.kind is ActuatorKind.POSITION:
            gain[0], bias[1], bias[2] = kp, -kp, -kv
        elif handle.kind is ActuatorKind.VELOCITY:
            gain[0], bias[2] = kv, -kv
        else:
            return
        enabled = saved is None or bool(np.any(np.array(act.gainprm)))
        self._actuator_gains[handle.name] = (gain, bias)
        self.set_actuator_enabled(handle, enabled)

    def set_actuator_enabled(self, handle: ActuatorHandle, enabled: bool) -> None:
        """Switch an actuator on (its gains as added) or off (no force at all), as ros2_control's
        command mode switch does between a joint's position, velocity and effort interfaces.

        Kept in the model description too, so a recompile (a spawn elsewhere) keeps it."""
        act = self.spec.actuator(handle.name)
        if act is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"no actuator '{handle.name}'")
        saved = self._actuator_gains.get(handle.name)
        if saved is None:
            saved = self._actuator_gains[handle.name] = (np.array(act.gainprm), np.array(act.biasprm))
        gain, bias = (saved[0], saved[1]) if enabled else (np.zeros_like(saved[0]), np.zeros_like(saved[1]))
        act.gainprm, act.biasprm = gain.copy(), bias.copy()
        aid = self.actuator_id(handle.name)
        if aid >= 0:
            n_g, n_b = self.model.actuator_gainprm.shape[1], self.model.actuator_biasprm.shape[1]
            self.model.actuator_gainprm[aid] = gain[:n_g]
            self.model.actuator_biasprm[aid] = bias[:n_b]

    def joint(self, entity: str, joint: str) -> JointHandle:
        """A handle on a 1-dof joint of an entity (by its description name; MuJoCo joint ``joint``).

        Raises:
            WorldError: (``NOT_FOUND``) the entity (staged or in the world) has no such joint.
        """
        if self.spec.joint(scoped(entity, joint)) is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no joint '{joint}'")
        return JointHandle(self, entity, joint)

    def body(self, entity: str, link: str | None = None) -> BodyHandle:
        """A handle on a link of an entity (None: its root link, the model frame)."""
        return BodyHandle(self, entity, link)

    def make_wheel_contacts_pointlike(self, entity: Entity, link: str) -> int:
        """Turn the cylinder collisions of a drive wheel into ellipsoids of the same radius.

        A cylinder lying on the ground touches it at both rim edges, so a robot turning
        in place scrubs its wheels sideways: we measured the seed robot turning 1.5 %
        slower than (v_r - v_l)/separation. An ellipsoid with semi-axes (r, r, width/2)
        rolls exactly like the cylinder but touches at one point, the centre of a real
        tyre's contact patch. The capsule standing in for a wheel with anisotropic friction on planes
        (``_contact_pairs``) becomes a point at its centre too. Call from ``configure`` (before the
        recompile). Returns how many geoms were changed.
        """
        body = self.spec.body(scoped(entity.name, link))
        if body is None:
            return 0
        changed = 0
        for geom in body.geoms:
            if geom.type == mujoco.mjtGeom.mjGEOM_CAPSULE and geom.name.endswith(PROXY_SUFFIX):
                geom.size = [float(geom.size[0]), POINT_HALF_LENGTH, 0.0]
            elif geom.type == mujoco.mjtGeom.mjGEOM_CYLINDER:
                r, half = float(geom.size[0]), float(geom.size[1])
                geom.type = mujoco.mjtGeom.mjGEOM_ELLIPSOID
                geom.size = [r, r, half]
                changed += 1
        return changed

    def make_caster_frictionless(self, entity: Entity, link: str) -> int:
        """Make the sphere collisions of ``link`` roll like a ball caster: frictionless contacts
        (``condim`` 1 and ``mu`` 0, with the priority the builder gives a frictionless surface, so the
        other geom's friction is not used: ODE's min rule). Call from ``configure`` (before the
        recompile). Returns how many geoms changed."""
        body = self.spec.body(scoped(entity.name, link))
        if body is None:
            return 0
        changed = 0
        for geom in body.geoms:
            if geom.type == mujoco.mjtGeom.mjGEOM_SPHERE and geom.contype:
                geom.condim = 1
                geom.friction = [0.0, 0.0, 0.0]
                geom.priority = friction_priority(0.0)
                changed += 1
        return changed

    def set_joint_armature(self, entity: Entity, joint: str, armature: float) -> None:
        """Set the armature (reflected rotor inertia, kg·m²) of a 1-dof joint; call from ``configure``."""
        j = self.spec.joint(scoped(entity.name, joint))
        if j is None:
            raise WorldError(ErrorKind.NOT_FOUND, _no_joint_message(entity, joint))
        j.armature = armature

    # ------------------------------------------------------------------ stepping
    @property
    def time(self) -> float:
        """Simulation time, seconds."""
        return float(self.data.time)

    @property
    def armature(self) -> float:
        """The armature every 1-dof joint gets (see the builder)."""
        return JOINT_ARMATURE

    @property
    def timestep(self) -> float:
        """The physics step, seconds (fixed for the world's lifetime)."""
        return self._timestep

    def _held_dofs(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The position and velocity addresses of the kinematic links' one-degree-of-freedom joints, found once per
        compiled model; None when there are none."""
        if self._held is False:
            qadr: list[int] = []
            dadr: list[int] = []
            for e in self.entities.values():
                for mj in e.built.kinematic_joints:
                    jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj)
                    if jid >= 0 and int(self.model.jnt_type[jid]) in ONE_DOF_JOINTS:
                        qadr.append(int(self.model.jnt_qposadr[jid]))
                        dadr.append(int(self.model.jnt_dofadr[jid]))
            self._held = (np.array(qadr), np.array(dadr)) if qadr else None
        return self._held if isinstance(self._held, tuple) else None

    def step(self, n: int = 1) -> int:
        """Take ``n`` physics steps with the actuators' commands held; returns the steps taken.

        The steps run inside MuJoCo (``mj_step(m, d, nstep)``), bit-identical to ``n`` single steps.
        Two things need Python between steps, and only while they apply: kinematic joints (held
        exactly, every step) and the overlap watch after something was placed (every
        :data:`OVERLAP_CHECK_EVERY` steps, every step while something is deep in).

        Live servo plans (:meth:`add_servo_plan`) run their cycles in the same loop, one per step, and
        bound it: fewer than ``n`` steps are taken when a plan has fewer cycles left, or stops after
        a cycle that left its path tolerance.
        """
        plans = [p for p in self._servo_plans if p.remaining > 0] if self._servo_plans else []
        if plans:
            n = min(n, min(p.remaining for p in plans))
        if not self._overlap_steps and self._held_dofs() is None:  # the usual case: one MuJoCo call
            self.queries.kinematics_stale = True
            return self._steps(n, plans)
        taken = 0
        while taken < n:
            if self._held_dofs() is not None:
                k = 1
            elif self._overlap_steps:
                # stop exactly where single steps would have checked (see _step_block)
                k = (
                    1
                    if self._deep
                    else min(n - taken, self._overlap_steps % OVERLAP_CHECK_EVERY or OVERLAP_CHECK_EVERY)
                )
            else:
                k = n - taken
            done = self._step_block(k, plans)
            taken += done
            if done < k:
                break
        return taken

    def add_servo_plan(self, plan: ServoPlan) -> None:
        """Let the steps run ``plan``'s cycles (until it is removed; a plan with no cycles left is skipped)."""
        if plan not in self._servo_plans:
            self._servo_plans.append(plan)

    def remove_servo_plan(self, plan: ServoPlan) -> None:
        """Stop running ``plan`` (unknown plans are ignored)."""
        if plan in self._servo_plans:
            self._servo_plans.remove(plan)

    @staticmethod
    def servo_plans_available() -> bool:
        """Whether the compiled servo loop is there (see :mod:`gazelle.physics._native`)."""
        from . import _native

        return _native.available()

    def _step_block(self, k: int, plans: list[ServoPlan]) -> int:
        """Step ``k`` times (fewer when a servo plan ends the block early) and return how many were taken. With
        kinematic joints, one step at a time, each joint then put where its own velocity takes it (no force moves
        it). After something was placed, deep penetrations are watched for a while and the velocity correcting
        them bounded, so an overlapping spawn is pushed apart, not launched."""
        held = self._held_dofs()
        if held is None:
            k = self._steps(k, plans)
        else:
            # kinematic joints: no force moves them; they keep their own velocity exactly
            qadr, dadr = held
            q0, v0 = self.data.qpos[qadr], self.data.qvel[dadr]
            k = self._steps(1, plans)
            self.data.qvel[dadr] = v0
            self.data.qpos[qadr] = q0 + v0 * self.model.opt.timestep
        # mj_step computes kinematics *before* it integrates, so xpos/xquat/cvel now describe
        # the previous step's state; refresh them lazily, on the first query
        self.queries.kinematics_stale = True
        if self._overlap_steps:  # only for a while after something was placed: costs nothing in steady state
            self._overlap_steps = max(0, self._overlap_steps - k)
            # every step while something is deep in, else every OVERLAP_CHECK_EVERY steps (~2 µs a check)
            if self._deep or self._overlap_steps % OVERLAP_CHECK_EVERY == 0:
                d = self.data
                self._deep = bool(d.ncon) and float(d.contact.dist[: d.ncon].min()) < -DEEP_PENETRATION_M
                if self._deep:
                    self._limit_correcting_velocity()
        return k

    def _steps(self, k: int, plans: list[ServoPlan] | None = None) -> int:
        """``k`` steps in one MuJoCo call (with ``plans``' cycles, which may stop it sooner: the steps
        taken are returned); after an arena growth (see :meth:`_guarded`) only the rest.

        One ``mj_step(nstep=k)`` keeps the whole block in C: Python runs once per block, not per step.
        MuJoCo reports a full arena (more contacts than the model's memory holds: a pile of spawned
        objects) as a fatal error partway through; the steps already taken stand, the arena is grown and
        only the steps left to ``t_end`` are taken, so the block ends at the time it would have. Any other
        fatal error is the caller's (a diverged world, reported with the entity that diverged)."""
        if plans:
            return self._planned_steps(k, plans)
        t0 = self.data.time
        try:
            mujoco.mj_step(self.model, self.data, nstep=k)
            return k
        except mujoco.FatalError as err:
            if "memory" not in str(err).lower() and "stack" not in str(err).lower():
                raise
            reason = str(err).strip().splitlines()[0]
        dt = self._timestep
        t_end = t0 + k * dt

        def rest(m: mujoco.MjModel, d: mujoco.MjData) -> None:
            left = max(0, round((t_end - d.time) / dt))
            if left:
                mujoco.mj_step(m, d, nstep=left)

        self._grow_arena(rest, reason)
        return k

    def _planned_steps(self, k: int, plans: list[ServoPlan]) -> int:
        """``k`` steps running ``plans``' servo cycles in compiled code (see :mod:`._servo_plan`)."""
        taken, error = run_plans(self, plans, k)
        if error is None:
            return taken
        if "memory" not in error.lower() and "stack" not in error.lower():
            raise mujoco.FatalError(error)
        total = [taken]

        def rest(m: mujoco.MjModel, d: mujoco.MjData) -> None:
            """MuJoCo's control callback between the steps of a planned block: the servo plans run the cycles that
            fall due (a cycle that was interrupted runs again with a zero integral step); a plan that must stop
            the block raises, which ends the steps there."""
            # the interrupted cycle runs again: its integral step is zero the second time (no time passed)
            more, again = run_plans(self, plans, k - total[0])
            total[0] += more
            if again is not None:
                raise mujoco.FatalError(again)

        self._grow_arena(rest, error.splitlines()[0])
        return total[0]

    def _watch_overlaps(self) -> None:
        """Something was placed (spawn, set-state, reset): watch for deep overlaps for a while."""
        self._overlap_steps = max(1, int(OVERLAP_WATCH_SEC / max(self.timestep, 1e-6)))
        self._deep = True  # check at the very next step

    def _limit_correcting_velocity(self) -> None:
        """Bodies deep in penetration come out at most :data:`MAX_CORRECTING_VEL` fast.

        MuJoCo pushes penetrating geoms apart with a spring whose force grows with the depth, so a
        robot spawned with its wheels 0.2 m into the ground was launched 29 m up and landed upside
        down. ODE (Gazebo) caps the correcting velocity (``max_correcting_vel``); here the free root
        of a body in a contact deeper than :data:`DEEP_PENETRATION_M` may not move apart along the
        contact normal faster than the cap, nor spin faster than :data:`MAX_CORRECTING_SPIN`.
        """
        m, d = self.model, self.data
        free = int(mujoco.mjtJoint.mjJNT_FREE)
        for i in range(d.ncon):
            c = d.contact[i]
            if c.dist >= -DEEP_PENETRATION_M:
                continue
            normal = c.frame[:3]
            for geom, sign in ((c.geom1, -1.0), (c.geom2, 1.0)):
                root = int(m.body_rootid[m.geom_bodyid[geom]])
                jnt = int(m.body_jntadr[root])
                if root == 0 or jnt < 0 or int(m.jnt_type[jnt]) != free:
                    continue
                dof = int(m.jnt_dofadr[jnt])
                v = d.qvel[dof : dof + 3]
                apart = sign * float(normal @ v)
                if apart > MAX_CORRECTING_VEL:
                    v -= sign * (apart - MAX_CORRECTING_VEL) * normal
                w = d.qvel[dof + 3 : dof + 6]
                spin = float(np.linalg.norm(w))
                if spin > MAX_CORRECTING_SPIN:
                    w *= MAX_CORRECTING_SPIN / spin

    def offscreen_renderer(self, width: int, height: int) -> OffscreenRenderer:
        """A renderer of this world's images (create and use it on the simulation thread)."""
        return OffscreenRenderer(self, width, height)

    def stage_many(self, items: list[StagedRequest]) -> list[Entity | WorldError]:
        """:meth:`stage` several models; each that fails its own checks gets its error in its slot."""
        out: list[Entity | WorldError] = []
        taken = set(self.entities)
        for it in items:
            try:
                entity = self._stage(it.model, it.name, it.X_WM, it.namespace, it.spawned, taken)
            except WorldError as err:
                out.append(err)
                continue
            taken.add(it.name)
            out.append(entity)
        return out

    # ------------------------------------------------------------------ queries (the WorldQueries part's)
    def refresh_kinematics(self) -> None:
        """See :meth:`WorldQueries.refresh_kinematics`."""
        self.queries.refresh_kinematics()

    def joint_wrench(self, body_id: int, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """See :meth:`WorldQueries.joint_wrench`."""
        return self.queries.joint_wrench(body_id, point)

    def collision_geoms(self, entity: str, link: str, collision: str | None = None) -> frozenset[int]:
        """See :meth:`WorldQueries.collision_geoms`."""
        return self.queries.collision_geoms(entity, link, collision)

    def contacts_of(self, geoms: frozenset[int]) -> list[ContactPoint]:
        """See :meth:`WorldQueries.contacts_of`."""
        return self.queries.contacts_of(geoms)

    def body_id(self, entity: str, link: str | None = None) -> int:
        """See :meth:`WorldQueries.body_id`."""
        return self.queries.body_id(entity, link)

    def body_pose(self, body_id: int) -> Pose:
        """See :meth:`WorldQueries.body_pose`."""
        return self.queries.body_pose(body_id)

    def body_poses(self, body_ids: Sequence[int] | np.ndarray) -> np.ndarray:
        """See :meth:`WorldQueries.body_poses`."""
        return self.queries.body_poses(body_ids)

    def link_poses_along(
        self, entity: str, link: str, joints: Sequence[str], positions: Sequence[Sequence[float]]
    ) -> list[Pose]:
        """See :meth:`WorldQueries.link_poses_along`."""
        return self.queries.link_poses_along(entity, link, joints, positions)

    def body_velocity(self, body_id: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """See :meth:`WorldQueries.body_velocity`."""
        return self.queries.body_velocity(body_id)

    def cast_rays(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """See :meth:`WorldQueries.cast_rays`."""
        return self.queries.cast_rays(origin, directions, exclude_body, max_range)

    def cast_rays_from(
        self, body_id: int, offset: Pose, directions: np.ndarray, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """See :meth:`WorldQueries.cast_rays_from`."""
        return self.queries.cast_rays_from(body_id, offset, directions, max_range)

    def imu_reading(self, body_id: int, offset: Pose) -> list[float]:
        """See :meth:`WorldQueries.imu_reading`."""
        return self.queries.imu_reading(body_id, offset)

    def frame_pose(self, frame: str) -> Pose:
        """See :meth:`WorldQueries.frame_pose`."""
        return self.queries.frame_pose(frame)

    def entity_state(self, entity: str, link: str | None = None) -> EntityState:
        """See :meth:`WorldQueries.entity_state`."""
        return self.queries.entity_state(entity, link)

    # ------------------------------------------------------------------ state (the WorldState part's)
    def state_digest(self) -> str:
        """See :meth:`WorldState.state_digest`."""
        return self.state.state_digest()

    def checkpoint_extras(self) -> dict[str, object]:
        """See :meth:`WorldState.checkpoint_extras`."""
        return self.state.checkpoint_extras()

    def restore_checkpoint_extras(self, extras: dict[str, Any]) -> None:
        """See :meth:`WorldState.restore_checkpoint_extras`."""
        self.state.restore_checkpoint_extras(extras)

    def same_structure(self, extras: dict[str, Any]) -> bool:
        """See :meth:`WorldState.same_structure`."""
        return self.state.same_structure(extras)

    def recover_divergence(self) -> list[str] | None:
        """See :meth:`WorldState.recover_divergence`."""
        return self.state.recover_divergence()

    def diverged_entities(self) -> list[str]:
        """See :meth:`WorldState.diverged_entities`."""
        return self.state.diverged_entities()

    def set_entity_state(
        self,
        entity: str,
        pose: Pose,
        linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
        angular: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        """See :meth:`WorldState.set_entity_state`."""
        self.state.set_entity_state(entity, pose, linear, angular)

    def joint_address(self, entity: str, mj_joint: str) -> tuple[int, int]:
        """See :meth:`WorldState.joint_address`."""
        return self.state.joint_address(entity, mj_joint)

    def set_joint_state(
        self, entity: str, joint: str, position: float | None = None, velocity: float | None = None
    ) -> None:
        """See :meth:`WorldState.set_joint_state`."""
        self.state.set_joint_state(entity, joint, position, velocity)

    def actuator_id(self, name: str) -> int:
        """See :meth:`WorldState.actuator_id`."""
        return self.state.actuator_id(name)

    def reset_time(self) -> None:
        """See :meth:`WorldState.reset_time`."""
        self.state.reset_time()

    def reset_state(self) -> None:
        """See :meth:`WorldState.reset_state`."""
        self.state.reset_state()
