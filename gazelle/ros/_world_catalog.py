"""The world files a LoadWorld can name: what simulation_interfaces' GetAvailableWorlds lists.

A world file is an ``.sdf`` or ``.world`` file whose first :data:`HEAD_BYTES` hold a ``<world`` element, found
by walking the resource roots (:meth:`ResourceResolver.roots`: the resource paths and the ament share
folders) and the request's ``additional_sources``, and the worlds installed with gazelle (``empty.sdf``).
Only local folders are searched, whatever ``offline_only`` says: nothing is downloaded.

Every walk is bounded: at most :data:`MAX_DEPTH` folders deep, :data:`MAX_ENTRIES` files looked at and
:data:`MAX_WORLDS` worlds listed per request; folder links are not followed, and a file whose real place is
outside the allowed folders is not read.

A world's tags: the names of the folders between its root and the file (a package's name, ``worlds``), so
that a filter on a package's name finds its worlds; ``installed`` for gazelle's own, and ``default`` for the
world the server started with.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from simulation_interfaces.msg import Resource, TagsFilter, WorldResource

from ..description import ResourceResolver

HEAD_BYTES = 64 * 1024
"""How much of a candidate file is read to tell a world from a model and find its name."""
MAX_DEPTH = 6
"""The deepest a walk goes below a root or a source (``share/<package>/worlds/<sub>/x.sdf`` is 3)."""
MAX_ENTRIES = 50_000
"""The most files one request looks at over all its roots and sources."""
MAX_WORLDS = 1000
"""The most worlds one reply lists."""
WORLD_SUFFIXES = (".sdf", ".world")
_WORLD_NAME = re.compile(rb"<\s*world\b[^>]*?\bname\s*=\s*[\"']([^\"'<>]{0,200})[\"']")


class WorldCatalog:
    """The world files on the resource roots and in a request's sources (see the module docstring)."""

    def __init__(self, resolver: ResourceResolver, installed: dict[str, str], default: tuple[str, str]):
        """``installed``: the bare names a LoadWorld accepts for gazelle's own worlds, with their worlds' names;
        ``default``: the name and URI
        of the world the server started with (listed wherever it lies, and tagged ``default``)."""
        self.resolver = resolver
        self.installed = installed
        self.default_name, self.default_uri = default

    def tags(self, uri: str) -> list[str]:
        """The tags of the world a URI names (see the module docstring)."""
        out: list[str] = []
        if uri in self.installed:
            out.append("installed")
        elif uri:
            path = Path(uri.removeprefix("file://"))
            for root in self.resolver.roots():
                if root in path.parents:
                    out.extend(path.relative_to(root).parts[:-1])
                    break
        if uri and uri == self.default_uri:
            out.append("default")
        return out

    def available(self, sources: list[str]) -> tuple[list[WorldResource], list[str]]:
        """The worlds on the roots and in ``sources`` (each once), and what went wrong with each source that
        could not be searched (``additional_sources[i] 'x': why``)."""
        budget = [MAX_ENTRIES]  # files left to look at, over every folder of this request
        found: dict[str, WorldResource] = {}
        if self.default_uri:
            found[self.default_uri] = self.resource(
                self.default_name, self.default_uri, f"the world the server started with ({self.default_uri})"
            )
        for uri, name in self.installed.items():
            if uri not in found:
                found[uri] = self.resource(name, uri, f"gazelle's installed world '{uri}'")
        problems: list[str] = []
        folders: list[Path] = list(self.resolver.roots())
        for i, source in enumerate(sources):
            folder, why = self._source_folder(source)
            if folder is None:
                problems.append(f"additional_sources[{i}] '{source}': {why}")
            else:
                folders.append(folder)
        for folder in folders:
            for path, name in self._walk(folder, budget):
                uri = f"file://{path}"
                if uri not in found and len(found) < MAX_WORLDS:
                    found[uri] = self.resource(name, uri, f"SDF world '{name}' in {path.parent}")
        return list(found.values()), problems

    def resource(self, name: str, uri: str, description: str) -> WorldResource:
        """The WorldResource of a world named ``name`` that LoadWorld loads by ``uri``."""
        return WorldResource(name=name, world_resource=Resource(uri=uri), description=description, tags=self.tags(uri))

    def _source_folder(self, source: str) -> tuple[Path | None, str]:
        """The local folder an additional source names, or None and why it is not searched."""
        raw = source.strip()
        if "://" in raw and not raw.startswith(("file://", "package://", "model://")):
            return None, "only local folders are searched (offline only: nothing is downloaded)"
        path = self.resolver.resolve_uri(raw)
        if path is None:
            if self.resolver.refused(raw):
                return None, self.resolver.refusal(raw)
            return None, "no such folder, package or model on the resource paths"
        if not path.is_dir():
            return None, f"{path} is not a folder"
        return path, ""

    def _walk(self, root: Path, budget: list[int]) -> list[tuple[Path, str]]:
        """The world files below ``root`` with their world names, within the bounds (``budget[0]``: the files
        this request may still look at)."""
        out: list[tuple[Path, str]] = []
        base = len(root.parts)
        for folder, subfolders, files in os.walk(root):  # folder links are not followed
            if len(Path(folder).parts) - base >= MAX_DEPTH:
                subfolders[:] = []
            subfolders.sort()
            for file in sorted(files):
                budget[0] -= 1
                if budget[0] < 0:
                    return out
                if not file.lower().endswith(WORLD_SUFFIXES):
                    continue
                path = Path(folder) / file
                name = self._world_name(path)
                if name is not None:
                    out.append((path, name))
        return out

    def _world_name(self, path: Path) -> str | None:
        """The name of the world in ``path`` (the file's stem when it has none), or None when it holds no world or
        is not to be read (outside the allowed folders, not a regular file)."""
        if not path.is_file() or not self.resolver.allowed(path):
            return None
        try:
            with path.open("rb") as f:
                head = f.read(HEAD_BYTES)
        except OSError:
            return None
        if not re.search(rb"<\s*world\b", head):
            return None
        m = _WORLD_NAME.search(head)
        return m.group(1).decode("utf-8", "replace") if m else path.stem


def check_filter(tag_filter: TagsFilter) -> None:
    """Raise ValueError, naming the field, for a filter mode the standard does not define."""
    if tag_filter.filter_mode not in (TagsFilter.FILTER_MODE_ANY, TagsFilter.FILTER_MODE_ALL):
        raise ValueError(
            f"filter.filter_mode {tag_filter.filter_mode} is neither FILTER_MODE_ANY (0) nor FILTER_MODE_ALL (1)"
        )


def matches(tags: list[str], tag_filter: TagsFilter) -> bool:
    """Whether a world with ``tags`` passes ``tag_filter`` (no tags in the filter: every world)."""
    wanted = list(tag_filter.tags)
    if not wanted:
        return True
    if tag_filter.filter_mode == TagsFilter.FILTER_MODE_ALL:
        return all(t in tags for t in wanted)
    return any(t in tags for t in wanted)
