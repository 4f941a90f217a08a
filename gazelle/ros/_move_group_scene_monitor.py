"""move_group's planning scene: MoveIt's ``PlanningSceneMonitor`` as move_group runs it
(moveit_ros/planning/planning_scene_monitor/src/planning_scene_monitor.cpp, jazzy: ``startSceneMonitor``,
``startWorldGeometryMonitor``, ``startStateMonitor``), kept in gazelle's planners. It listens on
``/planning_scene`` (diffs and whole scenes), ``/collision_object`` and ``/attached_collision_object``, and on
the simulation's collision geometry (``/gazelle/planning_scene_world``); the capabilities
``get_planning_scene`` and ``apply_planning_scene`` read and change the scene through it."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

import numpy as np
from moveit_msgs.msg import (
    AllowedCollisionEntry,
    AttachedCollisionObject,
    CollisionObject,
    PlanningScene,
    PlanningSceneWorld,
)

from ..planning import ArmPlanner, CollisionMatrix, PlanningError, SceneObject, quoted
from ._move_group_common import LATCHED, MAX_SCENE_OBJECTS, OBJECT_PADDING_PARAMETER, _log, _same_shapes
from ._planning_scene import attached_message, checked_matrix, padded, shapes_of, to_message
from ._planning_scene import matrix as _matrix

if TYPE_CHECKING:
    from rclpy.publisher import Publisher

    from ._move_group_protocols import MoveGroupCore

M = TypeVar("M")


class PlanningSceneMonitor:
    """The planning scene's topics and the changes they and ``apply_planning_scene`` make (each under the
    pool's write lock, which waits for the plans in progress, as MoveIt's scene monitor waits for its readers)."""

    def __init__(self, context: MoveGroupCore) -> None:
        self.context = context
        self.sim_objects: set[str] = set()
        """Ids of the objects that came from the simulation."""
        self.sim_world: PlanningSceneWorld | None = None
        """The simulation's geometry heard before the robot was known (taken when it is)."""
        self.object_padding = self._object_padding()
        self.changed = False
        """Whether the scene changed since it was last published on /monitored_planning_scene."""
        self._published_joints: dict[str, float] = {}
        self._publisher: Publisher | None = None

    def start(self) -> None:
        """Subscribe to the scene topics and the simulation's world (gazelle sim publishes its collision geometry:
        the table, the board, the other robots; this robot itself is left out)."""
        node, cb = self.context.node, self.context.callback_group
        on = self.scene_topic
        node.create_subscription(
            PlanningScene, "planning_scene", on("planning_scene", self.apply_scene), 10, callback_group=cb
        )
        node.create_subscription(
            CollisionObject, "collision_object", on("collision_object", self.apply_world_object), 10, callback_group=cb
        )
        node.create_subscription(
            AttachedCollisionObject,
            "attached_collision_object",
            on("attached_collision_object", self.apply_attached),
            10,
            callback_group=cb,
        )
        node.create_subscription(
            PlanningSceneWorld, "/gazelle/planning_scene_world", self.on_sim_world, LATCHED, callback_group=cb
        )

    def robot_loaded(self) -> None:
        """The robot is known: the simulation's world heard before it goes into the scene, and the scene is
        published from now on."""
        pool = self.context.pool
        if pool is not None and self.sim_world is not None:
            with pool.writing():
                self.take_sim_world(self.sim_world)
        self._start_publishing()

    def _start_publishing(self) -> None:
        """``/monitored_planning_scene`` (moveit_msgs/PlanningScene; RViz's MotionPlanning display and other
        tools follow the scene there), as MoveIt's PlanningSceneMonitor publishes it for move_group
        (planning_scene_monitor.cpp, startPublishingPlanningScene and scenePublishingThread: the whole scene
        once, then the updates at most ``publish_planning_scene_hz``, 4 by default). MoveItConfigsBuilder's
        launch files turn it on (moveit_configs_builder.py, planning_scene_monitor: ``publish_planning_scene``
        True), and so does gazelle unless the parameter says False. Each change of the objects or the
        allowed collisions is published as a whole scene; a move of the robot alone as a robot-state diff.
        Nothing is built while no one subscribes; the changes since are then one whole scene."""
        context = self.context
        if context.parameter("publish_planning_scene", True) is False:
            return
        hz = context.parameter("publish_planning_scene_hz", 4.0)
        hz = float(hz) if isinstance(hz, (int, float)) and not isinstance(hz, bool) and 0 < hz <= 100 else 4.0
        self._publisher = context.node.create_publisher(PlanningScene, "monitored_planning_scene", 100)
        self.changed = True  # the whole scene first
        context.node.create_timer(1.0 / hz, self._publish, callback_group=context.callback_group)

    def _publish(self) -> None:
        """The scene's update since the last one, if any (see :meth:`_start_publishing`)."""
        pool = self.context.pool
        if pool is None or self._publisher is None or not self._publisher.get_subscription_count():
            return  # no one listens: nothing is built (a subscriber's first message is a whole scene)
        joints = self.context.latest_joints
        if self.changed:
            self.changed = False
            with pool.using("query") as planner:
                msg = self.scene_message(planner)
        elif joints and joints != self._published_joints:
            msg = PlanningScene(is_diff=True)
            msg.robot_state.is_diff = True
            msg.robot_state.joint_state.name = list(joints)
            msg.robot_state.joint_state.position = [float(v) for v in joints.values()]
        else:
            return
        self._published_joints = joints
        self._publisher.publish(msg)

    def scene_message(self, planner: ArmPlanner) -> PlanningScene:
        """The whole scene as a PlanningScene (what ``get_planning_scene`` answers with every component): the
        robot's current state with its attached objects, the world's collision objects (the simulation's
        own included) and the allowed collision matrix, from ``planner`` (held by the caller)."""
        scene = PlanningScene(name="gazelle", robot_model_name=planner.semantics.robot_name, is_diff=False)
        scene.robot_state = self.context.robot_state(planner.state(self.context.latest_joints or None))
        objects = planner.objects()
        scene.robot_state.attached_collision_objects = [attached_message(o) for o in objects if o.link]
        scene.world.collision_objects = [to_message(o, planner.root_link) for o in objects if not o.link]
        acm = planner.acm
        scene.allowed_collision_matrix.entry_names = acm.message_names()
        scene.allowed_collision_matrix.entry_values = [AllowedCollisionEntry(enabled=row) for row in acm.rows()]
        scene.allowed_collision_matrix.default_entry_names = list(acm.defaults)
        scene.allowed_collision_matrix.default_entry_values = list(acm.defaults.values())
        return scene

    def _object_padding(self) -> float:
        """:data:`OBJECT_PADDING_PARAMETER`, 0 when absent; a value that is no finite non-negative number is
        named in a warning and taken as 0."""
        value = self.context.parameter(OBJECT_PADDING_PARAMETER, 0.0)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
            self.context.warn(
                f"{OBJECT_PADDING_PARAMETER} must be a non-negative number of metres, got {value!r}: using 0"
            )
            return 0.0
        if value:
            _log.info(f"world objects are padded by {value:g} m for collision checking ({OBJECT_PADDING_PARAMETER})")
        return float(value)

    def scene_topic(self, topic: str, fn: Callable[[M], object]) -> Callable[[M], None]:
        """A planning-scene topic's callback: the pool held for writing (it waits for a plan in progress, as
        MoveIt's scene monitor waits for its readers), a bad message logged, not raised."""

        def callback(msg: M) -> None:
            pool = self.context.pool
            if pool is None:
                return
            try:
                with pool.writing():
                    self.changed = True
                    fn(msg)
            except PlanningError as err:
                self.context.logger.warning(f"/{topic}: {err.code}: {err.message}")

        return callback

    def on_sim_world(self, msg: PlanningSceneWorld) -> None:
        """The simulation's collision geometry: every entity link but this robot's, in the planning frame."""
        pool = self.context.pool
        if pool is None:
            self.sim_world = msg  # taken when the robot is known
            return
        with pool.writing():
            self.changed = True
            self.take_sim_world(msg)

    def take_sim_world(self, msg: PlanningSceneWorld) -> None:
        """Replace the simulation's objects in the scene with ``msg``'s (each link of each other entity a
        collision object ``entity::link``), placed in the planning frame by this robot's own pose in the
        simulation; this robot's own links are left out."""
        planner = self.context.planner
        assert planner is not None
        by_entity: dict[str, list[CollisionObject]] = {}
        for co in msg.collision_objects:
            entity, _, link = co.id.rpartition("::")
            by_entity.setdefault(entity, []).append(co)
        ours = {
            entity
            for entity, objects in by_entity.items()
            if all(planner.has_link(co.id.rpartition("::")[2]) for co in objects)
        }
        root_in_world = self.root_in_world([co for e in ours for co in by_entity[e]])
        world_to_root = np.linalg.inv(root_in_world)
        names = set()
        for entity, objects in by_entity.items():
            if entity in ours:
                continue
            for co in objects:
                at = world_to_root @ _matrix(co.pose)
                names.add(co.id)
                existing = self.find(co.id)
                if existing is not None and existing.link:
                    continue  # attached to the robot (a grasp): MoveIt's scene moves it with its link, not from here
                pad = self.object_padding
                shapes = tuple(padded(sh, pad) if pad else sh for sh in shapes_of(co, self.context.warn))
                if not shapes:
                    continue
                if existing is not None and not existing.link and _same_shapes(existing.shapes, shapes):
                    planner.move_object(co.id, at)
                else:
                    planner.add_object(SceneObject(co.id, shapes, at))
        for stale in self.sim_objects - names:
            obj = self.find(stale)
            if obj is not None and not obj.link:
                planner.remove_object(stale)
        self.sim_objects = names

    def root_in_world(self, robot_links: list[CollisionObject]) -> np.ndarray:
        """Where the planning frame (the robot's root link) is in the simulation's world: from a link of
        this robot the simulation reports and the current joint values; the identity if none."""
        planner = self.context.planner
        assert planner is not None
        q = planner.state(self.context.latest_joints or None)
        for co in sorted(robot_links, key=lambda c: c.id.rpartition("::")[2] != planner.root_link):
            link = co.id.rpartition("::")[2]
            return _matrix(co.pose) @ np.linalg.inv(planner.fk(q, link))
        return np.eye(4)

    def apply_scene(self, scene: PlanningScene) -> None:
        """Apply a PlanningScene: the bounds and every object checked first, then (for a whole scene) the
        objects there were removed, then its world objects and attached objects applied in order."""
        planner = self.context.planner
        assert planner is not None
        given = len(scene.world.collision_objects) + len(scene.robot_state.attached_collision_objects)
        if given > MAX_SCENE_OBJECTS:
            raise PlanningError(
                "FAILURE", f"the scene has {given} collision objects; at most {MAX_SCENE_OBJECTS} are planned with"
            )
        # every object is checked before any is applied: a bad one refuses the request, the scene unchanged
        for co in [
            *scene.world.collision_objects,
            *(aco.object for aco in scene.robot_state.attached_collision_objects),
        ]:
            if co.operation != CollisionObject.REMOVE:
                checked_matrix(co.pose, f"collision object '{co.id[:80]}'")
                shapes_of(co, lambda _text: None)
        acm_msg = scene.allowed_collision_matrix
        acm = None
        if acm_msg.entry_names or acm_msg.default_entry_names:
            most = MAX_SCENE_OBJECTS + len(planner.acm.names)
            if len(acm_msg.entry_names) > most or len(acm_msg.default_entry_names) > most:
                raise PlanningError(
                    "FAILURE",
                    f"allowed_collision_matrix names {len(acm_msg.entry_names)} entries and "
                    f"{len(acm_msg.default_entry_names)} default entries",
                )
            try:
                acm = CollisionMatrix.from_rows(
                    [str(n) for n in acm_msg.entry_names],
                    [list(e.enabled) for e in acm_msg.entry_values],
                    [str(n) for n in acm_msg.default_entry_names],
                    [bool(v) for v in acm_msg.default_entry_values],
                )
            except ValueError as err:
                raise PlanningError("FAILURE", f"allowed_collision_matrix: {err}") from None
        self.changed = True
        self.note_scene_parts(scene)
        if not scene.is_diff:  # a whole scene replaces the objects there are but the simulation's own
            # MoveIt clears its world (planning_scene.cpp, setPlanningSceneMsg) and its world geometry monitor
            # fills in again what the sensors see; the simulation's objects are that sensed world, published
            # again only when they move: they stay (the ground was gone until the next movement)
            for obj in planner.objects():
                if obj.link or obj.name not in self.sim_objects:
                    planner.remove_object(obj.name)
        for co in scene.world.collision_objects:
            self.apply_world_object(co)
        for aco in scene.robot_state.attached_collision_objects:
            self.apply_attached(aco)
        if acm is not None:  # MoveIt replaces its matrix with the message's (setPlanningSceneDiffMsg)
            planner.set_allowed_collision_matrix(acm)

    def note_scene_parts(self, scene: PlanningScene) -> None:
        """Say, once per kind, what of a PlanningScene gazelle does not apply (MoveIt's planning_scene.cpp
        setPlanningSceneDiffMsg applies them all): nothing a client sends is dropped without a word."""
        notes = []
        if scene.link_padding or scene.link_scale:
            notes.append(("padding", "link_padding and link_scale are not applied"))
        if scene.fixed_frame_transforms:
            notes.append(("frames", "fixed_frame_transforms are not applied"))
        if scene.world.octomap.octomap.data:
            notes.append(("octomap", "the world's octomap is not applied"))
        for kind, note in notes:
            if f"scene-{kind}" not in self.context.noted:
                self.context.noted.add(f"scene-{kind}")
                self.context.logger.warning(f"planning scene: {note}")

    def find(self, name: str) -> SceneObject | None:
        """The scene object of that name, or None."""
        assert self.context.planner is not None
        return next((o for o in self.context.planner.objects() if o.name == name), None)

    def apply_world_object(self, co: CollisionObject) -> None:
        """A CollisionObject's ADD, REMOVE, APPEND or MOVE on the world's objects."""
        planner = self.context.planner
        assert planner is not None
        existing = self.find(co.id) if co.id else None
        if existing is not None and existing.link:
            existing = None  # an attached object of that name is changed through attached_collision_object
        if co.operation == CollisionObject.REMOVE:
            targets = [existing] if co.id else [o for o in planner.objects() if not o.link]
            for obj in targets:
                if obj is not None:
                    planner.remove_object(obj.name)
            return
        if not co.id:
            raise PlanningError("INVALID_OBJECT_NAME", "a collision object needs an id")
        if existing is None and co.operation == CollisionObject.ADD:
            mine = [o for o in planner.objects() if not o.link and o.name not in self.sim_objects]
            if len(mine) >= MAX_SCENE_OBJECTS:
                raise PlanningError(
                    "FAILURE", f"the scene holds {len(mine)} collision objects already; at most {MAX_SCENE_OBJECTS}"
                )
        pose = checked_matrix(co.pose, f"collision object '{co.id[:80]}'")
        at = self.context.frame(co.header.frame_id, planner.state(self.context.latest_joints or None)) @ pose
        if co.operation == CollisionObject.MOVE:
            if existing is None:
                raise PlanningError("INVALID_OBJECT_NAME", f"no collision object {quoted(co.id)} to move")
            planner.add_object(SceneObject(co.id, existing.shapes, at))
            return
        shapes = tuple(shapes_of(co, self.context.warn))
        if co.operation == CollisionObject.APPEND and existing is not None:
            relative = np.linalg.inv(existing.pose) @ at
            shapes = existing.shapes + tuple(type(sh)(sh.kind, sh.dimensions, relative @ sh.pose) for sh in shapes)
            at = existing.pose
        if not shapes:
            raise PlanningError(
                "INVALID_OBJECT_NAME", f"collision object {quoted(co.id)} has no shape gazelle plans with"
            )
        planner.add_object(SceneObject(co.id, shapes, at))

    def apply_attached(self, aco: AttachedCollisionObject) -> None:
        """Attach an object to a link (a world object of that id, or the message's shapes) or detach it
        back into the world where it is now."""
        planner = self.context.planner
        assert planner is not None
        co = aco.object
        q = planner.state(self.context.latest_joints or None)
        if co.operation == CollisionObject.REMOVE:
            attached = [o for o in planner.objects() if o.link and (o.name == co.id or not co.id)]
            attached = [o for o in attached if not aco.link_name or o.link == aco.link_name]
            for obj in attached:
                world = planner.fk(q, obj.link) @ obj.pose
                planner.add_object(SceneObject(obj.name, obj.shapes, world))
            return
        if not aco.link_name:
            raise PlanningError("INVALID_LINK_NAME", f"attached object {quoted(co.id)} names no link")
        link_pose = planner.fk(q, aco.link_name)
        existing = self.find(co.id)
        if existing is not None and not co.primitives and not co.meshes:
            world = existing.pose if not existing.link else planner.fk(q, existing.link) @ existing.pose
            shapes, at = existing.shapes, np.linalg.inv(link_pose) @ world
        else:
            shapes = tuple(shapes_of(co, self.context.warn))
            if not shapes:
                raise PlanningError(
                    "INVALID_OBJECT_NAME", f"attached object {quoted(co.id)} has no shape gazelle plans with"
                )
            frame = self.context.frame(co.header.frame_id or aco.link_name, q)
            at = np.linalg.inv(link_pose) @ frame @ checked_matrix(co.pose, f"attached object '{co.id[:80]}'")
        planner.add_object(SceneObject(co.id, shapes, at, aco.link_name, tuple(aco.touch_links)))
