"""Models a user can spawn from the viewer: what the resource paths hold (no viser here).

The same search paths ``model://`` and ``package://`` URIs resolve against
(:class:`gazelle.description.ResourceResolver`): in each folder and its direct
sub-folders, a Gazebo model folder (``model.config`` naming its SDF) or any
``*.sdf`` / ``*.urdf`` file. xacro files are not offered: the server never runs xacro
(expand them first, or spawn them with ``gazelle spawn -file``).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

from ..description import ResourceResolver

MODEL_SUFFIXES = (".sdf", ".urdf")
MAX_MODELS = 200


@dataclass(frozen=True)
class ModelFile:
    """A model description found on the resource paths, as the Spawn panel lists it."""

    label: str
    """What the dropdown shows: ``folder/file`` relative to its search path."""
    path: Path


def _config_sdf(folder: Path, resolver: ResourceResolver) -> Path | None:
    """The SDF a Gazebo ``model.config`` names (the last ``<sdf>`` element, as Gazebo picks the newest), when it
    lies in the model's folder (or is a link ``colcon build --symlink-install`` made: ``ResourceResolver.file_in``)."""
    try:
        root = ET.parse(folder / "model.config").getroot()
    except (OSError, ET.ParseError):
        return None
    names = [e.text.strip() for e in root.iter("sdf") if e.text and e.text.strip()]
    for name in reversed(names):
        cand = resolver.file_in(folder.resolve(), name)
        if cand is not None and cand != folder.resolve() and cand.is_file():
            return cand
    return None


def _files_in(folder: Path, resolver: ResourceResolver) -> list[Path]:
    """The model files of one folder of a resource path: a Gazebo model folder's SDF (from its model.config), else
    its URDF and SDF files."""
    if (folder / "model.config").is_file():
        sdf = _config_sdf(folder, resolver)
        return [sdf] if sdf is not None else []
    try:
        return sorted(p for p in folder.iterdir() if p.is_file() and p.suffix in MODEL_SUFFIXES)
    except OSError:
        return []


def find_models(resolver: ResourceResolver | None = None) -> list[ModelFile]:
    """Every model file on the resolver's search paths (depth <= 1 below each path), at most ``MAX_MODELS``."""
    resolver = resolver or ResourceResolver()
    found: dict[Path, ModelFile] = {}
    for root in resolver.search_paths():
        if not root.is_dir():
            continue
        folders = [root]
        try:
            folders += sorted(p for p in root.iterdir() if p.is_dir() and not p.name.startswith("."))
        except OSError:
            pass
        for folder in folders:
            for f in _files_in(folder, resolver):
                if f.resolve() not in found:
                    rel = f.relative_to(root) if root in f.parents else Path(f.name)
                    found[f.resolve()] = ModelFile(str(rel), f.resolve())
                if len(found) >= MAX_MODELS:
                    return list(found.values())
    return list(found.values())
