"""The SDF frame graph of one scope (a model or a world): poses and attached links by name.

SDF names frames in a scope: the scope's own frame (``__model__`` in a model, ``world`` in
a world), links, joints, ``<frame>`` elements and nested models; ``child::name`` reaches
into a nested model. Each frame has a pose relative to another frame of the same scope
(``relative_to``, with a per-kind default) and, except links, is attached to something
that ends in a link. :class:`Scope` resolves both, reporting unknown names and cycles.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._pose import IDENTITY, Pose

_FAILED = object()


@dataclass
class FrameNode:
    """One named frame of a scope as the file declares it."""

    name: str
    kind: str
    """``link``, ``joint``, ``frame`` or ``model`` (a nested or world-level model)."""
    pose: Pose
    """The ``<pose>`` value, relative to ``relative_to``."""
    relative_to: str
    """Frame the pose is measured in (the default for the kind when the file gives none)."""
    attached_to: str | None = None
    """Frames: ``attached_to``; joints: the child name; otherwise None."""
    post: Pose = IDENTITY
    """Applied after ``pose`` (models placed by a ``placement_frame``: X_PM)."""
    location: SourceLocation | None = None


@dataclass
class ScopeFrames:
    """What a finished nested scope exports to its parent: every name, resolved."""

    poses: dict[str, Pose] = field(default_factory=dict)
    """X_MF for every frame name (scoped with ``::`` for deeper models), ``__model__`` included."""
    bodies: dict[str, str] = field(default_factory=dict)
    """The link (scoped name) each frame is attached to."""


class Scope:
    """Resolves frame names of one model or world scope."""

    def __init__(self, root: str, sink: DiagnosticSink, canonical: str | None = None) -> None:
        """An SDF frame graph's scope (a model's ``__model__`` or the ``world``), its frames added as the loader
        reads them and resolved on demand."""
        self.root = root
        """``__model__`` or ``world``: the scope's own frame."""
        self.sink = sink
        self.canonical = canonical
        """The link the scope frame is attached to (scoped name); set once known."""
        self.nodes: dict[str, FrameNode] = {}
        self.nested: dict[str, ScopeFrames] = {}
        self._poses: dict[str, object] = {}
        self._bodies: dict[str, object] = {}
        self._quiet = False
        self._reported: set[tuple[str, str]] = set()

    def _error(self, code: ErrorCode, message: str, location: SourceLocation | None) -> None:
        """Report a frame-graph problem once (the poses and attached links of one name fail for the same reason),
        and not at all while a probe resolves quietly."""
        # Each problem once: poses and attached links of one name fail for the same reason.
        key = (code.value, message)
        if self._quiet or key in self._reported:
            return
        self._reported.add(key)
        self.sink.error(code, message, location)

    # ------------------------------------------------------------------ poses
    def pose(self, name: str, location: SourceLocation | None, _stack: tuple[str, ...] = ()) -> Pose | None:
        """X_SF: frame ``name`` in the scope frame, or None after reporting why not.

        SDF's pose graph (sdformat's ``resolveRelativeToGraph``): each element's ``<pose relative_to>`` names the
        frame it is placed in, up to the scope's root (the model frame, or the world). A name is resolved
        once and cached, a failure too, so an error is reported once however many frames lean on it; a cycle
        (``A relative_to B relative_to A``) is a FRAME_CYCLE naming the loop. ``child::frame`` reaches into a
        nested model's already resolved frames. ``node.post`` is applied after the ``<pose>``: a nested model
        placed by its ``placement_frame`` (``<include><placement_frame>``) is posed by that frame, not by its
        own model frame."""
        if name == self.root:
            return IDENTITY
        cached = self._poses.get(name)
        if cached is _FAILED:
            return None
        if isinstance(cached, Pose):
            return cached
        node = self.nodes.get(name)
        if node is not None:
            if name in _stack:
                cycle = " -> ".join(_stack[_stack.index(name) :] + (name,))
                self._error(ErrorCode.FRAME_CYCLE, f"cycle in pose relative_to: {cycle}", node.location)
                self._poses[name] = _FAILED
                return None
            base = self.pose(node.relative_to, node.location, _stack + (name,))
            result: object = _FAILED if base is None else base * node.pose * node.post
            if name not in self._poses:
                self._poses[name] = result
            return result if isinstance(result, Pose) else None
        head, sep, rest = name.partition("::")
        if sep and head in self.nested and rest in self.nested[head].poses:
            base = self.pose(head, location, _stack)
            return None if base is None else base * self.nested[head].poses[rest]
        self._error(ErrorCode.FRAME_INVALID, f"unknown frame '{name}'", location)
        self._poses[name] = _FAILED
        return None

    # ------------------------------------------------------------------ attached links
    def body(self, name: str, location: SourceLocation | None, _stack: tuple[str, ...] = ()) -> str | None:
        """The link frame ``name`` is attached to (scoped name; ``world`` for the world frame).

        SDF's attachment graph, which is not the pose graph: a ``<frame attached_to>`` moves with the link it
        is attached to wherever its pose is expressed (a sensor frame placed relative to the model but
        attached to the arm's wrist). The model frame is attached to the canonical link; a nested model's
        frame to its own canonical link, scoped (``gripper::base``); a joint's frame to its child link.
        Cycles and unknown names are reported once, as in :meth:`pose`."""
        if name == self.root:
            return self.canonical if self.root == "__model__" else "world"
        if name == "world" and self.root == "__model__":
            return "world"
        cached = self._bodies.get(name)
        if cached is _FAILED:
            return None
        if isinstance(cached, str):
            return cached
        node = self.nodes.get(name)
        result: object
        if node is not None:
            if name in _stack:
                cycle = " -> ".join(_stack[_stack.index(name) :] + (name,))
                self._error(ErrorCode.FRAME_CYCLE, f"cycle in attached_to: {cycle}", node.location)
                self._bodies[name] = _FAILED
                return None
            if node.kind == "link":
                result = name
            elif node.kind == "model":
                inner = self.nested.get(name)
                target = inner.bodies.get("__model__") if inner else None
                result = f"{name}::{target}" if target else _FAILED
            else:
                target_name = node.attached_to or self.root
                got = self.body(target_name, node.location, _stack + (name,))
                result = _FAILED if got is None else got
        else:
            head, sep, rest = name.partition("::")
            if sep and head in self.nested and rest in self.nested[head].bodies:
                result = f"{head}::{self.nested[head].bodies[rest]}"
            else:
                self._error(ErrorCode.FRAME_INVALID, f"unknown frame '{name}'", location)
                result = _FAILED
        if name not in self._bodies:
            self._bodies[name] = result
        return result if isinstance(result, str) else None

    def export(self) -> ScopeFrames:
        """Every frame name of this scope resolved, for the parent scope.

        Run after every element was resolved once (and its errors reported), so it is quiet.
        """
        self._quiet = True
        out = ScopeFrames()
        out.poses["__model__"] = IDENTITY
        if self.canonical is not None:
            out.bodies["__model__"] = self.canonical
        for name in self.nodes:
            pose = self.pose(name, None)
            body = self.body(name, None)
            if pose is not None:
                out.poses[name] = pose
            if body is not None:
                out.bodies[name] = body
        for head, inner in self.nested.items():
            base = out.poses.get(head)
            for sub, pose in inner.poses.items():
                if sub != "__model__" and base is not None:
                    out.poses[f"{head}::{sub}"] = base * pose
            for sub, body in inner.bodies.items():
                if sub != "__model__":
                    out.bodies[f"{head}::{sub}"] = f"{head}::{body}"
        return out
