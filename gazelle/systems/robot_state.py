"""robot_state_publisher built in, and the joint state publishers of Gazebo Classic and gz-sim.

Every spawned robot gets a :class:`RobotStatePublisher` unless its file says otherwise
(see :func:`robot_state_config`): ``/robot_description`` (std_msgs/String, reliable,
transient local), ``/tf_static`` for fixed joints (transient local), and ``/tf`` for
moving joints from the simulated joint positions, stamped with sim time, with the
URDF's frame names. A namespaced robot's topics go under its namespace and its frames
get the namespace as prefix (``r1/base_link``) unless ``frame_prefix`` says otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..description import JointType, Model, Pose
from ..physics import BodyHandle, Entity, JointHandle, PhysicsWorld
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, Qos, resolve_topic
from ._frames import RobotStateConfig as RobotStateConfig
from ._frames import entity_frame_prefix
from ._payloads import JointStates, Text, Transform, TransformBatch
from ._plugin_config import all_texts, child_text, parse_float, ros_block
from ._plugin_names import RSP_PLUGIN as RSP_PLUGIN
from ._registration import add_plugin


def gz_scoped_frames(model: Model) -> bool:
    """Whether a gz-sim DiffDrive of ``model`` uses its default, model-scoped frames (no ``<child_frame_id>``).
    A plugin is a DiffDrive when the registry runs it as one (every gz and Ignition spelling)."""
    from ._registry import system_class
    from .gz_diff_drive import GzDiffDrive

    return any(system_class(p) is GzDiffDrive and p.config.find("child_frame_id") is None for p in model.plugins)


@dataclass
class _MovingJoint:
    """A moving joint's transform, read from the simulated bodies: the child's pose in the parent's. A joint
    whose parent is the URDF's ``world`` link has no parent body (that link is MuJoCo's world, where the
    entity was placed): its parent frame is the entity's placement ``X_WM``."""

    parent: BodyHandle | Entity
    child: BodyHandle
    parent_frame: str
    child_frame: str

    def parent_pose(self) -> Pose:
        """The parent frame's world pose now."""
        return self.parent.X_WM if isinstance(self.parent, Entity) else self.parent.pose


class RobotStatePublisher(System):
    """What robot_state_publisher does, from the simulated state instead of /joint_states."""

    def __init__(self, config: RobotStateConfig | None = None) -> None:
        """An unconfigured robot_state_publisher (see :meth:`configure`)."""
        self.config = config or RobotStateConfig()
        self.prefix = ""
        self._moving: list[_MovingJoint] = []
        self._tf: Endpoint | None = None
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._bus: Any = None
        self._endpoints: list[Endpoint] = []

    def stop_publishing(self) -> None:
        """Publish nothing more, and take back what was advertised: the user's own robot_state_publisher,
        started beside this robot, publishes its transforms (see gazelle.ros's bridge), as in Gazebo,
        which publishes no robot TF of its own."""
        for ep in self._endpoints:
            self._bus.remove(ep)
        self._endpoints.clear()
        self._tf = None

    def configure(self, ctx: SystemContext) -> None:
        """Read the configuration, find the joints, advertise the topics (and publish the latched ones)."""
        c = self.config
        self._bus = ctx.bus
        model = ctx.entity.model
        self.prefix = entity_frame_prefix(ctx.entity, ctx.logger)
        if not self.prefix and gz_scoped_frames(model):
            # gz-sim's DiffDrive names its frames <model>/odom -> <model>/<canonical link>: the links hang
            # below that, so two vehicles of one SDF (gz-sim's diff_drive.sdf) never share a frame name
            self.prefix = f"{ctx.entity.name}/"
        owner = ctx.entity.name
        statics: list[Transform] = []
        # robot_state_publisher 3.3.3 (src/robot_state_publisher.cpp, addChildren) publishes every joint of the
        # URDF's KDL tree, those of a `world` link included (a fixed world -> base joint is a static transform
        # at its origin, wherever the robot was spawned); it skips floating joints and makes planar ones fixed
        for j in model.joints:
            if j.type is JointType.FLOATING:
                continue
            parent, child = self.prefix + j.parent, self.prefix + j.child
            if j.type in (JointType.FIXED, JointType.PLANAR):
                statics.append(Transform(0.0, parent, child, j.origin * j.child_offset))
            else:
                parent_of = ctx.entity if j.parent == "world" else ctx.world.body(owner, j.parent)
                self._moving.append(_MovingJoint(parent_of, ctx.world.body(owner, j.child), parent, child))
        if model.urdf:
            desc = ctx.bus.advertise(
                owner, resolve_topic("robot_description", c.namespace), MsgType.STRING, qos=Qos.LATCHED, depth=1
            )
            desc.publish(Text(model.urdf))
            self._endpoints.append(desc)
        if statics:
            static = ctx.bus.advertise(owner, "/tf_static", MsgType.TF_STATIC, qos=Qos.LATCHED, depth=1)
            static.publish(TransformBatch(tuple(statics)))
            self._endpoints.append(static)
        if self._moving:
            self._tf = ctx.bus.advertise(owner, "/tf", MsgType.TF, depth=100)
            self._endpoints.append(self._tf)
        ctx.logger.info(
            f"robot_state_publisher: {len(statics)} fixed and {len(self._moving)} moving joints, "
            f"frame prefix '{self.prefix}'"
        )

    def next_update(self, sim_time_sec: float) -> float:
        """The next publishing period (never when there is nothing to publish)."""
        return self._gate.next if self._tf is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Publish again at the next step (sim time went back)."""
        self._gate.reset()

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Publish, when due and wanted, from the simulated state."""
        if self._tf is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.publish_frequency):
            return
        if not self._tf.wanted:
            return  # nobody listens: nothing to build
        out = []
        for m in self._moving:
            X_WP, X_WC = m.parent_pose(), m.child.pose
            out.append(Transform(info.sim_time_sec, m.parent_frame, m.child_frame, X_WP.inverse() * X_WC))
        self._tf.publish(TransformBatch(tuple(out)))


# --------------------------------------------------------------------------- joint states
@dataclass(frozen=True)
class JointStateConfig:
    """``libgazebo_ros_joint_state_publisher.so`` / gz-sim ``JointStatePublisher`` parameters."""

    joint_names: tuple[str, ...] = ()
    """``<joint_name>`` (repeatable). Classic: required. gz-sim: default every joint of the model."""
    update_rate: float = 100.0
    """``<update_rate>``, Hz of sim time; default 100. (gz-sim's default, 0, publishes at every physics step;
    gazelle keeps 100 Hz then, as a publisher of every step would take Python into every step.)"""
    topic: str = "joint_states"
    """gz-sim's ``<topic>``, else ``/world/<world>/model/<model>/joint_state``; classic publishes
    ``joint_states`` under ``<ros><namespace>`` (remappable) and has no ``<topic>``."""
    namespace: str = ""


class JointStatePublisher(System):
    """Publishes sensor_msgs/JointState (name, position, velocity; effort empty) in sim time: gazebo_ros's
    plugin, which publishes only the ``<joint_name>`` joints it is given."""

    plugin_files = ("gazebo_ros_joint_state_publisher",)

    def __init__(self) -> None:
        """An unconfigured joint state publisher (no ``<joint_name>`` is gazebo_ros's error)."""
        self.config = JointStateConfig()
        self._pub: Endpoint | None = None
        self._joints: list[str] = []
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._handles: list[JointHandle] = []

    def _read_config(self, ctx: SystemContext, topic: str) -> dict[str, str]:
        """:attr:`config` from the plugin's ``<joint_name>``s, ``<update_rate>`` and ``<ros>``, publishing on
        ``topic``; returns the ``<ros>`` remappings."""
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        ns, remaps = ros_block(cfg)
        rate = parse_float(cfg, "update_rate", 100.0, ctx.logger)
        self.config = JointStateConfig(all_texts(cfg, "joint_name"), rate, topic, ns or ctx.entity.namespace)
        return remaps

    def configure(self, ctx: SystemContext) -> None:
        """Read the configuration, find the joints, advertise the topics (and publish the latched ones).

        As gazebo_ros_joint_state_publisher.cpp (gazebo_ros_pkgs, ros2 branch) ``Load``: ``<update_rate>``
        defaults to 100 Hz with its info line, only the ``<joint_name>``s listed are published (none listed is
        its error "Plugin missing <joint_name>s"), a joint the model lacks is skipped with "Joint X does not
        exist!", and the topic is ``joint_states`` in the plugin's ``<ros>`` namespace (the robot's, else)
        with its remappings. A fixed or floating joint counts as missing here: it has no position to
        publish."""
        log = ctx.logger
        model: Model = ctx.entity.model
        remaps = self._read_config(ctx, "joint_states")
        names, topic = self.config.joint_names, self.config.topic
        if ctx.plugin is not None and ctx.plugin.config.find("update_rate") is None:
            log.info(f"Missing <update_rate>, defaults to {self.config.update_rate:f}")
        movable = [j.name for j in model.joints if j.type not in (JointType.FIXED, JointType.FLOATING)]
        wanted = list(names)
        if not wanted:
            log.error("Plugin missing <joint_name>s")
            return
        for jn in wanted:
            if jn not in movable:
                log.error(f"Joint {jn} does not exist!")
                continue
            self._joints.append(jn)
            log.info(f"Going to publish joint [{jn}]")
        if not self._joints:
            log.error("No joints found.")
            return
        self._pub = ctx.bus.advertise(
            ctx.entity.name, resolve_topic(topic, self.config.namespace, remaps), MsgType.JOINT_STATE, depth=1000
        )
        self._entity = ctx.entity.name
        self._handles = [ctx.world.joint(self._entity, jn) for jn in self._joints]

    def next_update(self, sim_time_sec: float) -> float:
        """The next publishing period (never when there is nothing to publish)."""
        return self._gate.next if self._pub is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Publish again at the next step (sim time went back)."""
        self._gate.reset()

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Publish, when due and wanted, from the simulated state."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.update_rate):
            return
        if not self._pub.wanted:
            return  # nobody listens: nothing to build
        self._pub.publish(
            JointStates(
                info.sim_time_sec,
                tuple(self._joints),
                tuple(j.position for j in self._handles),
                tuple(j.velocity for j in self._handles),
            )
        )


class GzJointStatePublisher(JointStatePublisher):
    """gz-sim's JointStatePublisher (gz-sim8 ``src/systems/joint_state_publisher/JointStatePublisher.cc``), as
    ros_gz_bridge turns its gz.msgs.Model into sensor_msgs/JointState (``convert/sensor_msgs.cpp``): the
    ``<joint_name>`` joints, else every joint of the model (fixed ones too, at zero: they have no position),
    in the model's order; a name the model lacks is an error and left out. Each joint has a position,
    a velocity and an effort, the effort 0: gz-sim8's physics never fills the JointForce component the
    publisher reads. On ``<topic>``, else ``/world/<world>/model/<model>/joint_state``."""

    gz_plugin = "JointStatePublisher"

    def __init__(self) -> None:
        """An unconfigured gz-sim joint state publisher."""
        super().__init__()
        self._moving: list[JointHandle | None] = []
        """Per published joint: its handle, or None for a joint without one degree of freedom (zeros)."""

    def configure(self, ctx: SystemContext) -> None:
        """Read ``<joint_name>``, ``<topic>`` and ``<update_rate>``; find the joints; advertise the topic.

        As gz-sim 8's ``JointStatePublisher.cc``: every joint of the model when no ``<joint_name>`` is given,
        in the model's order; a named joint the model lacks is an error with upstream's text and the others
        still publish; the topic defaults to ``/world/<world>/model/<model>/joint_state``; a joint without one
        degree of freedom is listed at 0, and every effort is 0 (gz-sim's physics fills no ``JointForce``)."""
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        model: Model = ctx.entity.model
        topic = child_text(cfg, "topic") or f"/world/{ctx.world_name}/model/{ctx.entity.name}/joint_state"
        remaps = self._read_config(ctx, topic)
        names = self.config.joint_names
        joints = {j.name: j for j in model.joints}
        for name in names or tuple(joints):
            if name not in joints:
                log.error(f"Joint with name[{name}] not found. The JointStatePublisher will not publish this joint.")
                continue
            self._joints.append(name)
        one_dof = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)
        self._moving = [
            ctx.world.joint(ctx.entity.name, n) if joints[n].type in one_dof else None for n in self._joints
        ]
        self._pub = ctx.bus.advertise(
            ctx.entity.name, resolve_topic(topic, self.config.namespace, remaps), MsgType.JOINT_STATE, depth=1000
        )

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Publish, when due and wanted, from the simulated state (zeros for joints without one degree of
        freedom, and for every effort)."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.update_rate):
            return
        if not self._pub.wanted:
            return
        self._pub.publish(
            JointStates(
                info.sim_time_sec,
                tuple(self._joints),
                tuple(h.position if h is not None else 0.0 for h in self._moving),
                tuple(h.velocity if h is not None else 0.0 for h in self._moving),
                (0.0,) * len(self._moving),
            )
        )


add_plugin(JointStatePublisher)
add_plugin(GzJointStatePublisher)
