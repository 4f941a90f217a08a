"""What the world says once about an entity it just compiled: a non-convex collision mesh made convex parts (and
what that cost), and contact parameters MuJoCo cannot honour. ``reported`` is the world's memory of what was said
(model source and parameters -> how many entities had them), so the same file spawned again is not said again."""

from __future__ import annotations

import logging

from ._convex import cache_dir
from ._entities import Entity

_log = logging.getLogger("gazelle.physics")


def report_decomposed(entity: Entity, reported: dict[tuple[str, tuple[str, ...]], int]) -> None:
    """Say once per mesh file what was done to its non-convex collision mesh, and what it cost."""
    for path, parts, seconds, source in entity.built.decomposed:
        key = (path, ("decomposed",))
        if key in reported:
            continue
        reported[key] = 1
        if source == "triangles":  # a static mesh without parts: _convex said so when it made them
            continue
        how = f"in {seconds:.2f} s" if source == "computed" else f"from the {source}"
        _log.info(
            f"'{entity.name}': collision mesh {path} is not convex: it collides as {parts} convex parts "
            f"(CoACD, {how}; cache: {cache_dir()})"
        )


def report_unsimulated(entity: Entity, reported: dict[tuple[str, tuple[str, ...]], int]) -> None:
    """One warning per model file (or string) for the contact parameters MuJoCo cannot honour,
    naming them all with their places; the same file spawned again is not reported again
    (32 chess pieces made 100 lines)."""
    params = entity.built.unsimulated
    if not params:
        return
    source = entity.model.source_file
    origin = source if source and not source.startswith("<") else f"{source}:{entity.model.name}"
    key = (origin, tuple(sorted(params)))
    if key in reported:
        reported[key] += 1
        return
    reported[key] = 1
    places = sorted({w for where in params.values() for w in where})
    shown = ", ".join(places[:3]) + (f" and {len(places) - 3} more" if len(places) > 3 else "")
    names = ", ".join(f"<{p}>" for p in sorted(params))
    source = f" ({entity.model.source_file})" if entity.model.source_file else ""
    _log.warning(
        f"'{entity.name}'{source}: surface {names} not simulated (no MuJoCo counterpart, or read only by an "
        f"engine other than Gazebo's defaults; see docs/contact_parameters.md), on {shown}; later spawns of "
        "this model are not reported again"
    )
