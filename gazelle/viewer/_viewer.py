"""The browser viewer: a viser server showing and controlling a running :class:`Simulation`.

Threads: viser serves the browser on its own threads; one viewer thread polls the
world at ``rate_hz`` through ``sim.call`` (one call per frame returns every body
pose, the sim time and the entity set), so MuJoCo data is only ever read on the
simulation thread and the frame rate is independent of the physics rate. GUI
callbacks (buttons) also hand their work to the sim thread with ``sim.call``.

Selecting: the Entities dropdown is the selection (pose, Delete, Drive and the trail
follow it). Clicking an entity's visual geometry in the 3D view sets it too: every
visual mesh of a selectable entity gets a viser ``on_click`` callback (registered
once when the mesh is added, so it costs no per-frame messages; viser then outlines
the hovered mesh and shows a pointer cursor, and a press that moves, i.e. an orbit,
is not a click). Static world scenery (static models that came with the world, such
as the ground plane) is not clickable; spawned models are, static or not (the chess
board, each chess piece). Collision overlays are not clickable (the click goes through
their wireframe to the visual inside). Clicking elsewhere does not deselect: choose
"(none)" in the dropdown.

Driving: the viewer publishes ``cmd_vel`` the way teleop_twist_keyboard does,
by delivering a Twist to every cmd_vel subscription on the bus owned by the
selected entity (exactly what the ROS bridge does with a received message).
viser has no keyboard-event API; with "Keyboard drive" ticked, a small script in a
GUI HTML element turns WASD / arrow keys into clicks on the Drive buttons (held key:
drive; release: Stop) and keeps them from moving viser's camera.

Overlays (``_overlays.py``): the path trail follows the selected entity (or, with nothing selected, the
first diff-drive robot), sampled at 5 Hz even with no browser connected, at most 3000
points. Its source is the entity's odometry topic (what /odom reports, read from the bus
publisher's latest message, with the odom frame placed where odometry and ground truth
agreed when the trail started) or, chosen in the panel or for entities without
odometry, the ground-truth root position. Contact points are MuJoCo's
``data.contact``. Lidar points are where each lidar's rays hit now (noise-free, cast again at the
panel's rate on the sim thread, so the published scans' random noise is untouched). The Camera
panel shows the image of the camera chosen in its dropdown, rendered on the sim thread at the
panel's rate while one is chosen.
"""

from __future__ import annotations

import contextlib
import io
import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import viser

from ..description import Model, Pose, load
from ..physics import PerGeneration
from ..systems import MsgType, Twist
from ._framing import fit_view
from ._geometry import rgba_to_rgb255, to_trimesh
from ._models import ModelFile, find_models
from ._origin import OriginPolicy, guarded
from ._overlays import NO_SELECTION, PLAN_TOPIC, TRAIL_RATE_HZ, PlannedPath, ViewerOverlays, safe_name

if TYPE_CHECKING:
    from ..physics import PhysicsWorld
    from ..sim import Simulation

_log = logging.getLogger("gazelle.viewer")
# viser's websockets server logs every browser connect/close at INFO: noise in `gazelle sim`'s output
logging.getLogger("websockets").setLevel(logging.WARNING)

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8080
POSE_RATE_HZ = 30.0
GUI_RATE_HZ = 10.0
LINEAR_STEP = 0.5
"""m/s per drive button press (teleop_twist_keyboard's default ``speed``)."""
ANGULAR_STEP = 1.0
"""rad/s per turn button press (teleop_twist_keyboard's default ``turn``)."""
DRIVE_BUTTONS = {
    "Forward": (LINEAR_STEP, 0.0),
    "Back": (-LINEAR_STEP, 0.0),
    "Left": (0.0, ANGULAR_STEP),
    "Right": (0.0, -ANGULAR_STEP),
    "Stop": (0.0, 0.0),
}
"""(linear m/s, angular rad/s) each Drive button sends."""
CAMERA_POSITION = (1.6, -1.6, 1.2)
CAMERA_LOOK_AT = (0.0, 0.0, 0.05)
CAMERA_FOV_RAD = 50.0 * np.pi / 180.0
COLLISION_RGB = (255, 120, 0)
NO_MODELS = "(no models on the resource paths)"
VIEWER_OWNER = "_viewer"
"""The bus owner of the viewer's own subscriptions."""
KEYS_MARKER = "gazelle-keyboard-drive"
KEYS_HELP = "W/↑ forward, S/↓ back, A/← left, D/→ right (hold); release or Space/X: stop"
# viser has no keyboard-event API: this snippet (run through an <img onerror> in a GUI
# HTML element, as viser renders HTML without running <script>) maps keys to clicks on
# the Drive buttons, so the keys go through the same path as the buttons. It acts only
# while the marker element exists (the checkbox puts it there) and swallows the keys
# in the capture phase so viser's own WASD camera movement does not also fire.
KEYS_JS = (
    "if(!window.__gazelleKeys){window.__gazelleKeys=1;"
    "const M={KeyW:'Forward',ArrowUp:'Forward',KeyS:'Back',ArrowDown:'Back',KeyA:'Left',ArrowLeft:'Left',"
    "KeyD:'Right',ArrowRight:'Right',Space:'Stop',KeyX:'Stop'};const H=new Set();"
    "const on=()=>!!document.getElementById('" + KEYS_MARKER + "');"
    "const form=(t)=>t&&(t.tagName==='INPUT'||t.tagName==='TEXTAREA'||t.isContentEditable);"
    "const press=(n)=>{const b=[...document.querySelectorAll('button')]"
    ".find(b=>b.textContent.trim()===n);if(b)b.click();};"
    "window.addEventListener('keydown',(e)=>{if(!on()||!(e.code in M)||form(e.target))return;"
    "e.preventDefault();e.stopImmediatePropagation();if(e.repeat||H.has(e.code))return;"
    "if(M[e.code]!=='Stop')H.add(e.code);press(M[e.code]);},true);"
    "window.addEventListener('keyup',(e)=>{if(!on()||!(e.code in M)||form(e.target))return;"
    "e.preventDefault();e.stopImmediatePropagation();if(H.delete(e.code)&&H.size===0)press('Stop');},true);"
    "window.addEventListener('blur',()=>{if(H.size){H.clear();if(on())press('Stop');}});}"
)
KEYS_HTML = (
    f'<div id="{KEYS_MARKER}" style="font-size:0.8em;opacity:0.8">{KEYS_HELP}</div>'
    f'<img src="data:," alt="" style="display:none" onerror="{KEYS_JS}">'
)


@dataclass
class _LinkNode:
    frame: Any
    pose: tuple[tuple[float, ...], tuple[float, ...]] | None = None


@dataclass
class _EntityNodes:
    key: tuple[str, int]
    root: Any
    links: dict[str, _LinkNode] = field(default_factory=dict)
    visuals: list[Any] = field(default_factory=list)
    collisions: list[Any] = field(default_factory=list)
    selectable: bool = False
    """Its visuals select it when clicked (not static world scenery such as the ground plane)."""
    root_link: str | None = None


@dataclass(frozen=True)
class EntityView:
    """What the viewer thread may know of an entity, copied on the sim thread (it never reads the world)."""

    generation: int
    """The world generation it was added in (a re-spawn under the same name is a new entity)."""
    model: Model
    """Its description (immutable)."""
    links: frozenset[str]
    """The links that have a body."""
    root_link: str | None
    selectable: bool
    """Spawned, or not static: clicking its visuals selects it (not the ground plane)."""


@dataclass(frozen=True)
class Snapshot:
    """What one sim-thread call returns for a frame."""

    time: float
    paused: bool
    rtf: float
    entities: dict[str, int]
    """name -> generation it was added in (a re-spawn under the same name is a new entity)."""
    views: dict[str, EntityView]
    """name -> what the viewer needs to draw it (only for entities it does not draw yet)."""
    poses: dict[str, dict[str, tuple[tuple[float, ...], tuple[float, ...]]]]
    """entity -> link -> (position, wxyz) in the world."""


def _bodies(w: PhysicsWorld) -> list[tuple[str, str, int]]:
    """(entity, link, MuJoCo body id) of every link that has a body."""
    return [
        (e.name, link.name, w.body_id(e.name, link.name))
        for e in w.entities.values()
        for link in e.model.links
        if link.name in e.built.bodies
    ]


class Viewer:
    """A viser server mirroring a simulation; :meth:`start` it, :meth:`stop` it. Its overlays (path trail,
    planned paths, contacts, lidar points, camera image) are :attr:`overlays`."""

    def __init__(
        self,
        sim: Simulation,
        *,
        host: str = DEFAULT_HOST,
        port: int = DEFAULT_PORT,
        rate_hz: float = POSE_RATE_HZ,
        allow_origins: tuple[str, ...] = (),
    ):
        """
        Args:
            sim: the simulation to show and control.
            host: interface to bind (loopback by default; see :mod:`._origin` for what a wider one opens).
            port: port to bind, or the next free one.
            rate_hz: pose updates per second.
            allow_origins: web origins besides the viewer's own that may open its websocket.
        """
        self.sim = sim
        self.rate_hz = rate_hz
        self.origin_policy = OriginPolicy(host, allow_origins)
        with contextlib.redirect_stdout(io.StringIO()), guarded(self.origin_policy):  # viser's banner: we print our own
            self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._nodes: dict[str, _EntityNodes] = {}
        self._drawn: dict[str, int] = {}
        """Entity -> generation the viewer draws (read by the sim thread's snapshot: a new dict each frame)."""
        self._bodies = PerGeneration(_bodies)
        self._lock = threading.Lock()
        self._last: Snapshot | None = None
        self._wall0 = time.monotonic()
        self._next_trail = 0.0
        self.overlays = ViewerOverlays(sim, self.server, lambda: self._entity_dd.value)
        """What is drawn over the scene, and its part of the panel."""
        self._models: list[ModelFile] = []
        self.frames = 0
        """Frames pushed so far (for tests and the bench)."""
        self.cpu_sec = 0.0
        """CPU time the viewer thread spent on frames (for the bench)."""
        self._setup_scene()
        self._setup_gui()
        # MoveIt's planned paths: with a ROS bridge, a subscription of the simulation's node
        sim.bus.subscribe(VIEWER_OWNER, PLAN_TOPIC, MsgType.DISPLAY_TRAJECTORY, self.overlays.hear_plan, depth=1)

    # ------------------------------------------------------------------ lifecycle
    @property
    def url(self) -> str:
        """The address to open in a browser (loopback when the server listens on every interface)."""
        host = self.server.get_host()
        return f"http://{'127.0.0.1' if host in ('0.0.0.0', '') else host}:{self.server.get_port()}"

    def start(self) -> None:
        """Start the viewer thread (frames pulled from the simulation at ``rate_hz``)."""
        self._stop.clear()
        self._thread = threading.Thread(target=self._loop, name="gazelle-viewer", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the viewer thread and the web server."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(5.0)
        self.sim.bus.remove_owner(VIEWER_OWNER)
        with contextlib.redirect_stdout(io.StringIO()):
            self.server.stop()

    # ------------------------------------------------------------------ scene
    def _setup_scene(self) -> None:
        """The scene every client gets first: z up as in ROS, default lights without shadows (and no HDRI
        environment, which viser would fetch from a CDN: the viewer works offline), a 20 m ground grid of 0.5 m
        cells, the world axes and the initial camera looking at the origin."""
        s = self.server.scene
        s.set_up_direction("+z")
        # no HDRI: it would be fetched from a CDN, and gazelle works offline
        s.configure_environment_map(hdri=None)
        s.configure_default_lights(enabled=True, cast_shadow=False)
        s.add_grid("/grid", width=20.0, height=20.0, cell_size=0.5, section_size=1.0, plane="xy")
        s.add_frame("/world_axes", axes_length=0.5, axes_radius=0.01)
        cam = self.server.initial_camera
        cam.position = CAMERA_POSITION
        cam.look_at = CAMERA_LOOK_AT
        cam.up = (0.0, 0.0, 1.0)
        cam.fov = CAMERA_FOV_RAD

    def _add_entity(self, name: str, view: EntityView) -> None:
        """Add an entity's scene nodes: a frame per link (its TF axes shown when the overlay is on), its visuals as
        meshes in their link frames, and its collisions as wireframes hidden unless the overlay is on. Clicking a
        visual of a selectable entity selects it. Each frame's pose is then updated from the simulation's
        snapshots."""
        s = self.server.scene
        root_name = f"/entities/{safe_name(name)}"
        nodes = _EntityNodes((name, view.generation), s.add_frame(root_name, show_axes=False))
        nodes.selectable = view.selectable
        nodes.root_link = view.root_link
        show_tf = self.overlays.show_frames
        show_col = self.overlays.show_collisions
        for link in view.model.links:
            if link.name not in view.links:
                continue
            base = f"{root_name}/{safe_name(link.name)}"
            frame = s.add_frame(base, show_axes=show_tf, axes_length=0.1, axes_radius=0.004)
            nodes.links[link.name] = _LinkNode(frame)
            for i, vis in enumerate(link.visuals):
                h = self._add_geometry(
                    f"{base}/visual_{i}", vis.geometry, vis.pose, vis.material.diffuse if vis.material else None
                )
                if h is not None:
                    nodes.visuals.append(h)
                    if nodes.selectable:
                        h.on_click(lambda _ev, name=name: self.select(name))
            for i, col in enumerate(link.collisions):
                h = self._add_geometry(f"{base}/collision_{i}", col.geometry, col.pose, None, collision=True)
                if h is not None:
                    h.visible = show_col
                    nodes.collisions.append(h)
        self._nodes[name] = nodes

    def _add_geometry(self, name: str, geometry: object, pose: Any, rgba: Any, *, collision: bool = False) -> Any:
        """A visual or collision shape as a viser mesh at ``pose`` in its link frame; None for a shape with no mesh
        (an unresolved mesh file, an infinite plane drawn by the grid). A mesh file drawn without a material
        keeps its own colours and textures (viser's trimesh path); a transparent colour keeps its alpha."""
        tm = to_trimesh(geometry)
        if tm is None:
            return None
        kw = dict(position=pose.position, wxyz=pose.orientation)
        s = self.server.scene
        if collision:
            return s.add_mesh_simple(name, tm.vertices, tm.faces, color=COLLISION_RGB, wireframe=True, **kw)
        if rgba is None and tm.source is not None:
            return s.add_mesh_trimesh(name, tm.source, **kw)
        opacity = None if rgba is None or rgba[3] >= 1.0 else float(rgba[3])
        return s.add_mesh_simple(name, tm.vertices, tm.faces, color=rgba_to_rgb255(rgba), opacity=opacity, **kw)

    def select(self, name: str) -> bool:
        """Select entity ``name`` (what clicking its geometry does): the Entities dropdown shows it.

        Returns False, changing nothing, when ``name`` is not (or no longer) an entity in the dropdown.
        """
        with self._lock:
            if name not in self._entity_dd.options:
                return False
            if self._entity_dd.value != name:
                self._entity_dd.value = name
        return True

    def _remove_entity(self, name: str) -> None:
        nodes = self._nodes.pop(name, None)
        if nodes is not None:
            nodes.root.remove()

    def _set_overlays(self) -> None:
        """Show or hide every entity's link frames and collision shapes as the two switches say, in one update."""
        tf, col = self.overlays.show_frames, self.overlays.show_collisions
        with self.server.atomic():
            for nodes in self._nodes.values():
                for ln in nodes.links.values():
                    ln.frame.show_axes = tf
                for h in nodes.collisions:
                    h.visible = col

    # ------------------------------------------------------------------ overlays (see ViewerOverlays)
    @property
    def trail(self) -> list[tuple[float, float, float]]:
        """The path trail's points (world frame), oldest first."""
        return self.overlays.trail

    def trail_target(self) -> str | None:
        """The entity whose path is drawn: the selected one, else the first with a cmd_vel subscriber."""
        return self.overlays.trail_target()

    def sample_trail(self) -> None:
        """Add the trail target's current position to the trail (:meth:`ViewerOverlays.sample_trail`)."""
        self.overlays.sample_trail()

    def update_plan(self) -> PlannedPath | None:
        """Draw the latest planned motion heard (a plan whose robot is gone is cleared); returns what is drawn."""
        return self.overlays.update_plan(self._last.entities if self._last is not None else None)

    @property
    def planned(self) -> PlannedPath | None:
        """The planned motion drawn (its tips' paths and goals)."""
        return self.overlays.planned

    # ------------------------------------------------------------------ gui
    def _setup_gui(self) -> None:
        """The panel: a folder each for the simulation, entities, driving, spawning, overlays and cameras,
        then what each control does."""
        g = self.server.gui
        # the small panel, and the folders used less folded (Spawn, Overlays, Camera): open, the medium panel
        # covered a quarter of a 1200 x 800 view (issue 50, item 10)
        g.configure_theme(control_width="small")
        self._gui_simulation(g)
        self._gui_entities(g)
        self._gui_drive(g)
        self._gui_spawn(g)
        self.overlays.add_panel(g, self._set_overlays)
        self._wire_gui()

    def _gui_simulation(self, g: viser.GuiApi) -> None:
        """Play/pause, step, reset, and the clocks: sim time, wall time since the viewer started, and the real-time
        factor."""
        with g.add_folder("Simulation"):
            self._play = g.add_button("Pause", hint="Pause or resume physics")
            self._sim_btns = g.add_button_group(
                "World",
                ("Step", "Reset", "Fit all"),
                hint="Step: one physics step (while paused). Reset: time and state; removes spawned entities. "
                "Fit all: the camera moves to see every entity.",
            )
            self._time_text = g.add_text("Sim time", initial_value="0.000 s", disabled=True)
            self._real_text = g.add_text("Real time", initial_value="0.0 s", disabled=True)
            self._rtf_text = g.add_text("RTF", initial_value="-", disabled=True)

    def _gui_entities(self, g: viser.GuiApi) -> None:
        """The entity list (also selected by clicking in the 3D view), the selected entity's pose, and its delete
        button."""
        with g.add_folder("Entities"):
            entity_options: list[str] = [NO_SELECTION]  # (str, not a literal: the options change)
            self._entity_dd = g.add_dropdown(
                "Entity", options=entity_options, initial_value=NO_SELECTION, hint="Or click an entity in the 3D view"
            )
            self._pose_text = g.add_text("Pose", initial_value="", disabled=True)
            self._delete_btn = g.add_button("Delete entity", color="red")

    def _gui_drive(self, g: viser.GuiApi) -> None:
        """Buttons that publish Twist commands to the selected diff-drive robot's cmd_vel topic, and the keyboard
        switch (WASD/arrows press the buttons instead of moving the camera)."""
        with g.add_folder("Drive"):
            self._drive_text = g.add_text("cmd_vel", initial_value="select a diff-drive robot", disabled=True)
            # two rows of buttons, not five: the panel stays short enough to leave the view to the scene
            self._turn_btns = g.add_button_group("Turn", ("Left", "Stop", "Right"))
            self._move_btns = g.add_button_group("Move", ("Forward", "Back"))
            self._keys_box = g.add_checkbox(
                "Keyboard drive",
                initial_value=False,
                hint="WASD / arrow keys press the buttons above (instead of moving the camera)",
            )
            self._keys_html = g.add_html("")

    def _gui_spawn(self, g: viser.GuiApi) -> None:
        """Spawn a model found on the resource paths (GAZELLE_RESOURCE_PATH, GZ_SIM_RESOURCE_PATH,
        GAZEBO_MODEL_PATH, ROS_PACKAGE_PATH, ...) at a position and yaw, under a name of the user's or the
        model's own."""
        with g.add_folder("Spawn", expand_by_default=False):
            model_options: list[str] = [NO_MODELS]
            self._model_dd = g.add_dropdown("Model", options=model_options, initial_value=NO_MODELS)
            self._spawn_name = g.add_text("Name", initial_value="", hint="empty: the model's own name")
            self._spawn_xyz = g.add_vector3("Position", initial_value=(0.0, 0.0, 0.0), step=0.1)
            self._spawn_yaw = g.add_number("Yaw (deg)", initial_value=0.0, step=15.0)
            self._spawn_btn = g.add_button("Spawn")
            self._rescan_btn = g.add_button("Rescan resource paths")
            self._spawn_text = g.add_text("Spawn result", initial_value="", disabled=True)

    def _wire_gui(self) -> None:
        """Connect the panel's widgets to what they do. Callbacks run on viser's event-loop thread: anything that
        touches the world goes through ``Simulation.call`` (spawn, delete, step) or takes the snapshot the frame
        loop made."""
        self._play.on_click(lambda _e: self._toggle_pause())
        self._sim_btns.on_click(self._world_button)
        self._delete_btn.on_click(lambda _e: self._delete_selected())
        for group in (self._turn_btns, self._move_btns):
            group.on_click(self._drive_button)
        self._keys_box.on_update(
            lambda _e: setattr(self._keys_html, "content", KEYS_HTML if self._keys_box.value else "")
        )
        self._spawn_btn.on_click(lambda _e: self._spawn_selected())
        self._rescan_btn.on_click(self._on_gui_event(self.rescan_models))
        self.rescan_models()

    def _world_button(self, event: Any) -> None:
        """Step, Reset or Fit all."""
        if event.target.value == "Step":
            self._step()
        elif event.target.value == "Reset":
            self.sim.reset(time_=True, state=True, spawned=False)
        else:
            self.fit_all()

    def fit_all(self) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """Move every browser's camera to see all entities (their links' origins, from the last frame), looking
        from the initial camera's direction; returns (position, look-at)."""
        snap = self._last
        points = [pos for links in snap.poses.values() for pos, _q in links.values()] if snap is not None else []
        eye, target = fit_view(points, CAMERA_POSITION, CAMERA_LOOK_AT, CAMERA_FOV_RAD)
        for client in self.server.get_clients().values():
            with client.atomic():  # position first: viser keeps the view direction when the position moves
                client.camera.position = eye
                client.camera.look_at = target
        return eye, target

    def _toggle_pause(self) -> None:
        paused, t = self.sim.call(self._flip_paused)
        self._time_text.value = f"{t:.3f} s"
        self._play.label = "Play" if paused else "Pause"

    def _flip_paused(self) -> tuple[bool, float]:
        self.sim.paused = not self.sim.paused
        return self.sim.paused, self.sim.world.time

    def _step(self) -> None:
        """One physics step, only while paused (a step while running would be lost in the running clock)."""

        def do() -> None:
            if self.sim.paused:
                self.sim.step(1)

        self.sim.call(do)

    def _delete_selected(self) -> None:
        """Delete the selected entity; a failure (it was deleted meanwhile, the simulation is busy) is a warning in
        the log, never an error in the viewer."""
        name = self._entity_dd.value
        if name == NO_SELECTION:
            return
        try:
            self.sim.delete(name)
        except Exception as err:
            _log.warning(f"viewer: cannot delete '{name}': {err}")

    @staticmethod
    def _on_gui_event(action: Callable[[], object]) -> Callable[[object], None]:
        """A GUI callback that runs ``action`` (whatever it returns) for any event."""

        def run(_event: object) -> None:
            action()

        return run

    def _drive_button(self, event: Any) -> None:
        """A Drive button: its command (DRIVE_BUTTONS) to the selected robot."""
        self.drive(*DRIVE_BUTTONS[event.target.value])

    def drive(self, linear_x: float, angular_z: float, entity: str | None = None) -> int:
        """Publish a Twist to the cmd_vel subscriptions of ``entity`` (default: the selected one).

        Returns how many subscriptions received it (0: the entity has no diff drive).
        """
        name = entity if entity is not None else self._entity_dd.value
        twist = Twist((float(linear_x), 0.0, 0.0), (0.0, 0.0, float(angular_z)))
        # publish on the entity's command topics as teleop_twist_keyboard would: through the bus
        topics = sorted(
            {
                ep.topic
                for ep in self.sim.bus.endpoints()
                if ep.owner == name and not ep.is_publisher and ep.msg_type == MsgType.TWIST
            }
        )
        n = sum(self.sim.bus.inject(topic, MsgType.TWIST, twist) for topic in topics)
        self._drive_text.value = (
            f"{name}: linear {linear_x:+.2f} m/s, angular {angular_z:+.2f} rad/s"
            if n
            else f"{name}: no cmd_vel subscriber"
        )
        return n

    # ------------------------------------------------------------------ spawn
    def rescan_models(self) -> list[ModelFile]:
        """Refresh the Spawn dropdown from the resource paths; returns what was found."""
        self._models = find_models()
        labels = [m.label for m in self._models] or [NO_MODELS]
        current = self._model_dd.value
        self._model_dd.options = labels
        self._model_dd.value = current if current in labels else labels[0]
        return self._models

    def spawn_model(
        self, path: str, *, name: str = "", xyz: tuple[float, float, float] = (0.0, 0.0, 0.0), yaw: float = 0.0
    ) -> str:
        """Load ``path`` with the loaders the ROS layer uses and spawn it; returns the entity name.

        A name already taken gets a ``_2``, ``_3``... suffix. Raises on a file that does not load or spawn.
        """
        result = load(path, expand_xacro=False)  # the panel is remote input: it never runs xacro
        model = result.value
        if not isinstance(model, Model):
            raise ValueError(f"{path} is not a single model")
        base = name.strip() or model.name or "model"
        taken = set(self.sim.call(lambda: list(self.sim.world.entities)))
        entity, k = base, 2
        while entity in taken:
            entity, k = f"{base}_{k}", k + 1
        pose = Pose.from_xyz_rpy((float(xyz[0]), float(xyz[1]), float(xyz[2])), (0.0, 0.0, float(yaw)))
        return self.sim.spawn(model, name=entity, pose=pose).name

    def _spawn_selected(self) -> None:
        """Spawn the chosen model with the panel's name, position and yaw; the result (its name, or why it failed)
        is shown under the button."""
        label = self._model_dd.value
        mf = next((m for m in self._models if m.label == label), None)
        if mf is None:
            self._spawn_text.value = "no model selected"
            return
        x, y, z = self._spawn_xyz.value
        try:
            name = self.spawn_model(
                str(mf.path),
                name=self._spawn_name.value,
                xyz=(float(x), float(y), float(z)),
                yaw=math.radians(float(self._spawn_yaw.value)),
            )
        except Exception as err:
            self._spawn_text.value = f"failed: {err}"[:300]
            _log.warning(f"viewer: cannot spawn {mf.path}: {err}")
        else:
            self._spawn_text.value = f"spawned '{name}'"

    # ------------------------------------------------------------------ frames
    def _snapshot(self) -> Snapshot:
        """Runs on the sim thread: every link pose, the time and the entity set."""
        sim, w = self.sim, self.sim.world
        bodies = self._bodies.get(w)
        poses: dict[str, dict[str, tuple[tuple[float, ...], tuple[float, ...]]]] = {}
        for ename, lname, bid in bodies:
            p = w.body_pose(bid)
            poses.setdefault(ename, {})[lname] = (p.position, p.orientation)
        drawn = self._drawn
        views = {
            e.name: EntityView(
                e.generation_added,
                e.model,
                frozenset(link.name for link in e.model.links if link.name in e.built.bodies),
                next((ln for ln, b in e.built.bodies.items() if b == e.built.root_body), None),
                bool(e.spawned or not e.static),
            )
            for e in w.entities.values()
            if drawn.get(e.name) != e.generation_added
        }
        return Snapshot(
            time=w.time,
            paused=sim.paused,
            rtf=sim.measured_rtf().rtf,
            entities={e.name: e.generation_added for e in w.entities.values()},
            views=views,
            poses=poses,
        )

    def update(self) -> Snapshot | None:
        """Pull one snapshot and push it to the browsers (the viewer thread calls this at ``rate_hz``)."""
        try:
            snap = self.sim.call(self._snapshot, timeout=5.0)
        except TimeoutError:
            return None
        # entities: added, removed, or re-spawned under the same name
        for name in [n for n, nodes in self._nodes.items() if snap.entities.get(n) != nodes.key[1]]:
            self._remove_entity(name)
        with self.server.atomic():
            for name in snap.entities:
                if name not in self._nodes and name in snap.views:
                    self._add_entity(name, snap.views[name])
        self._drawn = {name: nodes.key[1] for name, nodes in self._nodes.items()}
        with self.server.atomic():
            for name, links in snap.poses.items():
                nodes = self._nodes.get(name)
                if nodes is None:
                    continue
                for lname, pose in links.items():
                    ln = nodes.links.get(lname)
                    if ln is None or ln.pose == pose:
                        continue  # unchanged poses (static models, paused sim) cost nothing
                    ln.pose = pose
                    ln.frame.position = pose[0]
                    ln.frame.wxyz = pose[1]
        names = [NO_SELECTION, *sorted(snap.entities)]
        if tuple(self._entity_dd.options) != tuple(names):
            with self._lock:  # against a click selecting meanwhile (select() runs on viser's threads)
                current = self._entity_dd.value
                self._entity_dd.options = names
                self._entity_dd.value = current if current in names else NO_SELECTION
        self._last = snap
        self.frames += 1
        return snap

    def _update_gui(self, snap: Snapshot) -> None:
        """Refresh the panel from a snapshot: the clocks, the play/pause label, and the selected entity's pose (its
        root link's position and yaw, the way a 2D robot is read)."""
        self._time_text.value = f"{snap.time:.3f} s"
        self._real_text.value = f"{time.monotonic() - self._wall0:.1f} s"
        self._rtf_text.value = "paused" if snap.paused else f"{snap.rtf:.2f}"
        label = "Play" if snap.paused else "Pause"
        if self._play.label != label:
            self._play.label = label
        sel = self._entity_dd.value
        links = snap.poses.get(sel)
        if sel != NO_SELECTION and links:
            nodes = self._nodes.get(sel)
            link = nodes.root_link if nodes is not None and nodes.root_link in links else next(iter(links))
            pos, q = links.get(link, next(iter(links.values())))
            yaw = np.degrees(np.arctan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2)))
            self._pose_text.value = f"x {pos[0]:.3f}  y {pos[1]:.3f}  z {pos[2]:.3f}  yaw {yaw:.1f}°"
        else:
            self._pose_text.value = ""

    def _loop(self) -> None:
        """The viewer thread: at ``rate_hz`` while a browser is connected, push the newest poses (one snapshot of
        the world per frame), and at the panel's slower rate the GUI, overlays and camera image; with no browser
        connected, only the path trail is sampled, so an unwatched viewer costs the simulation next to nothing. A
        frame that fails is logged and the loop goes on: the viewer never stops the simulation."""
        gui_period = 1.0 / GUI_RATE_HZ
        next_gui = 0.0
        next_frame = time.monotonic()
        while not self._stop.is_set():
            period = 1.0 / self.rate_hz
            if not self.server.get_clients():
                # nobody watching: cost the simulation next to nothing (a client that connects
                # gets the whole scene on the next frame); only the path trail keeps sampling
                try:
                    now = time.monotonic()
                    if now >= self._next_trail:
                        self.sample_trail()
                        self._next_trail = now + 1.0 / TRAIL_RATE_HZ
                except Exception:
                    _log.exception("viewer: trail sample failed")
                self._stop.wait(period)
                next_frame = time.monotonic()
                continue
            cpu0 = time.thread_time()
            try:
                snap = self.update()
                now = time.monotonic()
                if snap is not None and now >= next_gui:
                    with self.server.atomic():  # one wake-up of viser's event loop for the whole panel
                        self._update_gui(snap)
                    self.overlays.refresh(snap.entities)
                    next_gui = now + gui_period
                if now >= self._next_trail:
                    self.sample_trail()
                    self.overlays.redraw_trail()
                    self._next_trail = now + 1.0 / TRAIL_RATE_HZ
            except Exception:
                _log.exception("viewer: frame update failed")
            self.cpu_sec += time.thread_time() - cpu0
            next_frame += period
            delay = next_frame - time.monotonic()
            if delay < 0:
                next_frame = time.monotonic()
                delay = 0.0
            self._stop.wait(delay)
