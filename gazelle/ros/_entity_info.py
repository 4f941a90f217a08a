"""simulation_interfaces' SetEntityInfo (:class:`EntityInfoSetter`): a client's category, description and tags
for an entity, which GetEntityInfo then answers and the entity filters match. As the service defines it, the
info given replaces the entity's current values, all three: set what you read with GetEntityInfo to change one.
The info lives with the entity: it goes when the entity is deleted (or removed by a SCOPE_SPAWNED reset) and
stays through a SCOPE_STATE reset."""

from __future__ import annotations

from typing import TYPE_CHECKING

from simulation_interfaces.msg import Result, SimulatorFeatures
from simulation_interfaces.srv import SetEntityInfo

from ..physics import ErrorKind, WorldError
from ._entity_filters import CATEGORY_NAMES, checked_tags
from ._si_results import _attempt, _Refused

if TYPE_CHECKING:
    from ._si_context import InterfacesContext

MAX_DESCRIPTION_CHARS = 10_000
"""The longest description an entity may be given."""


class EntityInfoSetter:
    """``~/set_entity_info``, a part of simulation_interfaces registered on the context's node."""

    FEATURES = (SimulatorFeatures.ENTITY_INFO_SETTING,)

    def __init__(self, context: InterfacesContext):
        """Serve SetEntityInfo (``context.services`` holds it, so ``context.destroy`` removes it)."""
        self.sim = context.sim
        context.serve(SetEntityInfo, "set_entity_info", self.set)

    def set(self, req: SetEntityInfo.Request, res: SetEntityInfo.Response) -> SetEntityInfo.Response:
        """SetEntityInfo: the entity's category, description and tags become the request's."""
        info = req.info
        category = info.category.category

        def do() -> None:
            if category not in CATEGORY_NAMES:
                known = ", ".join(f"{c} ({n})" for c, n in sorted(CATEGORY_NAMES.items()))
                raise _Refused(Result.RESULT_OPERATION_FAILED, f"info.category {category} is unknown: {known}")
            if len(info.description) > MAX_DESCRIPTION_CHARS:
                raise _Refused(
                    Result.RESULT_OPERATION_FAILED,
                    f"info.description has {len(info.description)} characters; at most {MAX_DESCRIPTION_CHARS}",
                )
            tags = checked_tags(info.tags, "info.tags")

            def apply() -> None:
                e = self.sim.world.entities.get(req.entity)
                if e is None:
                    raise WorldError(ErrorKind.NOT_FOUND, f"entity '{req.entity}' does not exist")
                e.category, e.description, e.tags = category, str(info.description), tags

            self.sim.call(apply)

        res.result, _ = _attempt(do)
        return res
