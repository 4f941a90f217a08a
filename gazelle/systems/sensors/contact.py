"""Contact sensors and gazebo_ros's bumper: the contacts of a link's collisions, as gazebo_msgs/ContactsState
(gazebo_ros_bumper) or ros_gz_interfaces/Contacts (gz-sim's Contact system, as ros_gz_bridge sends it)."""

from __future__ import annotations

import dataclasses
from typing import ClassVar

from ...description import (
    Sensor,
)
from ...physics import PerGeneration, PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._bus import MsgType, resolve_topic
from .._payloads import ContactPair, Contacts
from .._plugin_config import child_text
from .._registration import add_plugin
from ._common import (
    SENSOR_DEPTH,
    _SensorSystem,
    gz_scoped_topic,
)


# --------------------------------------------------------------------------- contact
class ContactSensor(_SensorSystem):
    """A contact sensor (``<sensor type="contact">`` with ``<contact><collision>``): every contact of its
    collisions, forces on the sensor's collision, all in the world frame. gazebo_ros_bumper publishes
    gazebo_msgs/ContactsState on ``bumper_states`` labelled ``<frame_name>`` (default ``world``) at the sensor's
    rate; gz-sim's contact system
    ros_gz_interfaces/Contacts on ``<contact><topic>``, else ``/world/<w>/model/<m>/link/<l>/sensor/<s>/contact``,
    at every step with contacts (see :meth:`_configure_gz`)."""

    sdf_types = frozenset({"contact"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_bumper": None}
    gz_system = "Contact"
    output_kind = "contact"

    kind = "contact"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.collisions: tuple[str, ...] = ()
        self._geoms: PerGeneration[PhysicsWorld, frozenset[int]] | None = None
        self._only_contacts = False
        """Publish only while there are contacts (gz-sim); gazebo_ros_bumper publishes every update."""

    def _find_geoms(self, world: PhysicsWorld) -> frozenset[int]:
        """The collision geoms of the sensor's ``<collision>`` elements in the world's current model."""
        return frozenset().union(*(world.collision_geoms(self._entity, self.link, n) for n in self._collisions))

    def configure(self, ctx: SystemContext) -> None:
        """Read the collisions it watches and the plugin; declare the output topic."""
        sensor = ctx.sensor
        if self._parse_sensor(ctx, "contact", lambda _s, _log: True) is None or sensor is None:
            return
        block = sensor.config.find("contact") if sensor.config is not None else None
        names = tuple(el.text.strip() for el in (block.findall("collision") if block is not None else ()))
        link = next((lk for lk in ctx.entity.model.links if lk.name == ctx.link), None)
        known = {c.name for c in link.collisions} if link is not None else set()
        where = f"{sensor.location}: " if sensor.location else ""
        # Gazebo names a URDF link's first unnamed <collision> '<link>_collision' (sdformat's URDF
        # conversion; the later ones '_1', '_2', ... as here): a contact sensor written for Gazebo names it so
        if link is not None and link.collisions:
            first = link.collisions[0].name
            alias = f"{ctx.link}_collision"
            if first == f"{alias}_0" and alias not in known:
                names = tuple(first if n == alias else n for n in names)
        missing = [n for n in names if n not in known]
        if not names or missing:
            what = f"its <collision> {', '.join(missing)} is not" if missing else "it names no <collision>"
            ctx.logger.error(
                f"{where}contact sensor '{sensor.name}': {what} a collision of link '{ctx.link}' "
                f"(it has {', '.join(sorted(known)) or 'none'}); it does nothing"
            )
            return
        if not self._configure_common(ctx, advertise=False):
            return
        self.collisions = names
        gz_topic = child_text(block, "topic")
        assert self.output is not None
        if ctx.plugin is None:
            self._configure_gz(ctx, sensor, gz_topic)
        else:  # gazebo_ros_bumper: bumper_states under its node's namespace (remappable), labelled <frame_name>
            c = self.config
            self.output = dataclasses.replace(
                self.output,
                topic=resolve_topic("bumper_states", c.namespace, dict(c.remappings)),
                frame_id=c.frame_name or "world",
            )
            if c.frame_name and c.frame_name not in ("world", "map"):
                # ROS 1's bumper turned the contacts into <frame_name>'s frame; ROS 2's only writes the name into
                # the header (gazebo_ros_bumper.cpp OnUpdate; Convert<ContactsState> in conversions/gazebo_msgs.hpp
                # keeps "frame_rot is identity"), so a file written for ROS 1 gets world values under a link's name
                where = f"{ctx.plugin.location}: " if ctx.plugin.location else ""
                ctx.logger.warning(
                    f"{where}<frame_name> '{c.frame_name}': as gazebo_ros_bumper in ROS 2, the contacts are in the "
                    "world frame; the name is only the header's frame_id"
                )
        self._pub = ctx.bus.advertise(ctx.entity.name, self.output.topic, self.output.msg_type, depth=SENSOR_DEPTH)
        self._entity, self._collisions = ctx.entity.name, tuple(names)
        self._geoms = PerGeneration(self._find_geoms)
        ctx.logger.info(
            f"contact sensor '{sensor.name}' on [{', '.join(names)}] at {self.rate_hz:g} Hz on [{self.output.topic}]"
        )

    def _configure_gz(self, ctx: SystemContext, sensor: Sensor, gz_topic: str | None) -> None:
        """gz-sim's Contact system (gz-sim8 ``src/systems/contact/Contact.cc``): it publishes on
        ``<contact><topic>``, else ``/world/<w>/model/<m>/link/<l>/sensor/<s>/contact`` (the sensor's own
        ``<topic>`` is not read), at every step that has contacts (``<update_rate>`` is not read either),
        as ros_gz_interfaces/Contacts once bridged, with no frame_id. What it does not read is named."""
        assert self.output is not None
        where = f"{sensor.location}: " if sensor.location else ""
        if sensor.topic and not gz_topic:
            ctx.logger.warning(
                f"{where}contact sensor '{sensor.name}': gz-sim's Contact system publishes on <contact><topic>, "
                f"not the sensor's <topic> '{sensor.topic}'; it publishes on its default topic"
            )
        if self.rate_hz > 0:
            ctx.logger.warning(
                f"{where}contact sensor '{sensor.name}': gz-sim's Contact system does not read <update_rate> "
                f"({self.rate_hz:g} Hz): it publishes at every step that has contacts"
            )
        self.rate_hz = 0.0
        self._only_contacts = True
        topic = gz_topic or gz_scoped_topic(ctx, self.link, sensor, "contact")
        self.output = dataclasses.replace(
            self.output, topic=resolve_topic(topic, ctx.entity.namespace), frame_id="", msg_type=MsgType.GZ_CONTACTS
        )

    def read(self, world: PhysicsWorld) -> tuple[ContactPair, ...]:
        """The current contacts of the watched collisions, grouped by pair, in the world frame."""
        assert self._geoms is not None
        # every MuJoCo contact touching a watched geom, seen from its side: the force the other body exerts on
        # it (MuJoCo's contact force turned into the world frame), the normal pointing into it
        points = world.contacts_of(self._geoms.get(world))
        # in the world frame: gz-sim's Contact system, and gazebo_ros_bumper whatever its <frame_name>
        pairs: dict[tuple[str, str], list] = {}  # one ContactState per pair of collisions, as Gazebo groups them
        for p in points:
            pairs.setdefault((p.collision1, p.collision2), []).append(p)
        return tuple(
            ContactPair(
                c1,
                c2,
                tuple(p.position for p in group),
                tuple(p.normal for p in group),
                tuple(p.force for p in group),
                tuple(p.torque for p in group),
                tuple(p.depth for p in group),
            )
            for (c1, c2), group in pairs.items()
        )

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the contacts stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        pairs = self.read(world)
        if pairs or not self._only_contacts:  # gz-sim's Contact system sends nothing while nothing touches
            self._pub.publish(Contacts(info.sim_time_sec, self.output.frame_id, pairs))


add_plugin(ContactSensor)
