"""SDFormat 1.2–1.11 into the description model (:class:`Model` or :class:`World`).

What the root holds decides what comes back:

* ``<world>`` → :class:`World` (the first one; more are reported and skipped);
* ``<model>`` → :class:`Model`;
* ``<light>`` alone (e.g. the ``sun`` model of the Gazebo model database) → a
  :class:`World` named ``default`` holding just that light, so callers can merge it.

Older files are read the way libsdformat converts them, the visible differences being:

* SDF ≤ 1.4: a joint ``<axis><xyz>`` is expressed in the parent *model* frame
  (libsdformat's 1.4→1.5 converter adds ``use_parent_model_frame=true``);
* SDF 1.5–1.6: in the joint frame unless ``<use_parent_model_frame>``; ``<pose frame=...>``
  acts like ``relative_to``;
* SDF ≥ 1.7: in the joint frame unless ``<xyz expressed_in=...>``;
* ``<gazebo version="1.2">`` is accepted as the root of SDF 1.2 files.

Nested models (and ``<include>`` inside a model) are flattened into their parent with
scoped names (``child::link``) and composed poses. ``JointAxis.xyz`` is always in the
joint frame; ``Joint.origin`` is X_PJ and ``Joint.child_offset`` X_JC.

Every problem is reported into the sink with file:line; see :data:`._sdf_reader.IGNORED` for the
elements skipped on purpose without a warning (everything else unknown is
``ELEMENT_UNSUPPORTED``). Custom elements with a namespace prefix (``gz:...``) are kept
silently, as libsdformat does.
"""

from __future__ import annotations

from pathlib import Path

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._model import (
    Model,
    World,
)
from ._resources import ResourceResolver
from ._sdf_model import finish_model, placement_inverse, read_model
from ._sdf_parts import read_light
from ._sdf_reader import (
    Workspace,
    _findall,
    _tag,
    location_of,
    read_document,
    warn_extra,
    warn_unsupported,
)
from ._sdf_world import read_world
from ._xml import (
    child_elements,
)

__all__ = ["parse_sdf"]


def parse_sdf(
    text: str,
    *,
    source: str,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
    base_dir: str | None,
) -> Model | World | None:
    """Parse SDF text.

    Args:
        text: the document.
        source: file name used in diagnostics.
        sink: receives every diagnostic.
        resolver: finds ``model://`` and ``package://`` URIs.
        base_dir: folder relative URIs resolve against (None: a string, relative URIs resolve nowhere).

    Returns:
        A :class:`World` (for ``<world>`` or a lone ``<light>``) or a :class:`Model`;
        None when errors prevent building one (they are in ``sink``).
    """
    try:
        return load_text(Workspace(sink, resolver), text, source, Path(base_dir) if base_dir is not None else None)
    except RecursionError:
        sink.error(ErrorCode.VALUE_INVALID, "document nests too deeply to be read", SourceLocation(source))
        return None


# ================================================================== documents, models (nested and included), worlds
def load_text(ws: Workspace, text: str, source: str, base_dir: Path | None) -> Model | World | None:
    """An SDF document's content: its first ``<world>`` (a world file), else its first ``<model>`` placed by its
    pose (and ``placement_frame``), else a lone ``<light>`` as a world holding it. What else the ``<sdf>``
    holds is warned about; a second world or model is warned about and left out, as gz-sim loads only the
    first."""
    got = read_document(ws, text, source, base_dir)
    if got is None:
        return None
    root, doc = got
    worlds = _findall(root, "world")
    models = _findall(root, "model")
    lights = _findall(root, "light")
    for child in child_elements(root):
        tag = _tag(child)
        if tag not in ("world", "model", "light") and ":" not in tag:
            warn_unsupported(ws, child, doc, "sdf")
    if worlds:
        for extra in worlds[1:] + models + lights:
            warn_extra(ws, extra, doc, "only the first <world> is loaded")
        return read_world(ws, worlds[0], doc)
    if models:
        for extra in models[1:] + lights:
            warn_extra(ws, extra, doc, "only the first <model> is loaded")
        built = read_model(ws, models[0], doc, depth=0)
        if built is None:
            return None
        if built.relative_to not in (None, "world"):
            ws.sink.error(
                ErrorCode.FRAME_INVALID,
                f"top-level model pose cannot be relative_to '{built.relative_to}'",
                built.location,
            )
            return None
        pose = built.pose
        if built.placement_frame is not None:
            inverse = placement_inverse(ws, built)
            if inverse is None:
                return None
            pose = pose * inverse
        return finish_model(ws, built, pose)
    if lights:
        for extra in lights[1:]:
            warn_extra(ws, extra, doc, "only the first <light> is loaded")
        light = read_light(ws, lights[0], doc, None)
        if light is None:
            return None
        return World(name="default", lights=(light,), source_file=doc.source, location=location_of(root, doc))
    ws.sink.error(
        ErrorCode.ELEMENT_MISSING,
        "<sdf> holds no <world>, <model> or <light>",
        location_of(root, doc),
    )
    return None
