"""Spawning from XML and gazebo_ros's services (:class:`GazeboServices`, a part the simulation's node,
``SimulationNode`` in ``_bridge.py``, owns; it registers its own services on the node): ``/spawn_entity``,
``/delete_entity``, ``/get_entity_state``, ``/set_entity_state``, ``/get_model_list``, pause, unpause and the two
resets at the root as gazebo_ros (ROS 2) serves them, and ROS 1's ``/gazebo/...`` names that older spawners call;
the XML a request carries is data (parsed, never expanded: ``_spawn_preamble.py``, shared with
simulation_interfaces' spawns), and a refused spawn leaves the world as it was."""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

from gazebo_msgs.srv import DeleteEntity as GzDeleteEntity
from gazebo_msgs.srv import DeleteModel as GzDeleteModel
from gazebo_msgs.srv import GetEntityState as GzGetEntityState
from gazebo_msgs.srv import GetModelList as GzGetModelList
from gazebo_msgs.srv import GetModelState as GzGetModelState
from gazebo_msgs.srv import SetEntityState as GzSetEntityState
from gazebo_msgs.srv import SetModelState as GzSetModelState
from gazebo_msgs.srv import SpawnEntity as GzSpawnEntity
from gazebo_msgs.srv import SpawnModel as GzSpawnModel
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node
from std_srvs.srv import Empty

from ..description import Pose, Vec3, quat_conj, quat_rotate, reply_text
from ..physics import WORLD_FRAMES, EntityState, WorldError
from ..sim import Simulation
from ..systems import (
    RSP_PLUGIN,
    JointStatePublisher,
    RobotStatePublisher,
)
from ._convert import from_pose_msg, to_pose_msg, to_time
from ._replies import Req, Res, ServiceCallback, ServiceType, guarded_service, serve, with_warnings
from ._spawn_entity import with_joint_state_publisher, with_robot_state_options
from ._spawn_preamble import SpawnFailed, check_pose, frame_in_world, model_to_spawn

if TYPE_CHECKING:
    from rclpy.impl.rcutils_logger import RcutilsLogger
    from rclpy.service import Service

RSP_WATCH_SEC = 30.0
"""How long after a spawn the user's robot_state_publisher may still appear and take the robot's TF over."""


def relative_state(entity: EntityState, frame: EntityState | None) -> tuple[Pose, Vec3, Vec3]:
    """An entity's pose, linear and angular velocity as gazebo_ros's ``/get_entity_state`` reports them in a
    reference frame (gazebo_ros_state.cpp ``GetEntityState``): the pose relative to the frame's, and each
    velocity less the frame's, turned into the frame's axes; unchanged against the world (``frame`` None).
    Upstream's arithmetic, kept as it is: the linear difference omits the ``ω × r`` a rigid frame would add,
    so it is the difference of the two points' world velocities, seen in the frame's axes."""
    if frame is None:
        return entity.pose, entity.linear_velocity, entity.angular_velocity
    q_inv = quat_conj(frame.pose.orientation)
    (ex, ey, ez), (fx, fy, fz) = entity.linear_velocity, frame.linear_velocity
    (ax, ay, az), (bx, by, bz) = entity.angular_velocity, frame.angular_velocity
    lin = quat_rotate(q_inv, (ex - fx, ey - fy, ez - fz))
    ang = quat_rotate(q_inv, (ax - bx, ay - by, az - bz))
    return frame.pose.inverse() * entity.pose, lin, ang


class GazeboServices:
    """gazebo_ros's services and spawning from XML, registered on the simulation's node (see the module
    docstring)."""

    def __init__(self, node: Node, sim: Simulation, callback_group: ReentrantCallbackGroup):
        """Serve gazebo_ros's services on ``node`` (at the root, and ROS 1's names) for ``sim``, every callback in
        ``callback_group``; and, every 0.5 s, hand a robot's TF to a robot_state_publisher the user starts
        (:meth:`_watch_for_user_publishers`)."""
        self.node = node
        self.sim = sim
        self._cb = callback_group
        self._lock = threading.Lock()
        self._watched: dict[str, tuple[str, float]] = {}
        """Entity -> (its description topic, until when): see :meth:`_watch_for_user_publishers`."""
        node.create_timer(0.5, self._watch_for_user_publishers, callback_group=callback_group)
        self.services = self._serve_gazebo_services()

    def get_logger(self) -> RcutilsLogger:
        """The node's logger (gazebo_ros's services log as the ``gazelle`` node)."""
        return self.node.get_logger()

    def _serve_gazebo_services(self) -> list[Service]:
        """gazebo_ros's services (ROS 2 names, and ROS 1's that the seed's chessboard spawner calls)."""

        def one(srv_type: ServiceType[Req, Res], name: str, cb: ServiceCallback[Req, Res]) -> Service:
            return serve(self.node, srv_type, name, guarded_service(name, cb), self._cb)

        return [
            one(GzSpawnEntity, "/spawn_entity", self._gz_spawn),
            one(GzDeleteEntity, "/delete_entity", self._gz_delete),
            one(GzGetEntityState, "/get_entity_state", self._gz_get_state),
            one(GzSetEntityState, "/set_entity_state", self._gz_set_state),
            one(GzGetModelList, "/get_model_list", self._gz_model_list),
            one(Empty, "/pause_physics", self._pause),
            one(Empty, "/unpause_physics", self._unpause),
            one(Empty, "/reset_simulation", self._reset_simulation),
            one(Empty, "/reset_world", self._reset_world),
            # ROS 1 gazebo_ros's names (the seed's chessboard spawner calls /gazebo/spawn_sdf_model)
            one(GzSpawnModel, "/gazebo/spawn_sdf_model", self._ros1_spawn),
            one(GzSpawnModel, "/gazebo/spawn_urdf_model", self._ros1_spawn),
            one(GzDeleteModel, "/gazebo/delete_model", self._ros1_delete),
            one(GzGetModelState, "/gazebo/get_model_state", self._ros1_get_state),
            one(GzSetModelState, "/gazebo/set_model_state", self._ros1_set_state),
        ]

    def spawn_xml(
        self, xml: str, *, name: str, namespace: str, pose: Pose, reference_frame: str, source: str
    ) -> tuple[str, list[str]]:
        """Parse and spawn; returns the entity name and the description's warnings.

        Raises:
            SpawnFailed: the pose is not finite or out of reach, the XML is bad or holds no model, or the frame
                is unknown.
            WorldError: the world refused (duplicate name, NaN pose, build failure).
        """
        check_pose(pose, "initial_pose")
        auto = RSP_PLUGIN not in xml
        xml = self._leave_tf_to_a_running_publisher(xml, namespace)
        watch = auto and RSP_PLUGIN not in xml  # gazelle publishes its TF: unless the user's shows up soon
        model, warnings = model_to_spawn(xml, source=source, logger=self.get_logger())
        X_WF = frame_in_world(self.sim, reference_frame, "reference_frame")
        entity = self.sim.spawn(model, name=name or model.name, pose=X_WF * pose, namespace=namespace)
        if watch:
            ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
            with self._lock:
                self._watched[entity.name] = (f"{ns}/robot_description", time.monotonic() + RSP_WATCH_SEC)
        return entity.name, list(warnings)

    def _watch_for_user_publishers(self) -> None:
        """A robot spawned while the user's robot_state_publisher was still starting (a launch file starts both
        at once: TurtleBot3's jazzy turtlebot3_world.launch.py even lists the spawn first) kept gazelle's own
        publisher beside it. For :data:`RSP_WATCH_SEC` after a spawn, once the graph shows a
        robot_state_publisher on the robot's description topic, gazelle's stops and takes back its /tf,
        /tf_static part and description, when the robot publishes joint states for the user's (its joint
        state publisher plugin, or ros2_control)."""
        now = time.monotonic()
        with self._lock:
            watched = dict(self._watched)
        for entity_name, (topic, deadline) in watched.items():
            if now > deadline:
                with self._lock:
                    self._watched.pop(entity_name, None)
                continue
            try:
                names = {p.node_name for p in self.node.get_publishers_info_by_topic(topic)}
            except Exception:
                names = set()
            if "robot_state_publisher" not in names:
                continue
            with self._lock:
                self._watched.pop(entity_name, None)

            def hand_over(entity_name: str = entity_name) -> bool:
                from ..systems.ros2_control import ControllerManager

                entity = self.sim.world.entities.get(entity_name)
                if entity is None:
                    return False
                if not any(isinstance(s, (JointStatePublisher, ControllerManager)) for s in entity.systems):
                    return False  # the user's publisher would have no joint states to turn into TF
                for system in entity.systems:
                    if isinstance(system, RobotStatePublisher):
                        system.stop_publishing()
                return True

            try:
                if self.sim.call(hand_over):
                    self.get_logger().info(
                        f"a robot_state_publisher now publishes {topic}: gazelle's built-in one is off for "
                        f"'{entity_name}'"
                    )
            except (WorldError, TimeoutError):
                pass

    def _leave_tf_to_a_running_publisher(self, xml: str, namespace: str) -> str:
        """A spawn's XML with gazelle's built-in robot_state_publisher off when the user runs their own in the
        robot's namespace (a node named robot_state_publisher publishing ``<ns>/robot_description``), and a
        joint state publisher for it unless the model has one or ros2_control (whose joint_state_broadcaster
        publishes them). Gazebo publishes no robot TF of its own: TurtleBot3's turtlebot3_world.launch.py runs
        robot_state_publisher with the URDF and spawns model.sdf with -file, and gazelle's built-in publisher
        made /tf_static go out twice. The server's graph decides (a spawner's own is seconds from complete);
        a model that configures the built-in publisher (-no_robot_state_publisher, -frame_prefix, a -topic
        spawn) is left as it is."""
        if RSP_PLUGIN in xml:
            return xml
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
        try:
            publishers = self.node.get_publishers_info_by_topic(f"{ns}/robot_description")
        except Exception:  # a namespace that is no valid topic: the spawn says so itself
            return xml
        if not any(p.node_name == "robot_state_publisher" for p in publishers):
            return xml
        self.get_logger().info(
            f"a running robot_state_publisher publishes {ns}/robot_description: gazelle's built-in one is off "
            "for this robot, which publishes joint_states for it (or its ros2_control joint_state_broadcaster)"
        )
        return with_robot_state_options(with_joint_state_publisher(xml), enabled=False, frame_prefix=None)

    def _gz_spawn(self, req: GzSpawnEntity.Request, res: GzSpawnEntity.Response) -> GzSpawnEntity.Response:
        """gazebo_ros's ``/spawn_entity`` (gazebo_ros_factory.cpp): the XML (URDF, SDF or xacro output) spawned
        as ``name`` at ``initial_pose`` in ``reference_frame``, its plugins under ``robot_namespace``; Gazebo's
        "SpawnEntity: Successfully spawned entity [name]" or a one-line failure, the world unchanged."""
        t0 = time.monotonic()
        label = req.name or "entity"
        try:
            name, warnings = self.spawn_xml(
                req.xml,
                name=req.name,
                namespace=req.robot_namespace,
                pose=from_pose_msg(req.initial_pose),
                reference_frame=req.reference_frame,
                source=f"<spawn_entity:{label}>",
            )
        except (SpawnFailed, WorldError, TimeoutError) as err:
            res.success = False
            res.status_message = reply_text(f"SpawnEntity: Failure - {err}")
            self.get_logger().error(res.status_message)
            return res
        res.success = True
        res.status_message = f"SpawnEntity: Successfully spawned entity [{name}]" + with_warnings(warnings)
        self.get_logger().info(f"{res.status_message} in {1000 * (time.monotonic() - t0):.1f} ms")
        return res

    def _gz_delete(self, req: GzDeleteEntity.Request, res: GzDeleteEntity.Response) -> GzDeleteEntity.Response:
        """gazebo_ros's ``/delete_entity``: the entity and its plugins, topics and nodes go; the others stay
        bit-identical."""
        try:
            self.sim.delete(req.name)
        except (WorldError, TimeoutError) as err:
            res.success = False
            res.status_message = reply_text(f"DeleteEntity: Failure - {err}")
            return res
        res.success = True
        res.status_message = f"Successfully deleted entity [{req.name}]"
        return res

    def _gz_get_state(self, req: GzGetEntityState.Request, res: GzGetEntityState.Response) -> GzGetEntityState.Response:
        """gazebo_ros's ``/get_entity_state`` (gazebo_ros_state.cpp): ``model`` or ``model::link``, its pose and
        twist in ``reference_frame`` (an entity or link name; empty or ``world`` is the world), stamped with
        the simulation time."""
        entity, _, link = req.name.partition("::")
        frame = req.reference_frame

        def query() -> tuple[EntityState, EntityState | None, float]:
            world = self.sim.world
            st = world.entity_state(entity, link or None)
            fe, _, fl = frame.partition("::")
            return st, None if frame in WORLD_FRAMES else world.entity_state(fe, fl or None), world.time

        try:
            st, frame_state, t = self.sim.call(query)
        except (WorldError, TimeoutError) as err:
            res.success = False
            self.get_logger().error(f"GetEntityState: {err}")
            return res
        X_FE, lin, ang = relative_state(st, frame_state)
        res.header.stamp = to_time(t)
        res.header.frame_id = frame
        res.state.name = req.name
        res.state.pose = to_pose_msg(X_FE)
        res.state.twist.linear.x, res.state.twist.linear.y, res.state.twist.linear.z = lin
        res.state.twist.angular.x, res.state.twist.angular.y, res.state.twist.angular.z = ang
        res.state.reference_frame = frame
        res.success = True
        return res

    def _gz_set_state(self, req: GzSetEntityState.Request, res: GzSetEntityState.Response) -> GzSetEntityState.Response:
        """gazebo_ros's ``/set_entity_state`` (gazebo_ros_state.cpp): pose and twist given in
        ``reference_frame``, applied on the simulation thread between steps."""
        s = req.state
        entity, _, _link = s.name.partition("::")
        try:
            X_WF = frame_in_world(self.sim, s.reference_frame, "reference_frame")
            pose = X_WF * from_pose_msg(s.pose)
            lin = quat_rotate(X_WF.orientation, (s.twist.linear.x, s.twist.linear.y, s.twist.linear.z))
            ang = quat_rotate(X_WF.orientation, (s.twist.angular.x, s.twist.angular.y, s.twist.angular.z))
            self.sim.call(lambda: self.sim.world.set_entity_state(entity, pose, lin, ang))
        except (SpawnFailed, WorldError, TimeoutError) as err:
            self.get_logger().error(f"SetEntityState: {err}")
            res.success = False
            return res
        res.success = True
        return res

    # ------------------------------------------------------------------ ROS 1 names
    def _ros1_spawn(self, req: GzSpawnModel.Request, res: GzSpawnModel.Response) -> GzSpawnModel.Response:
        """/gazebo/spawn_sdf_model and /gazebo/spawn_urdf_model: SpawnEntity under ROS 1's names."""
        inner = GzSpawnEntity.Request(
            name=req.model_name,
            xml=req.model_xml,
            robot_namespace=req.robot_namespace,
            initial_pose=req.initial_pose,
            reference_frame=req.reference_frame,
        )
        out = self._gz_spawn(inner, GzSpawnEntity.Response())
        res.success = out.success
        res.status_message = out.status_message.replace("SpawnEntity:", "SpawnModel:", 1)
        return res

    def _ros1_delete(self, req: GzDeleteModel.Request, res: GzDeleteModel.Response) -> GzDeleteModel.Response:
        """/gazebo/delete_model."""
        out = self._gz_delete(GzDeleteEntity.Request(name=req.model_name), GzDeleteEntity.Response())
        res.success = out.success
        res.status_message = out.status_message.replace("DeleteEntity:", "DeleteModel:", 1)
        return res

    def _ros1_get_state(self, req: GzGetModelState.Request, res: GzGetModelState.Response) -> GzGetModelState.Response:
        """/gazebo/get_model_state: the entity's pose and twist relative to ``relative_entity_name``."""
        out = self._gz_get_state(
            GzGetEntityState.Request(name=req.model_name, reference_frame=req.relative_entity_name),
            GzGetEntityState.Response(),
        )
        res.success = out.success
        res.header = out.header
        res.pose = out.state.pose
        res.twist = out.state.twist
        where = f"model [{req.model_name}] or frame [{req.relative_entity_name}]"
        res.status_message = "GetModelState: got properties" if out.success else f"GetModelState: no {where}"
        return res

    def _ros1_set_state(self, req: GzSetModelState.Request, res: GzSetModelState.Response) -> GzSetModelState.Response:
        """/gazebo/set_model_state."""
        m = req.model_state
        inner = GzSetEntityState.Request()
        inner.state.name = m.model_name
        inner.state.pose = m.pose
        inner.state.twist = m.twist
        inner.state.reference_frame = m.reference_frame
        out = self._gz_set_state(inner, GzSetEntityState.Response())
        res.success = out.success
        res.status_message = (
            "SetModelState: set model state done"
            if out.success
            else (f"SetModelState: could not set the state of [{m.model_name}] (see the server's log)")
        )
        return res

    def _gz_model_list(self, req: GzGetModelList.Request, res: GzGetModelList.Response) -> GzGetModelList.Response:
        """gazebo_msgs' ``/get_model_list``: the entities' names, the world's own models included, at the
        simulation time."""
        names, t = self.sim.call(lambda: (list(self.sim.world.entities), self.sim.world.time))
        res.header.stamp = to_time(t)
        res.model_names = names
        res.success = True
        return res

    def _pause(self, req: Empty.Request, res: Empty.Response) -> Empty.Response:
        """gazebo_ros_init.cpp's ``/pause_physics``: steps stop, /clock stops, services keep answering."""
        self.sim.call(lambda: setattr(self.sim, "paused", True))
        return res

    def _unpause(self, req: Empty.Request, res: Empty.Response) -> Empty.Response:
        """gazebo_ros_init.cpp's ``/unpause_physics``."""
        self.sim.call(lambda: setattr(self.sim, "paused", False))
        return res

    def _reset_simulation(self, req: Empty.Request, res: Empty.Response) -> Empty.Response:
        """gazebo_ros_init.cpp's ``/reset_simulation`` (world->Reset()): time to zero and every entity back to
        where it started; spawned entities stay."""
        self.sim.reset(time_=True, state=True, spawned=False)
        return res

    def _reset_world(self, req: Empty.Request, res: Empty.Response) -> Empty.Response:
        """gazebo_ros_init.cpp's ``/reset_world`` (world->ResetEntities): every entity back to where it started,
        the time goes on."""
        self.sim.reset(time_=False, state=True, spawned=False)
        return res
