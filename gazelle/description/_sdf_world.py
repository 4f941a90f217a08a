"""SDF worlds: a ``<world>``'s own settings (which ``<physics>`` runs, gravity and the magnetic field, spherical
coordinates, the ``<scene>``, SDF 1.7's world ``<frame>`` elements, the world's frame graph), what it is made of
(models and includes, placed; lights; a saved ``<state>``'s poses), and its plugins.

Free functions over a :class:`~._sdf_reader.Workspace`; the models come from :mod:`._sdf_model`.
"""

from __future__ import annotations

from lxml import etree

from ._diagnostics import ErrorCode
from ._model import (
    DEFAULT_MAGNETIC_FIELD,
    Light,
    Model,
    NamedPose,
    PhysicsSettings,
    Scene,
    SphericalCoordinates,
    World,
)
from ._pose import IDENTITY, Pose, Vec3
from ._sdf_frames import FrameNode, Scope
from ._sdf_model import _link_pose, _merge, finish_model, placement_inverse, read_include, read_model
from ._sdf_parts import read_light
from ._sdf_reader import (
    Workspace,
    _Built,
    _Doc,
    _find,
    _findall,
    _tag,
    check_children,
    child_text,
    location_of,
    read_color,
    read_flag,
    read_name,
    read_number,
    read_opt_number,
    read_plugin,
    read_pose,
    read_unique_name,
    read_vec3,
    read_vector,
    warn_unsupported,
)
from ._xml import child_elements, parse_bool

# The readers of a world's settings (see the module docstring).


def physics_element(ws: Workspace, element: etree._Element, doc: _Doc) -> etree._Element | None:
    """The world's ``<physics>``: the one marked default, else the first (checked)."""
    physics_els = _findall(element, "physics")  # one per engine profile; gz-sim runs the default one
    physics_el = next(
        (p for p in physics_els if parse_bool(p.get("default") or "") is True),
        physics_els[0] if physics_els else None,
    )
    if physics_el is not None:
        check_children(ws, physics_el, doc, "physics")
    return physics_el


def read_world_fields(
    ws: Workspace, element: etree._Element, physics_el: etree._Element | None, doc: _Doc
) -> tuple[Vec3, Vec3]:
    """Gravity and the magnetic field: the world's own elements, else the ones SDF ≤ 1.5 kept in ``<physics>``."""
    gravity = (0.0, 0.0, -9.8)  # SDF's default (world.sdf), not 9.81: m/s², world frame
    if _find(element, "gravity") is not None:
        gravity = read_vec3(ws, element, "gravity", gravity, doc)
    elif physics_el is not None:
        gravity = read_vec3(ws, physics_el, "gravity", gravity, doc)
    magnetic = DEFAULT_MAGNETIC_FIELD  # tesla, world frame: what magnetometers read before their noise
    if _find(element, "magnetic_field") is not None:
        magnetic = read_vec3(ws, element, "magnetic_field", magnetic, doc)
    elif physics_el is not None and _find(physics_el, "magnetic_field") is not None:
        magnetic = read_vec3(ws, physics_el, "magnetic_field", magnetic, doc)
    return gravity, magnetic


def read_spherical_coordinates(ws: Workspace, element: etree._Element, doc: _Doc) -> SphericalCoordinates | None:
    """``<spherical_coordinates>``, which GPS sensors read; None when the world has none. Only an ENU world
    frame is simulated (another orientation is a warning).

    The world origin's latitude and longitude (degrees, WGS84) and ``<elevation>`` (metres), and
    ``<heading_deg>``, which turns the world frame about the vertical against ENU (the GPS sensor's
    ``world_to_enu`` applies it). gz-sim reads the same element for its NavSat sensor; absent, gz-sim 8 has
    no fix to give (it publishes a constant 0, 0, 0), where gazelle's GPS sensors measure from an origin
    at 0° N 0° E (with a warning at the sensor)."""
    spherical = None
    sph_el = _find(element, "spherical_coordinates")
    if sph_el is not None:
        check_children(ws, sph_el, doc, "spherical_coordinates")
        orientation = (child_text(sph_el, "world_frame_orientation") or "ENU").strip().upper()
        if orientation != "ENU":
            ws.sink.warning(
                ErrorCode.VALUE_INVALID,
                f"<world_frame_orientation> {orientation} is not simulated; GPS sensors assume ENU",
                location_of(sph_el, doc),
            )
        spherical = SphericalCoordinates(
            latitude_deg=read_number(ws, sph_el, "latitude_deg", 0.0, doc),
            longitude_deg=read_number(ws, sph_el, "longitude_deg", 0.0, doc),
            elevation=read_number(ws, sph_el, "elevation", 0.0, doc),
            heading_deg=read_number(ws, sph_el, "heading_deg", 0.0, doc),
            surface_model=(child_text(sph_el, "surface_model") or "EARTH_WGS84").strip(),
            world_frame_orientation=orientation,
        )
    return spherical


def read_physics(ws: Workspace, physics_el: etree._Element | None, doc: _Doc) -> PhysicsSettings:
    """Step size and real-time settings (SDF ≤ 1.3 called the rate ``update_rate``); bad values reported."""
    # only these three are read: the engine is always MuJoCo, so the engine blocks (<ode>, <bullet>,
    # <dart>, <simbody>: solver iterations, ERP/CFM) are skipped on purpose (_sdf_reader.IGNORED)
    default_physics = PhysicsSettings()
    step = read_number(ws, physics_el, "max_step_size", default_physics.max_step_size_sec, doc)
    rate_tag = (
        "update_rate"
        if doc.version <= (1, 3) and physics_el is not None and _find(physics_el, "update_rate") is not None
        else "real_time_update_rate"
    )
    physics = PhysicsSettings(
        max_step_size_sec=step,
        real_time_factor=read_number(ws, physics_el, "real_time_factor", default_physics.real_time_factor, doc),
        real_time_update_rate_hz=read_number(ws, physics_el, rate_tag, default_physics.real_time_update_rate_hz, doc),
    )
    if physics_el is not None:
        for value, what in ((physics.max_step_size_sec, "max_step_size"),):
            if not value > 0:
                ws.sink.error(
                    ErrorCode.VALUE_INVALID, f"<{what}> must be > 0, got {value:g}", location_of(physics_el, doc)
                )
        if physics.real_time_factor < 0 or physics.real_time_update_rate_hz < 0:
            ws.sink.error(
                ErrorCode.VALUE_INVALID,
                "real_time_factor and real_time_update_rate must be >= 0",
                location_of(physics_el, doc),
            )
    return physics


def read_scene(ws: Workspace, element: etree._Element, doc: _Doc) -> Scene:
    """``<scene>``: ambient and background colours, shadows, grid; SDF's defaults for what it leaves out.

    The defaults are ``sdf/1.11/scene.sdf``'s (ambient 0.4 grey, background 0.7 grey, shadows and grid on),
    kept in :class:`Scene`. Cameras render with the ambient, background and shadows; the grid is the
    browser viewer's. ``<fog>``, ``<sky>`` and the rest are named by :func:`~._sdf_reader.check_children` as not
    simulated."""
    scene_el = _find(element, "scene")
    scene = Scene()
    if scene_el is not None:
        check_children(ws, scene_el, doc, "scene")
        scene = Scene(
            ambient=read_color(ws, scene_el, "ambient", doc) or scene.ambient,
            background=read_color(ws, scene_el, "background", doc) or scene.background,
            shadows=read_flag(ws, scene_el, "shadows", scene.shadows, doc),
            grid=read_flag(ws, scene_el, "grid", scene.grid, doc),
        )
    return scene


def read_world_frame(
    ws: Workspace, child: etree._Element, doc: _Doc, scope: Scope, names: set[str], world: str | None
) -> None:
    """A world's ``<frame>`` into its frame graph (a name used twice is an error).

    SDF 1.7's world frames: a named pose in the world, ``attached_to`` a model or another frame (moving
    with it) or to the world. Its pose is ``relative_to`` its ``<pose>``'s frame, else to the frame it is
    attached to, else the world (sdformat's rule); models' and lights' poses may then be relative to it."""
    frame_name = read_unique_name(ws, child, doc, names, "name", f"world '{world}'")
    if frame_name is None:
        return
    fpose, frel = read_pose(ws, child, doc)
    attached = (child.get("attached_to") or "").strip() or None
    scope.nodes[frame_name] = FrameNode(
        frame_name,
        "frame",
        fpose,
        frel or attached or "world",
        attached_to=attached,
        location=location_of(child, doc),
    )


def read_world(ws: Workspace, element: etree._Element, doc: _Doc) -> World | None:
    """A ``<world>``: gravity and the magnetic field, ``<spherical_coordinates>``, ``<physics>`` (step size and
    pace), ``<scene>``, its models (``<include>`` resolved) and lights, and its plugins.

    What gz-sim takes from a world file is what is kept; the physics engine's own blocks are skipped on
    purpose (MuJoCo steps every world). The world's plugins matter beyond themselves: gz-sim's sensor
    systems among them (``gz-sim-sensors-system``, ``-imu-system``...) decide which of a gz model's
    sensors publish, and gazebo_ros's world plugins (``gazebo_ros_state``, ``gazebo_ros_factory``) are
    the services gazelle serves anyway. Every part is read even when the world has no name (so all
    problems are reported in one pass); then the world is refused."""
    name = read_name(ws, element, doc)
    loc = location_of(element, doc)
    check_children(ws, element, doc, "world")
    physics_el = physics_element(ws, element, doc)
    gravity, magnetic = read_world_fields(ws, element, physics_el, doc)
    spherical = read_spherical_coordinates(ws, element, doc)
    physics = read_physics(ws, physics_el, doc)
    scene = read_scene(ws, element, doc)
    models, lights, named = read_world_contents(ws, element, doc, name)
    plugins = tuple(p for p in (read_plugin(ws, e, doc) for e in _findall(element, "plugin")) if p is not None)
    if name is None:
        return None
    return World(
        name=name,
        gravity=gravity,
        physics=physics,
        scene=scene,
        models=tuple(models),
        lights=tuple(lights),
        plugins=plugins,
        source_file=doc.source,
        location=loc,
        spherical_coordinates=spherical,
        magnetic_field=magnetic,
        named_poses=tuple(named),
    )


def read_named_pose(ws: Workspace, child: etree._Element, doc: _Doc, scope: Scope) -> NamedPose | None:
    """A world ``<frame>`` attached to the world as a named pose (None for one attached to a model, which
    moves, or one whose pose the frame graph could not resolve: reported there), with gazelle's custom
    elements: ``<gazelle:description>``, ``<gazelle:tag>`` (repeatable), and its free space,
    ``<gazelle:box>`` (six numbers: two opposite corners in the pose's frame) or ``<gazelle:sphere>`` (a
    radius about the pose)."""
    name = (child.get("name") or "").strip()
    attached = (child.get("attached_to") or "").strip()
    loc = location_of(child, doc)
    if not name or attached not in ("", "world") or scope.nodes.get(name) is None:
        return None
    X_WF = scope.pose(name, loc)
    if X_WF is None:
        return None
    description = child_text(child, "gazelle:description") or ""
    tags = tuple(t for t in ((e.text or "").strip() for e in _findall(child, "gazelle:tag")) if t)
    raw = read_vector(ws, child, "gazelle:box", 6, None, doc)
    box = ((raw[0], raw[1], raw[2]), (raw[3], raw[4], raw[5])) if raw is not None else None
    radius = read_opt_number(ws, child, "gazelle:sphere", doc)
    if radius is not None and radius <= 0:
        ws.sink.error(ErrorCode.VALUE_INVALID, f"<gazelle:sphere> must be > 0, got {radius:g}", loc)
        radius = None
    if box is not None and radius is not None:
        ws.sink.warning(
            ErrorCode.VALUE_INVALID, f"frame '{name}' has both <gazelle:box> and <gazelle:sphere>; the box is used", loc
        )
        radius = None
    return NamedPose(name, X_WF, description, tags, box, radius, loc)


def read_world_state(ws: Workspace, element: etree._Element, doc: _Doc, builts: dict[str, _Built]) -> dict[str, Pose]:
    """X_WM of each model a world's ``<state>`` places: a world saved from Gazebo Classic keeps where its models
    were moved in ``<state>`` (Husky's playpen turns its barriers there), and Classic's ``World::Load`` applies
    the first ``<state>`` over the models' own poses (``WorldState``, ``World::SetState``; gz-sim reads no
    ``<state>``). A model's state pose is in the world frame; its links' state poses are only where the model
    pose puts them in a saved world, and one that says otherwise (a link moved apart from its model, a joint
    turned) is named, not applied. Insertions and deletions are named as not applied."""
    out: dict[str, Pose] = {}
    state = _find(element, "state")
    if state is None:
        return out
    for child in child_elements(state):
        tag = _tag(child)
        if tag in _STATE_STAMPS or tag == "light":
            continue
        if tag != "model":
            warn_unsupported(ws, child, doc, "state")
            continue
        model_name = (child.get("name") or "").strip()
        if model_name not in builts:
            ws.sink.warning(
                ErrorCode.VALUE_INVALID,
                f"<state> names model '{model_name}', which the world does not have; ignored",
                location_of(child, doc),
            )
            continue
        if _find(child, "pose") is None:
            continue
        X_WM = out[model_name] = read_pose(ws, child, doc)[0]
        for link_el in _findall(child, "link"):
            X_ML = _link_pose(builts[model_name], (link_el.get("name") or "").strip())
            if _find(link_el, "pose") is not None and not _near(read_pose(ws, link_el, doc)[0], X_WM * X_ML):
                ws.sink.warning(
                    ErrorCode.ELEMENT_UNSUPPORTED,
                    f"<state> moves link '{model_name}::{link_el.get('name')}' apart from its model; only the "
                    "model's state pose is applied",
                    location_of(link_el, doc),
                )
    return out


def read_world_contents(
    ws: Workspace, element: etree._Element, doc: _Doc, name: str | None
) -> tuple[list[Model], list[Light], list[NamedPose]]:
    """The world's models (and includes) placed through its frame graph, its lights, and its named poses.

    An ``<include>`` may bring a light (Fuel's ``sun`` is one), so lights are collected from both, in
    file order. Other children of ``<world>`` are read elsewhere (physics, scene, plugins, gravity) or
    reported by :func:`~._sdf_reader.check_children`."""
    # the world is a frame graph of its own (SDF 1.7+): a model's <pose relative_to> may name another
    # model or a world <frame>, so every model is read first and placed once the whole graph is known;
    # model names must be unique in a world (sdformat's rule; the second is an error, not a rename)
    scope = Scope("world", ws.sink, canonical="world")
    builts: list[_Built] = []
    light_items: list[etree._Element | Light] = []
    frame_items: list[etree._Element] = []
    names: set[str] = set()
    for child in child_elements(element):
        tag = _tag(child)
        sub: _Built | Light | None = None
        if tag == "model":
            sub = read_model(ws, child, doc, 1)
        elif tag == "include":
            if _merge(child):  # libsdformat refuses it too (MERGE_INCLUDE_UNSUPPORTED)
                ws.sink.error(
                    ErrorCode.VALUE_INVALID,
                    "merge-include does not support a parent element of type world",
                    location_of(child, doc),
                )
                continue
            sub = read_include(ws, child, doc, 0, allow_light=True)
        elif tag == "light":
            light_items.append(child)
            continue
        elif tag == "frame":
            read_world_frame(ws, child, doc, scope, names, name)
            frame_items.append(child)
            continue
        else:
            continue
        if isinstance(sub, Light):
            light_items.append(sub)
        elif isinstance(sub, _Built):
            if sub.name in names:
                ws.sink.error(
                    ErrorCode.DUPLICATE_NAME,
                    f"model name '{sub.name}' is used twice in world '{name}'",
                    sub.location,
                )
                continue
            names.add(sub.name)
            post = placement_inverse(ws, sub) or IDENTITY  # a bad placement_frame: reported, placed as if none
            builts.append(sub)
            scope.nested[sub.name] = sub.exported
            scope.nodes[sub.name] = FrameNode(
                sub.name, "model", sub.pose, sub.relative_to or "world", post=post, location=sub.location
            )
    models = []
    saved = read_world_state(ws, element, doc, {sub.name: sub for sub in builts})
    for sub in builts:
        X_WM = saved.get(sub.name) or scope.pose(sub.name, sub.location)
        if X_WM is None:
            continue
        model = finish_model(ws, sub, X_WM)
        if model is not None:
            models.append(model)
    # lights last: a light's pose may be relative_to a model's frame, known only once the models are placed
    lights = []
    for item in light_items:
        light = item if isinstance(item, Light) else read_light(ws, item, doc, scope)
        if light is not None:
            lights.append(light)
    named = [p for p in (read_named_pose(ws, el, doc, scope) for el in frame_items) if p is not None]
    return models, lights, named


_STATE_STAMPS = frozenset({"sim_time", "wall_time", "real_time", "iterations"})
"""When a world was saved: Gazebo Classic sets its clock from ``sim_time``; gazelle's clock starts at 0."""


def _near(a: Pose, b: Pose, tol: float = 1e-3) -> bool:
    """Two poses within ``tol`` (metres, and quaternion components, either sign)."""
    if any(abs(x - y) > tol for x, y in zip(a.position, b.position, strict=True)):
        return False
    same = all(abs(x - y) <= tol for x, y in zip(a.orientation, b.orientation, strict=True))
    return same or all(abs(x + y) <= tol for x, y in zip(a.orientation, b.orientation, strict=True))
