"""gz-sim's PosePublisher system: the poses of a model's links (and, on request, of the model, its visuals,
collisions and sensors), each in its parent's frame, as a robot's bring-up bridges them to ``/tf``.

Read against gz-sim's ``src/systems/pose_publisher/PosePublisher.cc`` (and its test,
``test/integration/pose_publisher_system.cc``):

* parameters and defaults: ``<publish_link_pose>`` true; ``<publish_visual_pose>``, ``<publish_collision_pose>``,
  ``<publish_sensor_pose>``, ``<publish_nested_model_pose>`` false; ``<publish_model_pose>`` defaults to
  ``<publish_nested_model_pose>``'s value (upstream's backward compatibility); ``<update_frequency>`` -1 (every
  step); ``<static_publisher>`` false, with ``<static_update_frequency>`` defaulting to ``<update_frequency>``;
  ``<use_pose_vector_msg>`` false; ``<topic>``, default ``/model/<model>/pose``, the static poses on the topic's
  name + ``_static``. A ``<topic>`` that is not a valid gz topic is upstream's error, and the default is used;
* each pose is the entity's own pose in its parent's frame: frame_id is the parent's scoped name and
  child_frame_id the entity's, both without the world (``model``, ``model::link``, ``model::link::visual``; a
  joint's sensor under ``model::joint``); the model's is in ``world``;
* with ``<static_publisher>``, the "dynamic" poses (the links a non-fixed joint moves, the canonical link
  excepted) go on the topic and every other pose on ``<topic>_static``, as upstream sorts them; without it,
  all go on the topic. Published at the rates' multiples of sim time, never while paused; nothing is
  published to nobody.

As every gz topic in gazelle, the topic is a ROS topic of the same name, carrying what ros_gz_bridge makes of
gz's messages for tf: with ``<use_pose_vector_msg>`` one ``tf2_msgs/TFMessage`` per update (the bridge's
mapping of ``gz.msgs.Pose_V``); without it, one message per pose, each a TFMessage of the one
``TransformStamped`` the bridge makes of a ``gz.msgs.Pose`` (a topic here has one type, and tf listeners take
this one).

Differs: gazelle merges nested models into their parent, so a nested model's links are published in the
top model's frame and ``<publish_nested_model_pose>`` has no nested model to publish (said once, if it has
any). Upstream's ``std::unordered_map`` gives no order; here it is the model, then each link followed by its
visuals, collisions and sensors, in the file's order.
"""

from __future__ import annotations

import logging
import math
import re
from dataclasses import dataclass

from ..description import IDENTITY, JointType, Model, Pose
from ..physics import PhysicsWorld
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, resolve_topic
from ._payloads import Transform, TransformBatch
from ._plugin_config import child_text, parse_bool, parse_float
from ._registration import add_plugin

_INVALID_TOPIC = re.compile(r"\s|~|@|//|:=")
"""What gz-transport's ``TopicUtils::IsValidTopic`` refuses in a topic (besides an empty one)."""


@dataclass(frozen=True)
class PosePublisherConfig:
    """Parameters of gz-sim's PosePublisher (``PosePublisher.cc``'s names and defaults)."""

    publish_link_pose: bool = True
    """``<publish_link_pose>``: each link's pose in the model frame."""
    publish_nested_model_pose: bool = False
    """``<publish_nested_model_pose>``: nested models' poses (gazelle merges nested models: none to publish)."""
    publish_model_pose: bool = False
    """``<publish_model_pose>``: the model's pose in the world; default ``<publish_nested_model_pose>``'s value."""
    publish_visual_pose: bool = False
    """``<publish_visual_pose>``: each visual's pose in its link."""
    publish_collision_pose: bool = False
    """``<publish_collision_pose>``: each collision's pose in its link."""
    publish_sensor_pose: bool = False
    """``<publish_sensor_pose>``: each sensor's pose in its link (a joint's sensor: in its joint)."""
    update_frequency: float = -1.0
    """``<update_frequency>``, Hz of sim time; 0 or less: every step."""
    static_publisher: bool = False
    """``<static_publisher>``: the poses no joint moves go on ``<topic>_static`` instead."""
    static_update_frequency: float = -1.0
    """``<static_update_frequency>``, Hz of sim time; default ``<update_frequency>``."""
    use_pose_vector_msg: bool = False
    """``<use_pose_vector_msg>``: all poses of an update in one message (gz Pose_V), not one message each."""
    topic: str = ""
    """``<topic>``; default ``/model/<model>/pose``."""


def parse_config(ctx: SystemContext, log: logging.Logger) -> PosePublisherConfig:
    """The plugin's parameters, with upstream's defaults (``publish_model_pose`` and ``static_update_frequency``
    default to other parameters' values, as ``PosePublisher::Configure`` reads them)."""
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    nested = parse_bool(cfg, "publish_nested_model_pose", False, log)
    update_frequency = parse_float(cfg, "update_frequency", -1.0, log)
    static = parse_bool(cfg, "static_publisher", False, log)
    topic = child_text(cfg, "topic") or ""
    if topic and _INVALID_TOPIC.search(topic):
        log.error(f"Provided topic: {topic} is not a valid topic.")
        topic = ""
    return PosePublisherConfig(
        publish_link_pose=parse_bool(cfg, "publish_link_pose", True, log),
        publish_nested_model_pose=nested,
        publish_model_pose=parse_bool(cfg, "publish_model_pose", nested, log),
        publish_visual_pose=parse_bool(cfg, "publish_visual_pose", False, log),
        publish_collision_pose=parse_bool(cfg, "publish_collision_pose", False, log),
        publish_sensor_pose=parse_bool(cfg, "publish_sensor_pose", False, log),
        update_frequency=update_frequency,
        static_publisher=static,
        # read only with a static publisher, as upstream reads it
        static_update_frequency=parse_float(cfg, "static_update_frequency", update_frequency, log)
        if static
        else update_frequency,
        use_pose_vector_msg=parse_bool(cfg, "use_pose_vector_msg", False, log),
        topic=topic,
    )


@dataclass(frozen=True)
class PoseEntry:
    """One pose the system publishes: ``child`` in ``parent``, where ``link`` (None: the model in the world)
    carries it at the fixed offset ``X_LE`` (a link's own pose in the model frame moves: ``moves``)."""

    parent: str
    """frame_id: the parent's scoped name (``world`` for the model)."""
    child: str
    """child_frame_id: the entity's scoped name."""
    link: str | None = None
    """The link whose pose in the model frame is published (``X_LE`` none), or that carries a fixed part."""
    X_LE: Pose | None = None
    """A visual's, collision's or sensor's fixed pose in its parent (None: the link's or model's own pose)."""
    dynamic: bool = False
    """Whether a non-fixed joint moves it (upstream's ``dynamicEntities``): on the topic with a static publisher."""


def pose_entries(model: Model, name: str, c: PosePublisherConfig) -> list[PoseEntry]:
    """What ``c`` asks to publish of ``model`` (spawned as ``name``), as ``InitializeEntitiesToPublish`` picks
    it: the model, then each link with its visuals, collisions and sensors."""
    canonical = model.canonical_link or model.root_link
    moved = {end for j in model.joints if j.type is not JointType.FIXED for end in (j.parent, j.child)}
    out = [PoseEntry("world", name)] if c.publish_model_pose else []
    for link in model.links:
        scoped = f"{name}::{link.name}"
        if c.publish_link_pose:
            out.append(PoseEntry(name, scoped, link.name, None, link.name in moved and link.name != canonical))
        parts = [
            *((v.name, v.pose) for v in (link.visuals if c.publish_visual_pose else ())),
            *((g.name, g.pose) for g in (link.collisions if c.publish_collision_pose else ())),
        ]
        out.extend(PoseEntry(scoped, f"{scoped}::{part}", link.name, pose) for part, pose in parts)
        for sensor in link.sensors if c.publish_sensor_pose else ():
            parent = f"{name}::{sensor.joint}" if sensor.joint else scoped
            out.append(PoseEntry(parent, f"{parent}::{sensor.name}", link.name, sensor.pose))
    return out


class PosePublisher(System):
    """gz-sim's PosePublisher: a model's poses, each in its parent's frame (see the module docstring)."""

    gz_plugin = "PosePublisher"

    def __init__(self) -> None:
        """An unconfigured PosePublisher (see :meth:`configure`)."""
        self.config = PosePublisherConfig()
        self.entries: list[PoseEntry] = []
        self._entity = ""
        self._canonical = ""
        self._X_CM = IDENTITY
        self._pub: Endpoint | None = None
        self._static_pub: Endpoint | None = None
        self._gate = RateGate()
        self._static_gate = RateGate()

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block, list the poses to publish and advertise the topic (and ``<topic>_static``)."""
        log = ctx.logger
        self.config = c = parse_config(ctx, log)
        entity, model = ctx.entity, ctx.entity.model
        name = self._entity = entity.name
        self._canonical = model.canonical_link or model.root_link
        canonical = next(link for link in model.links if link.name == self._canonical)
        # the model frame rides on the canonical link: X_WM = X_WC * X_CM, X_CM the inverse of its pose in the model
        self._X_CM = canonical.pose.inverse() if canonical.pose is not None else IDENTITY
        self.entries = pose_entries(model, name, c)
        if c.publish_nested_model_pose and any("::" in link.name for link in model.links):
            log.warning(
                f"PosePublisher of '{name}': <publish_nested_model_pose> publishes nothing; gazelle merges nested "
                "models into their parent, whose frame their links are published in"
            )
        topic = resolve_topic(c.topic or f"/model/{name}/pose", entity.namespace)
        self._pub = ctx.bus.advertise(name, topic, MsgType.TF, depth=100)
        if c.static_publisher:
            self._static_pub = ctx.bus.advertise(name, f"{topic}_static", MsgType.TF, depth=100)
        else:
            self.phase_gate = self._gate  # one gate decides every call
        log.info(f"PosePublisher publishing {len(self.entries)} poses on [{topic}]")

    def next_update(self, sim_time_sec: float) -> float:
        if self._pub is None:
            return math.inf
        return min(self._gate.next, self._static_gate.next if self._static_pub is not None else math.inf)

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        self._gate.reset()
        self._static_gate.reset()

    def poses(self, world: PhysicsWorld, entries: list[PoseEntry]) -> tuple[Transform, ...]:
        """``entries``' poses now, as transforms stamped 0 (the caller stamps them)."""
        X_WM = world.entity_state(self._entity, self._canonical).pose * self._X_CM
        X_MW = X_WM.inverse()
        out = []
        for e in entries:
            if e.link is None:
                pose = X_WM
            elif e.X_LE is not None:
                pose = e.X_LE
            else:
                pose = X_MW * world.entity_state(self._entity, e.link).pose
            out.append(Transform(0.0, e.parent, e.child, pose))
        return tuple(out)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At each gate's rate, while the topic has a listener: the poses, one message each or all in one."""
        if self._pub is None or info.paused:
            return
        c, t = self.config, info.sim_time_sec
        if self._static_pub is None:
            if self._gate.due(t, c.update_frequency) and self._pub.wanted:
                self._publish(self._pub, world, self.entries, t)
            return
        if self._static_gate.due(t, c.static_update_frequency) and self._static_pub.wanted:
            self._publish(self._static_pub, world, [e for e in self.entries if not e.dynamic], t)
        if self._gate.due(t, c.update_frequency) and self._pub.wanted:
            self._publish(self._pub, world, [e for e in self.entries if e.dynamic], t)

    def _publish(self, pub: Endpoint, world: PhysicsWorld, entries: list[PoseEntry], stamp: float) -> None:
        if not entries:
            return  # upstream publishes nothing for no poses
        transforms = tuple(Transform(stamp, tf.parent, tf.child, tf.pose) for tf in self.poses(world, entries))
        if self.config.use_pose_vector_msg:
            pub.publish(TransformBatch(transforms))
        else:
            for tf in transforms:
                pub.publish(TransformBatch((tf,)))


add_plugin(PosePublisher)
