"""simulation_interfaces' GetSpawnables (:class:`SpawnablesService`): the Gazebo model folders (a folder with a
``model.config``) on the resource paths, then in the request's ``sources``, each as the ``uri`` SpawnEntity takes,
with its description and its spawn bounds.

* ``uri``: ``model://NAME`` when ``model://NAME`` resolves to that folder and its config names ``model.sdf``
  (``model://NAME/FILE`` when it names another file); else ``file://`` and the model file's path.
* ``description``: the config's ``<name>``, and its ``<description>`` after a colon.
* ``spawn_bounds``: ``TYPE_BOX``, the box around the model's collision geometry in its model frame as it would be
  spawned (:func:`gazelle.physics.model_box`), remembered per file until the file changes.
* ``sources``: folders, as a path, ``file://``, ``model://`` or ``package://`` URI, each read only when it lies
  inside the resource paths (the folders SpawnEntity reads; symbolic links resolved): the folder itself if it is
  a model folder, and its direct sub-folders. As the service says, an entry it does not recognise is named in
  the reply's message (without saying whether such a folder exists) and the reply is still ``RESULT_OK``.

A model folder whose file does not load or build is left out; the reply's message says how many and why (the
first). At most :data:`MAX_SPAWNABLES` are listed (the message says when more were found).
"""

from __future__ import annotations

from collections import OrderedDict
from pathlib import Path
from typing import TYPE_CHECKING

from geometry_msgs.msg import Vector3
from simulation_interfaces.msg import Bounds, Result, SimulatorFeatures, Spawnable
from simulation_interfaces.srv import GetSpawnables

from ..description import (
    Model,
    ModelFolder,
    ModelLoadError,
    World,
    excerpt,
    load,
    model_folders,
    read_model_folder,
)
from ..physics import WorldError, model_box
from ._si_results import OK, _result

if TYPE_CHECKING:
    from ..description import ResourceResolver
    from ._si_context import InterfacesContext

MAX_SPAWNABLES = 500
"""The most model folders one reply lists."""
MAX_SOURCES = 32
"""The most ``sources`` one request may name."""
CACHE_ENTRIES = 1024
"""Model files whose spawn bounds are remembered (the oldest are forgotten first)."""


class SpawnablesService:
    """``~/get_spawnables``, a part of simulation_interfaces registered on the context's node."""

    FEATURES = (SimulatorFeatures.SPAWNABLES,)

    def __init__(self, context: InterfacesContext):
        """Serve GetSpawnables (``context.services`` holds it, so ``context.destroy`` removes it)."""
        self.resolver: ResourceResolver = context.resolver
        self._bounds: OrderedDict[tuple[Path, int, int], Bounds | str] = OrderedDict()
        context.serve(GetSpawnables, "get_spawnables", self.get)

    def _source(self, source: str) -> Path | None:
        """A source as a folder inside the resource paths (see the module docstring), or None."""
        path = self.resolver.resolve_uri(source) if source.strip() else None
        if path is None or not path.is_dir() or not self.resolver.is_inside_roots(path):
            return None
        return path

    def _uri(self, found: Path, mf: ModelFolder) -> str:
        """The URI SpawnEntity takes for a model folder's file (see the module docstring)."""
        if self.resolver.find_package(found.name) == mf.folder and mf.folder in mf.sdf.parents:
            rel = mf.sdf.relative_to(mf.folder).as_posix()
            return f"model://{found.name}" if rel == "model.sdf" else f"model://{found.name}/{rel}"
        return mf.sdf.as_uri()

    def _spawn_bounds(self, sdf: Path) -> Bounds | str:
        """The model's spawn bounds, or why it cannot be spawned (remembered per file version)."""
        try:
            st = sdf.stat()
        except OSError as err:
            return f"{sdf}: {err}"
        key = (sdf, st.st_mtime_ns, st.st_size)
        if key in self._bounds:
            self._bounds.move_to_end(key)
            return self._bounds[key]
        try:
            value = load(sdf, resolver=self.resolver, expand_xacro=False).value
            model = value.models[0] if isinstance(value, World) and value.models else value
            if not isinstance(model, Model):
                raise ModelLoadError([])
            box = model_box(model)
            out: Bounds | str = Bounds(
                type=Bounds.TYPE_BOX, points=[Vector3(x=x, y=y, z=z) for x, y, z in (box.lower, box.upper)]
            )
        except ModelLoadError as err:
            out = f"{sdf}: {err.summary(1) if err.diagnostics else 'no <model> to spawn'}"
        except WorldError as err:
            out = f"{sdf}: {err}"
        self._bounds[key] = out
        while len(self._bounds) > CACHE_ENTRIES:
            self._bounds.popitem(last=False)
        return out

    def _spawnable(self, found: Path) -> Spawnable | str:
        """One model folder as a Spawnable, or why it is left out."""
        mf = read_model_folder(found, self.resolver)
        if isinstance(mf, str):
            return mf
        if not self.resolver.is_inside_roots(mf.sdf):
            return f"{mf.sdf}: outside the resource paths"
        bounds = self._spawn_bounds(mf.sdf)
        if isinstance(bounds, str):
            return bounds
        text = f"{mf.name}: {mf.description}" if mf.description else mf.name
        return Spawnable(uri=self._uri(found, mf), description=text, spawn_bounds=bounds)

    def get(self, req: GetSpawnables.Request, res: GetSpawnables.Response) -> GetSpawnables.Response:
        """GetSpawnables: the model folders on the resource paths and in ``sources``."""
        if len(req.sources) > MAX_SOURCES:
            message = f"sources has {len(req.sources)} entries; at most {MAX_SOURCES}"
            res.result = _result(Result.RESULT_OPERATION_FAILED, message)
            return res
        sources: list[Path] = []
        unrecognised: list[str] = []
        for i, source in enumerate(req.sources):
            path = self._source(source)
            if path is None:
                unrecognised.append(f"sources[{i}] {excerpt(source, 120)}")
            else:
                sources.append(path)
        folders, more = model_folders(self.resolver, sources, MAX_SPAWNABLES)
        listed: list[Spawnable] = []
        left_out: list[str] = []
        for found in folders:
            item = self._spawnable(found)
            if isinstance(item, str):
                left_out.append(item)
            else:
                listed.append(item)
        notes = []
        if unrecognised:
            notes.append(
                f"not recognised as a folder inside the resource paths (GAZELLE_RESOURCE_PATH and the other search "
                f"paths; symbolic links resolved), so not searched: {', '.join(unrecognised)}"
            )
        if left_out:
            notes.append(f"{len(left_out)} model folder(s) left out, the first: {left_out[0]}")
        if more:
            notes.append(f"more than {MAX_SPAWNABLES} model folders: the first {MAX_SPAWNABLES} are listed")
        res.spawnables = listed
        res.result = _result(OK, "; ".join(notes))
        return res
