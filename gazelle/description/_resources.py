"""Resolving ``package://``, ``model://``, ``file://`` and ``$(find pkg)`` the way ROS and Gazebo do.

Search order for a package or model name ``NAME``:

1. every folder in ``GAZELLE_RESOURCE_PATH``, ``GZ_SIM_RESOURCE_PATH``,
   ``IGN_GAZEBO_RESOURCE_PATH``, ``GAZEBO_MODEL_PATH`` and ``ROS_PACKAGE_PATH``
   (plus any extra folders passed in): ``<folder>/NAME`` if it exists;
2. the ament index: ``<prefix>/share/NAME`` for each prefix in ``AMENT_PREFIX_PATH``
   that registers ``NAME`` in ``share/ament_index/resource_index/packages``.

Only names that resolve this way are read: a URI never escapes the folder it resolves to.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

SEARCH_PATH_VARIABLES = (
    "GAZELLE_RESOURCE_PATH",
    "GZ_SIM_RESOURCE_PATH",
    "IGN_GAZEBO_RESOURCE_PATH",
    "GAZEBO_MODEL_PATH",
    "ROS_PACKAGE_PATH",
)


def _split(value: str | None) -> list[Path]:
    return [Path(p) for p in (value or "").split(os.pathsep) if p]


@dataclass
class ResourceResolver:
    """Finds packages and models on the search paths and the ament index."""

    extra_paths: list[Path] = field(default_factory=list)
    """Folders searched before the environment's."""
    env: dict[str, str] | None = None
    """Environment to read (defaults to ``os.environ``)."""

    def search_paths(self) -> list[Path]:
        """Folders whose sub-folders are packages or models, in search order."""
        env = self.env if self.env is not None else os.environ
        paths = list(self.extra_paths)
        for var in SEARCH_PATH_VARIABLES:
            paths.extend(_split(env.get(var)))
        return paths

    def find_package(self, name: str) -> Path | None:
        """The share folder of package (or model) ``name``, or None."""
        if not name or "/" in name or name in (".", ".."):
            return None
        for folder in self.search_paths():
            cand = folder / name
            if cand.is_dir():
                return cand.resolve()
        env = self.env if self.env is not None else os.environ
        for prefix in _split(env.get("AMENT_PREFIX_PATH")):
            marker = prefix / "share" / "ament_index" / "resource_index" / "packages" / name
            share = prefix / "share" / name
            if marker.exists() and share.is_dir():
                return share.resolve()
        return None

    def resolve_uri(self, uri: str, base_dir: str | os.PathLike[str] | None = None) -> Path | None:
        """Absolute path of a ``package://``, ``model://``, ``file://`` URI or a plain path.

        Relative plain paths are taken relative to ``base_dir``. Returns None when the
        URI cannot be resolved or would leave the package folder it names.
        """
        uri = uri.strip()
        for scheme in ("package://", "model://"):
            if uri.startswith(scheme):
                rest = uri[len(scheme):]
                name, _, sub = rest.partition("/")
                root = self.find_package(name)
                if root is None:
                    return None
                path = (root / sub).resolve()
                if path != root and root not in path.parents:
                    return None
                return path
        if uri.startswith("file://"):
            uri = uri[len("file://"):]
        if "://" in uri:
            return None
        path = Path(uri)
        if not path.is_absolute():
            path = Path(base_dir or ".") / path
        return path.resolve()

    def roots(self) -> list[Path]:
        """Every folder a resource may come from: the search paths and the ament prefixes' share folders."""
        env = self.env if self.env is not None else os.environ
        found = list(self.search_paths())
        found.extend(prefix / "share" for prefix in _split(env.get("AMENT_PREFIX_PATH")))
        return [r.resolve() for r in found if r.is_dir()]

    def is_inside_roots(self, path: Path) -> bool:
        """Whether ``path`` lies in one of :meth:`roots` (spawning by URI reads nothing else)."""
        path = path.resolve()
        return any(path == root or root in path.parents for root in self.roots())

