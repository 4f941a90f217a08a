"""The transforms between frames that the filter needs (a sensor's mount, a world frame's offset), from the
``/tf`` and ``/tf_static`` messages it hears: the latest transform of each child frame.

robot_localization looks a transform up in a tf2 buffer at the reading's stamp and falls back to the latest
one when that fails (``lookupTransformSafe``); this tree keeps only the latest, which is the same for the
static mounts of the common configurations. A frame to itself is the identity even when nothing is heard."""

from __future__ import annotations

from dataclasses import dataclass, field

from ._rigid import Rigid

MAX_FRAMES = 4096
"""Frames the tree holds at most: a transform naming a new frame beyond this is not kept (the frame names
come from the wire)."""
MAX_DEPTH = 256
"""The longest chain of parents walked: a loop in what was heard (a frame its own ancestor) ends here."""


@dataclass
class FrameTree:
    """child frame -> (parent frame, the child's pose in the parent), latest wins."""

    parents: dict[str, tuple[str, Rigid]] = field(default_factory=dict)
    refused: int = 0
    """Transforms not kept because the tree was full."""

    def set(self, parent: str, child: str, pose: Rigid) -> bool:
        """Record ``child``'s pose in ``parent``; False when it names a new frame and the tree is full (or a
        frame is its own parent, or a name is empty)."""
        if not parent or not child or parent == child:
            return False
        if child not in self.parents and len(self.parents) >= MAX_FRAMES:
            self.refused += 1
            return False
        self.parents[child] = (parent, pose)
        return True

    def _chain(self, frame: str) -> dict[str, Rigid]:
        """Every ancestor of ``frame`` (itself included) -> ``frame``'s pose in it."""
        out = {frame: Rigid()}
        pose = Rigid()
        for _ in range(MAX_DEPTH):
            link = self.parents.get(frame)
            if link is None or link[0] in out:
                break
            frame, step = link
            pose = step * pose
            out[frame] = pose
        return out

    def lookup(self, target: str, source: str) -> Rigid | None:
        """The transform that takes coordinates in ``source`` to ``target`` (tf2's ``lookupTransform(target,
        source)``), or None when the two frames are not connected by what was heard."""
        if target == source:
            return Rigid()
        up_source = self._chain(source)
        up_target = self._chain(target)
        if target in up_source:
            return up_source[target]
        common = next((f for f in up_target if f in up_source), None)
        if common is None:
            return None
        return up_target[common].inverse() * up_source[common]
