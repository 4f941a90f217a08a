"""The URDF of one planning group, as MoveIt's ``get_urdf`` service builds it.

MoveIt (moveit_ros/move_group/src/default_capabilities/get_group_urdf_capability.cpp, Jazzy) answers
``GetGroupUrdf`` with ``<robot name="GROUP">`` holding, copied from the robot's URDF, the group's links
(sorted, each once), then its joints (sorted), each followed by an empty ``<link name="PARENT"/>`` when the
joint's parent link is not one of them yet; a result ``urdfdom`` cannot parse is a failure. The group's
joints and links are MoveIt's ``JointModelGroup``'s (moveit_core/robot_model/src/robot_model.cpp,
``addJointModelGroup``): the joints along each chain (from the tip up to the base, or through their common
ancestor), the named joints, the parent joint of each named link and the joints of each subgroup; its links
are those joints' child links. MoveIt copies the elements by searching the URDF's text; here they are the
parsed elements, serialised.
"""

from __future__ import annotations

from lxml import etree

from .._errors import SimError
from ..description import Semantics
from ._names import quoted

_HEADER = '<?xml version="1.0" ?><robot name="{}" xmlns:xacro="http://ros.org/wiki/xacro">'


class GroupUrdfError(SimError, ValueError):
    """The group is not in the SRDF, or its URDF would not be valid: the message says which, as MoveIt's."""


def group_joints_and_links(robot: etree._Element, semantics: Semantics, group: str) -> tuple[list[str], list[str]]:
    """MoveIt's ``getJointModelNames()`` and ``getLinkModelNames()`` of ``group`` (fixed joints included)."""
    parent_joint: dict[str, tuple[str, str]] = {}  # child link -> (joint, parent link)
    for joint in robot.findall("joint"):  # top level: not a <transmission>'s or <ros2_control>'s
        parent, child = joint.find("parent"), joint.find("child")
        if parent is not None and child is not None:
            parent_joint[str(child.get("link"))] = (str(joint.get("name")), str(parent.get("link")))
    by_name = {g.name: g for g in semantics.groups}

    def up(link: str) -> list[tuple[str, str]]:
        """(link, the joint above it) from ``link`` up to the root, whose joint is "" (a loop in a malformed
        tree ends the walk instead of looping)."""
        out, seen = [], set()
        while link in parent_joint and link not in seen:
            seen.add(link)
            out.append((link, parent_joint[link][0]))
            link = parent_joint[link][1]
        out.append((link, ""))
        return out

    def joints_of(name: str, visiting: frozenset[str] = frozenset()) -> set[str]:
        """The joints of group ``name`` as MoveIt's JointModelGroup takes them from the SRDF: each chain's
        joints from its base link down to its tip (through their common ancestor when the base is not above
        the tip), the listed joints, the joints above the listed links, and its subgroups' joints (a cycle of
        subgroups is cut where it comes back)."""
        g = by_name[name]
        found: set[str] = set()
        for chain in g.chains:
            tip_path, base_path = up(chain.tip_link), up(chain.base_link)
            base_links = [link for link, _ in base_path]
            for link, joint in tip_path:
                if link in base_links:  # the base itself, or the common ancestor of base and tip
                    found.update(j for b, j in base_path[: base_links.index(link)] if j)
                    break
                if joint:
                    found.add(joint)
        found.update(g.joints)
        found.update(parent_joint[link][0] for link in g.links if link in parent_joint)
        for sub in g.subgroups:
            if sub in by_name and sub not in visiting:
                found |= joints_of(sub, visiting | {name})
        return found

    joints = joints_of(group)
    child_of = {joint: child for child, (joint, _parent) in parent_joint.items()}
    links = sorted({child_of[j] for j in joints if j in child_of})
    return sorted(joints), links


def group_urdf(urdf: str, semantics: Semantics, group: str) -> str:
    """The URDF text of ``group`` (see the module's docstring); :class:`GroupUrdfError` when the SRDF has
    no such group or the result would have no single root link (urdfdom's rule)."""
    if group not in {g.name for g in semantics.groups}:
        raise GroupUrdfError(f"Cannot create URDF because planning group {quoted(group)} does not exist")
    parser = etree.XMLParser(resolve_entities=False, no_network=True, remove_blank_text=True)
    robot = etree.fromstring(urdf.encode(), parser)
    joints, links = group_joints_and_links(robot, semantics, group)
    elements = {("link", str(e.get("name"))): e for e in robot.findall("link")}
    elements.update({("joint", str(e.get("name"))): e for e in robot.findall("joint")})

    def text(kind: str, name: str) -> str:
        element = elements[(kind, name)]
        return etree.tostring(element, encoding="unicode", with_tail=False)

    out = [_HEADER.format(group)]
    out += [text("link", name) for name in links]
    shown = list(links)
    roots = set(links)
    for name in joints:
        out.append(text("joint", name))
        joint = elements[("joint", name)]
        parent, child = joint.find("parent"), joint.find("child")
        roots.discard(str(child.get("link")) if child is not None else "")
        parent_link = str(parent.get("link")) if parent is not None else ""
        if parent_link not in shown:
            out.append(f'<link name="{parent_link}"/>')
            shown.append(parent_link)
            roots.add(parent_link)
    out.append("</robot>")
    if len(roots) != 1:  # urdfdom: a tree with one root ("Two root links found", "No root link found")
        raise GroupUrdfError("Failed to create valid urdf")
    return "".join(out)
