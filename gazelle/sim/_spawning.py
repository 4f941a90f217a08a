"""Spawn orchestration: how a model becomes an entity of the running simulation.

A model is *staged* into the physics world (its bodies, joints and actuators added to MuJoCo's spec, not
yet compiled), its plugins are *configured* into systems (a plugin whose parameters are bad refuses here,
and the staged entity is discarded, so a bad spawn leaves the world bit-identical), then the world is
*committed* (one MuJoCo recompile) and the systems attached. Batches (the world file's models,
simulation_interfaces' SpawnEntities) stage and configure each, then commit once: one recompile per batch,
not per model; a batch that does not compile is added one model at a time, so an error names its model.

The stage/configure/commit/undo/retry sequence is written once (:meth:`Spawner._add_batch`): a single spawn is a
batch of one. :class:`Simulation` owns a :class:`Spawner` (``sim.spawner``) and hands its ``spawn``, ``spawn_many``,
``delete`` and ``add_entity_placed`` on to it; everything here runs on the simulation thread (the public methods
hand their work to it with ``call``).
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from ..description import Model, Plugin, Pose, config_reads
from ..physics import (
    Entity,
    ErrorKind,
    StagedRequest,
    WorldError,
    build_failed,
    prepare_meshes,
)
from ..systems import (
    RSP_PLUGIN,
    RobotStatePublisher,
    System,
    SystemContext,
    audit_model,
    create_system,
    plan_sensors,
    plugin_node,
    plugin_node_name,
    robot_state_config,
    unread_parameters,
)
from ..systems.ros2_control import ControllerManager
from ._host import SimulationHost
from ._runtime_types import SpawnRequest

_log = logging.getLogger("gazelle")


def _shutdown_system(system: System) -> None:
    """Shut down a system whose entity never made it into the world (its spawn failed)."""
    try:
        system.shutdown()
    except Exception:
        _log.exception(f"{type(system).__name__}.shutdown raised after a failed spawn")


class Spawner:
    """How models become entities of the running simulation, and how entities go (see the module docstring): a
    part the simulation owns (``sim.spawner``); its thread-safe methods are also :class:`Simulation`'s."""

    def __init__(self, sim: SimulationHost, loaded: Callable[[], bool]):
        """``sim`` is the simulation this part adds to; ``loaded`` says whether a world is loaded (a spawn is
        refused after an unload: see :mod:`._world_swap`)."""
        self._sim = sim
        self._loaded = loaded

    # ------------------------------------------------------------------ plugins
    def _configure_plugins(self, entity: Entity) -> list[System]:
        """Create and configure (while the entity is staged) a system for each supported plugin of
        ``entity``, and the built-in robot_state_publisher for anything with joints or a URDF.

        Raises whatever a plugin's ``configure`` raises, after shutting down the systems made so far.
        """
        sim = self._sim
        made: list[System] = []
        try:
            # unsupported plugins and sensors: named, never dropped silently
            for problem in audit_model(entity.model, sim.world_plugins):
                _log.warning(f"'{entity.name}': {problem.format()}")
            for plugin in entity.model.plugins:
                if plugin.filename == RSP_PLUGIN:
                    continue  # configures the built-in one below
                system = create_system(plugin)
                if system is None or (isinstance(system, ControllerManager) and not entity.model.ros2_control):
                    continue
                logger = logging.getLogger(plugin.name or plugin.filename)
                made.append(system)
                sim._seed_noise(system, entity.name, plugin.name or plugin.filename)
                with sim.bus.declaring(plugin_node_name(plugin, entity.namespace)), config_reads() as reads:
                    system.configure(
                        SystemContext(sim.world, entity, plugin, sim.bus, logger, world_name=sim.world_name)
                    )
                for problem in unread_parameters(plugin, reads):
                    logger.warning(problem)
                self._announce_node(entity, system, plugin)
            if entity.model.ros2_control and not any(isinstance(s, ControllerManager) for s in made):
                # as mujoco_ros2_control and the mock hardware do: <ros2_control> alone runs a manager
                manager = ControllerManager()
                made.append(manager)
                manager.configure(
                    SystemContext(
                        sim.world,
                        entity,
                        None,
                        sim.bus,
                        logging.getLogger("controller_manager"),
                        world_name=sim.world_name,
                    )
                )
            self._configure_sensors(entity, made)
            if sim.robot_state_publisher and (entity.model.joints or entity.model.urdf):
                logger = logging.getLogger(f"{entity.name}.robot_state_publisher")
                config, plugin = robot_state_config(entity, logger)
                if config.enabled:
                    rsp = RobotStatePublisher(config)
                    made.append(rsp)
                    rsp.configure(SystemContext(sim.world, entity, plugin, sim.bus, logger))
        except Exception:
            self._undo_systems(entity.name, made)
            raise
        return made

    def _configure_sensors(self, entity: Entity, made: list[System]) -> None:
        """A system for each sensor of ``entity`` that something runs (its plugin, or a world sensor system),
        each added to ``made`` before it configures (so a failure shuts it down with the others)."""
        sim = self._sim
        for plan in plan_sensors(entity.model, sim.world_plugins)[0]:
            system = plan.make()
            named = plan.plugin.name if plan.plugin is not None else plan.sensor.name
            logger = logging.getLogger(named or plan.sensor.name)
            made.append(system)
            sim._seed_noise(system, entity.name, f"{plan.link}/{plan.sensor.name}/{named}")
            with sim.bus.declaring(plugin_node_name(plan.plugin, entity.namespace)), config_reads() as reads:
                system.configure(
                    SystemContext(
                        sim.world,
                        entity,
                        plan.plugin,
                        sim.bus,
                        logger,
                        sensor=plan.sensor,
                        link=plan.link,
                        world_name=sim.world_name,
                        spherical_coordinates=sim.spherical_coordinates,
                        magnetic_field=sim.magnetic_field,
                    )
                )
            for problem in unread_parameters(plan.plugin, reads):
                logger.warning(problem)
            self._announce_node(entity, system, plan.plugin)

    def _announce_node(self, entity: Entity, system: System, plugin: Plugin | None) -> None:
        """A gazebo_ros plugin is a ROS node of its own (its parameters: its configuration)."""
        node = plugin_node(system, plugin, entity.namespace)
        if node is not None:
            self._sim.bus.add_component(entity.name, node)

    def _undo_systems(self, name: str, systems: list[System]) -> None:
        """Shut down the systems of an entity that never made it into the world, and drop its endpoints."""
        for system in systems:
            _shutdown_system(system)
        self._sim.bus.remove_owner(name)

    # ------------------------------------------------------------------ the one sequence
    def _add_batch(self, requests: list[StagedRequest], *, whole: bool) -> list[Entity | WorldError]:
        """The one way entities come into the world: each model staged and its plugins configured, then all
        committed with one MuJoCo recompile and their systems attached. Returns, per request, its entity or the
        error that refused it.

        A model that fails its own checks or its plugins' configure is left out with its error (its staged
        elements discarded, its systems shut down). A batch that does not compile is undone (each model's staged
        elements and systems) and added again one model at a time, so an error names its model. ``whole`` (the
        world file's models): no model may fail, so any refusal undoes the batch and adds it one at a time, and
        the first model refused raises its error (the ones before it stay, the ones after are never tried). A
        batch of one is not retried (a retry would be the same batch); with ``whole`` it raises its error."""
        world = self._sim.world
        staged = world.stage_many(requests)
        out = list(staged)
        ready: list[tuple[Entity, list[System]]] = []
        for i, entity in enumerate(staged):
            if isinstance(entity, WorldError):
                continue
            try:
                ready.append((entity, self._configure_plugins(entity)))
            except Exception as err:
                world.discard(entity)
                out[i] = build_failed(entity.name, err)
        refused = [r for r in out if isinstance(r, WorldError)]
        if refused and whole:
            self._undo(ready)
            if len(requests) == 1:
                raise refused[0]
            return self._one_at_a_time(requests, staged, whole)
        try:
            world.commit([e for e, _ in ready])
        except WorldError as err:
            self._undo(ready)
            if len(requests) == 1:
                if whole:
                    raise
                return [err]
            if whole and any(e.name in world.entities for e, _ in ready):
                raise  # committed, then refused (an overload): nothing to retry
            return self._one_at_a_time(requests, staged, whole)
        for entity, systems in ready:
            entity.systems.extend(systems)
            for system in systems:
                self._sim.systems.add(entity.name, system)
        return out

    def _undo(self, ready: list[tuple[Entity, list[System]]]) -> None:
        """Take back what a batch that failed staged and configured: each entity not in the world (a commit that
        failed already took its elements out: discarding again finds nothing) discarded, its systems shut down."""
        world = self._sim.world
        for entity, systems in ready:
            if entity.name not in world.entities:
                world.discard(entity)
                self._undo_systems(entity.name, systems)

    def _one_at_a_time(
        self, requests: list[StagedRequest], staged: list[Entity | WorldError], whole: bool
    ) -> list[Entity | WorldError]:
        """A batch that failed, added again one model at a time (each a batch of one); a model the batch's staging
        refused keeps that error (a taken name, a bad pose, a description that does not build) unless ``whole``,
        where every model is tried again and the first refusal raises."""
        out: list[Entity | WorldError] = []
        for request, tried in zip(requests, staged):
            if isinstance(tried, WorldError) and not whole:
                out.append(tried)
                continue
            try:
                out += self._add_batch([request], whole=whole)
            except WorldError as err:
                if whole:
                    raise
                out.append(err)
        return out

    def _require_world(self) -> None:
        """Refuse a spawn while no world is loaded (after an unload: see :mod:`._world_swap`)."""
        if not self._loaded():
            raise WorldError(
                ErrorKind.INCORRECT_STATE, "no world is loaded (it was unloaded): load one before spawning entities"
            )

    # ------------------------------------------------------------------ on the simulation thread
    def add_world_models(self, models: list[Model]) -> None:
        """The world file's models, staged and configured one by one and compiled into MuJoCo once: one
        recompile a model made loading quadratic (gz-sim's 3k_shapes.sdf, 3,000 models: over 5 minutes).
        Should the batch not compile, the models are added one at a time, so the error names its model
        (on the simulation thread: the constructor's, or a load's).

        Raises:
            WorldError: the first model that cannot be added (the ones before it are in the world).
        """
        names = [m.name for m in models]
        if len(models) < 2 or len(set(names)) != len(names):
            for m in models:
                self.add_entity(m, name=m.name, pose=Pose(), namespace="", spawned=False)
            return
        self._add_batch([StagedRequest(m, m.name, m.pose, "", spawned=False) for m in models], whole=True)

    def add_entity(
        self, model: Model, *, name: str, pose: Pose, namespace: str, spawned: bool, X_WM: Pose | None = None
    ) -> Entity:
        """Stage the model, configure its systems, commit (on the simulation thread). ``X_WM``, when given, is
        where its model frame goes (else ``pose`` composed with the file's own)."""
        if spawned:
            self._require_world()
        placed = X_WM if X_WM is not None else pose * model.pose
        (entity,) = self._add_batch([StagedRequest(model, name, placed, namespace, spawned)], whole=True)
        assert isinstance(entity, Entity)  # a batch of one raises its error
        return entity

    # ------------------------------------------------------------------ thread-safe (Simulation's own)
    def add_entity_placed(
        self, model: Model, name: str, X_WM: Pose, namespace: str = "", *, spawned: bool = True
    ) -> Entity:
        """:meth:`Simulation.add_entity_placed`: a model added with its model frame at ``X_WM`` (thread-safe)."""
        prepare_meshes(model)
        return self._sim.call(
            lambda: self.add_entity(model, name=name, pose=Pose(), namespace=namespace, spawned=spawned, X_WM=X_WM)
        )

    def spawn(self, model: Model, *, name: str | None = None, pose: Pose = Pose(), namespace: str = "") -> Entity:
        """:meth:`Simulation.spawn`: a model added at run time (thread-safe)."""
        prepare_meshes(model)  # slow work (convex decompositions) here, in the caller's thread
        return self._sim.call(
            lambda: self.add_entity(model, name=name or model.name, pose=pose, namespace=namespace, spawned=True)
        )

    def delete(self, name: str) -> None:
        """:meth:`Simulation.delete`: an entity and its systems removed (thread-safe)."""
        sim = self._sim

        def do() -> None:
            """On the simulation thread: the entity's systems, then its topics, then its bodies, so no system runs
            on an entity that is gone."""
            if name not in sim.world.entities:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{name}' does not exist")
            sim.systems.remove_owner(name)
            sim.bus.remove_owner(name)
            sim.world.remove_entity(name)
            sim._forget_divergence(name)

        sim.call(do)

    def spawn_many(self, requests: list[SpawnRequest], timeout: float | None = 60.0) -> list[Entity | WorldError]:
        """:meth:`Simulation.spawn_many`: several models, one recompile (thread-safe)."""
        for request in requests:
            prepare_meshes(request.model)
        return self._sim.call(lambda: self._spawn_many(requests), timeout=timeout)

    def _spawn_many(self, requests: list[SpawnRequest]) -> list[Entity | WorldError]:
        """Add several models with one MuJoCo recompile (SpawnEntities): names made unique where renaming is
        allowed, then one batch (:meth:`_add_batch`), so one bad model never takes the others with it. Returns,
        per request, the entity or the error."""
        try:
            self._require_world()
        except WorldError as err:
            return [err] * len(requests)
        taken = set(self._sim.world.entities)
        names: list[str] = []
        for r in requests:
            name = r.name or r.model.name
            if r.allow_renaming and name in taken:
                i = 1
                while f"{name}_{i}" in taken:
                    i += 1
                name = f"{name}_{i}"
            taken.add(name)
            names.append(name)
        batch = [StagedRequest(r.model, name, r.pose * r.model.pose, r.namespace) for r, name in zip(requests, names)]
        return self._add_batch(batch, whole=False)
