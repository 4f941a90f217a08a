"""simulation_interfaces' GetNamedPoses and GetNamedPoseBounds (:class:`NamedPosesService`).

The named poses are the world's ``<frame>`` elements attached to the world (``attached_to`` absent or
``world``; one attached to a model moves with it and is not a named pose), in the world frame, in file order,
with gazelle's custom elements for what SDF has no word for: ``<gazelle:description>``, ``<gazelle:tag>``
(repeatable) and the free space about the pose, ``<gazelle:box>`` (two opposite corners in the pose's frame) or
``<gazelle:sphere>`` (a radius) (see :class:`gazelle.description.NamedPose`). More come from ``gazelle sim
--named-poses FILE``: the world frames of another SDF file, added to every world's. The tags filter is the
standard's: ``FILTER_MODE_ANY`` keeps a pose with any of the tags, ``FILTER_MODE_ALL`` one with all of them;
no tags keeps every pose. A named pose without bounds answers ``TYPE_EMPTY`` (unbounded, as Bounds.msg says)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from geometry_msgs.msg import Vector3
from simulation_interfaces.msg import Bounds, NamedPose, Result, SimulatorFeatures, TagsFilter
from simulation_interfaces.srv import GetNamedPoseBounds, GetNamedPoses

from ..description import NamedPose as Place
from ..description import excerpt
from ._convert import to_pose_msg
from ._entity_filters import checked_tags
from ._si_results import OK, _Refused, _result

if TYPE_CHECKING:
    from ._si_context import InterfacesContext


def _bounds(place: Place) -> Bounds:
    """A named pose's free space as Bounds, relative to the pose: TYPE_BOX, TYPE_SPHERE or TYPE_EMPTY."""
    if place.box is not None:
        return Bounds(type=Bounds.TYPE_BOX, points=[Vector3(x=c[0], y=c[1], z=c[2]) for c in place.box])
    if place.sphere_radius is not None:
        return Bounds(type=Bounds.TYPE_SPHERE, points=[Vector3(), Vector3(x=place.sphere_radius)])
    return Bounds(type=Bounds.TYPE_EMPTY)


class NamedPosesService:
    """``~/get_named_poses`` and ``~/get_named_pose_bounds``, a part of simulation_interfaces registered on the
    context's node."""

    FEATURES = (SimulatorFeatures.NAMED_POSES, SimulatorFeatures.POSE_BOUNDS)

    def __init__(self, context: InterfacesContext):
        """Serve both (``context.services`` holds them, so ``context.destroy`` removes them)."""
        self.sim = context.sim
        context.serve(GetNamedPoses, "get_named_poses", self.get_named_poses)
        context.serve(GetNamedPoseBounds, "get_named_pose_bounds", self.get_named_pose_bounds)

    def _places(self) -> tuple[Place, ...]:
        """The current world's named poses (read on the sim thread: a world loaded at run time replaces them)."""
        return self.sim.call(lambda: tuple(self.sim.named_poses))

    def get_named_poses(self, req: GetNamedPoses.Request, res: GetNamedPoses.Response) -> GetNamedPoses.Response:
        """GetNamedPoses: every named pose that passes the tags filter."""
        mode = req.tags.filter_mode
        try:
            if mode not in (TagsFilter.FILTER_MODE_ANY, TagsFilter.FILTER_MODE_ALL):
                raise _Refused(
                    Result.RESULT_OPERATION_FAILED,
                    f"tags.filter_mode {mode} is unknown: FILTER_MODE_ANY (0) or FILTER_MODE_ALL (1)",
                )
            wanted = checked_tags(req.tags.tags, "tags.tags")
            places = self._places()
        except _Refused as err:
            res.result = _result(err.code, str(err))
            return res
        except TimeoutError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}")
            return res
        match = all if mode == TagsFilter.FILTER_MODE_ALL else any
        res.poses = [
            NamedPose(name=p.name, description=p.description, tags=list(p.tags), pose=to_pose_msg(p.pose))
            for p in places
            if not wanted or match(t in p.tags for t in wanted)
        ]
        res.result = _result(OK)
        return res

    def get_named_pose_bounds(
        self, req: GetNamedPoseBounds.Request, res: GetNamedPoseBounds.Response
    ) -> GetNamedPoseBounds.Response:
        """GetNamedPoseBounds: the free space about a named pose, relative to it (RESULT_NOT_FOUND for no such
        name)."""
        try:
            places = self._places()
        except TimeoutError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}")
            return res
        place = next((p for p in places if p.name == req.name), None)
        if place is None:
            names = ", ".join(p.name for p in places[:20]) or "none: add <frame>s to the world"
            res.result = _result(Result.RESULT_NOT_FOUND, f"no named pose {excerpt(req.name)}; named poses: {names}")
            return res
        res.bounds = _bounds(place)
        res.result = _result(OK)
        return res
