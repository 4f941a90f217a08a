"""SDFormat 1.2–1.11 into the description model (:class:`Model` or :class:`World`).

What the root holds decides what comes back:

* ``<world>`` → :class:`World` (the first one; more are reported and skipped);
* ``<model>`` → :class:`Model`;
* ``<light>`` alone (e.g. the ``sun`` model of the Gazebo model database) → a
  :class:`World` named ``default`` holding just that light, so callers can merge it.

Older files are read the way libsdformat converts them, the visible differences being:

* SDF ≤ 1.4: a joint ``<axis><xyz>`` is expressed in the parent *model* frame
  (libsdformat's 1.4→1.5 converter adds ``use_parent_model_frame=true``);
* SDF 1.5–1.6: in the joint frame unless ``<use_parent_model_frame>``; ``<pose frame=...>``
  acts like ``relative_to``;
* SDF ≥ 1.7: in the joint frame unless ``<xyz expressed_in=...>``;
* ``<gazebo version="1.2">`` is accepted as the root of SDF 1.2 files.

Nested models (and ``<include>`` inside a model) are flattened into their parent with
scoped names (``child::link``) and composed poses. ``JointAxis.xyz`` is always in the
joint frame; ``Joint.origin`` is X_PJ and ``Joint.child_offset`` X_JC.

Every problem is reported into the sink with file:line; see :data:`._sdf_reader.IGNORED` for the
elements skipped on purpose without a warning (everything else unknown is
``ELEMENT_UNSUPPORTED``). Custom elements with a namespace prefix (``gz:...``) are kept
silently, as libsdformat does.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._fuel import BUILTIN as FUEL_BUILTIN
from ._fuel import CLASSIC_BUILTIN, FuelModel, cache_roots, find_cached, parse_fuel_uri
from ._model import (
    Frame,
    Joint,
    JointType,
    Light,
    Mimic,
    Model,
    NamedPose,
    World,
)
from ._pose import IDENTITY, Pose
from ._resources import ResourceResolver
from ._sdf_frames import FrameNode, Scope
from ._sdf_reader import (
    MAX_NESTING,
    MAX_VERSION,
    _Built,
    _Doc,
    _find,
    _findall,
    _tag,
)
from ._sdf_world import _WorldParts
from ._xml import (
    child_elements,
)

__all__ = ["parse_sdf"]


def parse_sdf(
    text: str,
    *,
    source: str,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
    base_dir: str | None,
) -> Model | World | None:
    """Parse SDF text.

    Args:
        text: the document.
        source: file name used in diagnostics.
        sink: receives every diagnostic.
        resolver: finds ``model://`` and ``package://`` URIs.
        base_dir: folder relative URIs resolve against (None: a string, relative URIs resolve nowhere).

    Returns:
        A :class:`World` (for ``<world>`` or a lone ``<light>``) or a :class:`Model`;
        None when errors prevent building one (they are in ``sink``).
    """
    loader = _Loader(sink, resolver)
    try:
        return loader.load_text(text, source, Path(base_dir) if base_dir is not None else None)
    except RecursionError:
        sink.error(ErrorCode.VALUE_INVALID, "document nests too deeply to be read", SourceLocation(source))
        return None


class _Loader(_WorldParts):
    """Documents, models (nested and included) and worlds."""

    def load_text(self, text: str, source: str, base_dir: Path | None) -> Model | World | None:
        """An SDF document's content: its first ``<world>`` (a world file), else its first ``<model>`` placed by its
        pose (and ``placement_frame``), else a lone ``<light>`` as a world holding it. What else the ``<sdf>``
        holds is warned about; a second world or model is warned about and left out, as gz-sim loads only the
        first."""
        got = self.read(text, source, base_dir)
        if got is None:
            return None
        root, doc = got
        worlds = _findall(root, "world")
        models = _findall(root, "model")
        lights = _findall(root, "light")
        for child in child_elements(root):
            tag = _tag(child)
            if tag not in ("world", "model", "light") and ":" not in tag:
                self.unsupported(child, doc, "sdf")
        if worlds:
            for extra in worlds[1:] + models + lights:
                self.warn_extra(extra, doc, "only the first <world> is loaded")
            return self.world(worlds[0], doc)
        if models:
            for extra in models[1:] + lights:
                self.warn_extra(extra, doc, "only the first <model> is loaded")
            built = self.model(models[0], doc, depth=0)
            if built is None:
                return None
            if built.relative_to not in (None, "world"):
                self.sink.error(
                    ErrorCode.FRAME_INVALID,
                    f"top-level model pose cannot be relative_to '{built.relative_to}'",
                    built.location,
                )
                return None
            pose = built.pose
            if built.placement_frame is not None:
                inverse = self.placement(built)
                if inverse is None:
                    return None
                pose = pose * inverse
            return self.finish_model(built, pose)
        if lights:
            for extra in lights[1:]:
                self.warn_extra(extra, doc, "only the first <light> is loaded")
            light = self.light(lights[0], doc, None)
            if light is None:
                return None
            return World(name="default", lights=(light,), source_file=doc.source, location=self.loc(root, doc))
        self.sink.error(
            ErrorCode.ELEMENT_MISSING,
            "<sdf> holds no <world>, <model> or <light>",
            self.loc(root, doc),
        )
        return None

    def include_file(self, uri: str, path: Path | None, doc: _Doc, loc: SourceLocation) -> tuple[str, str, Path] | None:
        """(text, source, folder) of an included file, or None after reporting why it is not read.

        A folder is a model folder: its ``model.config`` picks the file (:meth:`pick_sdf`). What is refused
        and what is merely missing are told apart, because the user's fix differs: a URI outside the
        resource roots (or a file that links out of them) is an error naming the roots; a model that is not
        found is a warning and the include is skipped, as Gazebo skips it; a file that cannot be decoded is
        an error with the reason."""
        if path is not None and path.is_dir():
            path = self.pick_sdf(path, loc)
        if path is None and self.resolver.refused(uri, doc.base_dir):
            self.sink.error(ErrorCode.URI_UNRESOLVED, f"include {self.resolver.refusal(uri)}", loc)
            return None
        if path is None or not path.is_file():
            self.sink.warning(ErrorCode.URI_UNRESOLVED, f"cannot resolve include URI '{uri}'; include skipped", loc)
            return None
        if not self.resolver.allowed(path):  # e.g. a model.sdf that links out of the resource paths
            self.sink.error(ErrorCode.URI_UNRESOLVED, f"include {self.resolver.refusal(uri)}", loc)
            return None
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as err:
            self.sink.error(ErrorCode.FILE_READ_ERROR, f"cannot read included file {path}: {err}", loc)
            return None
        return text, str(path), path.parent

    def fuel_include(self, fuel: FuelModel, uri: str, loc: SourceLocation) -> tuple[str, str, Path | None] | None:
        """A Fuel model without the network: built in, or from Gazebo's local Fuel cache (see :mod:`._fuel`).

        gazelle never downloads (a simulation's inputs must not change under it, and CI has no network):
        the handful of models nearly every world includes (ground plane, sun) are built in, and anything
        Gazebo itself once downloaded is read from its cache, trusted as the user's own files. Anything else
        is skipped with a warning that says where gazelle looked."""
        builtin = FUEL_BUILTIN.get(fuel.name.lower()) if fuel.owner.lower() == "openrobotics" else None
        if builtin is not None:
            return builtin, f"<builtin:fuel {fuel.label()}>", None
        cached = find_cached(fuel, cache_roots())
        if cached is not None:
            self.resolver = self.resolver.trusting(cached)  # the user's own Gazebo cache
            sdf = self.pick_sdf(cached, loc)
            if sdf is not None:
                return self.include_file(uri, sdf, _Doc(str(sdf), cached, MAX_VERSION, False), loc)
        # a warning, not an error: gz-sim too goes on loading the world without a model it cannot get
        self.sink.warning(
            ErrorCode.URI_UNRESOLVED,
            f"Fuel model '{fuel.label()}' is not built in and not in a local Fuel cache "
            f"({', '.join(str(r) for r in cache_roots()) or '~/.gz/fuel: none'}); nothing was fetched "
            f'(gazelle never downloads): get it with `gz fuel download -u "{uri}"` where Gazebo is installed '
            "and copy ~/.gz/fuel here (or set GZ_FUEL_CACHE_PATH), or put the model folder on "
            "GZ_SIM_RESOURCE_PATH and include it as model://; include skipped, the world loads without it",
            loc,
        )
        return None

    def include(self, element: etree._Element, doc: _Doc, depth: int, allow_light: bool) -> _Built | Light | None:
        """Load an ``<include>``: a model (or, in a world, a light) with the overrides applied."""
        self.check(element, doc, "include")
        loc = self.loc(element, doc)
        uri = self.text(element, "uri")
        if not uri:
            self.sink.error(ErrorCode.ELEMENT_MISSING, "<include> has no <uri>", loc)
            return None
        if depth >= MAX_NESTING:
            self.sink.error(
                ErrorCode.URI_UNRESOLVED, f"includes nest deeper than {MAX_NESTING} (a cycle?) at '{uri}'", loc
            )
            return None
        # three kinds of URI: a Fuel model (https://fuel.gazebosim.org/...), read from what is built in or
        # from Gazebo's own download cache, never fetched; model://, package://, file:// and paths, found on
        # the resource roots; anything else (http:// to elsewhere) is not read
        fuel = parse_fuel_uri(uri)
        if fuel is not None:
            got = self.fuel_include(fuel, uri, loc)
            if got is None:
                return None
            text, source, base = got
        else:
            path = (
                None
                if "://" in uri and not uri.startswith(("model://", "package://", "file://"))
                else self.resolve(uri, doc)
            )
            stock = CLASSIC_BUILTIN.get(uri[len("model://") :].strip("/")) if uri.startswith("model://") else None
            if path is None and stock is not None:
                # Gazebo Classic installs these with itself; without them a Classic world has no floor
                got_file = (stock, f"<builtin:{uri}>", None)
            else:
                got_file = self.include_file(uri, path, doc, loc)
            if got_file is None:
                return None
            text, source, base = got_file
        got = self.read(text, source, base)  # the included file has its own version and folder
        if got is None:
            return None
        root, inner_doc = got
        model_el = _find(root, "model")
        light_el = _find(root, "light") if allow_light else None
        if model_el is None and light_el is not None:  # the "sun" of Gazebo's model database is a light
            light = self.light(light_el, inner_doc, None)
            if light is None:
                return None
            name = self.text(element, "name")
            pose = self.pose(element, doc)[0] if _find(element, "pose") is not None else light.pose
            return replace(light, name=name or light.name, pose=pose, location=loc)
        if model_el is None:
            self.sink.error(ErrorCode.ELEMENT_MISSING, f"included file {source} holds no <model>", loc)
            return None
        built = self.model(model_el, inner_doc, depth + 1)
        if built is None:
            return None
        self.include_overrides(built, element, doc)
        built.location = loc
        return built

    def include_overrides(self, built: _Built, element: etree._Element, doc: _Doc) -> None:
        """The ``<include>``'s own children override the included model's (sdformat's rule): its ``<name>``, its
        ``<pose>`` (in the including file's frames), ``<static>``, ``<placement_frame>``; its ``<plugin>`` s are
        added to the model's."""
        name = self.text(element, "name")
        if name:
            built.name = name
        if _find(element, "pose") is not None:
            built.pose, built.relative_to = self.pose(element, doc)
        if _find(element, "static") is not None:
            built.static = self.flag(element, "static", built.static, doc)
        placement = self.text(element, "placement_frame")
        if placement:
            built.placement_frame = placement
        for plugin_el in _findall(element, "plugin"):
            plugin = self.plugin(plugin_el, doc)
            if plugin is not None:
                built.plugins.append(plugin)

    # ================================================================== models
    def model(self, element: etree._Element, doc: _Doc, depth: int) -> _Built | None:
        """Parse a ``<model>`` (recursively flattening nested models) in its own frame."""
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        if name is None:
            return None
        if depth >= MAX_NESTING:
            self.sink.error(ErrorCode.VALUE_INVALID, f"models nest deeper than {MAX_NESTING}", loc)
            return None
        self.check(element, doc, "model")
        pose, relative_to = self.pose(element, doc)
        built = _Built(
            name=name,
            static=self.flag(element, "static", False, doc),
            self_collide=self.flag(element, "self_collide", False, doc),
            pose=pose,
            relative_to=relative_to,
            placement_frame=(element.get("placement_frame") or "").strip() or None,
            canonical=None,
            doc=doc,
            location=loc,
        )
        scope = Scope("__model__", self.sink)
        kinds: dict[str, str] = {}

        # -- pass 1: names, frame nodes, nested models. Two passes because SDF's frame graph is declarative: a
        # pose may be relative_to a frame written further down the file, so every frame is known before any
        # pose is resolved
        link_els: list[tuple[str, etree._Element]] = []
        joint_els: list[tuple[str, etree._Element]] = []
        frame_els: list[tuple[str, etree._Element]] = []
        nested: list[_Built] = []
        merged: list[tuple[str, _Built]] = []  # (proxy frame, model) of each <include merge="true">
        merged_first = False  # a merged include came before any link of the model's own
        for child in child_elements(element):
            tag = _tag(child)
            if tag in ("link", "joint", "frame"):
                child_name = self.name(child, doc)
                if child_name is None or not self.register(kinds, child_name, tag, child, doc, name):
                    continue
                {"link": link_els, "joint": joint_els, "frame": frame_els}[tag].append((child_name, child))
                scope.nodes[child_name] = self.frame_node(tag, child_name, child, doc)
            elif tag in ("model", "include"):
                sub = self.model(child, doc, depth + 1) if tag == "model" else self.include(child, doc, depth, False)
                if isinstance(sub, _Built) and tag == "include" and _merge(child):
                    merged_first = merged_first or not (link_els or merged)
                    merged.append((self.merge(sub, child, doc, kinds, scope, name), sub))
                    continue
                if not isinstance(sub, _Built) or not self.register(kinds, sub.name, "model", child, doc, name):
                    continue
                post = self.placement(sub) or IDENTITY  # a bad placement_frame: reported, placed as if none
                nested.append(sub)
                scope.nested[sub.name] = sub.exported
                scope.nodes[sub.name] = FrameNode(
                    sub.name, "model", sub.pose, sub.relative_to or "__model__", post=post, location=sub.location
                )

        # -- canonical link
        built.canonical = self.canonical_link(element, scope, link_els, nested, name, loc)
        if merged and merged[0][1].canonical and element.get("canonical_link") is None and merged_first:
            built.canonical = merged[0][1].canonical  # merged links are this model's own, in the file's order
        scope.canonical = built.canonical
        if built.canonical is None:
            self.sink.error(ErrorCode.LINK_MISSING, f"model '{name}' has no link", loc)
            return None

        # -- pass 2: links, joints, frames; then the nested models flattened into this one
        self.model_parts(element, doc, scope, built, link_els, joint_els, frame_els)
        for proxy, sub in merged:
            X_MS = scope.pose(proxy, sub.location)
            if X_MS is not None:
                self.flatten(built, sub, X_MS, prefix="")
        self.flatten_nested(built, nested, scope)
        built.exported = scope.export()
        return built

    def merge(self, sub: _Built, el: etree._Element, doc: _Doc, kinds: dict[str, str], scope: Scope, model: str) -> str:
        """sdformat 1.9's ``<include merge="true">`` (sdf/1.9/model.sdf; libsdformat's merge-include): the included
        model's links, joints, frames and plugins become the parent model's own, with their own names (not
        ``sub::``), placed through a proxy frame ``_merged__<name>__model__`` that stands where the included
        model frame would (the include's ``<pose>``), attached to its canonical link. Returns the proxy's name;
        the content is moved in by :meth:`flatten` once the parent's frames are resolved."""
        proxy = f"_merged__{sub.name}__model__"
        post = self.placement(sub) or IDENTITY
        scope.nodes[proxy] = FrameNode(
            proxy, "frame", sub.pose, sub.relative_to or "__model__", sub.canonical, post, sub.location
        )
        links = {link.name for link in sub.links}
        for frame_name, X_SF in sub.exported.poses.items():
            kind = "link" if frame_name in links else "frame"
            if frame_name == "__model__" or not self.register(kinds, frame_name, kind, el, doc, model):
                continue
            body = sub.exported.bodies.get(frame_name)
            scope.nodes[frame_name] = FrameNode(frame_name, kind, X_SF, proxy, body, location=sub.location)
        return proxy

    def register(
        self, kinds: dict[str, str], node_name: str, kind: str, el: etree._Element, doc: _Doc, model: str
    ) -> bool:
        """Claim ``node_name`` in model ``model``'s frame graph (``kinds``: name -> kind so far) for a link, joint,
        frame or nested model: a reserved name (``world``, ``__model__``, ``__*__``) is an error, and so is a name
        used twice (by any two kinds from SDF 1.7 on; before it, only by two of one kind). False when refused."""
        if node_name in ("__model__", "world") or (node_name.startswith("__") and node_name.endswith("__")):
            self.sink.error(ErrorCode.VALUE_INVALID, f"'{node_name}' is a reserved name", self.loc(el, doc))
            return False
        previous = kinds.get(node_name)
        if previous is not None and (previous == kind or doc.version >= (1, 7)):
            self.sink.error(
                ErrorCode.DUPLICATE_NAME,
                f"{kind} name '{node_name}' is already used by a {previous} in model '{model}'",
                self.loc(el, doc),
            )
            return False
        if previous is None:
            kinds[node_name] = kind
        return previous is None

    def placement(self, sub: _Built) -> Pose | None:
        """X_PM⁻¹ for a model placed by its ``placement_frame`` (identity without one); None, reported, when
        the frame is not one of the model's."""
        if sub.placement_frame is None:
            return IDENTITY
        inner = sub.exported.poses.get(sub.placement_frame)
        if inner is None:
            self.sink.error(
                ErrorCode.FRAME_INVALID,
                f"placement_frame '{sub.placement_frame}' is not a frame of model '{sub.name}'",
                sub.location,
            )
            return None
        return inner.inverse()

    def frame_node(self, tag: str, name: str, child: etree._Element, doc: _Doc) -> FrameNode:
        """The frame-graph node of a model's ``<link>``, ``<joint>`` (attached to its child) or ``<frame>``."""
        # what a pose is relative to when it does not say (SDF 1.7's defaults): a link's, the model frame; a
        # joint's, its child link; a frame's, what it is attached to (else the model frame)
        child_pose, child_rel = self.pose(child, doc)
        child_loc = self.loc(child, doc)
        if tag == "link":
            return FrameNode(name, "link", child_pose, child_rel or "__model__", location=child_loc)
        if tag == "joint":
            child_ref = self.text(child, "child") or ""
            return FrameNode(
                name,
                "joint",
                child_pose,
                child_rel or child_ref or "__model__",
                attached_to=child_ref,
                location=child_loc,
            )
        attached = (child.get("attached_to") or "").strip() or None
        return FrameNode(
            name, "frame", child_pose, child_rel or attached or "__model__", attached_to=attached, location=child_loc
        )

    def canonical_link(
        self,
        element: etree._Element,
        scope: Scope,
        link_els: list[tuple[str, etree._Element]],
        nested: list[_Built],
        name: str,
        loc: SourceLocation,
    ) -> str | None:
        """The model's canonical link: ``canonical_link`` if it names one, else its first link, else the
        first nested model's (scoped).

        It matters beyond naming: the model frame is attached to it (SDF 1.7's rule), so the pose gz-sim and
        gazelle report for a model is its canonical link's carried along, and gz-sim's DiffDrive names its
        ``child_frame_id`` after it (``<model>/<canonical link>``). A ``canonical_link`` that names a frame
        that is not a link is an error, as sdformat makes it."""
        canonical_attr = (element.get("canonical_link") or "").strip() or None
        if canonical_attr is not None:
            body = scope.body(canonical_attr, loc) if canonical_attr in scope.nodes or "::" in canonical_attr else None
            if body is None or (
                canonical_attr in scope.nodes
                and scope.nodes[canonical_attr].kind != "link"
                and "::" not in canonical_attr
            ):
                self.sink.error(
                    ErrorCode.FRAME_INVALID, f"canonical_link '{canonical_attr}' is not a link of model '{name}'", loc
                )
            else:
                return body
        if link_els:
            return link_els[0][0]
        for sub in nested:
            if sub.canonical is not None:
                return f"{sub.name}::{sub.canonical}"
        return None

    def model_parts(
        self,
        element: etree._Element,
        doc: _Doc,
        scope: Scope,
        built: _Built,
        link_els: list[tuple[str, etree._Element]],
        joint_els: list[tuple[str, etree._Element]],
        frame_els: list[tuple[str, etree._Element]],
    ) -> None:
        """A model's links, joints, frames (in the frame of the body they are attached to) and plugins.

        SDF 1.7's ``<frame>`` is a named pose attached to a link, a joint or another frame; what a frame
        finally rides on is a body, so each is kept as (that body, its pose in the body: X_BF = X_BM · X_MF),
        which is what a sensor, a tf lookup or a joint's ``relative_to`` needs (sdformat's FrameAttachedTo
        graph resolves it the same way). A frame attached to ``world`` is fixed in the world. Links come
        before joints because a joint's frame is resolved against its child link's pose."""
        for link_name, link_el in link_els:
            link = self.link(link_name, link_el, doc, scope)
            if link is not None:
                built.links.append(link)
        for joint_name, joint_el in joint_els:
            self.joint(joint_name, joint_el, doc, scope, built)
        for frame_name, frame_el in frame_els:
            X_MF = scope.pose(frame_name, self.loc(frame_el, doc))
            body = scope.body(frame_name, self.loc(frame_el, doc))
            if X_MF is None or body is None:
                continue
            X_MB = IDENTITY if body == "world" else scope.pose(body, self.loc(frame_el, doc))
            if X_MB is not None:
                built.frames.append(Frame(frame_name, body, X_MB.inverse() * X_MF, self.loc(frame_el, doc)))
        for plugin_el in _findall(element, "plugin"):
            plugin = self.plugin(plugin_el, doc)
            if plugin is not None:
                built.plugins.append(plugin)

    def flatten_nested(self, built: _Built, nested: list[_Built], scope: Scope) -> None:
        """Nested models into ``built``; a static one inside a non-static model is welded to the world."""
        for sub in nested:
            X_MS = scope.pose(sub.name, sub.location)
            if X_MS is None:
                continue
            self.flatten(built, sub, X_MS)
            # a static model nested in a moving one (a sensor mount, a fixed fixture) stays where it is:
            # welded to the world at its placed pose, as gz-sim keeps a nested static model static
            if sub.static and not built.static and sub.canonical is not None:
                built.joints.append(
                    Joint(
                        name=f"{sub.name}::__static_weld__",
                        type=JointType.FIXED,
                        parent="world",
                        child=f"{sub.name}::{sub.canonical}",
                        location=sub.location,
                    )
                )
                built.world_joints[f"{sub.name}::__static_weld__"] = X_MS * _link_pose(sub, sub.canonical)

    def flatten(self, parent: _Built, sub: _Built, X_PS: Pose, prefix: str | None = None) -> None:
        """Move ``sub``'s content into ``parent`` with ``sub::`` names (``prefix``: "" for a merged include),
        given X_PS.

        A nested model becomes part of one flat model, its links, joints and frames scoped as gz-sim scopes
        them (``gripper::finger``), so a plugin or a sensor topic that names ``gripper::finger`` finds it; its
        plugins run on the flat model. Links are re-expressed in the parent's frame; joints keep their
        origins, which are relative to their own links."""
        prefix = f"{sub.name}::" if prefix is None else prefix

        def scoped(n: str) -> str:
            return n if n == "world" else prefix + n

        # links move into the parent's frame; joints' origins and offsets are relative to their own links, so
        # they keep them; a joint to the world is kept with its pose for the model's world pose, known last
        for link in sub.links:
            parent.links.append(replace(link, name=prefix + link.name, pose=X_PS * (link.pose or IDENTITY)))
        for joint in sub.joints:
            parent.joints.append(
                Joint(
                    name=prefix + joint.name,
                    type=joint.type,
                    parent=scoped(joint.parent),
                    child=scoped(joint.child),
                    origin=joint.origin,
                    child_offset=joint.child_offset,
                    axis=joint.axis,
                    axis2=joint.axis2,
                    screw_thread_pitch=joint.screw_thread_pitch,
                    mimic=Mimic(prefix + joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset)
                    if joint.mimic
                    else None,
                    location=joint.location,
                )
            )
        for jname, X_SJ in sub.world_joints.items():
            parent.world_joints[prefix + jname] = X_PS * X_SJ
        for frame in sub.frames:
            parent.frames.append(Frame(prefix + frame.name, scoped(frame.attached_to), frame.pose, frame.location))
        parent.plugins.extend(sub.plugins)

    def finish_model(self, built: _Built, X_WM: Pose) -> Model | None:
        """The final :class:`Model` once its world pose is known."""
        joints = []
        for joint in built.joints:
            # a joint to the world holds its child where the file places it: its origin in the world frame is
            # the model's world pose times the joint's pose in the model
            X_MJ = built.world_joints.get(joint.name)
            if X_MJ is not None and joint.parent == "world":
                joint = replace(joint, origin=X_WM * X_MJ)
            joints.append(joint)
        if not built.links:
            if self.sink.has_hard_errors:
                return None  # its links failed and were reported
            self.sink.error(ErrorCode.LINK_MISSING, f"model '{built.name}' has no link", built.location)
            return None
        return Model(
            name=built.name,
            links=tuple(  # a joint's force_torque sensors live on the joint's child link
                replace(lk, sensors=(*lk.sensors, *built.joint_sensors[lk.name]))
                if lk.name in built.joint_sensors
                else lk
                for lk in built.links
            ),
            joints=tuple(joints),
            frames=tuple(built.frames),
            plugins=tuple(built.plugins),
            static=built.static,
            pose=X_WM,
            canonical_link=built.canonical,
            self_collide=built.self_collide,
            source_format="sdf",
            source_file=built.doc.source if built.doc else "",
            location=built.location,
        )

    def world(self, element: etree._Element, doc: _Doc) -> World | None:
        """A ``<world>``: gravity and the magnetic field, ``<spherical_coordinates>``, ``<physics>`` (step size and
        pace), ``<scene>``, its models (``<include>`` resolved) and lights, and its plugins.

        What gz-sim takes from a world file is what is kept; the physics engine's own blocks are skipped on
        purpose (MuJoCo steps every world). The world's plugins matter beyond themselves: gz-sim's sensor
        systems among them (``gz-sim-sensors-system``, ``-imu-system``...) decide which of a gz model's
        sensors publish, and gazebo_ros's world plugins (``gazebo_ros_state``, ``gazebo_ros_factory``) are
        the services gazelle serves anyway. Every part is read even when the world has no name (so all
        problems are reported in one pass); then the world is refused."""
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        self.check(element, doc, "world")
        physics_el = self.physics_element(element, doc)
        gravity, magnetic = self.world_fields(element, physics_el, doc)
        spherical = self.spherical_coordinates(element, doc)
        physics = self.physics(physics_el, doc)
        scene = self.scene(element, doc)
        models, lights, named = self.world_contents(element, doc, name)
        plugins = tuple(p for p in (self.plugin(e, doc) for e in _findall(element, "plugin")) if p is not None)
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

    def world_state(self, element: etree._Element, doc: _Doc, builts: dict[str, _Built]) -> dict[str, Pose]:
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
                self.unsupported(child, doc, "state")
                continue
            model_name = (child.get("name") or "").strip()
            if model_name not in builts:
                self.sink.warning(
                    ErrorCode.VALUE_INVALID,
                    f"<state> names model '{model_name}', which the world does not have; ignored",
                    self.loc(child, doc),
                )
                continue
            if _find(child, "pose") is None:
                continue
            X_WM = out[model_name] = self.pose(child, doc)[0]
            for link_el in _findall(child, "link"):
                X_ML = _link_pose(builts[model_name], (link_el.get("name") or "").strip())
                if _find(link_el, "pose") is not None and not _near(self.pose(link_el, doc)[0], X_WM * X_ML):
                    self.sink.warning(
                        ErrorCode.ELEMENT_UNSUPPORTED,
                        f"<state> moves link '{model_name}::{link_el.get('name')}' apart from its model; only the "
                        "model's state pose is applied",
                        self.loc(link_el, doc),
                    )
        return out

    def world_contents(
        self, element: etree._Element, doc: _Doc, name: str | None
    ) -> tuple[list[Model], list[Light], list[NamedPose]]:
        """The world's models (and includes) placed through its frame graph, its lights, and its named poses.

        An ``<include>`` may bring a light (Fuel's ``sun`` is one), so lights are collected from both, in
        file order. Other children of ``<world>`` are read elsewhere (physics, scene, plugins, gravity) or
        reported by :meth:`check`."""
        # the world is a frame graph of its own (SDF 1.7+): a model's <pose relative_to> may name another
        # model or a world <frame>, so every model is read first and placed once the whole graph is known;
        # model names must be unique in a world (sdformat's rule; the second is an error, not a rename)
        scope = Scope("world", self.sink, canonical="world")
        builts: list[_Built] = []
        light_items: list[etree._Element | Light] = []
        frame_items: list[etree._Element] = []
        names: set[str] = set()
        for child in child_elements(element):
            tag = _tag(child)
            sub: _Built | Light | None = None
            if tag == "model":
                sub = self.model(child, doc, 1)
            elif tag == "include":
                if _merge(child):  # libsdformat refuses it too (MERGE_INCLUDE_UNSUPPORTED)
                    self.sink.error(
                        ErrorCode.VALUE_INVALID,
                        "merge-include does not support a parent element of type world",
                        self.loc(child, doc),
                    )
                    continue
                sub = self.include(child, doc, 0, allow_light=True)
            elif tag == "light":
                light_items.append(child)
                continue
            elif tag == "frame":
                self.world_frame(child, doc, scope, names, name)
                frame_items.append(child)
                continue
            else:
                continue
            if isinstance(sub, Light):
                light_items.append(sub)
            elif isinstance(sub, _Built):
                if sub.name in names:
                    self.sink.error(
                        ErrorCode.DUPLICATE_NAME,
                        f"model name '{sub.name}' is used twice in world '{name}'",
                        sub.location,
                    )
                    continue
                names.add(sub.name)
                post = self.placement(sub) or IDENTITY  # a bad placement_frame: reported, placed as if none
                builts.append(sub)
                scope.nested[sub.name] = sub.exported
                scope.nodes[sub.name] = FrameNode(
                    sub.name, "model", sub.pose, sub.relative_to or "world", post=post, location=sub.location
                )
        models = []
        saved = self.world_state(element, doc, {sub.name: sub for sub in builts})
        for sub in builts:
            X_WM = saved.get(sub.name) or scope.pose(sub.name, sub.location)
            if X_WM is None:
                continue
            model = self.finish_model(sub, X_WM)
            if model is not None:
                models.append(model)
        # lights last: a light's pose may be relative_to a model's frame, known only once the models are placed
        lights = []
        for item in light_items:
            light = item if isinstance(item, Light) else self.light(item, doc, scope)
            if light is not None:
                lights.append(light)
        named = [p for p in (self.named_pose(el, doc, scope) for el in frame_items) if p is not None]
        return models, lights, named


_STATE_STAMPS = frozenset({"sim_time", "wall_time", "real_time", "iterations"})
"""When a world was saved: Gazebo Classic sets its clock from ``sim_time``; gazelle's clock starts at 0."""


def _link_pose(built: _Built, link_name: str) -> Pose:
    """The pose of link ``link_name`` in the model frame (the identity when it has none or is not there)."""
    for link in built.links:
        if link.name == link_name:
            return link.pose or IDENTITY
    return IDENTITY


def _near(a: Pose, b: Pose, tol: float = 1e-3) -> bool:
    """Two poses within ``tol`` (metres, and quaternion components, either sign)."""
    if any(abs(x - y) > tol for x, y in zip(a.position, b.position, strict=True)):
        return False
    same = all(abs(x - y) <= tol for x, y in zip(a.orientation, b.orientation, strict=True))
    return same or all(abs(x + y) <= tol for x, y in zip(a.orientation, b.orientation, strict=True))


def _merge(include: etree._Element) -> bool:
    """``<include merge="true">`` (SDF 1.9): sdformat reads the attribute as a bool."""
    return (include.get("merge") or "").strip().lower() in ("true", "1")
