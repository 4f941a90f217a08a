"""move_group's planner queries: ``query_planner_interface``, ``get_planner_params``, ``set_planner_params``.

MoveIt serves them from its default capability ``MoveGroupQueryPlannersService``
(moveit_ros/move_group/src/default_capabilities/query_planners_service_capability.cpp, jazzy); RViz's
MotionPlanning panel fills its planner list from the first, and MoveGroupInterface's
``getInterfaceDescriptions`` / ``getPlannerParams`` / ``setPlannerParams`` call them.

gazelle plans every request with roboplan's RRT-Connect, which stands in for MoveIt's OMPL pipeline (the
pipeline ``ompl`` is the one requests may name without a note). So one pipeline is described, ``ompl``,
with the planner configurations MoveIt's OMPL interface would read from the same parameters
(moveit_planners/ompl/ompl_interface/src/ompl_interface.cpp, ``loadPlannerConfigurations``): per planning
group a default configuration named after the group (its ``default_planner_config``, else
``type: geometric::RRTConnect``) and ``group[planner_id]`` for each of the group's ``planner_configs``
that has parameters under ``ompl.planner_configs.<planner_id>``; each holds the group's known parameters
(``projection_evaluator``, ...) overridden by the configuration's own. Values are strings as MoveIt makes
them: a configuration's parameter as rclcpp's ``Parameter::value_to_string`` (a double as ``%f``, a bool
as ``true``/``false``), a group's with ``moveit::core::toString`` (a double as ``%g``; a bool 1/0).

``set_planner_params`` stores a configuration as MoveIt's does (``group[config]`` when a group is given;
``replace`` clears it first); gazelle's planner does not read these settings, which it says once.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from moveit_msgs.msg import PlannerInterfaceDescription
from moveit_msgs.srv import GetPlannerParams, QueryPlannerInterfaces, SetPlannerParams

from ..planning import quoted
from ._move_group_capability import serve_on_planner

if TYPE_CHECKING:
    from ..planning import ArmPlanner
    from ._move_group_context import MoveGroupContext

PIPELINE = "ompl"
"""The one planning pipeline gazelle describes: requests planned by roboplan's RRT-Connect."""
DESCRIPTION = "OMPL"
"""What MoveIt's OMPL planner manager calls itself (ompl_planner_manager.cpp, getDescription)."""
GROUP_PARAMETERS = {
    "projection_evaluator": str,
    "longest_valid_segment_fraction": float,
    "enforce_joint_model_state_space": bool,
    "enforce_constrained_state_space": bool,
}
"""A group's parameters every configuration of that group inherits (ompl_interface.cpp, KNOWN_GROUP_PARAMS),
with the type MoveIt expects; another type is an error and the parameter is left out, as there."""
MAX_CONFIGURATIONS = 1024
"""set_planner_params adds at most this many configurations (a peer cannot grow the node without end)."""


def _value_to_string(value: object) -> str:
    """rclcpp's ``to_string(ParameterValue)`` (rclcpp/src/rclcpp/parameter_value.cpp)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:f}"  # std::to_string(double)
    if isinstance(value, (list, tuple)):
        items = ["true" if v else "false" if isinstance(v, bool) else str(v) for v in value]
        return "[" + ", ".join(items) + "]"
    return str(value)


def _group_value_to_string(value: object) -> str:
    """``moveit::core::toString`` for doubles (an ostream's default: ``%g``), std::to_string otherwise."""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        return f"{value:g}" if math.isfinite(value) else str(value).lower()
    return str(value)


class QueryPlannersService:
    """The three planner services (see the module docstring), on the query planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context
        self._planner_configs: dict[str, dict[str, str]] | None = None
        """Planner configuration name -> its parameters, read from the node's parameters on first use."""

    def initialize(self) -> None:
        context = self.context
        serve_on_planner(
            context, QueryPlannerInterfaces, "query_planner_interface", self.query_planner_interface, "query"
        )
        serve_on_planner(context, GetPlannerParams, "get_planner_params", self.get_planner_params, "query")
        serve_on_planner(context, SetPlannerParams, "set_planner_params", self.set_planner_params, "query")

    def destroy(self) -> None:
        pass  # its services go with the node

    def _configurations(self) -> dict[str, dict[str, str]]:
        if self._planner_configs is None:
            self._planner_configs = self._read_configurations()
        return self._planner_configs

    def _read_configurations(self) -> dict[str, dict[str, str]]:
        """What MoveIt's OMPL interface reads (see the module docstring), for this robot's groups."""
        planner = self.context.planner
        assert planner is not None
        params = self.context.parameters()
        out: dict[str, dict[str, str]] = {}
        for group in planner.groups:
            base = f"{PIPELINE}.{group}"
            inherited: dict[str, str] = {}
            for key, kind in GROUP_PARAMETERS.items():
                if f"{base}.{key}" not in params:
                    continue
                value = params[f"{base}.{key}"]
                if not isinstance(value, kind) or (kind is not bool and isinstance(value, bool)):
                    self.context.logger.error(
                        f"Invalid type for parameter '{key}' expected [{kind.__name__}] got [{type(value).__name__}]"
                    )
                    continue
                inherited[key] = _group_value_to_string(value)
            default = self._configuration(params, group, params.get(f"{base}.default_planner_config"), inherited)
            if default is None:
                default = {**inherited, "type": "geometric::RRTConnect"}
            out[group] = default
            ids = params.get(f"{base}.planner_configs")
            for planner_id in ids if isinstance(ids, (list, tuple)) else ():
                config = self._configuration(params, group, planner_id, inherited)
                if config is not None:
                    out[f"{group}[{planner_id}]"] = config
        return out

    def _configuration(
        self, params: dict[str, object], group: str, planner_id: object, inherited: dict[str, str]
    ) -> dict[str, str] | None:
        """One ``ompl.planner_configs.<planner_id>`` configuration over the group's parameters (MoveIt's
        ``loadPlannerConfiguration``), or None with MoveIt's error when it has no parameters."""
        if not isinstance(planner_id, str) or not planner_id:
            return None
        prefix = f"{PIPELINE}.planner_configs.{planner_id}."
        own = {name[len(prefix) :]: value for name, value in params.items() if name.startswith(prefix)}
        if not own:
            self.context.logger.error(
                f"Could not find the planner configuration {quoted(planner_id)} on the param server"
            )
            return None
        return {**inherited, **{key: _value_to_string(value) for key, value in own.items()}}

    def _pipeline_known(self, pipeline_id: str) -> bool:
        """MoveIt's ``resolvePlanningPipeline``: empty means the default pipeline; another one than gazelle's
        is MoveIt's "Pipeline '...' does not exist." and an empty answer."""
        if pipeline_id in ("", PIPELINE):
            return True
        self.context.logger.warning(f"Couldn't find requested planning pipeline {quoted(pipeline_id)}")
        self.context.logger.error(f"Pipeline {quoted(pipeline_id)} does not exist.")
        return False

    def query_planner_interface(
        self, _req: QueryPlannerInterfaces.Request, res: QueryPlannerInterfaces.Response, _planner: ArmPlanner
    ) -> QueryPlannerInterfaces.Response:
        """``query_planner_interface``: one description, pipeline ``ompl``, its configurations' names in
        MoveIt's (std::map's) order."""
        res.planner_interfaces = [
            PlannerInterfaceDescription(
                name=DESCRIPTION, pipeline_id=PIPELINE, planner_ids=sorted(self._configurations())
            )
        ]
        return res

    def get_planner_params(
        self, req: GetPlannerParams.Request, res: GetPlannerParams.Response, _planner: ArmPlanner
    ) -> GetPlannerParams.Response:
        """``get_planner_params``: the configuration ``planner_config``, merged with ``group[planner_config]``
        when a group is given (the group's values do not replace the configuration's: std::map::insert)."""
        if not self._pipeline_known(req.pipeline_id):
            return res
        configs = self._configurations()
        merged = dict(configs.get(req.planner_config, {}))
        if req.group:
            for key, value in configs.get(f"{req.group}[{req.planner_config}]", {}).items():
                merged.setdefault(key, value)
        res.params.keys = sorted(merged)
        res.params.values = [merged[k] for k in res.params.keys]
        return res

    def set_planner_params(
        self, req: SetPlannerParams.Request, res: SetPlannerParams.Response, _planner: ArmPlanner
    ) -> SetPlannerParams.Response:
        """``set_planner_params``: store the values under ``planner_config`` (``group[planner_config]``
        with a group), cleared first with ``replace``."""
        if len(req.params.keys) != len(req.params.values):
            self.context.logger.error("Number of parameter names does not match the number of parameters")
            return res
        if not self._pipeline_known(req.pipeline_id):
            return res
        name = f"{req.group}[{req.planner_config}]" if req.group else req.planner_config
        configs = self._configurations()
        if name not in configs and len(configs) >= MAX_CONFIGURATIONS:
            self.context.logger.error(f"set_planner_params: more than {MAX_CONFIGURATIONS} planner configurations")
            return res
        config = {} if req.replace else dict(configs.get(name, {}))
        config.update(zip(req.params.keys, req.params.values))
        configs[name] = config
        self.context.note_once(
            "planner_params",
            f"set_planner_params: {quoted(name)} is stored and answered by get_planner_params, but gazelle's "
            "planner does not read planner configurations: every request is planned with roboplan's RRT-Connect",
        )
        return res
