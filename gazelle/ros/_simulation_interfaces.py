"""The ``simulation_interfaces`` (Jazzy 1.5.1) services and action, under the node's namespace.

Everything is advertised as ``~/<name>`` on the node named ``gazelle``, i.e.
``/gazelle/spawn_entity``, ``/gazelle/get_entities``, ... and the action
``/gazelle/simulate_steps``. Callbacks run in a :class:`ReentrantCallbackGroup`
on the bridge's multi-threaded executor and hand every piece of world work to
the simulation thread with ``sim.call``. Its parts share an :class:`~._si_context.InterfacesContext` (the node,
the simulation, the resolver, the callback group) and each registers its own services: the entity queries and
SetEntityState (``_entity_queries.py``), and the others below; StepSimulation's node and executor are in
``_stepping.py``. A spawn's pose, description and frame go through ``_spawn_preamble.py``, as gazebo_ros's do.

Decisions (also what :func:`features` advertises, nothing more):

* Simulation state: ``STATE_STOPPED`` is reported while paused with no step
  taken since the last time reset (``sim.iterations == 0``), like ros_gz.
  Setting STOPPED = pause + reset everything (time, state, spawned entities).
  Setting PAUSED from STOPPED succeeds (it stays reported as STOPPED until a
  step is taken). ``STATE_QUITTING`` (and NO_WORLD / LOADING_WORLD) are refused
  with ``INCORRECT_TRANSITION``: the server is stopped with Ctrl-C / SIGTERM,
  never by a service request.
* StepSimulation and SimulateSteps require the simulation to be paused
  (``RESULT_OPERATION_FAILED`` otherwise, as both .srv files say) and step in chunks, each chunk one
  ``sim.call``, so other requests are served between chunks. Before the first chunk, the messages
  the server's subscriptions had received are handed to the simulation (``_inbound``): a command
  delivered before the request acts from its first step.
* Entity categories: ``CATEGORY_STATIC_OBJECT`` for static models (no free
  root), ``CATEGORY_ROBOT`` for dynamic models that have plugins or a movable
  (non-fixed) joint, ``CATEGORY_DYNAMIC_OBJECT`` for the other dynamic models, unless SetEntityInfo set
  another (``_entity_info.py``). Tags filters match what SetEntityInfo set (any or all); bounds filters are
  ``TYPE_BOX`` and ``TYPE_SPHERE`` in the world frame, against each collision geom's world box
  (``_entity_filters.py``); ``TYPE_CONVEX_HULL`` is ``RESULT_FEATURE_UNSUPPORTED``.
* The other parts of the standard are classes of their own, each registering its services on the node and
  declaring its features (``FEATURES``): the entity queries (``_entity_queries.py``), SetEntityInfo
  (``_entity_info.py``), GetEntityBounds (``_entity_bounds.py``), GetNamedPoses and GetNamedPoseBounds
  (``_named_poses.py``), GetSpawnables (``_spawnables.py``), the worlds (``_world_services.py``).
  GetSimulatorFeatures lists the union, nothing more.
* Name filters are Python regular expressions (the ``regex`` module, ``re`` syntax; POSIX-extended
  syntax is a subset for the usual cases) of at most 1,000 characters, compiled and matched in a
  helper process bounded to 256 MiB and 1 s of CPU, and 0.2 s of matching: a backtracking or
  compile bomb (``a{4294967294}``) is refused, and the simulation never waits on it. A bad pattern,
  or one over a bound, is ``RESULT_OPERATION_FAILED``.
* States (get and set) are in the world frame: ``header.frame_id = "world"``,
  ``header.stamp`` = sim time. SetEntityState also accepts an entity or
  ``entity::link`` frame in ``state.header.frame_id``. Accelerations are ignored.
* Spawning by ``uri``: ``model://`` and ``package://`` resolve through
  :class:`gazelle.description.ResourceResolver` (a URI that does not resolve,
  or escapes its package folder, is ``NO_RESOURCE``); ``file://`` and plain
  paths must name an existing file inside the resource paths (or an ament share
  folder). A folder (``model://box``) means its ``model.sdf``. URDF, xacro and
  SDF are accepted (by suffix, or detected).
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from rclpy.node import Node
from simulation_interfaces.action import SimulateSteps
from simulation_interfaces.msg import (
    Result,
    SimulationState,
    SimulatorFeatures,
    SpawnResult,
)
from simulation_interfaces.srv import (
    DeleteEntity,
    GetSimulationState,
    GetSimulatorFeatures,
    ResetSimulation,
    SetSimulationState,
    SpawnEntities,
    SpawnEntity,
    StepSimulation,
)

from ..description import (
    Model,
    Pose,
    ResourceResolver,
    format_for_path,
)
from ..physics import Entity, ErrorKind, WorldError
from ..sim import Simulation, SpawnRequest, WorldBusy
from ._convert import from_pose_msg
from ._entity_bounds import EntityBoundsService
from ._entity_info import EntityInfoSetter
from ._entity_queries import EntityQueries
from ._named_poses import NamedPosesService
from ._replies import guarded_service, serve_action, with_warnings
from ._si_context import InterfacesContext
from ._si_results import OK, _attempt, _Refused, _result
from ._spawn_preamble import SpawnFailed, SpawnFailure, check_pose, frame_in_world, model_to_spawn
from ._spawnables import SpawnablesService
from ._stepping import SteppingService
from ._world_services import WorldServices

if TYPE_CHECKING:
    from geometry_msgs.msg import PoseStamped
    from rclpy.action.server import ServerGoalHandle

STEP_CHUNK = 200
"""Physics steps per sim-thread call while stepping on request."""
FEEDBACK_PERIOD_SEC = 0.1
MAX_STEPS = 2**32 - 1

FEATURES = (
    SimulatorFeatures.SPAWNING,
    SimulatorFeatures.DELETING,
    SimulatorFeatures.SPAWNING_RESOURCE_STRING,
    SimulatorFeatures.SIMULATION_RESET,
    SimulatorFeatures.SIMULATION_RESET_TIME,
    SimulatorFeatures.SIMULATION_RESET_STATE,
    SimulatorFeatures.SIMULATION_RESET_SPAWNED,
    SimulatorFeatures.SIMULATION_STATE_GETTING,
    SimulatorFeatures.SIMULATION_STATE_SETTING,
    SimulatorFeatures.SIMULATION_STATE_PAUSE,
    SimulatorFeatures.STEP_SIMULATION_SINGLE,
    SimulatorFeatures.STEP_SIMULATION_MULTIPLE,
    SimulatorFeatures.STEP_SIMULATION_ACTION,
    SimulatorFeatures.SPAWNING_ENTITIES,
)
"""What this class serves; each part adds its own."""

PARTS = (EntityQueries, EntityInfoSetter, EntityBoundsService, NamedPosesService, SpawnablesService, WorldServices)
"""The parts of the standard served by classes of their own (each registers its services on the node)."""

_NAMESPACE_RE = re.compile(r"^/?([A-Za-z_][A-Za-z0-9_]*)(/[A-Za-z_][A-Za-z0-9_]*)*/?$")

_PREAMBLE_TO_SPAWN = {
    SpawnFailure.INVALID_POSE: SpawnEntity.Response.INVALID_POSE,
    SpawnFailure.PARSE: SpawnEntity.Response.RESOURCE_PARSE_ERROR,
    SpawnFailure.UNSUPPORTED_FORMAT: SpawnEntity.Response.UNSUPPORTED_FORMAT,
    SpawnFailure.NO_MODEL: SpawnEntity.Response.RESOURCE_PARSE_ERROR,
    SpawnFailure.FRAME: Result.RESULT_OPERATION_FAILED,
}
"""The result code of a spawn the preamble refused (``_spawn_preamble.py``), by why."""

_WORLD_KIND_TO_SPAWN = {
    ErrorKind.NAME_NOT_UNIQUE: SpawnResult.NAME_NOT_UNIQUE,
    ErrorKind.NAME_INVALID: SpawnResult.NAME_INVALID,
    ErrorKind.INVALID_POSE: SpawnResult.INVALID_POSE,
}


def builtin_resource_paths() -> list[Path]:
    """gazelle's own example packages (``package://simple_robot/...``), when installed from a checkout."""
    examples = Path(__file__).resolve().parents[2] / "examples"
    return [examples] if examples.is_dir() else []


@dataclass
class _Prepared:
    model: Model
    name: str
    pose: Pose
    namespace: str
    allow_renaming: bool
    warnings: tuple[str, ...] = ()
    """The description's warnings, also carried in the success reply's message."""


class SimulationInterfaces:
    """The services and action, on the simulation's node, with their parts (see the module docstring)."""

    def __init__(
        self,
        node: Node,
        sim: Simulation,
        publish_clock: Callable[[float], None],
        take_inbound: Callable[[], int],
        resolver: ResourceResolver | None = None,
    ):
        """The simulation_interfaces (ROS 2's standard simulator API) services under ``node``'s ``~/``, each guarded
        so that bad input gets a result code and a message, never a dead server; StepSimulation on a service of
        its own; the SimulateSteps action; and a diverged entity reported on /rosout. ``publish_clock`` sends /clock
        at once, ``take_inbound`` hands the simulation what its subscriptions hold (the bridge node's)."""
        resolver = resolver or ResourceResolver(extra_paths=builtin_resource_paths())
        self.context = InterfacesContext(node, sim, resolver, publish_clock, take_inbound)
        """What the parts share: the node, the simulation, the resolver, the callback group, the services."""
        self.node = node
        self.sim = sim
        self.resolver = resolver
        self.cb = self.context.cb

        # a diverged entity is reported on /rosout (the sim thread calls this once per divergence)
        def report(_name: str, reason: str) -> None:
            node.get_logger().error(reason)

        self.sim.divergence_listeners.append(report)
        self.context.serve(GetSimulatorFeatures, "get_simulator_features", self.get_simulator_features)
        self.context.serve(GetSimulationState, "get_simulation_state", self.get_simulation_state)
        self.context.serve(SetSimulationState, "set_simulation_state", self.set_simulation_state)
        self.context.serve(ResetSimulation, "reset_simulation", self.reset_simulation)
        self.context.serve(SpawnEntity, "spawn_entity", self.spawn_entity)
        self.context.serve(SpawnEntities, "spawn_entities", self.spawn_entities)
        self.context.serve(DeleteEntity, "delete_entity", self.delete_entity)
        self.stepping = SteppingService(node, guarded_service("step_simulation", self.step_simulation))
        self.action = serve_action(node, SimulateSteps, "~/simulate_steps", self._simulate_steps, self.cb)
        self.features: set[int] = {int(f) for f in FEATURES}
        """Every feature id served: GetSimulatorFeatures lists these."""
        self.parts: list[object] = []
        for part in PARTS:
            self.parts.append(part(self.context))
            self.features.update(int(f) for f in part.FEATURES)

    def destroy(self) -> None:
        """Stop the action server and the services (the node is being destroyed)."""
        self.action.destroy()
        self.context.destroy()
        self.stepping.destroy()

    # ------------------------------------------------------------------ features and state
    def get_simulator_features(
        self, req: GetSimulatorFeatures.Request, res: GetSimulatorFeatures.Response
    ) -> GetSimulatorFeatures.Response:
        """simulation_interfaces GetSimulatorFeatures: what this simulator supports (features, formats)."""
        res.features.features = sorted(self.features)
        res.features.spawn_formats = ["urdf", "sdf"]
        res.features.custom_info = (
            "gazelle (MuJoCo): xacro is never expanded by the server (a description is data): "
            "expand it first, or use `gazelle spawn -file robot.urdf.xacro`, which expands it locally; "
            "uri: model://, package://, file:// or a path; name filters are Python regular expressions; "
            "states are in the world frame"
        )
        return res

    def _state(self) -> int:
        if self.sim.worlds.current is None:
            return SimulationState.STATE_NO_WORLD
        if self.sim.paused:
            return SimulationState.STATE_STOPPED if self.sim.iterations == 0 else SimulationState.STATE_PAUSED
        return SimulationState.STATE_PLAYING

    def get_simulation_state(
        self, req: GetSimulationState.Request, res: GetSimulationState.Response
    ) -> GetSimulationState.Response:
        """GetSimulationState: playing, paused or stopped; no world, or loading one (said without waiting for it)."""
        loading = self.sim.worlds.loading
        res.state.state = SimulationState.STATE_LOADING_WORLD if loading else self.sim.call(self._state)
        res.result = _result(OK)
        return res

    def set_simulation_state(
        self, req: SetSimulationState.Request, res: SetSimulationState.Response
    ) -> SetSimulationState.Response:
        """SetSimulationState: play, pause, stop (reset and pause) or quit (refused)."""
        target = req.state.state
        S = SimulationState
        names = {S.STATE_STOPPED: "STOPPED", S.STATE_PLAYING: "PLAYING", S.STATE_PAUSED: "PAUSED"}
        if target in (S.STATE_QUITTING, S.STATE_NO_WORLD, S.STATE_LOADING_WORLD):
            res.result = _result(
                SetSimulationState.Response.INCORRECT_TRANSITION,
                f"transition to state {target} is not supported: worlds are loaded and unloaded with "
                "LoadWorld and UnloadWorld, and the server quits on Ctrl-C / SIGTERM only",
            )
            return res
        if target not in names:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"unknown simulation state {target}")
            return res

        def do() -> int:
            current = self._state()
            if current == S.STATE_NO_WORLD:
                raise WorldError(ErrorKind.INCORRECT_STATE, "no world is loaded: LoadWorld first")
            if current == target:
                return current
            if target == S.STATE_PLAYING:
                self.sim.paused = False
            elif target == S.STATE_PAUSED:
                self.sim.paused = True
            else:
                self.sim.paused = True
                self.sim.reset(time_=True, state=True, spawned=True)  # runs inline: we are on the sim thread
            return -1

        try:
            before = self.sim.call(do)
        except (WorldError, TimeoutError) as err:
            res.result = _result(SetSimulationState.Response.STATE_TRANSITION_ERROR, str(err))
            return res
        if before == target:
            res.result = _result(
                SetSimulationState.Response.ALREADY_IN_TARGET_STATE, f"the simulation is already {names[target]}"
            )
        else:
            res.result = _result(OK)
        return res

    def reset_simulation(self, req: ResetSimulation.Request, res: ResetSimulation.Response) -> ResetSimulation.Response:
        """ResetSimulation: time, state and/or spawned entities, by scope."""
        R = ResetSimulation.Request
        scope = req.scope
        if scope in (R.SCOPE_DEFAULT, R.SCOPE_ALL):
            scope = R.SCOPE_TIME | R.SCOPE_STATE | R.SCOPE_SPAWNED
        elif scope & ~(R.SCOPE_TIME | R.SCOPE_STATE | R.SCOPE_SPAWNED):
            res.result = _result(
                Result.RESULT_FEATURE_UNSUPPORTED,
                f"unknown scope bits in {scope}: use SCOPE_TIME=1, SCOPE_STATE=2, SCOPE_SPAWNED=4 or SCOPE_ALL",
            )
            return res
        try:
            self.sim.reset(
                time_=bool(scope & R.SCOPE_TIME),
                state=bool(scope & R.SCOPE_STATE),
                spawned=bool(scope & R.SCOPE_SPAWNED),
            )
        except (WorldError, TimeoutError) as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"reset failed: {err}")
            return res
        res.result = _result(OK)
        return res

    # ------------------------------------------------------------------ stepping
    @staticmethod
    def _check_steps(steps: int) -> None:
        if steps < 1 or steps > MAX_STEPS:
            raise _Refused(Result.RESULT_OPERATION_FAILED, f"steps must be between 1 and {MAX_STEPS}, got {steps}")

    @staticmethod
    def _not_paused(done: int, steps: int) -> _Refused:
        """The refusal when a chunk found the simulation running: it never was paused (the first chunk; its
        check is the chunk's own, on the sim thread, not a hop of its own: a lockstep test steps 10 ms at a
        time and each hop cost ~0.5 ms), or it was unpaused meanwhile."""
        if done == 0:
            return _Refused(
                Result.RESULT_OPERATION_FAILED,
                "the simulation must be paused to step it (SetSimulationState STATE_PAUSED first)",
            )
        return _Refused(Result.RESULT_OPERATION_FAILED, f"the simulation was unpaused after {done} of {steps} steps")

    def _step_chunk(self, n: int) -> int:
        """Take up to ``n`` steps on the sim thread; returns how many were taken (0 if it was unpaused)."""

        def do() -> int:
            if not self.sim.paused:
                return 0
            self.sim.step(n)
            return n

        return self.sim.call(do)

    def step_simulation(self, req: StepSimulation.Request, res: StepSimulation.Response) -> StepSimulation.Response:
        """StepSimulation: take N steps while paused (the reply comes when they are done). What the server's
        subscriptions had received when the request came takes effect from the first step (``_inbound``)."""
        try:
            self._check_steps(req.steps)
            with self.sim.worlds.stepping("a StepSimulation call"):
                self.context.take_inbound()
                done = 0
                while done < req.steps:
                    taken = self._step_chunk(min(STEP_CHUNK, req.steps - done))
                    if taken == 0:
                        raise self._not_paused(done, req.steps)
                    done += taken
        except WorldBusy as err:
            res.result = _result(Result.RESULT_INCORRECT_STATE, str(err))
            return res
        except _Refused as err:
            res.result = _result(err.code, str(err))
            return res
        except (WorldError, TimeoutError) as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"stepping failed: {err}")
            return res
        res.result = _result(OK)
        return res

    def _simulate_steps(self, goal_handle: ServerGoalHandle) -> SimulateSteps.Result:
        """SimulateSteps: the requested steps in chunks, feedback at most every :data:`FEEDBACK_PERIOD_SEC` and at
        the end; a cancel ends it after the chunk in progress; a simulation that is not paused (someone pressed
        play) or fails aborts it with the steps done so far."""
        steps = goal_handle.request.steps
        result = SimulateSteps.Result()
        try:
            self._check_steps(steps)
            with self.sim.worlds.stepping("a SimulateSteps goal"):  # no LoadWorld while the goal runs
                return self._run_goal(goal_handle, steps, result)
        except (_Refused, WorldBusy) as err:
            result.result = _result(getattr(err, "code", Result.RESULT_INCORRECT_STATE), str(err))
            goal_handle.abort()
            return result

    def _run_goal(
        self, goal_handle: ServerGoalHandle, steps: int, result: SimulateSteps.Result
    ) -> SimulateSteps.Result:
        """The steps of one accepted SimulateSteps goal (see :meth:`_simulate_steps`)."""
        self.context.take_inbound()  # as StepSimulation: what came before the goal acts from its first step
        done = 0
        last_feedback = 0.0
        try:
            while done < steps:
                if goal_handle.is_cancel_requested:
                    goal_handle.canceled()
                    result.result = _result(OK, f"cancelled after {done} of {steps} steps")
                    return result
                taken = self._step_chunk(min(STEP_CHUNK, steps - done))
                if taken == 0:
                    goal_handle.abort()
                    refused = self._not_paused(done, steps)
                    result.result = _result(refused.code, str(refused))
                    return result
                done += taken
                now = time.monotonic()
                if now - last_feedback >= FEEDBACK_PERIOD_SEC or done == steps:
                    last_feedback = now
                    goal_handle.publish_feedback(
                        SimulateSteps.Feedback(completed_steps=done, remaining_steps=steps - done)
                    )
        except (WorldError, TimeoutError) as err:
            goal_handle.abort()
            result.result = _result(Result.RESULT_OPERATION_FAILED, f"stepping failed after {done} steps: {err}")
            return result
        goal_handle.succeed()
        result.result = _result(OK)
        return result

    # ------------------------------------------------------------------ spawning
    def _read_uri(self, uri: str) -> tuple[str, str, str]:
        """(text, format, source path) of a URI; raises NO_RESOURCE / UNSUPPORTED_FORMAT."""
        path = self.resolver.resolve_uri(uri)
        if path is None and self.resolver.refused(uri):
            where = ", ".join(str(p) for p in self.resolver.roots()) or "none; set GAZELLE_RESOURCE_PATH"
            raise _Refused(
                SpawnEntity.Response.NO_RESOURCE,
                f"uri '{uri}' is outside the resource paths (symbolic links resolved), so it is not read; "
                f"resource paths: {where}",
            )
        if path is None:
            where = ", ".join(str(p) for p in self.resolver.search_paths()) or "none; set GAZELLE_RESOURCE_PATH"
            raise _Refused(
                SpawnEntity.Response.NO_RESOURCE,
                f"uri '{uri}' cannot be resolved (unknown model/package, outside its package, or unsupported scheme); "
                f"resource paths: {where}",
            )
        if not uri.startswith(("model://", "package://")) and not self.resolver.is_inside_roots(path):
            where = ", ".join(str(p) for p in self.resolver.roots()) or "none; set GAZELLE_RESOURCE_PATH"
            raise _Refused(
                SpawnEntity.Response.NO_RESOURCE,
                f"uri '{uri}' is outside the resource paths, so it is not read; resource paths: {where}",
            )
        if path.is_dir():
            cands = [path / "model.sdf", *sorted(path.glob("*.sdf")), *sorted(path.glob("*.urdf"))]
            found = next((c for c in cands if c.is_file()), None)
            if found is None:
                raise _Refused(SpawnEntity.Response.NO_RESOURCE, f"uri '{uri}' is a folder ({path}) with no model.sdf")
            path = found
        if not path.is_file():
            raise _Refused(SpawnEntity.Response.NO_RESOURCE, f"uri '{uri}': no such file {path}")
        if not self.resolver.allowed(path):  # a model.sdf that links out of the resource paths is not read
            raise _Refused(SpawnEntity.Response.NO_RESOURCE, f"uri {self.resolver.refusal(uri)}")
        fmt = format_for_path(path)
        if fmt is None or fmt == "srdf":
            raise _Refused(
                SpawnEntity.Response.UNSUPPORTED_FORMAT,
                f"uri '{uri}': unsupported format '{Path(path).suffix}' (use .urdf or .sdf)",
            )
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as err:
            raise _Refused(SpawnEntity.Response.NO_RESOURCE, f"uri '{uri}': cannot read {path}: {err}") from None
        return text, fmt, str(path)

    def _prepare(
        self,
        *,
        name: str,
        allow_renaming: bool,
        uri: str,
        resource_string: str,
        namespace: str,
        initial_pose: PoseStamped,
    ) -> _Prepared:
        """Parse and place one spawn request (off the sim thread, except the frame lookup)."""
        R = SpawnEntity.Response
        try:
            requested = from_pose_msg(initial_pose.pose)
            check_pose(requested, "initial_pose.pose")
            if namespace and not _NAMESPACE_RE.match(namespace):
                raise _Refused(R.NAMESPACE_INVALID, f"entity_namespace {namespace!r} is not a valid ROS namespace")
            if uri:
                text, fmt, source = self._read_uri(uri)
            elif resource_string:
                text, fmt, source = resource_string, "auto", f"<resource_string:{name or 'entity'}>"
            else:
                raise _Refused(R.NO_RESOURCE, "either uri or resource_string must be set")
            model, warnings = model_to_spawn(
                text, source=source, logger=self.node.get_logger(), format=fmt, resolver=self.resolver
            )
            X_WF = frame_in_world(self.sim, initial_pose.header.frame_id, "initial_pose.header.frame_id")
        except SpawnFailed as err:
            raise _Refused(_PREAMBLE_TO_SPAWN[err.kind], str(err)) from None
        return _Prepared(model, name, X_WF * requested, namespace.strip("/"), allow_renaming, warnings)

    def _commit(self, prepared: list[_Prepared]) -> list[Entity | WorldError]:
        return self.sim.spawn_many(
            [SpawnRequest(p.model, p.name, p.pose, p.namespace, p.allow_renaming) for p in prepared]
        )

    @staticmethod
    def _world_error_result(err: WorldError) -> Result:
        code = _WORLD_KIND_TO_SPAWN.get(err.kind, Result.RESULT_OPERATION_FAILED)
        return _result(code, str(err))

    def spawn_entity(self, req: SpawnEntity.Request, res: SpawnEntity.Response) -> SpawnEntity.Response:
        """SpawnEntity: by ``uri`` (a resolvable model or package path) or ``resource_string`` (data, never xacro)."""
        t0 = time.monotonic()
        try:
            prepared = self._prepare(
                name=req.name,
                allow_renaming=req.allow_renaming,
                uri=req.uri,
                resource_string=req.resource_string,
                namespace=req.entity_namespace,
                initial_pose=req.initial_pose,
            )
            (out,) = self._commit([prepared])
        except _Refused as err:
            res.result = _result(err.code, str(err))
            return res
        except TimeoutError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}")
            return res
        if isinstance(out, WorldError):
            res.result = self._world_error_result(out)
            return res
        res.entity_name = out.name
        res.result = _result(OK, with_warnings(list(prepared.warnings)).lstrip("; "))
        self.node.get_logger().info(f"SpawnEntity: spawned [{out.name}] in {1000 * (time.monotonic() - t0):.1f} ms")
        return res

    def spawn_entities(self, req: SpawnEntities.Request, res: SpawnEntities.Response) -> SpawnEntities.Response:
        """SpawnEntities: several models with one recompile; one result per request."""
        results: list[SpawnResult | None] = []
        todo: list[tuple[int, _Prepared]] = []
        for i, r in enumerate(req.spawn_requests):
            try:
                todo.append(
                    (
                        i,
                        self._prepare(
                            name=r.name,
                            allow_renaming=r.allow_renaming,
                            uri=r.entity_resource.uri,
                            resource_string=r.entity_resource.resource_string,
                            namespace=r.entity_namespace,
                            initial_pose=r.initial_pose,
                        ),
                    )
                )
                results.append(None)
            except _Refused as err:
                results.append(SpawnResult(result=_result(err.code, str(err))))
            except TimeoutError as err:
                results.append(SpawnResult(result=_result(Result.RESULT_OPERATION_FAILED, str(err))))
        if todo:
            try:
                outs = self._commit([p for _, p in todo])
            except TimeoutError as err:
                outs = [WorldError(ErrorKind.BUILD_FAILED, f"the simulation did not answer: {err}")] * len(todo)
            for (i, _p), out in zip(todo, outs):
                if isinstance(out, WorldError):
                    results[i] = SpawnResult(result=self._world_error_result(out))
                else:
                    results[i] = SpawnResult(result=_result(OK), entity_name=out.name)
        res.results = results
        failed = [i for i, r in enumerate(results) if r is not None and r.result.result != OK]
        if failed:
            res.result = _result(
                SpawnEntities.Response.ENTITIES_SPAWN_FAILED,
                f"{len(failed)} of {len(results)} entities failed to spawn (indices {failed}); see results",
            )
        else:
            res.result = _result(OK)
        return res

    def delete_entity(self, req: DeleteEntity.Request, res: DeleteEntity.Response) -> DeleteEntity.Response:
        """DeleteEntity: remove one entity and its systems."""
        res.result, _ = _attempt(lambda: self.sim.delete(req.entity))
        return res
