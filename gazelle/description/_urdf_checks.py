"""The URDF loader's later passes (see :mod:`._urdf`): attributes no element knows, the kinematic structure
(names, parents, loops, one root), links without mass (dropped as sdformat does), and finishing links
(``<gazebo>`` materials applied, missing or invalid inertia derived from the collision shapes)."""

from __future__ import annotations

import dataclasses

from lxml import etree

from . import _inertia
from ._colors import GAZEBO_COLORS
from ._diagnostics import ErrorCode
from ._model import (
    Inertial,
    Joint,
    JointType,
    Link,
    Material,
    Visual,
)
from ._urdf_elements import _CHILDREN, ElementReader, LinkDraft, UrdfDocument
from ._xml import (
    LOCATION_ATTRIBUTE,
    child_elements,
    local_name,
)


# --------------------------------------------------------------------------- fragments
def is_fragment(root: etree._Element) -> bool:
    """Whether a ``<robot>`` defines no ``<link>`` and no ``<joint>`` (an include fragment)."""
    return root.find("link") is None and root.find("joint") is None


def report_fragment(root: etree._Element, doc: UrdfDocument, reader: ElementReader) -> None:
    """One FRAGMENT warning for a document that defines no links or joints.

    A xacro file meant to be included (macros, materials, ``<gazebo>`` blocks for links defined elsewhere) is
    a common thing to point gazelle at by mistake; the warning says what the file does hold, so the user sees
    at once that it is a fragment and which file to open instead, rather than an empty robot."""
    kept = []
    if doc.materials:
        kept.append(f"{len(doc.materials)} material(s)")
    if doc.gazebo:
        kept.append(f"{len(doc.gazebo)} <gazebo> block(s), for links defined elsewhere")
    if doc.transmissions:
        kept.append(f"{len(doc.transmissions)} transmission(s)")
    what = ", ".join(kept) if kept else "nothing once expanded (macros or properties only)"
    label = f"robot '{doc.name}'" if doc.name else "<robot>"
    reader.warn(
        ErrorCode.FRAGMENT,
        f"{label} defines no links (an include fragment?): it holds {what}; it cannot be simulated on its own",
        root,
    )


# --------------------------------------------------------------------------- attributes
_ATTRIBUTES: dict[str, frozenset[str]] = {
    "robot": frozenset({"name", "version"}),
    "link": frozenset({"name", "type"}),
    "joint": frozenset({"name", "type"}),
    "origin": frozenset({"xyz", "rpy"}),
    "parent": frozenset({"link"}),
    "child": frozenset({"link"}),
    "axis": frozenset({"xyz"}),
    "limit": frozenset({"lower", "upper", "effort", "velocity"}),
    "dynamics": frozenset({"damping", "friction"}),
    "mimic": frozenset({"joint", "multiplier", "offset"}),
    "safety_controller": frozenset({"soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"}),
    "calibration": frozenset({"rising", "falling", "reference_position"}),
    "inertial": frozenset(),
    "mass": frozenset({"value"}),
    "inertia": frozenset({"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}),
    "visual": frozenset({"name"}),
    "collision": frozenset({"name"}),
    "geometry": frozenset(),
    "box": frozenset({"size"}),
    "cylinder": frozenset({"radius", "length"}),
    "capsule": frozenset({"radius", "length"}),
    "sphere": frozenset({"radius"}),
    "mesh": frozenset({"filename", "scale"}),
    "material": frozenset({"name"}),
    "color": frozenset({"rgba"}),
    "texture": frozenset({"filename"}),
    "gazebo": frozenset({"reference"}),
}
"""Attributes the URDF loader reads (or knowingly accepts) on each element it interprets.

``link type`` and ``robot version`` come from the URDF spec/urdfdom and carry nothing to simulate.
Namespaced attributes (``xsi:schemaLocation``, ``{ns}...``) and namespace declarations are
extensions and never reported.
"""

_WALKED: dict[str, frozenset[str]] = {
    "robot": frozenset({"link", "joint", "material", "gazebo"}),
    "geometry": frozenset({"box", "cylinder", "capsule", "sphere", "mesh"}),
    **{k: v for k, v in _CHILDREN.items()},
}
"""Children whose attributes are checked, per element (raw blocks such as plugins are not)."""


def check_attributes(root: etree._Element, reader: ElementReader) -> None:
    """ATTRIBUTE_UNSUPPORTED warnings for attributes the loader ignores on elements it reads."""
    found: dict[tuple[str, str], list[etree._Element]] = {}
    stack = [root]
    while stack:
        element = stack.pop()
        tag = local_name(element)
        known = _ATTRIBUTES.get(tag)
        if known is not None:
            for raw in element.attrib:
                attr = str(raw)
                if attr != LOCATION_ATTRIBUTE and not attr.startswith("{") and attr not in known:
                    found.setdefault((tag, attr), []).append(element)
        walked = _WALKED.get(tag, frozenset())
        stack.extend(reversed([c for c in child_elements(element) if local_name(c) in walked]))
    # one warning per (element, attribute), at its first use: vendor attributes repeat on every joint
    for (tag, attr), elements in found.items():
        more = f" (and on {len(elements) - 1} more <{tag}>)" if len(elements) > 1 else ""
        reader.warn(
            ErrorCode.ATTRIBUTE_UNSUPPORTED,
            f'attribute {attr}="{elements[0].get(attr)}" of <{tag}> is not supported and is ignored{more}',
            elements[0],
        )


# --------------------------------------------------------------------------- structure
def check_structure(doc: UrdfDocument, reader: ElementReader) -> None:
    """Parents and children exist, one parent per link, no loops, one root.

    urdfdom's ``initTree`` and ``initRoot`` rules (what ``check_urdf`` and robot_state_publisher refuse),
    each an error at the joint's line: a joint's parent or child that is not a link (``world`` allowed as
    a parent, as Gazebo's URDF loader fixes the robot to the world through it), a link that is its own
    parent, a link with two parent joints (a kinematic loop URDF cannot describe), and more than one root
    link. A ``<mimic>`` naming a joint the robot lacks is a warning, and that mimic is not enforced.
    """
    parent_of: dict[str, Joint] = {}
    for joint in doc.joints.values():
        loc = joint.location
        if joint.parent not in doc.links and joint.parent != "world":
            reader.sink.error(
                ErrorCode.JOINT_PARENT_INVALID, f"joint '{joint.name}' has unknown parent link '{joint.parent}'", loc
            )
        if joint.child not in doc.links:
            reader.sink.error(
                ErrorCode.JOINT_CHILD_INVALID, f"joint '{joint.name}' has unknown child link '{joint.child}'", loc
            )
            continue
        if joint.child == joint.parent:
            reader.sink.error(
                ErrorCode.KINEMATIC_LOOP, f"joint '{joint.name}' connects link '{joint.child}' to itself", loc
            )
            continue
        if joint.child in parent_of:
            other = parent_of[joint.child]
            reader.sink.error(
                ErrorCode.JOINT_CHILD_INVALID,
                f"link '{joint.child}' has two parents: joint '{other.name}' ({other.location})"
                f" and joint '{joint.name}'",
                loc,
            )
            continue
        parent_of[joint.child] = joint
    _check_loops(doc, parent_of, reader)
    for joint in doc.joints.values():
        if joint.mimic is not None and joint.mimic.joint not in doc.joints:
            reader.sink.warning(
                ErrorCode.ATTRIBUTE_INVALID,
                f"joint '{joint.name}' mimics unknown joint '{joint.mimic.joint}'",
                joint.location,
            )
    roots = [draft for name, draft in doc.links.items() if name not in parent_of]
    # one tree, as urdfdom requires: a second root would be a second robot that nothing holds together
    if len(roots) > 1:
        names = ", ".join(f"'{r.name}'" for r in roots)
        reader.sink.error(
            ErrorCode.MULTIPLE_ROOTS,
            f"robot '{doc.name}' has {len(roots)} root links ({names}); connect them with joints into one tree",
            roots[1].location,
        )
    if not doc.links and doc.joints:
        reader.sink.error(
            ErrorCode.LINK_MISSING,
            f"robot '{doc.name}' has {len(doc.joints)} joint(s) but no links",
            next(iter(doc.joints.values())).location,
        )


def _check_loops(doc: UrdfDocument, parent_of: dict[str, Joint], reader: ElementReader) -> None:
    """Report each cycle of the child -> parent relation once.

    Each link's parent chain is walked until it reaches the root, a link already cleared, or itself; the
    links cleared are never walked again, so a 5,000-link chain costs one pass. The message lists the cycle
    in joint order (``'a' -> 'b' -> 'a'``) at the line of the joint that closes it, where urdfdom's
    ``initRoot`` tells of a loop less directly (no root link found, or two)."""
    done: set[str] = set()
    for start in doc.links:
        path: list[str] = []
        node: str | None = start
        while node is not None and node not in done and node not in path:
            path.append(node)
            joint = parent_of.get(node)
            node = joint.parent if joint is not None else None
        if node is not None and node in path:
            cycle = path[path.index(node) :]
            chain = " -> ".join(f"'{n}'" for n in [*reversed(cycle), cycle[-1]])
            reader.sink.error(ErrorCode.KINEMATIC_LOOP, f"kinematic loop: {chain}", parent_of[cycle[0]].location)
        done.update(path)


# --------------------------------------------------------------------------- massless links (sdformat's rule)
def has_mass(draft: LinkDraft) -> bool:
    """Whether the link's ``<inertial>`` gives it a positive mass (as written: a mass that failed to parse
    is None)."""
    raw = draft.inertial
    return raw is not None and raw.mass is not None and raw.mass > 0


def drop_massless_links(doc: UrdfDocument, reader: ElementReader) -> None:
    """Leave out what Gazebo leaves out, as sdformat's URDF conversion does.

    Fixed joints are reduced first: a link fixed to its parent merges into it, massless or not, and
    a link's mass includes everything fixed below it. Then a link that still has no mass (no
    ``<inertial>``, or mass 0), reached by a moving joint or being the root, is not modelled: it
    is dropped with its parent joint and every link below it, with a warning. Its mass is never
    made up from its collision volume (that tripled Husky's mass). Static robots keep every link.
    """
    children: dict[str, list[Joint]] = {}
    parent_of: dict[str, Joint] = {}
    for j in doc.joints.values():
        children.setdefault(j.parent, []).append(j)
        parent_of[j.child] = j
    lumped: dict[str, bool] = {}
    """Link -> whether it, or anything welded below it by fixed joints, has mass (what sdformat lumps)."""
    order: list[str] = []
    stack = [name for name in doc.links if name not in parent_of]
    while stack:  # a pre-order walk, iterative (5,000-link chains)
        name = stack.pop()
        order.append(name)
        stack.extend(j.child for j in children.get(name, []) if j.child in doc.links)
    for name in reversed(order):  # children before parents
        lumped[name] = has_mass(doc.links[name]) or any(
            lumped.get(j.child, False) for j in children.get(name, []) if j.type is JointType.FIXED
        )
    dropped: set[str] = set()
    for name in order:
        if name in dropped:
            continue
        up = parent_of.get(name)
        # a link fixed to a kept parent becomes part of it (sdformat merges it), with or without mass
        merged = up is not None and up.type is JointType.FIXED and up.parent not in dropped
        if merged or lumped[name]:
            continue
        below: list[str] = []
        todo = [j.child for j in children.get(name, [])]
        while todo:
            child = todo.pop()
            below.append(child)
            todo.extend(j.child for j in children.get(child, []))
        dropped.update([name, *below])
        what = f"its joint '{up.name}'" if up is not None else "it is the root"
        tail = (
            f" and the {len(below)} link(s) below it ({', '.join(below[:4])}{', ...' if len(below) > 4 else ''})"
            if below
            else ""
        )
        reader.sink.warning(
            ErrorCode.INERTIA_MISSING,
            f"link '{name}' has no <inertial> with mass > 0 (nor has anything fixed to it): Gazebo does not model "
            f"it; it is left out ({what}){tail}",
            doc.links[name].location,
        )
    if dropped:
        for name in dropped:
            del doc.links[name]
        doc.joints = {k: j for k, j in doc.joints.items() if j.child not in dropped and j.parent not in dropped}


# --------------------------------------------------------------------------- finishing links
def finish_link(draft: LinkDraft, movable_by: str | None, reader: ElementReader, derive: bool) -> Link:
    """The frozen :class:`Link`: ``<gazebo>`` applied and the inertial settled.

    What the link's ``<gazebo reference>`` blocks set is applied here, after all of them were read, so their
    order in the file does not matter: surface parameters (``mu1``, ``kp`` ...) onto every collision, a
    material script onto every visual, the flags (``gravity``, ``kinematic``, ``self_collide``). ``movable_by``
    names the joint that moves the link (None for one welded to its parent or the root), which decides
    whether a missing inertial matters (see :func:`_settle_inertial`)."""
    collisions = tuple(
        dataclasses.replace(c, surface=dataclasses.replace(c.surface, **draft.surface)) for c in draft.collisions
    )
    visuals = tuple(_apply_gazebo_material(v, draft.gazebo_material) for v in draft.visuals)
    return Link(
        name=draft.name,
        inertial=_settle_inertial(draft, movable_by, reader, derive),
        visuals=visuals,
        collisions=collisions,
        sensors=tuple(draft.sensors),
        gravity=draft.flags.get("gravity", True),
        kinematic=draft.flags.get("kinematic", False),
        self_collide=draft.flags.get("self_collide"),
        location=draft.location,
    )


def _apply_gazebo_material(visual: Visual, script: str | None) -> Visual:
    """``visual`` with its link's ``<gazebo><material>`` script applied: the script's name, and its colour when
    :data:`GAZEBO_COLORS` knows it (else the visual's own). Gazebo draws the script, not the URDF colour."""
    if script is None:
        return visual
    diffuse = GAZEBO_COLORS.get(script) or (visual.material.diffuse if visual.material else None)
    base = visual.material or Material()
    return dataclasses.replace(visual, material=dataclasses.replace(base, name=script, diffuse=diffuse))


def _settle_inertial(draft: LinkDraft, movable_by: str | None, reader: ElementReader, derive: bool) -> Inertial | None:
    """The link's inertial; derived (with a warning per problem) when invalid, or when missing and ``derive``
    (a robot with no mass at all); otherwise a missing one stays missing (see :func:`drop_massless_links`)."""
    raw = draft.inertial
    if raw is not None and not raw.problems and raw.mass is not None and raw.tensor is not None:
        ixx, ixy, ixz, iyy, iyz, izz = raw.tensor
        return Inertial(raw.mass, raw.pose, ixx, ixy, ixz, iyy, iyz, izz)
    if raw is None and not derive:
        return None  # massless: merged into its parent, or carried by what is fixed to it
    if raw is None and not draft.collisions:
        if movable_by is None:
            return None  # a pure frame (base_footprint, sensor frames)
        inertial = _inertia.default_inertial()
        problems = [
            (ErrorCode.INERTIA_MISSING, f"has no <inertial> but moves with joint '{movable_by}'", draft.location)
        ]
        remedy = f"using a placeholder mass of {inertial.mass:g} kg"
    else:
        mass = raw.mass if raw is not None else None
        problems = (
            raw.problems
            if raw is not None
            else [(ErrorCode.INERTIA_MISSING, "has collision geometry but no <inertial>", draft.location)]
        )
        inertial, remedy = _derive(draft, mass)
    for code, text, loc in problems:
        reader.sink.warning(code, f"link '{draft.name}': {text}; {remedy}", loc)
    return inertial


def _derive(draft: LinkDraft, mass: float | None) -> tuple[Inertial, str]:
    """Inertia from the collision shapes (mass from volume when ``mass`` is None) and a note saying how.

    The note ends the warning the user reads, so it says what was assumed: the number of shapes used, the
    volume and the density behind a mass that was made up, and anything the shapes could not give (a mesh
    that would not load). With no volume at all, a placeholder inertia keeps MuJoCo from refusing the link;
    the warning says it is one."""
    result = _inertia.inertia_from_geometries([(c.geometry, c.pose) for c in draft.collisions], mass)
    if result is None:
        inertial = _inertia.default_inertial(mass)
        why = "no collision shape has a volume" if draft.collisions else "the link has no collision geometry"
        return inertial, f"{why}, using mass {inertial.mass:g} kg with a placeholder inertia"
    inertial = result.inertial
    how = f"inertia derived from {len(draft.collisions)} collision shape(s)"
    if result.mass_from_volume:
        how += (
            f", mass {inertial.mass:.4g} kg from volume {result.volume:.4g} m^3 at {_inertia.DEFAULT_DENSITY:g} kg/m^3"
        )
    if result.notes:
        how += " (" + "; ".join(result.notes) + ")"
    return inertial, how
