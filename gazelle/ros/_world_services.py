"""simulation_interfaces' worlds at run time: GetAvailableWorlds, LoadWorld, UnloadWorld and GetCurrentWorld,
under the ``gazelle`` node's ``~/`` beside the other services (``_simulation_interfaces.py``).

The runtime does the work (``sim.worlds``, :class:`gazelle.sim.WorldSwap`); this module reads and checks a
request's world and says how it went in the codes each ``.srv`` names:

* LoadWorld by ``uri``: the world the server started with (its file, as the operator named it, or
  ``empty.sdf``), an installed world by its bare name (``empty.sdf``), or an ``.sdf``/``.world`` file inside the
  resource paths by ``file://``, ``package://``, ``model://`` or a path. Anything else is ``NO_RESOURCE``; a URDF,
  a xacro or another suffix is ``UNSUPPORTED_FORMAT``.
* LoadWorld by ``resource_string``: SDF text, data only. xacro markup is ``UNSUPPORTED_FORMAT`` (never expanded);
  a DOCTYPE or entity declaration is ``RESOURCE_PARSE_ERROR`` (never expanded either); relative paths in it
  resolve against nothing.
* Bounds: at most :data:`MAX_WORLD_BYTES` of text and :data:`~gazelle.sim.MAX_WORLD_MODELS` models (counted in
  the text before it is parsed, then in the parsed world): more is ``RESULT_OPERATION_FAILED`` and the current
  world stays.
* ``ignore_missing_or_unsupported_assets`` false (the default): a mesh or include that cannot be found is
  ``MISSING_ASSETS``, a mesh that cannot be read ``UNSUPPORTED_ASSETS``, and the current world stays; true: the
  world loads without them and the reply's message counts the warnings.
* ``fail_on_unsupported_element`` true: an element, attribute, plugin or sensor gazelle does not simulate is
  ``UNSUPPORTED_ELEMENTS``; false (the default): it is ignored, as the ``.srv`` says, and logged.
* A load while another runs, or while a SimulateSteps goal or StepSimulation call steps the world, is
  ``RESULT_INCORRECT_STATE``; so is UnloadWorld then. UnloadWorld and GetCurrentWorld with no world loaded are
  ``NO_WORLD_LOADED``.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

from simulation_interfaces.msg import Resource, Result, SimulatorFeatures, WorldResource
from simulation_interfaces.srv import GetAvailableWorlds, GetCurrentWorld, LoadWorld, UnloadWorld

from ..description import (
    Diagnostic,
    ErrorCode,
    ModelLoadError,
    ResourceResolver,
    UntrustedInputError,
    World,
    detect_format,
    format_for_path,
    load_string,
    read_regular_file,
)
from ..physics import ErrorKind, WorldError
from ..sim import MAX_WORLD_MODELS, LoadedWorld, WorldBusy
from ..systems import audit_world
from ._log_diagnostic import log_diagnostic
from ._si_results import OK, _Refused, _result
from ._world_catalog import WorldCatalog, check_filter, matches

if TYPE_CHECKING:
    from ._si_context import InterfacesContext

MAX_WORLD_BYTES = 16 * 1024 * 1024
"""The largest world text LoadWorld reads, from a file or a string (gz-sim's 3k_shapes.sdf: about 0.6 MB)."""

_MISSING = frozenset({ErrorCode.MESH_NOT_FOUND, ErrorCode.URI_UNRESOLVED, ErrorCode.FILE_NOT_FOUND})
_UNREADABLE = frozenset({ErrorCode.MESH_LOAD_ERROR})
_UNSUPPORTED = frozenset(
    {
        ErrorCode.ELEMENT_UNSUPPORTED,
        ErrorCode.ATTRIBUTE_UNSUPPORTED,
        ErrorCode.PLUGIN_UNSUPPORTED,
        ErrorCode.SDF_VERSION_UNSUPPORTED,
    }
)
_DECLARATION = re.compile(r"<!\s*(DOCTYPE|ENTITY)\b", re.I)
_MODEL_TAG = re.compile(r"<\s*(model|include)\b")


class WorldServices:
    """The four world services, a part of simulation_interfaces (see the module docstring)."""

    FEATURES = (
        SimulatorFeatures.WORLD_LOADING,
        SimulatorFeatures.WORLD_RESOURCE_STRING,
        SimulatorFeatures.WORLD_TAGS,
        SimulatorFeatures.WORLD_UNLOADING,
        SimulatorFeatures.WORLD_INFO_GETTING,
        SimulatorFeatures.AVAILABLE_WORLDS,
    )
    """The feature ids these services serve, added to GetSimulatorFeatures' list."""

    def __init__(self, context: InterfacesContext):
        """Serve the four services on the context's node under ``~/``, finding files with its resolver;
        ``context.services`` holds them, so ``context.destroy`` removes them."""
        self.context = context
        self.node = context.node
        self.sim = context.sim
        self.resolver: ResourceResolver = context.resolver
        worlds = self.sim.worlds
        installed = {uri: make().name for uri, make in sorted(worlds.installed.items())}
        self.catalog = WorldCatalog(self.resolver, installed, (worlds.first.name, worlds.first.uri))
        self._from_string: tuple[LoadedWorld, str] | None = None
        """The last world loaded from a resource_string, and the string (GetCurrentWorld gives it back)."""
        context.serve(GetAvailableWorlds, "get_available_worlds", self.get_available_worlds)
        context.serve(LoadWorld, "load_world", self.load_world)
        context.serve(UnloadWorld, "unload_world", self.unload_world)
        context.serve(GetCurrentWorld, "get_current_world", self.get_current_world)

    # ------------------------------------------------------------------ the services
    def get_available_worlds(
        self, req: GetAvailableWorlds.Request, res: GetAvailableWorlds.Response
    ) -> GetAvailableWorlds.Response:
        """GetAvailableWorlds: the world files on the resource paths and in ``additional_sources``, filtered by
        tags; local only (``offline_only`` is always taken as true)."""
        try:
            check_filter(req.filter)
        except ValueError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, str(err))
            return res
        worlds, problems = self.catalog.available(list(req.additional_sources))
        res.worlds = [w for w in worlds if matches(list(w.tags), req.filter)]
        if problems and not req.continue_on_error:
            res.worlds = []
            res.result = _result(
                Result.RESULT_OPERATION_FAILED,
                f"{problems[0]} (set continue_on_error to list the other sources' worlds)",
            )
            return res
        note = f"skipped {len(problems)} source(s): {'; '.join(problems)}" if problems else ""
        res.result = _result(OK, note)
        return res

    def load_world(self, req: LoadWorld.Request, res: LoadWorld.Response) -> LoadWorld.Response:
        """LoadWorld: the current world and every entity go, the requested one comes; the clock starts again at
        zero, paused (STOPPED); the node, its services and /clock stay."""
        try:
            world, uri, warnings = self._read(req)
            loaded = self.sim.worlds.load(world, uri)
        except _Refused as err:
            res.result = _result(err.code, str(err))
            return res
        except WorldBusy as err:
            res.result = _result(Result.RESULT_INCORRECT_STATE, f"LoadWorld refused: {err}")
            return res
        except WorldError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"LoadWorld failed: {err}")
            return res
        except TimeoutError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}")
            return res
        if not uri:
            self._from_string = (loaded, req.resource_string)
        self.context.publish_clock(self.sim.world.time)  # nodes on sim time see the clock start again now
        res.world = self._resource(loaded)
        more = f"; {len(warnings)} warning(s) ignored, the first: {warnings[0]}" if warnings else ""
        res.result = _result(OK, f"loaded world '{loaded.name}' ({len(self.sim.world.entities)} entities){more}")
        self.node.get_logger().info(f"LoadWorld: loaded world '{loaded.name}'" + (f" from {uri}" if uri else ""))
        return res

    def unload_world(self, req: UnloadWorld.Request, res: UnloadWorld.Response) -> UnloadWorld.Response:
        """UnloadWorld: every entity and the world go; an empty simulation, paused, until the next LoadWorld."""
        try:
            self.sim.worlds.unload()
        except WorldBusy as err:
            res.result = _result(Result.RESULT_INCORRECT_STATE, f"UnloadWorld refused: {err}")
            return res
        except WorldError as err:
            code = UnloadWorld.Response.NO_WORLD_LOADED if err.kind is ErrorKind.NOT_FOUND else None
            res.result = _result(code or Result.RESULT_OPERATION_FAILED, str(err))
            return res
        except TimeoutError as err:
            res.result = _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}")
            return res
        self.context.publish_clock(self.sim.world.time)
        res.result = _result(OK)
        return res

    def get_current_world(
        self, req: GetCurrentWorld.Request, res: GetCurrentWorld.Response
    ) -> GetCurrentWorld.Response:
        """GetCurrentWorld: the loaded world's name, URI (or the string it came from) and tags."""
        loaded = self.sim.worlds.current
        if loaded is None:
            res.result = _result(
                GetCurrentWorld.Response.NO_WORLD_LOADED, "no world is loaded (UnloadWorld took it); use LoadWorld"
            )
            return res
        res.world = self._resource(loaded)
        res.result = _result(OK)
        return res

    def _resource(self, loaded: LoadedWorld) -> WorldResource:
        text = self._from_string[1] if self._from_string is not None and self._from_string[0] is loaded else ""
        where = f"from {loaded.uri}" if loaded.uri else "from a resource_string"
        return WorldResource(
            name=loaded.name,
            world_resource=Resource(uri=loaded.uri, resource_string=text),
            description=f"SDF world '{loaded.name}' {where}, {len(loaded.description.models)} model(s)",
            tags=self.catalog.tags(loaded.uri),
        )

    # ------------------------------------------------------------------ reading a request's world
    def _read(self, req: LoadWorld.Request) -> tuple[World, str, list[str]]:
        """The requested world, the URI a later load names it by ("" for a string) and the warnings ignored."""
        R = LoadWorld.Response
        if req.uri:
            known = self._known(req.uri)
            if known is not None:
                return known, req.uri, []
            text, source = self._read_uri(req.uri)
            uri = req.uri
        elif req.resource_string:
            text, source, uri = req.resource_string, "<resource_string>", ""
            if len(text.encode("utf-8", "replace")) > MAX_WORLD_BYTES:
                raise _Refused(
                    Result.RESULT_OPERATION_FAILED,
                    f"resource_string has more than the {MAX_WORLD_BYTES} bytes a world may have",
                )
        else:
            raise _Refused(R.NO_RESOURCE, "either uri or resource_string must be set")
        world, diagnostics = self._parse(text, source)
        return world, uri, self._judge(world, diagnostics, req)

    def _known(self, uri: str) -> World | None:
        """The world the server started with, or an installed one, when ``uri`` names it (nothing is read)."""
        worlds = self.sim.worlds
        if uri == worlds.first.uri:
            return worlds.first.description
        make = worlds.installed.get(uri)
        return make() if make is not None else None

    def _read_uri(self, uri: str) -> tuple[str, str]:
        """The text and path of a world file inside the resource paths; NO_RESOURCE or UNSUPPORTED_FORMAT."""
        R = LoadWorld.Response
        raw = uri.strip()
        if "://" in raw and not raw.startswith(("file://", "package://", "model://")):
            raise _Refused(R.NO_RESOURCE, f"uri '{uri}': unsupported scheme (local files only: nothing is downloaded)")
        path = self.resolver.resolve_uri(raw)
        roots = ", ".join(str(p) for p in self.resolver.roots()) or "none; set GAZELLE_RESOURCE_PATH"
        if path is None or not self.resolver.is_inside_roots(path):
            why = "is outside the resource paths" if path is not None or self.resolver.refused(raw) else "not found"
            raise _Refused(R.NO_RESOURCE, f"uri '{uri}' {why}, so it is not read; resource paths: {roots}")
        if not path.is_file():
            raise _Refused(R.NO_RESOURCE, f"uri '{uri}': {path} is not a file")
        if format_for_path(path) != "sdf":
            raise _Refused(
                R.UNSUPPORTED_FORMAT,
                f"uri '{uri}': a world is an SDF file (.sdf, .world), not '{Path(path).suffix or path.name}'",
            )
        try:
            return read_regular_file(path, MAX_WORLD_BYTES, "world file"), str(path)
        except UntrustedInputError as err:
            raise _Refused(R.NO_RESOURCE, f"uri '{uri}': {err}") from None

    def _parse(self, text: str, source: str) -> tuple[World, tuple[Diagnostic, ...]]:
        """``text`` read as an SDF world (data only); RESOURCE_PARSE_ERROR, UNSUPPORTED_FORMAT, MISSING_ASSETS or
        RESULT_OPERATION_FAILED (too many models) otherwise."""
        R = LoadWorld.Response
        if (m := _DECLARATION.search(text)) is not None:
            line = text.count("\n", 0, m.start()) + 1
            raise _Refused(
                R.RESOURCE_PARSE_ERROR,
                f"{source}:{line}: <!{m.group(1)}> declarations are refused: a world is data, its entities are "
                "never expanded",
            )
        fmt = detect_format(text)
        if fmt in ("xacro", "urdf", "srdf"):
            what = "xacro markup (never expanded: expand it first)" if fmt == "xacro" else f"a {fmt.upper()}"
            raise _Refused(R.UNSUPPORTED_FORMAT, f"{source}: {what}; a world is SDF with a <world> element")
        if (n := len(_MODEL_TAG.findall(text))) > MAX_WORLD_MODELS:
            raise _Refused(
                Result.RESULT_OPERATION_FAILED,
                f"{source}: {n} <model>/<include> elements, more than the {MAX_WORLD_MODELS} a world may have; "
                "nothing was changed",
            )
        try:
            loaded = load_string(text, format="sdf", source=source, resolver=self.resolver)
        except ModelLoadError as err:
            first = err.first
            code = R.MISSING_ASSETS if first is not None and first.code in _MISSING else R.RESOURCE_PARSE_ERROR
            raise _Refused(code, err.summary()) from None
        if not isinstance(loaded.value, World):
            raise _Refused(R.RESOURCE_PARSE_ERROR, f"{source}: no <world> in it (spawn a model with SpawnEntity)")
        return loaded.value, loaded.diagnostics

    def _judge(self, world: World, diagnostics: tuple[Diagnostic, ...], req: LoadWorld.Request) -> list[str]:
        """Refuse the world by the request's flags, or return the warnings it loads with (also logged)."""
        R = LoadWorld.Response
        problems = [*diagnostics, *audit_world(world)]
        if not req.ignore_missing_or_unsupported_assets:
            for codes, code, what in ((_MISSING, R.MISSING_ASSETS, "missing"), (_UNREADABLE, R.UNSUPPORTED_ASSETS, "")):
                found = [d for d in problems if d.code in codes]
                if found:
                    note = "" if len(found) == 1 else f" (and {len(found) - 1} more)"
                    raise _Refused(
                        code,
                        f"{found[0].format()}{note}; set ignore_missing_or_unsupported_assets to load without "
                        f"{'them' if what else 'the unreadable assets'}",
                    )
        if req.fail_on_unsupported_element:
            found = [d for d in problems if d.code in _UNSUPPORTED]
            if found:
                note = "" if len(found) == 1 else f" (and {len(found) - 1} more)"
                raise _Refused(R.UNSUPPORTED_ELEMENTS, f"{found[0].format()}{note}")
        for d in problems:
            log_diagnostic(self.node.get_logger(), d)
        return [d.format() for d in problems]
