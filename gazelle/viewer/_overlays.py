"""The viewer's overlays (:class:`ViewerOverlays`, owned by :class:`~gazelle.viewer.Viewer`): the path
trail (from odometry or ground truth), MoveIt's planned paths heard on :data:`PLAN_TOPIC`, contact points,
where each lidar's rays hit, and the chosen camera's image. Each is sampled on the simulation thread
(``sim.call``) at the panel's rate and drawn only while its box is ticked; see :mod:`._viewer` for the
threads."""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Collection
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import viser

from ..description import JointType, Model, Pose
from ..systems import DisplayTrajectory, Endpoint, MsgType
from ..systems.sensors import Camera, Lidar

if TYPE_CHECKING:
    from ..sim import Simulation


_log = logging.getLogger("gazelle.viewer")
TRAIL_RGB = (230, 30, 140)
TRAIL_RATE_HZ = 5.0
"""Trail samples per wall second (and trail redraws while a browser is connected)."""
TRAIL_MAX_POINTS = 3000
TRAIL_MIN_STEP = 0.005
"""Metres the robot must move before a new trail point is kept."""
TRAIL_ODOM = "odom"
TRAIL_TRUTH = "ground truth"
TRAIL_SOURCES = (TRAIL_ODOM, TRAIL_TRUTH)
CONTACT_RGB = (230, 20, 20)
CONTACT_MAX = 500
LIDAR_RGB = (20, 200, 60)
PLAN_RGB = (30, 110, 255)
NO_SELECTION = "(none)"
LIDAR_MAX_POINTS = 50_000
NO_CAMERA = "(none)"
PLAN_TOPIC = "/display_planned_path"
"""Where MoveIt's move_group (and gazelle's) publishes each planned motion (moveit_msgs/DisplayTrajectory)."""


@dataclass(frozen=True)
class _TrailSample:
    time: float
    generation: int
    truth: Pose
    """The root link's pose in the world."""
    odom_topic: str | None
    """The entity's odometry topic (a diff drive's ``odom``), if it has one."""
    odom: Any
    """The latest message on it (``systems._payloads.Odometry``), if any yet."""


def _odom_frame_in_world(truth: Pose, odom: Any, now: float) -> tuple[float, float, float]:
    """The planar (x, y, yaw) of the odometry frame in the world, from one pair of poses.

    The message is up to an update period old: it is first carried forward to ``now`` with its
    own twist (base frame), so a robot that is moving when the trail starts gets no offset.
    """
    dt = max(0.0, now - odom.stamp_sec)
    ox, oy, _ = odom.pose.position
    oyaw = odom.pose.rpy[2]
    vx, vy, _ = odom.twist.linear
    c, s = math.cos(oyaw), math.sin(oyaw)
    ox, oy, oyaw = ox + (c * vx - s * vy) * dt, oy + (s * vx + c * vy) * dt, oyaw + odom.twist.angular[2] * dt
    tx, ty, _ = truth.position
    yaw = truth.rpy[2] - oyaw
    c, s = math.cos(yaw), math.sin(yaw)
    return tx - (c * ox - s * oy), ty - (s * ox + c * oy), yaw


@dataclass(frozen=True)
class PlannedPath:
    """What the viewer draws of the latest planned motion: for each tip of the moving chains (an arm's
    flange or tool centre point), its path in the world and its pose at the end, the goal."""

    entity: str
    tips: tuple[str, ...]
    paths: tuple[np.ndarray, ...]
    """Per tip: N x 3 world positions along the plan."""
    goals: tuple[Pose, ...]
    """Per tip: the world pose at the plan's last point."""


def plan_tips(model: Model, joints: set[str]) -> list[str]:
    """The links whose path shows a motion of ``joints``: below each joint with no other moving joint
    under it, the child link, then down single fixed joints (``link7`` -> ``link8`` -> ``hand`` ->
    ``hand_tcp``), stopping where a link has no fixed child or several."""
    children: dict[str, list[tuple[str, str, JointType]]] = {}
    for j in model.joints:
        children.setdefault(j.parent, []).append((j.name, j.child, j.type))

    def below(link: str) -> bool:  # a moving joint somewhere under this link
        return any(name in joints or below(child) for name, child, _ in children.get(link, []))

    tips = []
    for j in model.joints:
        if j.name not in joints or below(j.child):
            continue
        link = j.child
        while True:
            fixed = [child for _, child, kind in children.get(link, []) if kind == JointType.FIXED]
            if len(fixed) != 1:
                break
            link = fixed[0]
        tips.append(link)
    return tips


def void(_result: object) -> None:
    """Nothing, whatever it is given: a GUI callback drops what the update it runs returns (viser's callbacks
    return None)."""


def safe_name(name: str) -> str:
    return name.replace("/", "_").replace(" ", "_") or "_"


class ViewerOverlays:
    """The overlays a :class:`~gazelle.viewer.Viewer` owns: their state, their part of the panel (the Overlays
    and Camera folders, :meth:`add_panel`) and their drawing in the viewer's scene."""

    def __init__(self, sim: Simulation, server: viser.ViserServer, selected: Callable[[], str]) -> None:
        """Overlays of ``sim`` drawn on ``server``'s scene; ``selected()`` is the entity chosen in the viewer's
        panel (:data:`NO_SELECTION` for none), whose path the trail follows."""
        self.sim = sim
        self.server = server
        self._selected = selected
        self._trail: list[tuple[float, float, float]] = []
        self._trail_entity: tuple[str, int, str] | None = None
        """(entity, generation added, source) the trail belongs to; a change starts a new trail."""
        self._trail_anchor: tuple[float, float, float] | None = None
        """/odom trails: the odometry frame in the world, planar (x, y, yaw)."""
        self._trail_handle: Any = None
        self._odom_heard: Endpoint | None = None
        """The odometry endpoint the trail listens to."""
        self._trail_drawn: tuple[int, tuple[float, float, float] | None] | int = -1
        """What the trail drawn last showed (points, anchor); -1 before the first drawing."""
        self._trail_last_t = -1.0
        self._contact_handle: Any = None
        self._lidar_handles: dict[str, Any] = {}
        self._plan_heard: DisplayTrajectory | None = None
        """The latest planned motion heard on :data:`PLAN_TOPIC`, not yet turned into a path."""
        self.planned: PlannedPath | None = None
        """The planned motion drawn (its tips' paths and goals), for tests and the panel."""
        self._plan_drawn: tuple[PlannedPath | None, bool] = (None, True)
        self._plan_handles: list[Any] = []

    # ------------------------------------------------------------------ panel
    def add_panel(self, g: viser.GuiApi, on_frames: Callable[[], None]) -> None:
        """The Overlays and Camera folders of the panel, each control wired to what it draws; the TF frames and
        collision geometry switches call ``on_frames`` (the viewer shows or hides its entities' nodes)."""
        with g.add_folder("Overlays", expand_by_default=False):
            self._tf_box = g.add_checkbox("TF frames", initial_value=False)
            self._col_box = g.add_checkbox("Collision geometry", initial_value=False)
            self._trail_box = g.add_checkbox(
                "Path trail",
                initial_value=True,
                hint="Path of the selected entity (or of the first diff-drive robot)",
            )
            self._trail_source = g.add_dropdown(
                "Trail source",
                options=TRAIL_SOURCES,
                initial_value=TRAIL_ODOM,
                hint="odom: what the robot's odometry topic reports (ground truth for entities without one)",
            )
            self._trail_text = g.add_text("Trail of", initial_value="", disabled=True)
            self._contact_box = g.add_checkbox("Contact points", initial_value=False, hint="MuJoCo contacts (red)")
            self._lidar_box = g.add_checkbox(
                "Lidar points", initial_value=True, hint="Where each lidar's rays hit now (green, noise-free)"
            )
            self._plan_box = g.add_checkbox(
                "Planned path",
                initial_value=True,
                hint=f"The latest arm motion planned ({PLAN_TOPIC}): the tool's path (blue) and goal (axes)",
            )
        # a camera sensor's live image, rendered for the panel (directly, not through its ROS topic) at the
        # panel's rate while one is chosen
        with g.add_folder("Camera", expand_by_default=False):
            camera_options: list[str] = [NO_CAMERA]
            self._camera_dd = g.add_dropdown(
                "Camera", options=camera_options, initial_value=NO_CAMERA, hint="A camera sensor's image, live"
            )
            self._camera_img = g.add_image(np.zeros((48, 64, 3), dtype=np.uint8), label="Image", format="jpeg")
        # callbacks run on viser's event-loop thread: what touches the world goes through Simulation.call
        self._tf_box.on_update(lambda _e: on_frames())
        self._col_box.on_update(lambda _e: on_frames())
        self._trail_box.on_update(lambda _e: self.redraw_trail(force=True))
        self._contact_box.on_update(lambda _e: void(self._update_contacts()))
        self._lidar_box.on_update(lambda _e: void(self._update_lidars()))
        self._plan_box.on_update(lambda _e: self._redraw_plan())

    @property
    def show_frames(self) -> bool:
        """The TF frames switch: each link's axes shown."""
        return bool(self._tf_box.value)

    @property
    def show_collisions(self) -> bool:
        """The collision geometry switch: each link's collision shapes shown as wireframes."""
        return bool(self._col_box.value)

    def hear_plan(self, plan: DisplayTrajectory) -> None:
        """A planned motion arrived on :data:`PLAN_TOPIC` (any thread): kept for the viewer thread, which draws
        the latest."""
        self._plan_heard = plan

    def refresh(self, entities: Collection[str] | None) -> None:
        """At the panel's rate, with a browser connected: contacts, lidar points and the planned path (each while
        on, or to clear it), and the camera image; ``entities`` are the world's as the last frame saw them."""
        if self._contact_box.value or self._contact_handle is not None:
            self._update_contacts()
        if self._lidar_box.value or self._lidar_handles:
            self._update_lidars()
        if self._plan_heard is not None or self.planned is not None:
            self.update_plan(entities)
        self._update_camera()

    def trail_target(self) -> str | None:
        """The entity whose path is drawn: the selected one, else the first with a cmd_vel subscriber."""
        sel = self._selected()
        names = self.sim.call(lambda: set(self.sim.world.entities), timeout=5.0)  # the world is the sim thread's
        if sel != NO_SELECTION and sel in names:
            return sel
        driven = sorted(
            {ep.owner for ep in self.sim.bus.endpoints() if not ep.is_publisher and ep.msg_type == MsgType.TWIST}
        )
        return next((n for n in driven if n in names), None)

    def _trail_sample(self, name: str) -> _TrailSample | None:
        """Runs on the sim thread: ``name``'s root link pose and its latest odometry message."""
        w = self.sim.world
        e = w.entities.get(name)
        if e is None:
            return None
        link = next((ln for ln, b in e.built.bodies.items() if b == e.built.root_body), None)
        odom = next(
            (
                ep
                for ep in self.sim.bus.endpoints()
                if ep.owner == name and ep.is_publisher and ep.msg_type == MsgType.ODOMETRY
            ),
            None,
        )
        if odom is not self._odom_heard:  # listen to the target's odometry (nothing is built for nobody)
            if self._odom_heard is not None:
                self._odom_heard.remove_sink(self._hear_odom)
            if odom is not None:
                odom.add_sink(self._hear_odom)
            self._odom_heard = odom
        return _TrailSample(
            w.time,
            e.generation_added,
            w.body_pose(w.body_id(name, link)),
            odom.topic if odom is not None else None,
            odom.last if odom is not None else None,
        )

    def _hear_odom(self, _payload: Any) -> None:
        """The trail's sink on its target's odometry endpoint: the endpoint keeps the latest message."""

    def sample_trail(self) -> None:
        """Add the trail target's current position to the trail (a new trail on a new target, source or reset).

        The "odom" source draws what the target's odometry topic reports: its odom frame is placed in
        the world where the robot's ground truth and its odometry agreed when the trail started (for
        gazebo_ros' default world odometry that is the world frame itself; for encoder odometry the
        trail then shows the drift). Entities without an odometry topic get their ground truth.
        """
        if not self._trail_box.value:
            return
        name = self.trail_target()
        sample = self.sim.call(lambda: self._trail_sample(name), timeout=5.0) if name else None
        if sample is None:
            if self._trail_entity is not None:
                self._trail, self._trail_entity = [], None
                self._trail_text.value = ""
            return
        source = TRAIL_ODOM if self._trail_source.value == TRAIL_ODOM and sample.odom_topic else TRAIL_TRUTH
        assert name is not None
        if self._trail_entity != (name, sample.generation, source) or sample.time < self._trail_last_t:
            self._trail, self._trail_entity, self._trail_anchor = [], (name, sample.generation, source), None
            label = (sample.odom_topic or "") if source == TRAIL_ODOM else "ground truth"
            if self._trail_source.value == TRAIL_ODOM and source != TRAIL_ODOM:
                label += ": no odometry topic"
            self._trail_text.value = f"{name} ({label})"
        self._trail_last_t = sample.time
        if source == TRAIL_TRUTH:
            p = sample.truth.position
            pos = (float(p[0]), float(p[1]), float(p[2]))
        else:
            odom = sample.odom
            if odom is None or odom.stamp_sec > sample.time:
                return  # nothing published yet, or the last message is from before a reset
            if self._trail_anchor is None:
                self._trail_anchor = _odom_frame_in_world(sample.truth, odom, sample.time)
            x, y, yaw = self._trail_anchor
            ox, oy, oz = odom.pose.position
            c, s_ = math.cos(yaw), math.sin(yaw)
            pos = (x + c * ox - s_ * oy, y + s_ * ox + c * oy, float(oz))
        if not self._trail or math.dist(self._trail[-1], pos) >= TRAIL_MIN_STEP:
            self._trail.append(pos)
            if len(self._trail) > TRAIL_MAX_POINTS:
                del self._trail[: len(self._trail) - TRAIL_MAX_POINTS]

    @property
    def trail(self) -> list[tuple[float, float, float]]:
        """The trail's points (world frame), oldest first."""
        return list(self._trail)

    def redraw_trail(self, *, force: bool = False) -> None:
        """Draw the path trail as line segments just above the ground, only when it changed (a new point, or the
        overlay switched)."""
        pts = self._trail if self._trail_box.value else []
        key = (len(pts), pts[-1] if pts else None)
        if not force and key == self._trail_drawn:
            return
        self._trail_drawn = key
        if self._trail_handle is not None:
            self._trail_handle.remove()
            self._trail_handle = None
        if len(pts) >= 2:
            a = np.asarray(pts, dtype=np.float32)
            a[:, 2] = 0.02  # just above the ground and the world axes (radius 1 cm), below the robot bodies
            segs = np.stack([a[:-1], a[1:]], axis=1)
            self._trail_handle = self.server.scene.add_line_segments(
                "/overlays/trail", segs, TRAIL_RGB, thickness=4.0, thickness_units="screen"
            )

    def _plan_path(self, plan: DisplayTrajectory) -> PlannedPath | None:
        """Runs on the sim thread: the tips' paths along ``plan`` (forward kinematics of the robot that
        has its joints: the entity named ``model_id`` if it does, else the first that does), or None
        when no entity has them."""
        w = self.sim.world
        trajectories = [t for t in plan.trajectories if t.joint_names and t.points]
        joints = {j for t in trajectories for j in t.joint_names}
        if not joints:
            return None
        candidates = sorted(w.entities.values(), key=lambda e: e.name != plan.model_id)
        entity = next((e for e in candidates if joints <= {j.name for j in e.model.joints}), None)
        if entity is None:
            return None
        tips = plan_tips(entity.model, joints)
        paths: list[list[Pose]] = [[] for _ in tips]
        for t in trajectories:
            rows = [p.positions for p in t.points if len(p.positions) == len(t.joint_names)]
            for i, tip in enumerate(tips):
                paths[i] += w.link_poses_along(entity.name, tip, t.joint_names, rows)
        kept = [(tip, poses) for tip, poses in zip(tips, paths) if poses]
        return PlannedPath(
            entity.name,
            tuple(tip for tip, _ in kept),
            tuple(np.array([p.position for p in poses], dtype=np.float32) for _, poses in kept),
            tuple(poses[-1] for _, poses in kept),
        )

    def update_plan(self, entities: Collection[str] | None = None) -> PlannedPath | None:
        """Turn the latest planned motion heard into paths (on the sim thread) and draw them; a plan whose
        robot is not among ``entities`` (the last frame's; None: not known yet) is cleared. Returns what is
        drawn."""
        heard, self._plan_heard = self._plan_heard, None
        if heard is not None:
            try:
                self.planned = self.sim.call(lambda: self._plan_path(heard), timeout=5.0)
            except Exception as err:  # a plan for joints the world cannot pose: nothing to draw
                _log.warning("viewer: cannot draw the planned path: %s", err)
                self.planned = None
        planned = self.planned
        if planned is not None and entities is not None and planned.entity not in entities:
            self.planned = None
        self._redraw_plan()
        return self.planned

    def _redraw_plan(self) -> None:
        """Draw the latest planned arm motion: each tool path as blue segments and its goal as axes; only when the
        plan or the switch changed."""
        shown = bool(self._plan_box.value)
        # by identity: a PlannedPath holds numpy arrays, and == between two of other lengths raised
        # "operands could not be broadcast" on every redraw (issue 27), leaving the old path drawn
        drawn, was_shown = self._plan_drawn
        if drawn is self.planned and was_shown == shown:
            return
        self._plan_drawn = (self.planned, shown)
        for handle in self._plan_handles:
            handle.remove()
        self._plan_handles = []
        if self.planned is None or not shown:
            return
        scene = self.server.scene
        for i, (path, goal) in enumerate(zip(self.planned.paths, self.planned.goals)):
            if len(path) >= 2:
                segs = np.stack([path[:-1], path[1:]], axis=1)
                self._plan_handles.append(
                    scene.add_line_segments(
                        f"/overlays/plan/{i}/path", segs, PLAN_RGB, thickness=5.0, thickness_units="screen"
                    )
                )
            self._plan_handles.append(
                scene.add_frame(
                    f"/overlays/plan/{i}/goal",
                    wxyz=goal.orientation,
                    position=goal.position,
                    axes_length=0.12,
                    axes_radius=0.008,
                )
            )

    def _contacts(self) -> np.ndarray:
        """Runs on the sim thread: the contact points (N x 3)."""
        d = self.sim.world.data
        n = min(int(d.ncon), CONTACT_MAX)
        return np.array(d.contact.pos[:n], dtype=np.float32).reshape(n, 3)

    def _update_contacts(self) -> np.ndarray | None:
        """Draw the world's contact points (read on the simulation thread) as red dots while the overlay is on; the
        points drawn."""
        pts = self.sim.call(self._contacts, timeout=5.0) if self._contact_box.value else None
        if self._contact_handle is not None:
            self._contact_handle.remove()
            self._contact_handle = None
        if pts is not None and len(pts):
            self._contact_handle = self.server.scene.add_point_cloud(
                "/overlays/contacts", pts, CONTACT_RGB, point_size=0.025, point_shape="circle", precision="float32"
            )
        return pts

    def _sensor_systems(self) -> tuple[dict[str, Lidar], dict[str, Camera]]:
        """Runs on the sim thread: every running lidar and camera, by ``entity/sensor``."""
        lidars: dict[str, Lidar] = {}
        cameras: dict[str, Camera] = {}
        for e in self.sim.world.entities.values():
            for s in e.systems:
                if not isinstance(s, (Lidar, Camera)) or s.sensor is None or s.next_update(0.0) == math.inf:
                    continue
                key = f"{e.name}/{s.sensor.name}"
                if isinstance(s, Lidar):
                    lidars[key] = s
                else:
                    cameras[key] = s
        return lidars, cameras

    def _lidar_points(self) -> dict[str, np.ndarray]:
        """Runs on the sim thread: each lidar's hit points now (world frame)."""
        lidars, _ = self._sensor_systems()
        return {key: lidar.world_points(self.sim.world)[:LIDAR_MAX_POINTS] for key, lidar in lidars.items()}

    def _update_lidars(self) -> dict[str, np.ndarray]:
        """Redraw the lidar overlay (or clear it when unticked); returns the points drawn per lidar."""
        pts = self.sim.call(self._lidar_points, timeout=5.0) if self._lidar_box.value else {}
        for key in [k for k in self._lidar_handles if k not in pts]:
            self._lidar_handles.pop(key).remove()
        for key, p in pts.items():
            old = self._lidar_handles.pop(key, None)
            if old is not None:
                old.remove()
            if len(p):
                self._lidar_handles[key] = self.server.scene.add_point_cloud(
                    f"/overlays/lidar/{safe_name(key)}",
                    p,
                    LIDAR_RGB,
                    point_size=0.03,
                    point_shape="circle",
                    precision="float32",
                )
        return pts

    def _camera_image(self, key: str) -> tuple[list[str], np.ndarray | None]:
        """Runs on the sim thread: the camera names, and the image of camera ``key`` (None: no such camera)."""
        _, cameras = self._sensor_systems()
        cam = cameras.get(key)
        out = cam.render(self.sim.world, depth=False) if cam is not None else None
        return sorted(cameras), (out[0] if out is not None else None)

    def _update_camera(self) -> np.ndarray | None:
        """Refresh the Camera dropdown and, with a camera chosen, its image; returns the image shown."""
        key = self._camera_dd.value
        names, image = self.sim.call(lambda: self._camera_image(key), timeout=5.0)
        options = [NO_CAMERA, *names]
        if tuple(self._camera_dd.options) != tuple(options):
            self._camera_dd.options = options
            if key not in options:
                self._camera_dd.value = NO_CAMERA
        if image is not None:
            self._camera_img.image = image
        return image
