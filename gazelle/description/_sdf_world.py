"""A world's own settings in SDF: which ``<physics>`` runs, gravity and the magnetic field, spherical
coordinates, the ``<scene>``, and SDF 1.7's world ``<frame>`` elements (the world's frame graph).

A mixin of the SDF loader (:class:`._sdf._Loader`), split from it along the seam between what a world is
made of (models, includes, lights: ``_sdf.py``) and how it is set up (here).
"""

from __future__ import annotations

from lxml import etree

from ._diagnostics import ErrorCode
from ._model import DEFAULT_MAGNETIC_FIELD, NamedPose, PhysicsSettings, Scene, SphericalCoordinates
from ._pose import Vec3
from ._sdf_frames import FrameNode, Scope
from ._sdf_parts import _Parts
from ._sdf_reader import _Doc, _find, _findall
from ._xml import parse_bool


class _WorldParts(_Parts):
    """The readers of a world's settings (see the module docstring)."""

    def physics_element(self, element: etree._Element, doc: _Doc) -> etree._Element | None:
        """The world's ``<physics>``: the one marked default, else the first (checked)."""
        physics_els = _findall(element, "physics")  # one per engine profile; gz-sim runs the default one
        physics_el = next(
            (p for p in physics_els if parse_bool(p.get("default") or "") is True),
            physics_els[0] if physics_els else None,
        )
        if physics_el is not None:
            self.check(physics_el, doc, "physics")
        return physics_el

    def world_fields(self, element: etree._Element, physics_el: etree._Element | None, doc: _Doc) -> tuple[Vec3, Vec3]:
        """Gravity and the magnetic field: the world's own elements, else the ones SDF ≤ 1.5 kept in ``<physics>``."""
        gravity = (0.0, 0.0, -9.8)  # SDF's default (world.sdf), not 9.81: m/s², world frame
        if _find(element, "gravity") is not None:
            gravity = self.vec3(element, "gravity", gravity, doc)
        elif physics_el is not None:
            gravity = self.vec3(physics_el, "gravity", gravity, doc)
        magnetic = DEFAULT_MAGNETIC_FIELD  # tesla, world frame: what magnetometers read before their noise
        if _find(element, "magnetic_field") is not None:
            magnetic = self.vec3(element, "magnetic_field", magnetic, doc)
        elif physics_el is not None and _find(physics_el, "magnetic_field") is not None:
            magnetic = self.vec3(physics_el, "magnetic_field", magnetic, doc)
        return gravity, magnetic

    def spherical_coordinates(self, element: etree._Element, doc: _Doc) -> SphericalCoordinates | None:
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
            self.check(sph_el, doc, "spherical_coordinates")
            orientation = (self.text(sph_el, "world_frame_orientation") or "ENU").strip().upper()
            if orientation != "ENU":
                self.sink.warning(
                    ErrorCode.VALUE_INVALID,
                    f"<world_frame_orientation> {orientation} is not simulated; GPS sensors assume ENU",
                    self.loc(sph_el, doc),
                )
            spherical = SphericalCoordinates(
                latitude_deg=self.number(sph_el, "latitude_deg", 0.0, doc),
                longitude_deg=self.number(sph_el, "longitude_deg", 0.0, doc),
                elevation=self.number(sph_el, "elevation", 0.0, doc),
                heading_deg=self.number(sph_el, "heading_deg", 0.0, doc),
                surface_model=(self.text(sph_el, "surface_model") or "EARTH_WGS84").strip(),
                world_frame_orientation=orientation,
            )
        return spherical

    def physics(self, physics_el: etree._Element | None, doc: _Doc) -> PhysicsSettings:
        """Step size and real-time settings (SDF ≤ 1.3 called the rate ``update_rate``); bad values reported."""
        # only these three are read: the engine is always MuJoCo, so the engine blocks (<ode>, <bullet>,
        # <dart>, <simbody>: solver iterations, ERP/CFM) are skipped on purpose (_sdf_reader.IGNORED)
        default_physics = PhysicsSettings()
        step = self.number(physics_el, "max_step_size", default_physics.max_step_size_sec, doc)
        rate_tag = (
            "update_rate"
            if doc.version <= (1, 3) and physics_el is not None and _find(physics_el, "update_rate") is not None
            else "real_time_update_rate"
        )
        physics = PhysicsSettings(
            max_step_size_sec=step,
            real_time_factor=self.number(physics_el, "real_time_factor", default_physics.real_time_factor, doc),
            real_time_update_rate_hz=self.number(physics_el, rate_tag, default_physics.real_time_update_rate_hz, doc),
        )
        if physics_el is not None:
            for value, what in ((physics.max_step_size_sec, "max_step_size"),):
                if not value > 0:
                    self.sink.error(
                        ErrorCode.VALUE_INVALID, f"<{what}> must be > 0, got {value:g}", self.loc(physics_el, doc)
                    )
            if physics.real_time_factor < 0 or physics.real_time_update_rate_hz < 0:
                self.sink.error(
                    ErrorCode.VALUE_INVALID,
                    "real_time_factor and real_time_update_rate must be >= 0",
                    self.loc(physics_el, doc),
                )
        return physics

    def scene(self, element: etree._Element, doc: _Doc) -> Scene:
        """``<scene>``: ambient and background colours, shadows, grid; SDF's defaults for what it leaves out.

        The defaults are ``sdf/1.11/scene.sdf``'s (ambient 0.4 grey, background 0.7 grey, shadows and grid on),
        kept in :class:`Scene`. Cameras render with the ambient, background and shadows; the grid is the
        browser viewer's. ``<fog>``, ``<sky>`` and the rest are named by :meth:`check` as not simulated."""
        scene_el = _find(element, "scene")
        scene = Scene()
        if scene_el is not None:
            self.check(scene_el, doc, "scene")
            scene = Scene(
                ambient=self.color(scene_el, "ambient", doc) or scene.ambient,
                background=self.color(scene_el, "background", doc) or scene.background,
                shadows=self.flag(scene_el, "shadows", scene.shadows, doc),
                grid=self.flag(scene_el, "grid", scene.grid, doc),
            )
        return scene

    def world_frame(self, child: etree._Element, doc: _Doc, scope: Scope, names: set[str], world: str | None) -> None:
        """A world's ``<frame>`` into its frame graph (a name used twice is an error).

        SDF 1.7's world frames: a named pose in the world, ``attached_to`` a model or another frame (moving
        with it) or to the world. Its pose is ``relative_to`` its ``<pose>``'s frame, else to the frame it is
        attached to, else the world (sdformat's rule); models' and lights' poses may then be relative to it."""
        frame_name = self.unique(child, doc, names, "name", f"world '{world}'")
        if frame_name is None:
            return
        fpose, frel = self.pose(child, doc)
        attached = (child.get("attached_to") or "").strip() or None
        scope.nodes[frame_name] = FrameNode(
            frame_name,
            "frame",
            fpose,
            frel or attached or "world",
            attached_to=attached,
            location=self.loc(child, doc),
        )

    def named_pose(self, child: etree._Element, doc: _Doc, scope: Scope) -> NamedPose | None:
        """A world ``<frame>`` attached to the world as a named pose (None for one attached to a model, which
        moves, or one whose pose the frame graph could not resolve: reported there), with gazelle's custom
        elements: ``<gazelle:description>``, ``<gazelle:tag>`` (repeatable), and its free space,
        ``<gazelle:box>`` (six numbers: two opposite corners in the pose's frame) or ``<gazelle:sphere>`` (a
        radius about the pose)."""
        name = (child.get("name") or "").strip()
        attached = (child.get("attached_to") or "").strip()
        if not name or attached not in ("", "world") or scope.nodes.get(name) is None:
            return None
        X_WF = scope.pose(name, self.loc(child, doc))
        if X_WF is None:
            return None
        description = self.text(child, "gazelle:description") or ""
        tags = tuple(t for t in ((e.text or "").strip() for e in _findall(child, "gazelle:tag")) if t)
        box = None
        raw = self.vector(child, "gazelle:box", 6, None, doc)
        if raw is not None:
            box = ((raw[0], raw[1], raw[2]), (raw[3], raw[4], raw[5]))
        radius = self.opt_number(child, "gazelle:sphere", doc)
        if radius is not None and radius <= 0:
            self.sink.error(
                ErrorCode.VALUE_INVALID, f"<gazelle:sphere> must be > 0, got {radius:g}", self.loc(child, doc)
            )
            radius = None
        if box is not None and radius is not None:
            self.sink.warning(
                ErrorCode.VALUE_INVALID,
                f"frame '{name}' has both <gazelle:box> and <gazelle:sphere>; the box is used",
                self.loc(child, doc),
            )
            radius = None
        return NamedPose(name, X_WF, description, tags, box, radius, self.loc(child, doc))
