"""SDF models: a ``<model>`` read into a :class:`_Built` (its links, joints, frames and plugins in its own frame),
nested models and ``<include>`` (a file, a model folder, a Fuel model) flattened into their parent with scoped
names (``child::link``) and composed poses, and the finished :class:`Model` placed in the world.

Free functions over a :class:`Workspace` (the sink and the resolver), as Drake's ``detail_sdf_parser.cc`` reads
models; :mod:`._sdf_parts` reads the parts, :mod:`._sdf_world` the worlds that hold models."""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from lxml import etree

from ._diagnostics import ErrorCode, SourceLocation
from ._fuel import BUILTIN as FUEL_BUILTIN
from ._fuel import CLASSIC_BUILTIN, FuelModel, cache_roots, find_cached, how_to_get, parse_fuel_uri
from ._model import (
    Frame,
    Joint,
    JointType,
    Light,
    Mimic,
    Model,
)
from ._pose import IDENTITY, Pose
from ._resources import classic_model_advice
from ._sdf_frames import FrameNode, Scope
from ._sdf_parts import read_joint, read_light, read_link
from ._sdf_reader import (
    MAX_NESTING,
    MAX_VERSION,
    Workspace,
    _Built,
    _Doc,
    _find,
    _findall,
    _tag,
    check_children,
    child_text,
    location_of,
    pick_sdf,
    read_document,
    read_flag,
    read_name,
    read_plugin,
    read_pose,
    resolve_uri,
)
from ._xml import (
    child_elements,
)


def include_file(
    ws: Workspace, uri: str, path: Path | None, doc: _Doc, loc: SourceLocation
) -> tuple[str, str, Path] | None:
    """(text, source, folder) of an included file, or None after reporting why it is not read.

    A folder is a model folder: its ``model.config`` picks the file (:func:`~._sdf_reader.pick_sdf`). What is refused
    and what is merely missing are told apart, because the user's fix differs: a URI outside the
    resource roots (or a file that links out of them) is an error naming the roots; a model that is not
    found is a warning and the include is skipped, as Gazebo skips it; a file that cannot be decoded is
    an error with the reason."""
    if path is not None and path.is_dir():
        path = pick_sdf(ws, path, loc)
    if path is None and ws.resolver.refused(uri, doc.base_dir):
        ws.sink.error(ErrorCode.URI_UNRESOLVED, f"include {ws.resolver.refusal(uri)}", loc)
        return None
    if path is None and uri.strip().startswith("model://"):
        name = uri.strip()[len("model://") :].partition("/")[0]
        if ws.resolver.find_package(name) is None:  # a model found nowhere: Classic's and gz-sim's error
            if name not in ws.missing_models:  # one line per model, however often it is named
                ws.missing_models.add(name)
                env = ws.resolver.env if ws.resolver.env is not None else os.environ
                ws.sink.skipped(ErrorCode.URI_UNRESOLVED, classic_model_advice(name, env), loc)
            return None
    if path is None or not path.is_file():
        ws.sink.warning(ErrorCode.URI_UNRESOLVED, f"cannot resolve include URI '{uri}'; include skipped", loc)
        return None
    if not ws.resolver.allowed(path):  # e.g. a model.sdf that links out of the resource paths
        ws.sink.error(ErrorCode.URI_UNRESOLVED, f"include {ws.resolver.refusal(uri)}", loc)
        return None
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as err:
        ws.sink.error(ErrorCode.FILE_READ_ERROR, f"cannot read included file {path}: {err}", loc)
        return None
    return text, str(path), path.parent


def fuel_include(ws: Workspace, fuel: FuelModel, uri: str, loc: SourceLocation) -> tuple[str, str, Path | None] | None:
    """A Fuel model without the network: built in, or from Gazebo's local Fuel cache (see :mod:`._fuel`).

    gazelle never downloads (a simulation's inputs must not change under it, and CI has no network):
    the handful of models nearly every world includes (ground plane, sun) are built in, and anything
    Gazebo itself once downloaded is read from its cache, trusted as the user's own files. Anything else
    is skipped with one error-level line that says where gazelle looked and how to get the model."""
    builtin = FUEL_BUILTIN.get(fuel.name.lower()) if fuel.owner.lower() == "openrobotics" else None
    if builtin is not None:
        return builtin, f"<builtin:fuel {fuel.label()}>", None
    cached = find_cached(fuel, cache_roots())
    if cached is not None:
        ws.resolver = ws.resolver.trusting(cached)  # the user's own Gazebo cache
        sdf = pick_sdf(ws, cached, loc)
        if sdf is not None:
            return include_file(ws, uri, sdf, _Doc(str(sdf), cached, MAX_VERSION, False), loc)
    # an error the load goes on past: gz-sim too logs an error and loads the world without a model it cannot get
    ws.sink.skipped(ErrorCode.URI_UNRESOLVED, how_to_get(fuel, uri, cache_roots()), loc)
    return None


def read_include(
    ws: Workspace, element: etree._Element, doc: _Doc, depth: int, allow_light: bool
) -> _Built | Light | None:
    """Load an ``<include>``: a model (or, in a world, a light) with the overrides applied."""
    check_children(ws, element, doc, "include")
    loc = location_of(element, doc)
    uri = child_text(element, "uri")
    if not uri:
        ws.sink.error(ErrorCode.ELEMENT_MISSING, "<include> has no <uri>", loc)
        return None
    if depth >= MAX_NESTING:
        ws.sink.error(ErrorCode.URI_UNRESOLVED, f"includes nest deeper than {MAX_NESTING} (a cycle?) at '{uri}'", loc)
        return None
    # three kinds of URI: a Fuel model (https://fuel.gazebosim.org/...), read from what is built in or
    # from Gazebo's own download cache, never fetched; model://, package://, file:// and paths, found on
    # the resource roots; anything else (http:// to elsewhere) is not read
    fuel = parse_fuel_uri(uri)
    if fuel is not None:
        got = fuel_include(ws, fuel, uri, loc)
        if got is None:
            return None
        text, source, base = got
    else:
        path = (
            None
            if "://" in uri and not uri.startswith(("model://", "package://", "file://"))
            else resolve_uri(ws, uri, doc)
        )
        stock = CLASSIC_BUILTIN.get(uri[len("model://") :].strip("/")) if uri.startswith("model://") else None
        if path is None and stock is not None:
            # Gazebo Classic installs these with itself; without them a Classic world has no floor
            got_file = (stock, f"<builtin:{uri}>", None)
        else:
            got_file = include_file(ws, uri, path, doc, loc)
        if got_file is None:
            return None
        text, source, base = got_file
    got = read_document(ws, text, source, base)  # the included file has its own version and folder
    if got is None:
        return None
    root, inner_doc = got
    model_el = _find(root, "model")
    light_el = _find(root, "light") if allow_light else None
    if model_el is None and light_el is not None:  # the "sun" of Gazebo's model database is a light
        light = read_light(ws, light_el, inner_doc, None)
        if light is None:
            return None
        name = child_text(element, "name")
        pose = read_pose(ws, element, doc)[0] if _find(element, "pose") is not None else light.pose
        return replace(light, name=name or light.name, pose=pose, location=loc)
    if model_el is None:
        ws.sink.error(ErrorCode.ELEMENT_MISSING, f"included file {source} holds no <model>", loc)
        return None
    built = read_model(ws, model_el, inner_doc, depth + 1)
    if built is None:
        return None
    apply_include_overrides(ws, built, element, doc)
    built.location = loc
    return built


def apply_include_overrides(ws: Workspace, built: _Built, element: etree._Element, doc: _Doc) -> None:
    """The ``<include>``'s own children override the included model's (sdformat's rule): its ``<name>``, its
    ``<pose>`` (in the including file's frames), ``<static>``, ``<placement_frame>``; its ``<plugin>`` s are
    added to the model's."""
    name = child_text(element, "name")
    if name:
        built.name = name
    if _find(element, "pose") is not None:
        built.pose, built.relative_to = read_pose(ws, element, doc)
    if _find(element, "static") is not None:
        built.static = read_flag(ws, element, "static", built.static, doc)
    placement = child_text(element, "placement_frame")
    if placement:
        built.placement_frame = placement
    for plugin_el in _findall(element, "plugin"):
        plugin = read_plugin(ws, plugin_el, doc)
        if plugin is not None:
            built.plugins.append(plugin)


# ================================================================== models
def read_model(ws: Workspace, element: etree._Element, doc: _Doc, depth: int) -> _Built | None:
    """Parse a ``<model>`` (recursively flattening nested models) in its own frame."""
    name = read_name(ws, element, doc)
    loc = location_of(element, doc)
    if name is None:
        return None
    if depth >= MAX_NESTING:
        ws.sink.error(ErrorCode.VALUE_INVALID, f"models nest deeper than {MAX_NESTING}", loc)
        return None
    check_children(ws, element, doc, "model")
    pose, relative_to = read_pose(ws, element, doc)
    built = _Built(
        name=name,
        static=read_flag(ws, element, "static", False, doc),
        self_collide=read_flag(ws, element, "self_collide", False, doc),
        pose=pose,
        relative_to=relative_to,
        placement_frame=(element.get("placement_frame") or "").strip() or None,
        canonical=None,
        doc=doc,
        location=loc,
    )
    scope = Scope("__model__", ws.sink)
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
            child_name = read_name(ws, child, doc)
            if child_name is None or not register_nested(ws, kinds, child_name, tag, child, doc, name):
                continue
            {"link": link_els, "joint": joint_els, "frame": frame_els}[tag].append((child_name, child))
            scope.nodes[child_name] = frame_node(ws, tag, child_name, child, doc)
        elif tag in ("model", "include"):
            sub = (
                read_model(ws, child, doc, depth + 1) if tag == "model" else read_include(ws, child, doc, depth, False)
            )
            if isinstance(sub, _Built) and tag == "include" and _merge(child):
                merged_first = merged_first or not (link_els or merged)
                merged.append((merge_nested(ws, sub, child, doc, kinds, scope, name), sub))
                continue
            if not isinstance(sub, _Built) or not register_nested(ws, kinds, sub.name, "model", child, doc, name):
                continue
            post = placement_inverse(ws, sub) or IDENTITY  # a bad placement_frame: reported, placed as if none
            nested.append(sub)
            scope.nested[sub.name] = sub.exported
            scope.nodes[sub.name] = FrameNode(
                sub.name, "model", sub.pose, sub.relative_to or "__model__", post=post, location=sub.location
            )

    # -- canonical link
    built.canonical = canonical_link(ws, element, scope, link_els, nested, name, loc)
    if merged and merged[0][1].canonical and element.get("canonical_link") is None and merged_first:
        built.canonical = merged[0][1].canonical  # merged links are this model's own, in the file's order
    scope.canonical = built.canonical
    if built.canonical is None:
        ws.sink.error(ErrorCode.LINK_MISSING, f"model '{name}' has no link", loc)
        return None

    # -- pass 2: links, joints, frames; then the nested models flattened into this one
    read_model_parts(ws, element, doc, scope, built, link_els, joint_els, frame_els)
    for proxy, sub in merged:
        X_MS = scope.pose(proxy, sub.location)
        if X_MS is not None:
            flatten(built, sub, X_MS, prefix="")
    flatten_nested(ws, built, nested, scope)
    built.exported = scope.export()
    return built


def merge_nested(
    ws: Workspace, sub: _Built, el: etree._Element, doc: _Doc, kinds: dict[str, str], scope: Scope, model: str
) -> str:
    """sdformat 1.9's ``<include merge="true">`` (sdf/1.9/model.sdf; libsdformat's merge-include): the included
    model's links, joints, frames and plugins become the parent model's own, with their own names (not
    ``sub::``), placed through a proxy frame ``_merged__<name>__model__`` that stands where the included
    model frame would (the include's ``<pose>``), attached to its canonical link. Returns the proxy's name;
    the content is moved in by :func:`flatten` once the parent's frames are resolved."""
    proxy = f"_merged__{sub.name}__model__"
    post = placement_inverse(ws, sub) or IDENTITY
    scope.nodes[proxy] = FrameNode(
        proxy, "frame", sub.pose, sub.relative_to or "__model__", sub.canonical, post, sub.location
    )
    links = {link.name for link in sub.links}
    for frame_name, X_SF in sub.exported.poses.items():
        kind = "link" if frame_name in links else "frame"
        if frame_name == "__model__" or not register_nested(ws, kinds, frame_name, kind, el, doc, model):
            continue
        body = sub.exported.bodies.get(frame_name)
        scope.nodes[frame_name] = FrameNode(frame_name, kind, X_SF, proxy, body, location=sub.location)
    return proxy


def register_nested(
    ws: Workspace, kinds: dict[str, str], node_name: str, kind: str, el: etree._Element, doc: _Doc, model: str
) -> bool:
    """Claim ``node_name`` in model ``model``'s frame graph (``kinds``: name -> kind so far) for a link, joint,
    frame or nested model: a reserved name (``world``, ``__model__``, ``__*__``) is an error, and so is a name
    used twice (by any two kinds from SDF 1.7 on; before it, only by two of one kind). False when refused."""
    if node_name in ("__model__", "world") or (node_name.startswith("__") and node_name.endswith("__")):
        ws.sink.error(ErrorCode.VALUE_INVALID, f"'{node_name}' is a reserved name", location_of(el, doc))
        return False
    previous = kinds.get(node_name)
    if previous is not None and (previous == kind or doc.version >= (1, 7)):
        ws.sink.error(
            ErrorCode.DUPLICATE_NAME,
            f"{kind} name '{node_name}' is already used by a {previous} in model '{model}'",
            location_of(el, doc),
        )
        return False
    if previous is None:
        kinds[node_name] = kind
    return previous is None


def placement_inverse(ws: Workspace, sub: _Built) -> Pose | None:
    """X_PM⁻¹ for a model placed by its ``placement_frame`` (identity without one); None, reported, when
    the frame is not one of the model's."""
    if sub.placement_frame is None:
        return IDENTITY
    inner = sub.exported.poses.get(sub.placement_frame)
    if inner is None:
        ws.sink.error(
            ErrorCode.FRAME_INVALID,
            f"placement_frame '{sub.placement_frame}' is not a frame of model '{sub.name}'",
            sub.location,
        )
        return None
    return inner.inverse()


def frame_node(ws: Workspace, tag: str, name: str, child: etree._Element, doc: _Doc) -> FrameNode:
    """The frame-graph node of a model's ``<link>``, ``<joint>`` (attached to its child) or ``<frame>``."""
    # what a pose is relative to when it does not say (SDF 1.7's defaults): a link's, the model frame; a
    # joint's, its child link; a frame's, what it is attached to (else the model frame)
    child_pose, child_rel = read_pose(ws, child, doc)
    child_loc = location_of(child, doc)
    if tag == "link":
        return FrameNode(name, "link", child_pose, child_rel or "__model__", location=child_loc)
    if tag == "joint":
        child_ref = child_text(child, "child") or ""
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
    ws: Workspace,
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
            canonical_attr in scope.nodes and scope.nodes[canonical_attr].kind != "link" and "::" not in canonical_attr
        ):
            ws.sink.error(
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


def read_model_parts(
    ws: Workspace,
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
        link = read_link(ws, link_name, link_el, doc, scope)
        if link is not None:
            built.links.append(link)
    for joint_name, joint_el in joint_els:
        read_joint(ws, joint_name, joint_el, doc, scope, built)
    for frame_name, frame_el in frame_els:
        X_MF = scope.pose(frame_name, location_of(frame_el, doc))
        body = scope.body(frame_name, location_of(frame_el, doc))
        if X_MF is None or body is None:
            continue
        X_MB = IDENTITY if body == "world" else scope.pose(body, location_of(frame_el, doc))
        if X_MB is not None:
            built.frames.append(Frame(frame_name, body, X_MB.inverse() * X_MF, location_of(frame_el, doc)))
    for plugin_el in _findall(element, "plugin"):
        plugin = read_plugin(ws, plugin_el, doc)
        if plugin is not None:
            built.plugins.append(plugin)


def flatten_nested(ws: Workspace, built: _Built, nested: list[_Built], scope: Scope) -> None:
    """Nested models into ``built``; a static one inside a non-static model is welded to the world."""
    for sub in nested:
        X_MS = scope.pose(sub.name, sub.location)
        if X_MS is None:
            continue
        flatten(built, sub, X_MS)
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


def flatten(parent: _Built, sub: _Built, X_PS: Pose, prefix: str | None = None) -> None:
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


def finish_model(ws: Workspace, built: _Built, X_WM: Pose) -> Model | None:
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
        if ws.sink.has_hard_errors:
            return None  # its links failed and were reported
        ws.sink.error(ErrorCode.LINK_MISSING, f"model '{built.name}' has no link", built.location)
        return None
    return Model(
        name=built.name,
        links=tuple(  # a joint's force_torque sensors live on the joint's child link
            replace(lk, sensors=(*lk.sensors, *built.joint_sensors[lk.name])) if lk.name in built.joint_sensors else lk
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


def _link_pose(built: _Built, link_name: str) -> Pose:
    """The pose of link ``link_name`` in the model frame (the identity when it has none or is not there)."""
    for link in built.links:
        if link.name == link_name:
            return link.pose or IDENTITY
    return IDENTITY


def _merge(include: etree._Element) -> bool:
    """``<include merge="true">`` (SDF 1.9): sdformat reads the attribute as a bool."""
    return (include.get("merge") or "").strip().lower() in ("true", "1")
