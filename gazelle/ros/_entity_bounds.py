"""simulation_interfaces' GetEntityBounds (:class:`EntityBoundsService`): ``TYPE_BOX``, the axis-aligned box around
the entity's collision geometry in the world frame at the current state (two points: its lower and upper
corners), computed by :func:`gazelle.physics.entity_box`. An entity with no collision geometry is the box around
its links' origins (a point, its model frame's origin, for one link); a plane is the rectangle its file draws.
The world frame, not the entity's canonical link as Bounds.msg's header says: the box then compares directly with
the ``bounds`` entity filter and named poses, and a moved entity's box moves with it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from geometry_msgs.msg import Vector3
from simulation_interfaces.msg import Bounds, SimulatorFeatures
from simulation_interfaces.srv import GetEntityBounds

from ..physics import entity_box
from ._si_results import _attempt

if TYPE_CHECKING:
    from ._si_context import InterfacesContext


class EntityBoundsService:
    """``~/get_entity_bounds``, a part of simulation_interfaces registered on the context's node."""

    FEATURES = (SimulatorFeatures.ENTITY_BOUNDS,)

    def __init__(self, context: InterfacesContext):
        """Serve GetEntityBounds (``context.services`` holds it, so ``context.destroy`` removes it)."""
        self.sim = context.sim
        context.serve(GetEntityBounds, "get_entity_bounds", self.get)

    def get(self, req: GetEntityBounds.Request, res: GetEntityBounds.Response) -> GetEntityBounds.Response:
        """GetEntityBounds: the entity's collision box in the world frame (RESULT_NOT_FOUND for no such entity)."""
        res.result, box = _attempt(lambda: self.sim.call(lambda: entity_box(self.sim.world, req.entity)))
        if box is not None:
            res.bounds = Bounds(
                type=Bounds.TYPE_BOX,
                points=[Vector3(x=lo, y=y, z=z) for lo, y, z in (box.lower, box.upper)],
            )
        return res
