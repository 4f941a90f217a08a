"""simulation_interfaces' entity queries and set-state (:class:`EntityQueries`, a part of simulation_interfaces
that registers its own services on the context's node): GetEntities, GetEntityState, GetEntitiesStates,
SetEntityState and GetEntityInfo, with the name filters (Python regular expressions matched in a bounded helper
process) and the entity categories; see ``_simulation_interfaces.py`` for the decisions."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

import regex
from simulation_interfaces.msg import (
    EntityFilters,
    EntityState,
    Result,
    SimulatorFeatures,
)
from simulation_interfaces.srv import (
    GetEntities,
    GetEntitiesStates,
    GetEntityInfo,
    GetEntityState,
    SetEntityState,
)

from ..description import (
    BoundedWorker,
    BoundExceeded,
    Pose,
    excerpt,
    quat_rotate,
)
from ..physics import WORLD_FRAMES, ErrorKind, WorldError, overlapping
from ._convert import from_pose_msg, to_pose_msg, to_time
from ._entity_filters import CATEGORY_NAMES, EntityFilter, category_of
from ._si_results import _attempt, _finite, _Refused, _result
from ._spawn_preamble import SpawnFailed, frame_in_world

if TYPE_CHECKING:
    from ._si_context import InterfacesContext


FILTER_TIME_LIMIT_SEC = 0.2
"""The most a request's name filter may spend matching: ``(a+)+$`` against long names would
otherwise backtrack for minutes, holding the interpreter (and so the simulation)."""
FILTER_MAX_CHARS = 1000
"""The longest name filter accepted (a name pattern of a page is a mistake or an attack)."""
FILTER_MEMORY_BYTES = 256 << 20
"""What compiling and matching one filter may allocate: ``a{4294967294}``, 13 bytes, compiles into
gigabytes, and ``(?:(?:a{100}){100}){100}`` into 264 MB."""
FILTER_CPU_SEC = 1.0
"""The CPU time compiling and matching one filter may take in its helper process."""


def _filter_request(request: dict) -> dict:
    """In the filter helper: compile the pattern and match the names (bounded by the helper's limits)."""
    try:
        pattern = regex.compile(request["pattern"])
    except (regex.error, ValueError, OverflowError) as err:
        return {"invalid": str(err)}
    deadline = time.monotonic() + FILTER_TIME_LIMIT_SEC
    out = []
    try:
        for name in request["names"]:
            if pattern.search(name, timeout=max(deadline - time.monotonic(), 1e-3)):
                out.append(name)
    except TimeoutError:
        return {"slow": True}
    return {"names": out}


_FILTER_WORKER = BoundedWorker(_filter_request, memory_bytes=FILTER_MEMORY_BYTES)
"""One helper process compiles and matches every name filter: the regex module compiles in C holding the
GIL, so a compile bomb run here would stall the simulation thread; there, it meets a memory limit and a
CPU budget, and the server's threads only wait on a pipe."""


def _check_filter(source: str) -> None:
    """Refuse a name filter that is too long or holds characters no entity name has, before any helper."""
    if len(source) > FILTER_MAX_CHARS:
        raise _Refused(
            Result.RESULT_OPERATION_FAILED,
            f"filters.filter has {len(source)} characters; at most {FILTER_MAX_CHARS} are accepted",
        )
    if "\x00" in source:
        raise _Refused(Result.RESULT_OPERATION_FAILED, "filters.filter must not contain a NUL character")


def _matching(source: str | None, names: list[str]) -> list[str]:
    """The names the pattern ``source`` finds (all without one), compiled and matched in the filter helper:
    at most :data:`FILTER_MEMORY_BYTES`, :data:`FILTER_CPU_SEC` of CPU and :data:`FILTER_TIME_LIMIT_SEC`
    of matching."""
    if not source:
        return names
    shown = excerpt(source, 80)
    try:
        reply = _FILTER_WORKER.call(
            {"pattern": source, "names": names},
            what=f"filters.filter {shown}",
            timeout_sec=FILTER_CPU_SEC,
            timeout_hint="the name filter's bound",
        )
    except BoundExceeded as err:
        raise _Refused(Result.RESULT_OPERATION_FAILED, f"{err}; simplify the pattern") from None
    assert isinstance(reply, dict)
    if "invalid" in reply:
        raise _Refused(
            Result.RESULT_OPERATION_FAILED,
            f"filters.filter {shown} is not a valid regular expression: {reply['invalid']}",
        )
    if reply.get("slow"):
        raise _Refused(
            Result.RESULT_OPERATION_FAILED,
            f"filters.filter {shown} took longer than {FILTER_TIME_LIMIT_SEC:g} s to match "
            "(catastrophic backtracking?); simplify it",
        )
    return [str(n) for n in reply["names"]]


class EntityQueries:
    """``~/get_entities``, ``~/get_entity_state``, ``~/get_entities_states``, ``~/set_entity_state`` and
    ``~/get_entity_info``: a part of simulation_interfaces registered on the context's node."""

    FEATURES = (
        SimulatorFeatures.ENTITY_CATEGORIES,
        SimulatorFeatures.ENTITY_STATE_GETTING,
        SimulatorFeatures.ENTITY_STATE_SETTING,
        SimulatorFeatures.ENTITY_INFO_GETTING,
        SimulatorFeatures.ENTITY_TAGS,
        SimulatorFeatures.ENTITY_BOUNDS_BOX,
    )
    """What these serve (the entity filters' tags and boxes included), added to GetSimulatorFeatures' list."""

    def __init__(self, context: InterfacesContext):
        """Serve the five (``context.services`` holds them, so ``context.destroy`` removes them)."""
        self.sim = context.sim
        context.serve(GetEntities, "get_entities", self.get_entities)
        context.serve(GetEntityState, "get_entity_state", self.get_entity_state)
        context.serve(GetEntitiesStates, "get_entities_states", self.get_entities_states)
        context.serve(SetEntityState, "set_entity_state", self.set_entity_state)
        context.serve(GetEntityInfo, "get_entity_info", self.get_entity_info)

    def _frame_pose(self, frame: str, field_name: str) -> Pose:
        """The world pose of a request's reference frame (an entity, or ``entity::link``); RESULT_OPERATION_FAILED
        naming the request field when there is no such frame."""
        try:
            return frame_in_world(self.sim, frame, field_name)
        except SpawnFailed as err:
            raise _Refused(Result.RESULT_OPERATION_FAILED, str(err)) from None

    def _select(self, filters: EntityFilters) -> list[str]:
        """The names of the entities that pass a request's filters: categories and tags on the sim thread (cheap),
        the name pattern off it (bounded in time), then the overlap bounds on it."""
        f = EntityFilter.from_msg(filters)
        if f.pattern is not None:
            _check_filter(f.pattern)
        names = _matching(f.pattern, self._names_in(f))
        if f.overlap:
            names = self.sim.call(lambda: overlapping(self.sim.world, names, box=f.box, sphere=f.sphere))
        return names

    def _names_in(self, f: EntityFilter) -> list[str]:
        """The entities of the filter's categories and tags (all when it names none), read on the sim thread."""
        return self.sim.call(lambda: [name for name, e in self.sim.world.entities.items() if f.keeps(e)])

    def get_entities(self, req: GetEntities.Request, res: GetEntities.Response) -> GetEntities.Response:
        """GetEntities: names, filtered by a bounded regular expression and by category."""
        res.result, found = _attempt(lambda: self._select(req.filters))
        res.entities = found or []
        return res

    def _state_msg(self, name: str) -> EntityState:
        """World-frame state of an entity (call on the sim thread)."""
        st = self.sim.world.entity_state(name)
        msg = EntityState()
        msg.header.frame_id = "world"
        msg.header.stamp = to_time(self.sim.world.time)
        msg.pose = to_pose_msg(st.pose)
        msg.twist.linear.x, msg.twist.linear.y, msg.twist.linear.z = (float(v) for v in st.linear_velocity)
        msg.twist.angular.x, msg.twist.angular.y, msg.twist.angular.z = (float(v) for v in st.angular_velocity)
        return msg

    def get_entity_state(self, req: GetEntityState.Request, res: GetEntityState.Response) -> GetEntityState.Response:
        """GetEntityState: an entity's pose and twist in a reference frame."""
        res.result, state = _attempt(lambda: self.sim.call(lambda: self._state_msg(req.entity)))
        if state is not None:
            res.state = state
        return res

    def get_entities_states(
        self, req: GetEntitiesStates.Request, res: GetEntitiesStates.Response
    ) -> GetEntitiesStates.Response:
        """GetEntitiesStates: the states of the filtered entities, in one sim-thread call."""

        def states() -> tuple[list[str], list[EntityState]]:
            wanted = self._select(req.filters)  # the names matched off the sim thread, bounded in time

            def do() -> tuple[list[str], list[EntityState]]:
                names = [n for n in wanted if n in self.sim.world.entities]  # one deleted meanwhile is left out
                return names, [self._state_msg(n) for n in names]

            return self.sim.call(do)

        res.result, found = _attempt(states)
        if found is not None:
            res.entities, res.states = found
        return res

    def set_entity_state(self, req: SetEntityState.Request, res: SetEntityState.Response) -> SetEntityState.Response:
        """SetEntityState: teleport an entity and set its twist."""
        s = req.state
        p, tw = s.pose, s.twist
        requested = from_pose_msg(p)
        if not _finite(*requested.position, *requested.orientation):
            res.result = _result(SetEntityState.Response.INVALID_POSE, "state.pose is not finite (NaN or inf)")
            return res
        if not _finite(tw.linear.x, tw.linear.y, tw.linear.z, tw.angular.x, tw.angular.y, tw.angular.z):
            res.result = _result(Result.RESULT_OPERATION_FAILED, "state.twist is not finite (NaN or inf)")
            return res

        def teleport() -> None:
            # the request's pose and twist are in state.header.frame_id: the world's, or an entity's or link's
            frame = s.header.frame_id
            X_WF = Pose() if frame in WORLD_FRAMES else self._frame_pose(frame, "state.header.frame_id")
            pose = X_WF * requested
            lin = quat_rotate(X_WF.orientation, (tw.linear.x, tw.linear.y, tw.linear.z))
            ang = quat_rotate(X_WF.orientation, (tw.angular.x, tw.angular.y, tw.angular.z))
            self.sim.call(lambda: self.sim.world.set_entity_state(req.entity, pose, lin, ang))

        res.result, _ = _attempt(teleport, {ErrorKind.INVALID_POSE: SetEntityState.Response.INVALID_POSE})
        return res

    def get_entity_info(self, req: GetEntityInfo.Request, res: GetEntityInfo.Response) -> GetEntityInfo.Response:
        """GetEntityInfo: an entity's category, description and tags (what SetEntityInfo set, else gazelle's
        own: the category its model implies, a description written from the model, no tags)."""

        def do() -> tuple[int, str, list[str]]:
            e = self.sim.world.entities.get(req.entity)
            if e is None:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{req.entity}' does not exist")
            cat = category_of(e)
            m = e.model
            parts = [
                f"{CATEGORY_NAMES.get(cat, 'entity')} '{e.name}'",
                f"model '{m.name}' ({m.source_format or 'unknown format'}"
                + (f", {m.source_file}" if m.source_file and not m.source_file.startswith("<") else "")
                + ")",
                f"{len(m.links)} links, {len(m.joints)} joints, {len(m.plugins)} plugins",
            ]
            if e.namespace:
                parts.append(f"namespace '/{e.namespace}'")
            parts.append("spawned" if e.spawned else "from the world file")
            if e.name in self.sim.diverged:
                parts.append(f"DIVERGED: {self.sim.diverged[e.name]}")
            return cat, "; ".join(parts) if e.description is None else e.description, list(e.tags)

        res.result, found = _attempt(lambda: self.sim.call(do))
        if found is not None:
            res.info.category.category, res.info.description, res.info.tags = found
        return res
