"""Reading a ``<plugin>`` block (or a sensor's configuration): its children's text, numbers and flags with
warnings that name file:line, the gazebo_ros ``<ros>`` block, and the ROS node a gazebo_ros plugin is in
Gazebo Classic, with the block's children as that node's parameters.

Every system reads its configuration through these, so a bad value reads the same way in every plugin:
the default is kept and the warning names the tag, the text and where it stands.
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from ..description import ConfigElement, Plugin, ReadLog
from ._bus import ParamValue, PluginNode

if TYPE_CHECKING:
    from ._base import System


# --------------------------------------------------------------------------- config helpers
def child_text(cfg: ConfigElement | None, tag: str) -> str | None:
    """The stripped text of ``<tag>``; None when it (or the whole configuration) is absent."""
    el = cfg.find(tag) if cfg is not None else None
    return el.text.strip() if el is not None else None


def all_texts(cfg: ConfigElement | None, tag: str) -> tuple[str, ...]:
    """The stripped text of every direct child ``<tag>`` (repeatable elements such as ``<joint_name>``)."""
    return tuple(el.text.strip() for el in cfg.findall(tag)) if cfg is not None else ()


def parse_float(cfg: ConfigElement | None, tag: str, default: float, log: logging.Logger) -> float:
    """The number in ``<tag>``, else ``default``; a non-number is warned about with its file:line."""
    raw = child_text(cfg, tag)
    if cfg is None or raw is None or raw == "":
        return default
    try:
        return float(raw)
    except ValueError:
        el = cfg.find(tag)
        where = f"{el.location}: " if el is not None and el.location else ""
        log.warning(f"{where}<{tag}> must be a number, got {raw!r}; using {default}")
        return default


def parse_bool(cfg: ConfigElement | None, tag: str, default: bool, log: logging.Logger) -> bool:
    """``true``/``false``/``1``/``0`` in ``<tag>`` (any case, as sdformat's ``Param`` parses a bool, which
    is what a plugin's ``_sdf->Get<bool>`` reads), else ``default``; anything else is warned about with its
    file:line and the default used, where sdformat would refuse the file."""
    raw = child_text(cfg, tag)
    if cfg is None or raw is None or raw == "":
        return default
    low = raw.lower()
    if low in ("1", "true"):
        return True
    if low in ("0", "false"):
        return False
    el = cfg.find(tag)
    where = f"{el.location}: " if el is not None and el.location else ""
    log.warning(f"{where}<{tag}> must be true/false, got {raw!r}; using {default}")
    return default


def ros_block(cfg: ConfigElement | None) -> tuple[str, dict[str, str]]:
    """The namespace and topic remapping rules of a gazebo_ros plugin's node, from its ``<ros>`` block as
    gazebo_ros builds the node (gazebo_ros/src/node.cpp, ``Node::Get``): ``<namespace>``, then the rules
    of its ``<argument>`` elements and its ``<remapping>`` elements (:func:`node_remaps`). A ``__ns:=``
    rule replaces the namespace, as rcl's does; for the others the first rule for a name wins."""
    ros = cfg.find("ros") if cfg is not None else None
    if ros is None:
        return "", {}
    ns = child_text(ros, "namespace") or ""
    rules: dict[str, str] = {}
    for src, dst in node_remaps(cfg):
        rules.setdefault(src, dst)
    ns = rules.pop("__ns", ns)
    return ns, rules


def node_remaps(cfg: ConfigElement | None) -> tuple[tuple[str, str], ...]:
    """The remapping rules of a gazebo_ros plugin's node in the order rcl tries them.

    gazebo_ros hands the node its ``<ros><argument>`` texts as they are, then ``--ros-args`` and
    ``--remap RULE`` for each ``<remapping>`` (node.cpp). rcl (humble's rcl/src/rcl/arguments.c) reads a
    ``from:=to`` before ``--ros-args`` as a remapping rule (the deprecated form, which Dashing-era
    robots such as articubot_one's lidar write: ``<argument>~/out:=scan</argument>``) and one after
    ``-r``/``--remap`` within the ROS arguments; other arguments rename nothing."""
    ros = cfg.find("ros") if cfg is not None else None
    if ros is None:
        return ()
    rules: list[tuple[str, str]] = []
    in_ros_args = False
    args = [a.text.strip() for a in ros.findall("argument")]
    for i, arg in enumerate(args):
        if in_ros_args:
            if arg == "--":
                in_ros_args = False
            elif i > 0 and args[i - 1] in ("-r", "--remap"):
                rules.extend(_remap_rule(arg))
        elif arg == "--ros-args":
            in_ros_args = True
        else:
            rules.extend(_remap_rule(arg))
    return (*rules, *ros_remaps(cfg))


def _remap_rule(text: str) -> list[tuple[str, str]]:
    """``[(from, to)]`` for a rule ``from:=to`` (both sides non-empty, no spaces), else ``[]``."""
    src, sep, dst = text.partition(":=")
    if not sep or not src or not dst or any(c.isspace() for c in text):
        return []
    return [(src, dst)]


def ros_remaps(cfg: ConfigElement | None) -> tuple[tuple[str, str], ...]:
    """The ``<ros><remapping>from:=to`` rules of a plugin in the order written (rcl takes the first rule that
    matches a name, so order matters where :func:`ros_block`'s dict would let a later rule win). ROS 2 spells
    a rule ``from:=to``; ROS 1-era files ``from=to``."""
    ros = cfg.find("ros") if cfg is not None else None
    rules = []
    for r in ros.findall("remapping") if ros is not None else ():
        text = r.text.strip()
        sep = ":=" if ":=" in text else "="
        if sep in text:
            src, dst = text.split(sep, 1)
            rules.append((src.strip(), dst.strip()))
    return tuple(rules)


def remap_arguments(args: list[str]) -> tuple[tuple[tuple[str, str], ...], list[str]]:
    """The remapping rules of node arguments (``--ros-args -r from:=to --remap a:=b``), and the arguments
    that are not remappings (``--ros-args`` itself is neither)."""
    rules: list[tuple[str, str]] = []
    others: list[str] = []
    i = 0
    while i < len(args):
        arg = args[i]
        if arg in ("-r", "--remap") and i + 1 < len(args):
            src, sep, dst = args[i + 1].partition(":=")
            if sep and src and dst:
                rules.append((src, dst))
            else:
                others += [arg, args[i + 1]]
            i += 2
            continue
        if arg not in ("--ros-args", "--"):
            others.append(arg)
        i += 1
    return tuple(rules), others


def unread_parameters(plugin: Plugin | None, reads: ReadLog) -> list[str]:
    """A warning for each parameter of ``plugin`` (a child element of the ``<plugin>``) that its system's
    ``configure`` never looked up (``reads``, from ``description.config_reads``): a typo, a ROS 1 name
    gazelle does not map, or a parameter gazelle does not simulate, each with its file:line."""
    if plugin is None:
        return []
    unread = [child for child in plugin.config.children if not reads.read(child.tag)]
    return [
        f"{f'{c.location}: ' if c.location else ''}<{c.tag}> is not read by {plugin.filename}; it is ignored"
        for c in unread
    ]


# --------------------------------------------------------------------------- plugin nodes
def _typed(text: str) -> ParamValue:
    low = text.lower()
    if low in ("true", "false"):
        return low == "true"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        # 15 significant digits: xacro arithmetic writes binary noise (0.3 + 0.04 as 0.33999999999999997),
        # which `ros2 param get` would print as such
        return float(f"{float(text):.15g}")
    except ValueError:
        return text


def plugin_parameters(plugin: Plugin) -> dict[str, ParamValue]:
    """A ``<plugin>``'s configuration as ROS parameters: each child element with text (not ``<ros>``) by
    its tag, typed as its text reads (bool, integer, double, else string); a repeated element (the
    wheel pairs of a multi-wheel diff drive) is an array of them, of strings when the types differ."""
    values: dict[str, list[ParamValue]] = {}
    for child in plugin.config.children:
        if child.tag == "ros" or child.children or not child.text.strip():
            continue
        values.setdefault(child.tag, []).append(_typed(child.text.strip()))
    out: dict[str, ParamValue] = {}
    for tag, vs in values.items():
        if len(vs) == 1:
            out[tag] = vs[0]
        elif len({type(v) for v in vs}) == 1:
            out[tag] = vs  # type: ignore[assignment] - a list of one element type, which ParamValue's union of list types cannot name generically
        else:
            out[tag] = [str(v) for v in vs]
    return out


def is_gazebo_ros_plugin(filename: str) -> bool:
    """A Gazebo Classic gazebo_ros plugin (``libgazebo_ros_*.so``): in Gazebo it is a ROS node of its own.
    gazebo_ros2_control is not one of them: its node is the controller manager."""
    name = filename.strip()
    return name.startswith("libgazebo_ros_") or name.startswith("gazebo_ros_")


def _node_namespace(plugin: Plugin, entity_namespace: str) -> str | None:
    """A gazebo_ros plugin node's namespace (no slashes around); None when the plugin is no such node."""
    if not plugin.name or not is_gazebo_ros_plugin(plugin.filename):
        return None
    ns, _ = ros_block(plugin.config)
    return (ns or child_text(plugin.config, "robotNamespace") or entity_namespace).strip("/")


def plugin_node_name(plugin: Plugin | None, entity_namespace: str) -> str:
    """The fully qualified name of a gazebo_ros plugin's node, as Gazebo names it: the plugin's ``name``
    under its ``<ros><namespace>`` (ROS 1: ``<robotNamespace>``; else the entity's namespace); "" for
    other plugins (gz-sim systems talk through ros_gz_bridge's node)."""
    ns = _node_namespace(plugin, entity_namespace) if plugin is not None else None
    if ns is None:
        return ""
    assert plugin is not None
    return f"/{ns}/{plugin.name}" if ns else f"/{plugin.name}"


def plugin_node(system: System, plugin: Plugin | None, entity_namespace: str) -> PluginNode | None:
    """The node of :func:`plugin_node_name` with the plugin's configuration and the system's own values
    as its parameters (see :func:`plugin_parameters`); None for other plugins."""
    ns = _node_namespace(plugin, entity_namespace) if plugin is not None else None
    if ns is None:
        return None
    assert plugin is not None
    params = plugin_parameters(plugin)
    params.update(system.node_parameters())
    return PluginNode(plugin.name, ns, params, system.parameter_setters(), plugin.filename)
