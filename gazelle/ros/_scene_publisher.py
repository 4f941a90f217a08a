"""The simulation's collision geometry for motion planners: ``/gazelle/planning_scene_world``.

A latched moveit_msgs/PlanningSceneWorld with one CollisionObject per entity link that has collision
geometry (id ``entity::link``, frame ``world``), sent when something was added, removed or moved
(1 mm or 0.01 rad), checked every 0.2 s of sim time and at most 5 times per wall second, and only
while someone subscribes. gazelle's move_group takes it as the world of its planning scene, leaving out
its own robot; it is how the table, the board and the other arm get there.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from ..sim import SceneGeometry, SceneLink, moved
from ..systems import UpdateInfo
from ._convert import to_pose_msg
from ._subscribed import Subscribed

if TYPE_CHECKING:
    from moveit_msgs.msg import PlanningSceneWorld
    from rclpy.node import Node

    from ..sim import Simulation
    from ._outbox import Lane, Outbox

TOPIC = "/gazelle/planning_scene_world"
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
RATE_HZ = 5.0
"""How often (sim time, and at most per wall second) the world's geometry is looked at."""


class ScenePublisher:
    """Publishes the world's collision geometry for a :class:`SimulationNode` (from its making; :meth:`close` stops)."""

    def __init__(self, node: Node, sim: Simulation, outbox: Outbox) -> None:
        """The latched topic on ``node``, published through a lane of ``outbox`` as ``sim`` steps."""
        from moveit_msgs.msg import PlanningSceneWorld  # built by the set-up; the sim runs without it

        self._node = node
        self._sim = sim
        self._pub = node.create_publisher(PlanningSceneWorld, TOPIC, LATCHED)
        self._heard = Subscribed(self._pub)
        self._geometry = SceneGeometry()
        self._last: dict[str, SceneLink] | None = None
        self._last_wall = 0.0
        self._lane: Lane[list[SceneLink]] = outbox.lane(lambda links: self._pub.publish(world_msg(links)), 1, TOPIC)
        self._sim.add_step_listener(self._on_step, RATE_HZ)

    def close(self) -> None:
        self._sim.remove_step_listener(self._on_step)

    def _on_step(self, info: UpdateInfo) -> None:
        """On the simulation thread: send the geometry if anyone listens and it changed."""
        if not self._heard():
            return
        wall = time.monotonic()
        if wall - self._last_wall < 1.0 / RATE_HZ:
            return
        self._last_wall = wall
        links = self._geometry.links(self._sim.world)
        current = {link.name: link for link in links}
        last = self._last
        if (
            last is not None
            and current.keys() == last.keys()
            and not any(
                moved(link.pose, last[name].pose) or link.shapes != last[name].shapes for name, link in current.items()
            )
        ):
            return
        self._last = current
        self._lane.put(links)


def world_msg(links: list[SceneLink]) -> PlanningSceneWorld:
    """moveit_msgs/PlanningSceneWorld of the links (shapes in each link's frame, the link in ``world``)."""
    from moveit_msgs.msg import CollisionObject, PlanningSceneWorld
    from shape_msgs.msg import SolidPrimitive

    types = {"box": SolidPrimitive.BOX, "sphere": SolidPrimitive.SPHERE, "cylinder": SolidPrimitive.CYLINDER}
    msg = PlanningSceneWorld()
    objects = []
    for link in links:
        co = CollisionObject(id=link.name, operation=CollisionObject.ADD)
        co.header.frame_id = "world"
        co.pose = to_pose_msg(link.pose)
        co.primitives = [SolidPrimitive(type=types[s.kind], dimensions=list(s.dimensions)) for s in link.shapes]
        co.primitive_poses = [to_pose_msg(s.pose) for s in link.shapes]
        objects.append(co)
    msg.collision_objects = objects
    return msg
