"""URDF text to :class:`Model`, with every problem reported as a located diagnostic.

Entry point: :func:`parse_urdf`. The loader reads the document in three passes:

1. elements to drafts (links, joints, materials: ``_urdf_elements.py``; ``<gazebo>`` blocks and
   ``<ros2_control>``: here), checking values;
2. the kinematic structure (names, parents, loops, roots: ``_urdf_checks.py``);
3. finishing links: ``<gazebo>`` extensions applied, missing or invalid inertia derived (``_urdf_checks.py``).

Fixed joints are kept as they are (no lumping). Elements expanded by xacro carry their
original file and line (see :mod:`._xml`), so diagnostics point into the xacro sources.

Where this differs from Gazebo's own URDF reading (sdformat's ``src/parser_urdf.cc``, which both Gazebo
Classic and gz-sim use):

* **No fixed-joint lumping.** sdformat merges every link hanging on a fixed joint into its parent (unless
  the joint has ``<disableFixedJointLumping>``/``<preserveFixedJoint>``): the child's mass is added to the
  parent's, its shapes and sensors move onto the parent, and the child link no longer exists in the
  simulation. gazelle keeps every link as its own welded body, so a link's name, its frame and what is on
  it stay where the URDF put them (the physics welds them, which costs no accuracy). One visible effect: a
  gazebo_ros sensor without ``<frame_name>`` reports in its own URDF link's frame here, where Classic
  reports the lumped parent's name for data still measured at the sensor (a long-standing Classic pitfall
  that robots work around by setting ``<frame_name>``; with it, both agree).
* **Massless links.** sdformat leaves out a link that has no mass after lumping and is reached by a moving
  joint (or is the root), with everything below it; gazelle leaves out the same links
  (``drop_massless_links``, a warning naming each), though the links it keeps stay unlumped. A
  description where no link has mass at all (kinematics-only files such as moveit_resources' Panda), of
  which Gazebo would simulate nothing, gets each link's inertia from its collisions instead.
* **``<gazebo>`` blocks.** The tags sdformat converts (``mu1``, ``mu2``, ``kp``, ``kd``, ``fdir1``,
  ``maxVel``, ``minDepth``, ``selfCollide``, ``turnGravityOff``) are applied from the tables below, as are
  the SDF elements sdformat copies into the link verbatim (``gravity``, ``kinematic``, ``material``,
  ``sensor``, ``plugin``) and into each of its collisions (``<collision><surface>``, before the short
  forms). The rest (``dampingFactor``, ``maxContacts``, ``laserRetro``, the joint tags
  ``stopCfm``/``stopErp``/``springStiffness``/...) are kept in :attr:`Model.gazebo` and named in a
  warning: nothing a user wrote is dropped silently.
"""

from __future__ import annotations

from dataclasses import fields, replace

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode
from ._model import GazeboExtension, JointType, Material, Model, Plugin, Sensor
from ._pose import Pose
from ._resources import ResourceResolver
from ._sdf_parts import read_surface
from ._sdf_reader import IGNORED, MAX_VERSION, Workspace, _Doc
from ._semantic_model import ControlComponent, ControlInterface, Ros2Control
from ._urdf_checks import (
    check_attributes,
    check_structure,
    drop_massless_links,
    finish_link,
    has_mass,
    is_fragment,
    report_fragment,
)
from ._urdf_elements import D, ElementReader, LinkDraft, UrdfDocument, gazebo_value
from ._xml import (
    child_elements,
    local_name,
    parse_floats,
    parse_xml,
    to_config,
)

# <gazebo reference="link"> tags applied to every collision's Surface: tag -> (field, vector length).
# sdformat writes them into each of the link's collisions as <surface><friction><ode><mu>/<mu2>/<fdir1>
# and <surface><contact><ode><kp>/<kd>/<max_vel>/<min_depth>: the same Surface fields an SDF collision fills.
_SURFACE_TAGS: dict[str, tuple[str, int]] = {
    "mu1": ("mu", 1),
    "mu2": ("mu2", 1),
    "kp": ("kp", 1),
    "kd": ("kd", 1),
    "maxVel": ("max_vel", 1),
    "minDepth": ("min_depth", 1),
    "fdir1": ("fdir1", 3),
}
# <gazebo reference="link"> boolean tags applied to the Link: tag -> (field, inverted).
# turnGravityOff is sdformat's own (true means <gravity>false); the other three are SDF link elements that
# sdformat copies into the link as written.
_LINK_FLAGS: dict[str, tuple[str, bool]] = {
    "selfCollide": ("self_collide", False),
    "gravity": ("gravity", False),
    "turnGravityOff": ("gravity", True),
    "kinematic": ("kinematic", False),
}
# <gazebo> (no reference) boolean tags applied to the Model: <static> (sdformat's own: the whole robot is
# fixed in the world) and <self_collide> (SDF's model element, the default for links that do not say).
_MODEL_FLAGS: dict[str, str] = {"static": "static", "self_collide": "self_collide"}


class _Reader:
    """Reads a whole ``<robot>``: its ``<gazebo>`` blocks and ``<ros2_control>``, the elements (links, joints,
    materials, values) through the :class:`ElementReader` it owns."""

    def __init__(self, elements: ElementReader) -> None:
        self.elements = elements
        """Reads the URDF elements and reports every problem with its location."""

    # ---- <gazebo>
    def plugin(self, element: etree._Element) -> Plugin | None:
        """A ``<plugin name filename>`` with its whole element as config."""
        filename = element.get("filename")
        if not filename:
            self.elements.error(
                ErrorCode.ATTRIBUTE_MISSING,
                f"<plugin name={element.get('name', '')!r}> has no 'filename' attribute",
                element,
            )
            return None
        return Plugin(
            element.get("name", ""), filename, to_config(element, self.elements.source), self.elements.loc(element)
        )

    def sensor(self, element: etree._Element) -> Sensor | None:
        """A ``<sensor type name>`` inside ``<gazebo reference=link>``: what sdformat's URDF parser copies into
        that link's SDF, so it is read as SDF's ``<sensor>`` is. The ``<pose>`` (x y z roll pitch yaw, six
        numbers, metres and radians) is in the link's frame; ``<update_rate>`` 0 or absent means every step
        for Gazebo's sensors; the whole element is kept (``config``) for the sensor's system to read its own
        block (``<ray>``, ``<camera>``, noise) and its ``<plugin>``s, which gazebo_ros's sensor plugins are."""
        name = self.elements.name(element, "<sensor>")
        stype = element.get("type")
        if not stype:
            self.elements.error(ErrorCode.ATTRIBUTE_MISSING, f"sensor '{name}' has no 'type' attribute", element)
        if name is None or not stype:
            return None
        pose = Pose()
        pose_el = element.find("pose")
        if pose_el is not None:
            values = parse_floats(pose_el.text or "0 0 0 0 0 0", 6)
            if values is None:
                self.elements.error(
                    ErrorCode.VALUE_INVALID, f"sensor '{name}' <pose> needs 6 numbers, got {pose_el.text!r}", pose_el
                )
            else:
                pose = Pose.from_xyz_rpy((values[0], values[1], values[2]), (values[3], values[4], values[5]))
        rate = self.elements.gazebo_float(element, "update_rate")
        always_on = self.elements.gazebo_flag(element, "always_on")
        plugins = [p for p in (self.plugin(el) for el in element.findall("plugin")) if p is not None]
        return Sensor(
            name=name,
            type=stype,
            pose=pose,
            update_rate_hz=rate if rate is not None else 0.0,
            always_on=bool(always_on),
            topic=(element.findtext("topic") or "").strip(),
            config=to_config(element, self.elements.source),
            plugins=tuple(plugins),
            location=self.elements.loc(element),
        )

    def gazebo(self, element: etree._Element, doc: UrdfDocument) -> None:
        """A ``<gazebo>`` block: kept whole, and its known tags applied."""
        reference = element.get("reference")
        doc.gazebo.append(
            GazeboExtension(reference, to_config(element, self.elements.source), self.elements.loc(element))
        )
        if reference is None:
            self.apply_model_gazebo(element, doc)
        elif reference in doc.links:
            self.apply_link_gazebo(element, doc.links[reference], doc)
        elif reference in doc.joints:
            # a joint's <gazebo> block holds sdformat's joint tags (stopCfm, stopErp, springStiffness,
            # provideFeedback, preserveFixedJoint, ...), none of which changes the physics here (no ODE
            # constraint mixing; fixed joints are never lumped), and sensors attached to the joint
            joint = doc.joints[reference]
            for child in child_elements(element):
                if local_name(child) == "sensor" and joint is not None and joint.child in doc.links:
                    sensor = self.sensor(child)  # force_torque: kept with the joint's child link
                    if sensor is not None:
                        doc.links[joint.child].sensors.append(replace(sensor, joint=reference))
                else:
                    self.elements.unsupported(
                        child, f'<{local_name(child)}> in <gazebo reference="{reference}"> (a joint)'
                    )
        else:
            self.elements.warn(
                ErrorCode.GAZEBO_REFERENCE_INVALID,
                f'<gazebo reference="{reference}"> names no link or joint; the block is ignored',
                element,
            )

    def apply_model_gazebo(self, element: etree._Element, doc: UrdfDocument) -> None:
        """Robot-level ``<gazebo>`` (no ``reference``): plugins and model flags.

        sdformat's URDF conversion (``parser_urdf.cc``) copies such a block into the SDF ``<model>``: its
        ``<plugin>`` elements become the model's plugins, ``<static>`` and ``<self_collide>`` the model's
        flags. Anything else in it is warned about by name rather than dropped in silence."""
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "plugin":
                plugin = self.plugin(child)
                if plugin is not None:
                    doc.plugins.append(plugin)
            elif tag in _MODEL_FLAGS:
                value = self.elements.gazebo_flag(element, tag)
                if value is not None:
                    doc.model_flags[_MODEL_FLAGS[tag]] = bool(value)
            else:
                self.elements.unsupported(child, f"<{tag}> in <gazebo>")

    def apply_link_gazebo(self, element: etree._Element, link: LinkDraft, doc: UrdfDocument) -> None:
        """``<gazebo reference=link>``: surface, flags, material, sensors and plugins.

        The block's ``<collision>`` children are applied first, then its short forms (``<mu1>`` ...), whatever
        their order in the block: sdformat's ``InsertSDFExtensionCollision`` inserts a block's collision blobs
        into the link's collisions and then writes the short forms over them."""
        for child in child_elements(element):
            if local_name(child) == "collision":
                self.apply_collision_blob(child, link)
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "collision":
                continue
            if tag in _SURFACE_TAGS:
                field_name, count = _SURFACE_TAGS[tag]
                text = gazebo_value(child)
                values = parse_floats(text, count)
                if values is None:
                    self.elements.error(
                        ErrorCode.VALUE_INVALID, f"<{tag}> needs {count} number(s), got {text!r}", child
                    )
                else:
                    link.surface[field_name] = values if count > 1 else values[0]
            elif tag in _LINK_FLAGS:
                field_name, inverted = _LINK_FLAGS[tag]
                flag = self.elements.gazebo_flag(element, tag)
                if flag is not None:
                    link.flags[field_name] = bool(flag) != inverted
            elif tag == "material":
                # Classic's OGRE material script (Gazebo/Red, ...): Gazebo draws the script, not the URDF's
                # colour, so it recolours the link's visuals (finish_link; a script not known keeps them)
                link.gazebo_material = (child.text or "").strip() or None
            elif tag == "sensor":
                sensor = self.sensor(child)
                if sensor is not None:
                    link.sensors.append(sensor)
            elif tag == "plugin":
                plugin = self.plugin(child)
                if plugin is not None:
                    doc.plugins.append(plugin)
            else:
                self.elements.unsupported(child, f'<{tag}> in <gazebo reference="{link.name}">')

    def apply_collision_blob(self, element: etree._Element, link: LinkDraft) -> None:
        """``<gazebo reference=link><collision>``: what it holds goes into every collision of the link, as sdformat's
        URDF conversion (``parser_urdf.cc``, ``collision_blobs``) copies it. Its ``<surface>`` is read as an SDF
        collision's (friction ``<ode><mu>/<mu2>/<fdir1>``, torsional, contact ``<kp>``/``<kd>``, the bitmask, ...)
        and, like sdformat's copy, replaces the surface the link's earlier blocks gave (a later block's short forms
        still apply on top). ``<laser_retro>`` and ``<max_contacts>`` are read silently as an SDF collision's are;
        anything else would be a second ``<pose>`` or ``<geometry>`` of the collision, and is warned about."""
        sdf, sdf_doc = (
            Workspace(self.elements.sink, self.elements.resolver),
            _Doc(self.elements.source, None, MAX_VERSION, False),
        )
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "surface":
                surface = read_surface(sdf, child, sdf_doc)
                link.surface = {f.name: v for f in fields(surface) if (v := getattr(surface, f.name)) is not None}
            elif tag not in IGNORED["collision"]:
                self.elements.unsupported(child, f'<{tag}> in <gazebo reference="{link.name}"><collision>')

    # ---- top level
    def document(self, root: etree._Element) -> UrdfDocument | None:
        """All of ``<robot>``, first pass.

        A ``<robot>`` with no ``<link>`` and no ``<joint>`` is an include fragment (a file of
        xacro macros, properties, materials, ``<gazebo>`` or ``<ros2_control>`` blocks): it
        needs no name, and its ``<gazebo reference>`` blocks name links defined elsewhere.
        """
        fragment = is_fragment(root)
        name = root.get("name", "").strip() if fragment else self.elements.name(root, "<robot>")
        doc = UrdfDocument(name or "")
        doc.materials = self.named_materials(root)
        gazebo_blocks: list[etree._Element] = []
        for child in child_elements(root):
            tag = local_name(child)
            if tag == "link":
                self.add_unique(doc.links, self.elements.link(child, doc.materials), "link", child)
            elif tag == "joint":
                self.add_unique(doc.joints, self.elements.joint(child), "joint", child)
            elif tag == "gazebo":
                gazebo_blocks.append(child)  # after all links and joints are known
            elif tag == "transmission":
                # ROS 1's gazebo_ros_control read transmissions; ros2_control reads <ros2_control> instead, so
                # they are kept (a converter could use them) and named, not run
                doc.transmissions.append(to_config(child, self.elements.source))
                self.elements.warn(
                    ErrorCode.ELEMENT_UNSUPPORTED,
                    f"transmission '{child.get('name', '')}' is kept but not simulated",
                    child,
                )
            elif tag == "ros2_control":
                doc.ros2_control.append(child)  # read once every joint is known
            elif tag != "material":
                self.elements.unsupported(child, f"<{tag}> in <robot>")
        for block in gazebo_blocks:
            if fragment and block.get("reference") is not None:
                doc.gazebo.append(
                    GazeboExtension(
                        block.get("reference"), to_config(block, self.elements.source), self.elements.loc(block)
                    )
                )
            else:
                self.gazebo(block, doc)
        return None if name is None else doc

    def ros2_control(self, element: etree._Element, doc: UrdfDocument) -> Ros2Control | None:
        """A ``<ros2_control name type>`` block. A joint it names that the robot lacks, or a tag it
        does not know, is warned about (file:line) and left out; the rest is kept."""
        name = self.elements.name(element, "<ros2_control>")
        if name is None:
            return None
        kind = (element.get("type") or "system").strip()
        if kind not in ("system", "actuator", "sensor"):
            self.elements.warn(
                ErrorCode.VALUE_INVALID,
                f"ros2_control '{name}' has type '{kind}' (system, actuator or sensor)",
                element,
            )
        plugin, hw_params = "", ()
        joints: list[ControlComponent] = []
        sensors: list[ControlComponent] = []
        gpios: list[ControlComponent] = []
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "hardware":
                # the hardware plugin decides who runs the block: gz_ros2_control/GazeboSimSystem and
                # gazebo_ros2_control/GazeboSystem (and mock_components/GenericSystem) are simulated by
                # systems/ros2_control; the name is kept as written and judged there
                plugin_el = child.find("plugin")
                if plugin_el is None:
                    plugin_el = child.find("classType")  # before Humble
                plugin = (plugin_el.text or "").strip() if plugin_el is not None else ""
                hw_params = self.control_params(child)
                if not plugin:
                    self.elements.warn(
                        ErrorCode.ELEMENT_MISSING, f"ros2_control '{name}' has no <hardware><plugin>", child
                    )
            elif tag in ("joint", "sensor", "gpio"):
                component = self.control_component(child, tag)
                if component is None:
                    continue
                if tag == "joint" and component.name not in doc.joints:
                    known = ", ".join(sorted(doc.joints)) or "none"
                    self.elements.warn(
                        ErrorCode.CONTROL_JOINT_INVALID,
                        f"ros2_control '{name}': joint '{component.name}' is not a joint of the robot "
                        f"(it has {known}); it is left out",
                        child,
                    )
                    continue
                {"joint": joints, "sensor": sensors, "gpio": gpios}[tag].append(component)
            else:
                self.elements.unsupported(child, f"<{tag}> in <ros2_control>")
        if element.find("hardware") is None:
            self.elements.warn(ErrorCode.ELEMENT_MISSING, f"ros2_control '{name}' has no <hardware>", element)
        return Ros2Control(
            name, kind, plugin, hw_params, tuple(joints), tuple(sensors), tuple(gpios), self.elements.loc(element)
        )

    def control_params(self, element: etree._Element) -> tuple[tuple[str, str], ...]:
        """The ``<param name=...>value</param>`` children, in order."""
        return tuple(
            ((p.get("name") or "").strip(), (p.text or "").strip())
            for p in element.findall("param")
            if (p.get("name") or "").strip()
        )

    def control_component(self, element: etree._Element, tag: str) -> ControlComponent | None:
        """A ``<joint>``/``<sensor>``/``<gpio>`` of a ros2_control block, with its interfaces.

        Read as ros2_control Jazzy's ``component_parser.cpp`` reads it: the component's and each interface's
        ``name`` attribute, the ``<param name=...>`` children of both (an interface's ``min``, ``max`` and
        ``initial_value`` among them, kept as text, as there). Where upstream throws and the whole hardware
        fails to load (an interface without a name), gazelle warns at the line and leaves that interface
        out, so one slip does not take the robot's other joints down with it."""
        name = self.elements.name(element, f"<{tag}> in <ros2_control>")
        if name is None:
            return None
        commands, states = [], []
        for child in child_elements(element):
            t = local_name(child)
            if t in ("command_interface", "state_interface"):
                iname = (child.get("name") or "").strip()
                if not iname:
                    self.elements.warn(ErrorCode.ATTRIBUTE_MISSING, f"<{t}> of {tag} '{name}' has no name", child)
                    continue
                iface = ControlInterface(iname, self.control_params(child), self.elements.loc(child))
                (commands if t == "command_interface" else states).append(iface)
            elif t != "param":
                self.elements.unsupported(child, f"<{t}> in ros2_control {tag} '{name}'")
        return ControlComponent(
            name, tuple(commands), tuple(states), self.control_params(element), self.elements.loc(element)
        )

    def named_materials(self, root: etree._Element) -> dict[str, Material]:
        """Materials usable by name: top-level ones first, then any defined inline in a visual.

        urdfdom (``model.cpp``) registers the top-level ``<material>`` elements, then, link by link, a
        visual's material that has a colour or texture under its name, so that a later visual can use it by
        name alone. gazelle takes the inline ones from every link before resolving any, so the order of the
        links does not matter; and where urdfdom refuses the whole robot (a top-level name given twice, a
        name never defined), gazelle warns at the line and goes on: the first definition wins, and an
        undefined name leaves the visual its own colour (see :meth:`material`)."""
        named: dict[str, Material] = {}
        top = [el for el in root.findall("material")]
        inline = [el for el in root.iterfind("link/visual/material")]
        for el in top + inline:
            has_content = el.find("color") is not None or el.find("texture") is not None
            name = el.get("name")
            if el in top and not name:
                self.elements.error(ErrorCode.ATTRIBUTE_MISSING, "<material> has no 'name' attribute", el)
                continue
            if not name or not has_content:
                continue
            if name in named:
                if el in top:
                    self.elements.warn(
                        ErrorCode.DUPLICATE_NAME, f"material '{name}' is defined more than once; the first is used", el
                    )
                continue
            named[name] = self.elements.material(el, named)
        return named

    def add_unique(self, table: dict[str, D], item: D | None, what: str, element: etree._Element) -> None:
        """Add a named link/joint draft, reporting a DUPLICATE_NAME error for a repeat."""
        if item is None:
            return
        name = item.name
        if name in table:
            first = getattr(table[name], "location", None)
            where = f" (first at {first})" if first is not None else ""
            self.elements.error(ErrorCode.DUPLICATE_NAME, f"{what} '{name}' is defined more than once{where}", element)
            return
        table[name] = item


# --------------------------------------------------------------------------- entry point
def parse_urdf(
    text: str,
    *,
    source: str,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
    base_dir: str | None,
) -> Model | None:
    """Parse URDF text into a :class:`Model`.

    Args:
        text: the URDF (possibly produced by :mod:`._xacro`, with location annotations).
        source: file name used in diagnostics.
        sink: receives every diagnostic.
        resolver: resolves ``package://`` and friends for meshes.
        base_dir: folder that relative mesh paths are relative to.

    Returns:
        The model, or None when an error was reported.
    """
    root = parse_xml(text, source=source, sink=sink)
    if root is None:
        return None
    elements = ElementReader(source, sink, resolver, base_dir)
    reader = _Reader(elements)
    if local_name(root) != "robot":
        elements.error(
            ErrorCode.ROOT_ELEMENT_INVALID, f"root element is <{local_name(root)}>; a URDF must have <robot>", root
        )
        return None
    check_attributes(root, elements)
    doc = reader.document(root)
    # Warnings promoted by strict mode do not stop the structure checks: only real errors do.
    if doc is None or sink.has_hard_errors:
        return None
    check_structure(doc, elements)
    if sink.has_hard_errors:
        return None
    if not doc.links:
        report_fragment(root, doc, elements)
    derive = False
    if doc.links and not doc.model_flags.get("static", False):
        if any(has_mass(d) for d in doc.links.values()):
            drop_massless_links(doc, elements)
        else:
            # Gazebo would model none of it (moveit_resources' Panda, kinematics-only descriptions):
            # here each link gets an inertia from its collision shapes, with a warning per link
            derive = True
    movers = {j.child: j.name for j in doc.joints.values() if j.type is not JointType.FIXED}
    links = tuple(finish_link(d, movers.get(d.name), elements, derive) for d in doc.links.values())
    if sink.has_errors:
        return None  # strict mode: warnings were promoted, every one of them is reported
    return Model(
        name=doc.name,
        links=links,
        joints=tuple(doc.joints.values()),
        plugins=tuple(doc.plugins),
        gazebo=tuple(doc.gazebo),
        static=doc.model_flags.get("static", False),
        self_collide=doc.model_flags.get("self_collide", False),
        source_format="urdf",
        source_file=source,
        location=elements.loc(root),
        transmissions=tuple(doc.transmissions),
        ros2_control=tuple(rc for rc in (reader.ros2_control(el, doc) for el in doc.ros2_control) if rc is not None),
    )
