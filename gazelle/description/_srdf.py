"""SRDF (MoveIt's semantic robot description) into :class:`Semantics`.

Read: ``group`` (links, joints, chains, subgroups), ``group_state``, ``end_effector``,
``virtual_joint``, ``passive_joint`` and ``disable_collisions``. References between these
elements (a state's group, a subgroup, an end effector's groups) are checked; links and
joints are not, since they live in the URDF. A broken reference is a warning, not an
error: srdfdom logs it and drops the element, and MoveIt's own dual-arm Panda SRDF has
end effectors naming groups it never defines (we keep them as written).

Quirk accepted: MoveIt's own Panda SRDF puts ``<passive_joint>`` inside a ``<group>``.
It is kept in :attr:`Semantics.passive_joints` without a warning (srdfdom itself only
reads top-level ones, but the author's intent is plain).
"""

from __future__ import annotations

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._sdf_text import prepare
from ._semantic_model import Chain, DisabledCollision, EndEffector, Group, GroupState, Semantics, VirtualJoint
from ._xml import child_elements, element_location, local_name, parse_float, parse_xml

IGNORED = frozenset({"disable_default_collisions", "enable_collisions", "link_sphere_approximation", "sphere"})
"""Known SRDF elements with no place in :class:`Semantics`: skipped without a warning."""

_VIRTUAL_JOINT_TYPES = frozenset({"fixed", "floating", "planar"})


def parse_srdf(text: str, *, source: str, sink: DiagnosticSink) -> Semantics | None:
    """Parse SRDF text.

    Args:
        text: the document.
        source: file name used in diagnostics.
        sink: receives every diagnostic.

    Returns:
        The semantics, or None when the root is unusable (errors are in ``sink``).
    """
    prepared, _ = prepare(text)
    root = parse_xml(prepared, source=source, sink=sink)
    if root is None:
        return None
    return _Reader(source, sink).robot(root)


class _Reader:
    """One pass over an SRDF's elements. Every problem goes to the sink with its file:line, and the reader goes
    on: an element that cannot be read (a missing name, an unknown virtual joint type) is reported and left
    out, and the rest of the file still loads, so one typo in a 300-line SRDF is one message, not a robot
    without semantics. Names are checked against each other only at the end (:meth:`check_references`),
    since SRDF lets a group name a subgroup defined further down."""

    def __init__(self, source: str, sink: DiagnosticSink) -> None:
        """Read elements of the file ``source`` (the name its diagnostics carry), reporting to ``sink``."""
        self.source = source
        self.sink = sink

    def loc(self, element: etree._Element) -> SourceLocation:
        """Where ``element`` is: the file and its line (for the diagnostics)."""
        return element_location(element, self.source)

    def attr(self, element: etree._Element, name: str) -> str | None:
        """A required attribute's stripped value; an error naming the element and the attribute (and None) when it
        is missing or empty."""
        value = (element.get(name) or "").strip()
        if not value:
            self.sink.error(
                ErrorCode.ATTRIBUTE_MISSING,
                f"<{local_name(element)}> is missing the required '{name}' attribute",
                self.loc(element),
            )
            return None
        return value

    def unsupported(self, element: etree._Element, parent: str) -> None:
        """Warn of an element the SRDF reader does not read, with its file:line: nothing a user wrote is dropped
        silently."""
        self.sink.warning(
            ErrorCode.ELEMENT_UNSUPPORTED,
            f"<{local_name(element)}> in <{parent}> is not supported and is ignored",
            self.loc(element),
        )

    def robot(self, root: etree._Element) -> Semantics | None:
        """The SRDF's ``<robot>``: its groups (a name defined twice is an error), group states, end effectors,
        virtual joints, passive joints and disabled collision pairs; then the references between them are checked
        (a subgroup, a state's group or an end effector's group that is not defined is a warning)."""
        if local_name(root) != "robot":
            self.sink.error(
                ErrorCode.ROOT_ELEMENT_INVALID,
                f"SRDF root element must be <robot>, got <{local_name(root)}>",
                self.loc(root),
            )
            return None
        robot_name = self.attr(root, "name") or ""
        groups: list[Group] = []
        group_els: dict[str, etree._Element] = {}
        states: list[tuple[GroupState, etree._Element]] = []
        effectors: list[tuple[EndEffector, etree._Element]] = []
        virtual_joints: list[VirtualJoint] = []
        passive: list[str] = []
        disabled: list[DisabledCollision] = []
        subgroup_refs: list[tuple[str, etree._Element]] = []
        for child in child_elements(root):
            tag = local_name(child)
            if tag == "group":
                group = self.group(child, passive, subgroup_refs)
                if group is None:
                    continue
                if group.name in group_els:
                    self.sink.error(ErrorCode.DUPLICATE_NAME, f"group '{group.name}' is defined twice", self.loc(child))
                    continue
                group_els[group.name] = child
                groups.append(group)
            elif tag == "group_state":
                state = self.group_state(child)
                if state is not None:
                    states.append((state, child))
            elif tag == "end_effector":
                effector = self.end_effector(child)
                if effector is not None:
                    effectors.append((effector, child))
            elif tag == "virtual_joint":
                vj = self.virtual_joint(child)
                if vj is not None:
                    virtual_joints.append(vj)
            elif tag == "passive_joint":
                name = self.attr(child, "name")
                if name is not None:
                    passive.append(name)
            elif tag == "disable_collisions":
                link1, link2 = self.attr(child, "link1"), self.attr(child, "link2")
                if link1 is not None and link2 is not None:
                    disabled.append(DisabledCollision(link1, link2, (child.get("reason") or "").strip()))
            elif tag not in IGNORED:
                self.unsupported(child, "robot")
        self.check_references(group_els, subgroup_refs, states, effectors)
        return Semantics(
            robot_name=robot_name,
            groups=tuple(groups),
            group_states=tuple(s for s, _ in states),
            end_effectors=tuple(e for e, _ in effectors),
            virtual_joints=tuple(virtual_joints),
            passive_joints=tuple(dict.fromkeys(passive)),
            disabled_collisions=tuple(disabled),
        )

    def end_effector(self, element: etree._Element) -> EndEffector | None:
        """``<end_effector name parent_link group [parent_group]>``; None when a required attribute is missing."""
        name, parent_link, group = (self.attr(element, a) for a in ("name", "parent_link", "group"))
        if name is None or parent_link is None or group is None:
            return None  # self.attr said which is missing
        parent_group = (element.get("parent_group") or "").strip() or None
        return EndEffector(name, parent_link, group, parent_group)

    def virtual_joint(self, element: etree._Element) -> VirtualJoint | None:
        """``<virtual_joint name type parent_frame child_link>`` with type fixed, floating or planar (another is an
        error)."""
        vj_name, vj_type, frame, child_link = (
            self.attr(element, a) for a in ("name", "type", "parent_frame", "child_link")
        )
        if vj_name is None or vj_type is None or frame is None or child_link is None:
            return None
        if vj_type not in _VIRTUAL_JOINT_TYPES:
            self.sink.error(
                ErrorCode.JOINT_TYPE_INVALID,
                f"virtual_joint '{vj_name}' has unknown type '{vj_type}' (expected fixed, floating or planar)",
                self.loc(element),
            )
            return None
        return VirtualJoint(vj_name, vj_type, frame, child_link)

    def check_references(
        self,
        group_els: dict[str, etree._Element],
        subgroup_refs: list[tuple[str, etree._Element]],
        states: list[tuple[GroupState, etree._Element]],
        effectors: list[tuple[EndEffector, etree._Element]],
    ) -> None:
        """References between SRDF elements: a subgroup, a group state's group, an end effector's groups
        that are not defined are warned about, and the semantics load.

        Warnings, not errors, as MoveIt's srdfdom loads such a file and leaves the dangling reference out
        (a MoveIt Setup Assistant file edited by hand, a group renamed and one state forgotten): the rest of
        the robot's semantics still plan. The planner then says which group it lacks if it is asked for
        one."""
        for ref, element in subgroup_refs:
            if ref not in group_els:
                self.sink.warning(
                    ErrorCode.SRDF_REFERENCE_INVALID, f"subgroup '{ref}' is not a defined group", self.loc(element)
                )
        for state, element in states:
            if state.group not in group_els:
                self.sink.warning(
                    ErrorCode.SRDF_REFERENCE_INVALID,
                    f"group_state '{state.name}' refers to unknown group '{state.group}'",
                    self.loc(element),
                )
        for effector, element in effectors:
            for role, ref in (("group", effector.group), ("parent_group", effector.parent_group)):
                if ref is not None and ref not in group_els:
                    self.sink.warning(
                        ErrorCode.SRDF_REFERENCE_INVALID,
                        f"end_effector '{effector.name}' {role} '{ref}' is not a defined group",
                        self.loc(element),
                    )

    def group(self, element: etree._Element, passive: list[str], subgroup_refs: list) -> Group | None:
        """``<group>``: its links, joints, chains, subgroups (checked once every group is read) and passive joints
        listed inside it.

        The four ways SRDF names a group's members, as MoveIt's JointModelGroup reads them: ``<link>``s (their
        parent joints), ``<joint>``s, a ``<chain base_link tip_link>`` (the joints between, the arm's usual
        form) and ``<group>``s (subgroups, whose members join). Names are kept as written; whether the URDF
        has them is checked against the robot when a scene is built (a group naming a missing link is left
        out there, with its line)."""
        name = self.attr(element, "name")
        links: list[str] = []
        joints: list[str] = []
        chains: list[Chain] = []
        subgroups: list[str] = []
        for child in child_elements(element):
            tag = local_name(child)
            if tag in ("link", "joint", "group", "passive_joint"):
                ref = self.attr(child, "name")
                if ref is None:
                    continue
                if tag == "link":
                    links.append(ref)
                elif tag == "joint":
                    joints.append(ref)
                elif tag == "group":
                    subgroups.append(ref)
                    subgroup_refs.append((ref, child))
                else:
                    passive.append(ref)
            elif tag == "chain":
                base, tip = self.attr(child, "base_link"), self.attr(child, "tip_link")
                if base is not None and tip is not None:
                    chains.append(Chain(base, tip))
            else:
                self.unsupported(child, "group")
        if name is None:
            return None
        return Group(name, tuple(links), tuple(joints), tuple(chains), tuple(subgroups))

    def group_state(self, element: etree._Element) -> GroupState | None:
        """``<group_state name group>``: each ``<joint name value>``, where ``value`` holds one number per degree of
        freedom (a planar or floating joint has several); a value that is not numbers is an error naming the
        joint."""
        name, group = self.attr(element, "name"), self.attr(element, "group")
        values: list[tuple[str, tuple[float, ...]]] = []
        for child in child_elements(element):
            if local_name(child) != "joint":
                self.unsupported(child, "group_state")
                continue
            joint, raw = self.attr(child, "name"), self.attr(child, "value")
            if joint is None or raw is None:
                continue
            numbers = tuple(parse_float(p) for p in raw.split())
            if not numbers or any(v is None for v in numbers):
                self.sink.error(
                    ErrorCode.VALUE_INVALID,
                    f"group_state '{name}': joint '{joint}' value must be numbers, got {raw!r}",
                    self.loc(child),
                )
                continue
            values.append((joint, tuple(v for v in numbers if v is not None)))
        if name is None or group is None:
            return None
        return GroupState(name, group, tuple(values))
