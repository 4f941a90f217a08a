"""Gazebo model folders (a folder with a ``model.config``): what simulation_interfaces' GetSpawnables lists.

:func:`model_folders` finds them on the resource paths (each search path's direct sub-folders, as
``model://NAME`` resolves them) and in folders a request names (the folder itself and its direct sub-folders);
:func:`read_model_folder` reads one config: its ``<name>``, ``<description>`` and the SDF file it names, chosen
as sdformat 14 chooses it (the highest ``<sdf version>`` gazelle reads, the first of equals; else the first
entry; ``model.sdf`` when it names none). The config is parsed without entities or network access.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ._resources import ResourceResolver
from ._sdf_reader import MAX_VERSION, Version, parse_version

MAX_CONFIG_BYTES = 1 << 20
"""The largest ``model.config`` read (a config is a few hundred bytes; a bigger one is not a model's)."""


@dataclass(frozen=True, slots=True)
class ModelFolder:
    """One Gazebo model folder."""

    folder: Path
    """The folder (symbolic links resolved)."""
    sdf: Path
    """The model file its config names."""
    name: str
    """The config's ``<name>``, else the folder's name."""
    description: str
    """The config's ``<description>``, white space collapsed ('' when it has none)."""


def _chosen_sdf(root: etree._Element) -> str | None:
    """The file name the config's ``<sdf>`` entries choose (see the module docstring)."""
    entries = [e for e in root.iter("sdf") if (e.text or "").strip()]
    best = entries[0] if entries else None
    best_version: Version = (0, 0)
    for entry in entries:
        version = parse_version(entry.get("version"))
        if version is not None and best_version < version <= MAX_VERSION:
            best, best_version = entry, version
    return (best.text or "").strip() if best is not None else None


def read_model_folder(folder: Path, resolver: ResourceResolver) -> ModelFolder | str:
    """The model folder at ``folder``, or why it is not one a spawn can use (a line naming the file)."""
    config = folder / "model.config"
    try:
        if config.stat().st_size > MAX_CONFIG_BYTES:
            return f"{config}: larger than {MAX_CONFIG_BYTES} bytes"
        root = etree.fromstring(config.read_bytes(), etree.XMLParser(resolve_entities=False, no_network=True))
    except (OSError, ValueError, etree.XMLSyntaxError) as err:
        return f"{config}: cannot be read: {err}"
    real = folder.resolve()
    chosen = _chosen_sdf(root) or "model.sdf"
    sdf = resolver.file_in(real, chosen)
    if sdf is None or not sdf.is_file():
        return f"{config}: names '{chosen}', which is not a file in {real}"
    name = " ".join((root.findtext("name") or "").split()) or folder.name
    description = " ".join((root.findtext("description") or "").split())
    return ModelFolder(real, sdf, name, description)


def _children(folder: Path) -> list[Path]:
    try:
        return sorted(p for p in folder.iterdir() if p.is_dir() and not p.name.startswith("."))
    except OSError:
        return []


def model_folders(resolver: ResourceResolver, sources: list[Path], limit: int) -> tuple[list[Path], bool]:
    """The folders with a ``model.config`` on the resolver's search paths, then in ``sources``, each once, in that
    order; and whether more than ``limit`` were found (then the first ``limit`` are returned)."""
    seen: set[Path] = set()
    found: list[Path] = []
    candidates = [c for root in resolver.search_paths() if root.is_dir() for c in _children(root)]
    for source in sources:
        candidates += [source, *_children(source)]
    for cand in candidates:
        if not (cand / "model.config").is_file():
            continue
        real = cand.resolve()
        if real in seen:
            continue
        seen.add(real)
        if len(found) == limit:
            return found, True
        found.append(cand)
    return found, False
