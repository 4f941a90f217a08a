"""Spawn orchestration: how a model becomes an entity of the running simulation.

A model is *staged* into the physics world (its bodies, joints and actuators added to MuJoCo's spec, not
yet compiled), its plugins are *configured* into systems (a plugin whose parameters are bad refuses here,
and the staged entity is discarded, so a bad spawn leaves the world bit-identical), then the world is
*committed* (one MuJoCo recompile) and the systems attached. Batches (the world file's models,
simulation_interfaces' SpawnEntities) stage and configure each, then commit once: one recompile per batch,
not per model; a batch that does not compile is added one model at a time, so an error names its model.

:class:`Simulation` takes these methods from :class:`SpawningMixin`; everything here runs on the simulation
thread (the public methods hand their work to it with ``call``).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

from ..description import Model, Plugin, Pose, SphericalCoordinates, Vec3, config_reads
from ..physics import (
    Entity,
    ErrorKind,
    PhysicsWorld,
    StagedRequest,
    WorldError,
    build_failed,
    prepare_meshes,
)
from ..systems import (
    RSP_PLUGIN,
    Bus,
    RobotStatePublisher,
    System,
    SystemContext,
    SystemManager,
    audit_model,
    create_system,
    plan_sensors,
    plugin_node,
    plugin_node_name,
    robot_state_config,
    unread_parameters,
)
from ..systems.ros2_control import ControllerManager
from ._runtime_types import SpawnRequest

T = TypeVar("T")
_log = logging.getLogger("gazelle")


def _shutdown_system(system: System) -> None:
    """Shut down a system whose entity never made it into the world (its spawn failed)."""
    try:
        system.shutdown()
    except Exception:
        _log.exception(f"{type(system).__name__}.shutdown raised after a failed spawn")


class SpawningMixin:
    """The entity half of :class:`~gazelle.sim.Simulation` (see the module docstring)."""

    world: PhysicsWorld
    bus: Bus
    systems: SystemManager
    robot_state_publisher: bool
    world_name: str
    world_plugins: tuple[Plugin, ...]
    spherical_coordinates: SphericalCoordinates | None
    magnetic_field: Vec3
    diverged: dict[str, str]
    _divergence_log: dict[str, tuple[int, float]]

    if TYPE_CHECKING:  # Simulation's, which this half calls
        from ._world_swap import WorldSwap

        worlds: WorldSwap

        def call(self, fn: Callable[[], T], timeout: float | None = 10.0) -> T: ...

        def _seed_noise(self, system: System, entity: str, name: str) -> None: ...

    # ------------------------------------------------------------------ entities
    def _configure_plugins(self, entity: Entity) -> list[System]:
        """Create and configure (while the entity is staged) a system for each supported plugin of
        ``entity``, and the built-in robot_state_publisher for anything with joints or a URDF.

        Raises whatever a plugin's ``configure`` raises, after shutting down the systems made so far.
        """
        made: list[System] = []
        try:
            # unsupported plugins and sensors: named, never dropped silently
            for problem in audit_model(entity.model, self.world_plugins):
                _log.warning(f"'{entity.name}': {problem.format()}")
            for plugin in entity.model.plugins:
                if plugin.filename == RSP_PLUGIN:
                    continue  # configures the built-in one below
                system = create_system(plugin)
                if system is None or (isinstance(system, ControllerManager) and not entity.model.ros2_control):
                    continue
                logger = logging.getLogger(plugin.name or plugin.filename)
                made.append(system)
                self._seed_noise(system, entity.name, plugin.name or plugin.filename)
                with self.bus.declaring(plugin_node_name(plugin, entity.namespace)), config_reads() as reads:
                    system.configure(
                        SystemContext(self.world, entity, plugin, self.bus, logger, world_name=self.world_name)
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
                        self.world,
                        entity,
                        None,
                        self.bus,
                        logging.getLogger("controller_manager"),
                        world_name=self.world_name,
                    )
                )
            for plan in plan_sensors(entity.model, self.world_plugins)[0]:
                system = plan.make()
                named = plan.plugin.name if plan.plugin is not None else plan.sensor.name
                logger = logging.getLogger(named or plan.sensor.name)
                made.append(system)
                self._seed_noise(system, entity.name, f"{plan.link}/{plan.sensor.name}/{named}")
                with self.bus.declaring(plugin_node_name(plan.plugin, entity.namespace)), config_reads() as reads:
                    system.configure(
                        SystemContext(
                            self.world,
                            entity,
                            plan.plugin,
                            self.bus,
                            logger,
                            sensor=plan.sensor,
                            link=plan.link,
                            world_name=self.world_name,
                            spherical_coordinates=self.spherical_coordinates,
                            magnetic_field=self.magnetic_field,
                        )
                    )
                for problem in unread_parameters(plan.plugin, reads):
                    logger.warning(problem)
                self._announce_node(entity, system, plan.plugin)
            if self.robot_state_publisher and (entity.model.joints or entity.model.urdf):
                logger = logging.getLogger(f"{entity.name}.robot_state_publisher")
                config, plugin = robot_state_config(entity, logger)
                if config.enabled:
                    rsp = RobotStatePublisher(config)
                    made.append(rsp)
                    rsp.configure(SystemContext(self.world, entity, plugin, self.bus, logger))
        except Exception:
            self._undo_systems(entity.name, made)
            raise
        return made

    def _announce_node(self, entity: Entity, system: System, plugin: Plugin | None) -> None:
        """A gazebo_ros plugin is a ROS node of its own (its parameters: its configuration)."""
        node = plugin_node(system, plugin, entity.namespace)
        if node is not None:
            self.bus.add_component(entity.name, node)

    def _undo_systems(self, name: str, systems: list[System]) -> None:
        """Shut down the systems of an entity that never made it into the world, and drop its endpoints."""
        for system in systems:
            _shutdown_system(system)
        self.bus.remove_owner(name)

    def _attach(self, entity: Entity, systems: list[System]) -> None:
        entity.systems.extend(systems)
        for s in systems:
            self.systems.add(entity.name, s)

    def _add_world_models(self, models: list[Model]) -> None:
        """The world file's models, staged and configured one by one and compiled into MuJoCo once: one
        recompile a model made loading quadratic (gz-sim's 3k_shapes.sdf, 3,000 models: over 5 minutes).
        Should the batch not compile, the models are added one at a time, so the error names its model."""
        names = [m.name for m in models]
        if len(models) < 2 or len(set(names)) != len(names):
            for m in models:
                self._add_entity(m, name=m.name, pose=Pose(), namespace="", spawned=False)
            return
        staged: list[tuple[Entity, list[System]]] = []
        try:
            for m in models:
                entity = self.world.stage(m, name=m.name, X_WM=m.pose, namespace="", spawned=False)
                try:
                    systems = self._configure_plugins(entity)
                except Exception as err:
                    self.world.discard(entity)
                    raise build_failed(m.name, err) from None
                staged.append((entity, systems))
            self.world.commit([e for e, _ in staged])
        except WorldError:
            for entity, systems in staged:
                if entity.name not in self.world.entities:
                    self.world.discard(entity)
                    self._undo_systems(entity.name, systems)
            if any(e.name in self.world.entities for e, _ in staged):
                raise  # committed, then refused (an overload): nothing to retry
            for m in models:  # one at a time: the error names its model
                self._add_entity(m, name=m.name, pose=Pose(), namespace="", spawned=False)
            return
        for entity, systems in staged:
            self._attach(entity, systems)

    def _add_entity(
        self, model: Model, *, name: str, pose: Pose, namespace: str, spawned: bool, X_WM: Pose | None = None
    ) -> Entity:
        """Stage the model, configure its systems, commit: the one way an entity comes into the world.
        ``X_WM``, when given, is where its model frame goes (else ``pose`` composed with the file's own)."""
        if spawned:
            self._require_world()
        placed = X_WM if X_WM is not None else pose * model.pose
        entity = self.world.stage(model, name=name, X_WM=placed, namespace=namespace, spawned=spawned)
        try:
            systems = self._configure_plugins(entity)
        except Exception as err:
            self.world.discard(entity)
            raise build_failed(name, err) from None
        try:
            self.world.commit([entity])
        except WorldError:
            self._undo_systems(name, systems)
            raise
        self._attach(entity, systems)
        return entity

    def _require_world(self) -> None:
        """Refuse a spawn while no world is loaded (after an unload: see :mod:`._world_swap`)."""
        if self.worlds.current is None:
            raise WorldError(
                ErrorKind.INCORRECT_STATE, "no world is loaded (it was unloaded): load one before spawning entities"
            )

    def add_entity_placed(
        self, model: Model, name: str, X_WM: Pose, namespace: str = "", *, spawned: bool = True
    ) -> Entity:
        """Add a model with its model frame at ``X_WM`` (the file's own pose already composed in), as a
        checkpoint recorded it (thread-safe).

        Args:
            model: the model as loaded.
            name: its entity's name.
            X_WM: the model frame in the world: :meth:`spawn`'s ``pose`` composed with the model's own.
            namespace: its ROS namespace.
            spawned: whether a reset with ``spawned`` removes it (spawned at run time) or keeps it (one of the
                world file's own models).
        """
        prepare_meshes(model)
        return self.call(
            lambda: self._add_entity(model, name=name, pose=Pose(), namespace=namespace, spawned=spawned, X_WM=X_WM)
        )

    def spawn(self, model: Model, *, name: str | None = None, pose: Pose = Pose(), namespace: str = "") -> Entity:
        """Add a model (thread-safe), as gazebo_ros's ``/spawn_entity`` and simulation_interfaces'
        ``SpawnEntity`` do: the model's plugins configured, its ros2_control started, its topics declared,
        all in the simulation thread's next gap between blocks.

        Args:
            model: a loaded robot or model (:func:`gazelle.description.load`).
            name: the entity's name (None: the model's own); it must not be taken.
            pose: where the model frame goes in the world, composed with the file's own ``<pose>`` (an SDF
                model's), as Gazebo places a spawned model: the request's pose times the model's.
            namespace: the ROS namespace of its topics and controller manager (``-robot_namespace``).

        Returns:
            The new entity.

        Raises:
            WorldError: on a duplicate/invalid name, a bad pose or a model that cannot be built; the world is
                then as it was (bit-identical: nothing of the model is left in it).
        """
        prepare_meshes(model)  # slow work (convex decompositions) here, in the caller's thread
        return self.call(
            lambda: self._add_entity(model, name=name or model.name, pose=pose, namespace=namespace, spawned=True)
        )

    def delete(self, name: str) -> None:
        """Remove an entity and its systems (thread-safe).

        Raises:
            WorldError: no such entity.
        """

        def do() -> None:
            """On the simulation thread: the entity's systems, then its topics, then its bodies, so no system runs
            on an entity that is gone."""
            if name not in self.world.entities:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{name}' does not exist")
            self.systems.remove_owner(name)
            self.bus.remove_owner(name)
            self.world.remove_entity(name)
            self.diverged.pop(name, None)
            self._divergence_log.pop(name, None)

        self.call(do)

    # ------------------------------------------------------------------ batch spawning (simulation_interfaces)
    def spawn_many(self, requests: list[SpawnRequest], timeout: float | None = 60.0) -> list[Entity | WorldError]:
        """Add several models in one sim-thread call with one recompile (thread-safe): simulation_interfaces'
        batch spawn, where a MuJoCo model rebuilt once for N models costs what one spawn does (a chessboard's
        32 pieces).

        Args:
            requests: the models with their names, poses and namespaces (:class:`SpawnRequest`).
            timeout: wall seconds to wait for the simulation thread (None: for ever).

        Returns:
            Per request, in order, the new entity or the :class:`WorldError` that refused it: one bad model
            never takes the others with it.
        """
        for request in requests:
            prepare_meshes(request.model)
        return self.call(lambda: self._spawn_many(requests), timeout=timeout)

    def _spawn_many(self, requests: list[SpawnRequest]) -> list[Entity | WorldError]:
        """Add several models with one MuJoCo recompile (SpawnEntities): names made unique where renaming is
        allowed, each staged and its plugins configured, then all committed together. A model whose plugins fail
        to configure is left out alone; if the combined build fails, each is added on its own, so one bad model
        never takes the others with it. Returns, per request, the entity or the error."""
        try:
            self._require_world()
        except WorldError as err:
            return [err] * len(requests)
        taken = set(self.world.entities)
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
        staged = self.world.stage_many(
            [StagedRequest(r.model, name, r.pose * r.model.pose, r.namespace) for r, name in zip(requests, names)]
        )
        out: list[Entity | WorldError] = []
        ready: list[tuple[Entity, list[System]]] = []
        for res, name in zip(staged, names):
            if isinstance(res, WorldError):
                out.append(res)
                continue
            try:
                systems = self._configure_plugins(res)
            except Exception as err:
                self.world.discard(res)
                out.append(build_failed(name, err))
                continue
            ready.append((res, systems))
            out.append(res)
        try:
            self.world.commit([e for e, _ in ready])
        except WorldError:
            # the combined build failed: undo every configure, then add one at a time
            for e, systems in ready:
                self._undo_systems(e.name, systems)
            out = []
            for r, name, res in zip(requests, names, staged):
                if isinstance(res, WorldError):
                    out.append(res)
                    continue
                try:
                    out.append(self._add_entity(r.model, name=name, pose=r.pose, namespace=r.namespace, spawned=True))
                except WorldError as err:
                    out.append(err)
            return out
        for e, systems in ready:
            self._attach(e, systems)
        return out
