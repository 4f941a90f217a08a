"""Resolving ``package://``, ``model://``, ``file://`` and ``$(find pkg)`` the way ROS and Gazebo do.

Search order for a package or model name ``NAME``:

1. every folder in ``GAZELLE_RESOURCE_PATH``, ``GZ_SIM_RESOURCE_PATH``,
   ``IGN_GAZEBO_RESOURCE_PATH``, ``GAZEBO_MODEL_PATH`` and ``ROS_PACKAGE_PATH``
   (plus any extra folders passed in): ``<folder>/NAME`` if it exists;
2. the ament index: ``<prefix>/share/NAME`` for each prefix in ``AMENT_PREFIX_PATH``
   that registers ``NAME`` in ``share/ament_index/resource_index/packages``.

Only names that resolve this way are read: a URI never escapes the folder it resolves to,
and no file is read from outside the *allowed folders*: the resource roots (the search paths
and the ament prefixes' ``share``), the folder of the file the user named (``trusted_dirs``),
for a package installed by ``colcon build --symlink-install``, the source folder its ``package.xml``
links to, and, for a link colcon made in an install prefix on the roots, the file it leads to in the
workspace that prefix was built from (see :mod:`._colcon`). Symbolic links are resolved first, so a
``model.sdf`` that links to ``/etc/passwd`` is not read. A description that arrives as a string has no
trusted folder.
"""

from __future__ import annotations

import functools
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from ._colcon import colcon_linked

SEARCH_PATH_VARIABLES = (
    "GAZELLE_RESOURCE_PATH",
    "GZ_SIM_RESOURCE_PATH",
    "IGN_GAZEBO_RESOURCE_PATH",
    "GAZEBO_MODEL_PATH",
    "ROS_PACKAGE_PATH",
)


CLASSIC_MODEL_DATABASE = "http://models.gazebosim.org"
"""Gazebo Classic's online model database (``GAZEBO_MODEL_DATABASE_URI``'s default; its models are also in
github.com/osrf/gazebo_models)."""


def classic_model_folder(env: dict[str, str] | os._Environ[str]) -> Path:
    """``$HOME/.gazebo/models``: the first of Gazebo Classic's model paths (gazebo/common/SystemPaths.cc) and where
    its ModelDatabase puts a ``model://`` model it downloads; a user's own copy of the models, read like
    ``GAZEBO_MODEL_PATH`` (gazelle downloads nothing into it)."""
    return Path(env.get("HOME") or "/tmp/gazebo") / ".gazebo" / "models"


def classic_model_advice(name: str, env: dict[str, str] | os._Environ[str]) -> str:
    """What a user does about a ``model://NAME`` found nowhere: where Gazebo Classic would have got it."""
    database = env.get("GAZEBO_MODEL_DATABASE_URI") or CLASSIC_MODEL_DATABASE
    return (
        f"model '{name}' is not on the model paths nor in {classic_model_folder(env)}; Gazebo Classic downloads such "
        f"a model from its online model database ({database}) into ~/.gazebo/models, gazelle never downloads: get it "
        "by running Gazebo Classic once where there is a network, or copy its folder from "
        "https://github.com/osrf/gazebo_models into ~/.gazebo/models (or onto GAZEBO_MODEL_PATH / "
        "GZ_SIM_RESOURCE_PATH); include skipped, the world loads without it"
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
    trusted_dirs: list[Path] = field(default_factory=list)
    """Folders besides the resource roots whose files may be read: the folder of the file the user named."""

    def trusting(self, folder: str | os.PathLike[str] | None) -> ResourceResolver:
        """This resolver, also allowing files under ``folder`` (the folder of a file the user named)."""
        if folder is None:
            return self
        return ResourceResolver(list(self.extra_paths), self.env, [*self.trusted_dirs, Path(folder)])

    def allowed_roots(self) -> list[Path]:
        """Every folder a file may be read from (resolved): the roots and the trusted folders."""
        return [*self.roots(), *(t.resolve() for t in self.trusted_dirs if t.is_dir())]

    def allowed(self, path: str | os.PathLike[str]) -> bool:
        """Whether ``path``, with its symbolic links resolved, lies in an allowed folder, or ``path`` is a
        link that colcon's ``--symlink-install`` made in an allowed folder (:func:`._colcon.colcon_linked`)."""
        roots = self.allowed_roots()
        real = Path(path).resolve()
        for root in roots:
            if real == root or root in real.parents:
                return True
            source = _symlinked_source(root, real)
            if source is not None:
                return True
        return colcon_linked(path, roots) is not None

    def search_paths(self) -> list[Path]:
        """Folders whose sub-folders are packages or models, in search order: the extra folders, the
        environment's (with Gazebo Classic's ``~/.gazebo/models`` before ``GAZEBO_MODEL_PATH``, as Classic's
        SystemPaths puts it first), then the model folders that installed packages export
        (``gazebo_model_path``)."""
        env = self.env if self.env is not None else os.environ
        paths = list(self.extra_paths)
        for var in SEARCH_PATH_VARIABLES:
            if var == "GAZEBO_MODEL_PATH":
                paths.append(classic_model_folder(env))
            paths.extend(_split(env.get(var)))
        paths.extend(exported_model_paths(env.get("AMENT_PREFIX_PATH") or ""))
        return paths

    def find_package(self, name: str) -> Path | None:
        """The share folder of package (or model) ``name``, or None."""
        if not name or "/" in name or name in (".", ".."):
            return None
        folders = self.search_paths()
        for folder in folders:
            cand = folder / name
            if cand.is_dir() and _confined_folder(folder, cand):
                return cand.resolve()
        # ROS finds a package by the <name> in its package.xml, not its folder's name (a moveit_resources
        # clone keeps moveit_resources_panda_moveit_config in panda_moveit_config/)
        for folder in folders:
            cand = packages_by_name(folder).get(name)
            if cand is not None and _confined_folder(folder, cand):
                return cand.resolve()
        env = self.env if self.env is not None else os.environ
        for prefix in _split(env.get("AMENT_PREFIX_PATH")):
            marker = prefix / "share" / "ament_index" / "resource_index" / "packages" / name
            share = prefix / "share" / name
            if marker.exists() and share.is_dir() and _confined_folder(prefix / "share", share):
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
                rest = uri[len(scheme) :]
                name, _, sub = rest.partition("/")
                root = self.find_package(name)
                if root is None:
                    return None
                return self.file_in(root, sub)
        path = _local_path(uri, base_dir)
        if path is None:
            return None
        real = path.resolve()
        if self.allowed(real):
            return real
        return colcon_linked(path, self.allowed_roots())

    def file_in(self, root: Path, sub: str) -> Path | None:
        """``root/sub`` for the package or model folder ``root`` (resolved), when it does not leave it: its
        real location, in the folder or in the package's source (a ``--symlink-install`` package.xml's);
        or, when it is a link colcon made that leads into the workspace, the link (:mod:`._colcon`). None
        when it climbs out (``model://a/../../etc``) or links out of both."""
        path = (root / sub).resolve()
        if path == root or root in path.parents or _in_package_source(root, path):
            return path
        lexical = Path(os.path.normpath(root / sub))
        if root not in lexical.parents:
            return None
        return colcon_linked(lexical, self.allowed_roots())

    def unresolved_reason(self, uri: str, base_dir: str | os.PathLike[str] | None = None) -> str:
        """Why :meth:`resolve_uri` gave None for ``uri``: an unknown package, or a file outside the allowed folders.

        The message a mesh or include warning carries, so that the user learns which of the three it was: a
        package or model not on any search path (with where gazelle looked), a scheme gazelle does not fetch
        (``https://`` outside Fuel: nothing is downloaded), or a file it found but will not read because it
        lies outside the resource roots (the refusal names the roots)."""
        raw = uri.strip()
        if raw.startswith(("package://", "model://")):
            name = raw.split("://", 1)[1].partition("/")[0]
            if self.find_package(name) is None:
                if self.confined_out(name) is not None:
                    return self.refusal(uri)
                return f"package or model '{name}' not found (is it on GAZELLE_RESOURCE_PATH or the ament index?)"
            return self.refusal(uri)
        if "://" in raw and not raw.startswith("file://"):
            return f"unsupported URI scheme in '{uri}' (nothing is downloaded)"
        return self.refusal(uri) if self.refused(uri, base_dir) else f"no such file: {uri}"

    def confined_out(self, name: str) -> Path | None:
        """A folder named ``name`` on the search paths that is not used as a package or model because it
        links out of its root to something that is neither (see :func:`_confined_folder`), or None."""
        if not name or "/" in name or name in (".", ".."):
            return None
        for folder in self.search_paths():
            cand = folder / name
            if cand.is_dir() and not _confined_folder(folder, cand):
                return cand
        return None

    def refused(self, uri: str, base_dir: str | os.PathLike[str] | None = None) -> bool:
        """Whether ``uri`` names an existing file that is not read because it lies outside the allowed folders."""
        raw = uri.strip()
        if raw.startswith(("package://", "model://")):
            name, _, sub = raw.split("://", 1)[1].partition("/")
            root = self.find_package(name)
            if root is None:
                return self.confined_out(name) is not None
            return (root / sub).exists() and self.resolve_uri(uri, base_dir) is None
        path = _local_path(raw, base_dir)
        return path is not None and path.exists() and not self.allowed(path)

    def refusal(self, uri: str) -> str:
        """Why a URI that names an existing file is not read (for error messages)."""
        roots = ", ".join(str(r) for r in self.allowed_roots()) or "none"
        return (
            f"'{uri}' is outside the folders files may be read from (after resolving symbolic links); "
            f"add its folder to GAZELLE_RESOURCE_PATH. Allowed: {roots}"
        )

    def roots(self) -> list[Path]:
        """Every folder a resource may come from: the search paths and the ament prefixes' share folders."""
        env = self.env if self.env is not None else os.environ
        found = list(self.search_paths())
        found.extend(prefix / "share" for prefix in _split(env.get("AMENT_PREFIX_PATH")))
        return [r.resolve() for r in found if r.is_dir()]

    def is_inside_roots(self, path: Path) -> bool:
        """Whether ``path`` lies in one of :meth:`roots`, or is a link colcon made there that leads into its
        workspace (spawning by URI reads nothing else)."""
        roots = self.roots()
        real = path.resolve()
        return any(real == root or root in real.parents for root in roots) or colcon_linked(path, roots) is not None


@functools.lru_cache(maxsize=8)
def _exports(prefixes: str, stamp: tuple[float, ...]) -> tuple[Path, ...]:
    """The Gazebo model folders that the ament packages under ``prefixes`` export (their package.xml's
    ``<export><gazebo_ros gazebo_model_path=...>``), in index order, each once; ``stamp`` (the index folders'
    times) invalidates the cache."""
    out: list[Path] = []
    for prefix in _split(prefixes):
        index = prefix / "share" / "ament_index" / "resource_index" / "packages"
        try:
            names = sorted(p.name for p in index.iterdir())
        except OSError:
            continue
        for name in names:
            share = prefix / "share" / name
            out.extend(_gazebo_model_paths(share))
    return tuple(dict.fromkeys(out))


def _gazebo_model_paths(share: Path) -> list[Path]:
    """The ``<export><gazebo_ros gazebo_model_path="${prefix}/models"/>`` folders of the package at ``share``
    (``${prefix}``: the package's share folder), those inside the package only.

    This is how gazebo_ros's launch files (``gazebo_ros_paths.py``) add a package's models to
    ``GAZEBO_MODEL_PATH``, so ``model://`` URIs of a workspace's worlds resolve the same here. The
    manifest is read only when it mentions the attribute (most do not), parsed without entities, DTDs or the
    network, and a path that leaves the package is not added: a package.xml is data, and cannot widen what
    gazelle reads."""
    from lxml import etree

    manifest = share / "package.xml"
    try:
        if not manifest.is_file() or manifest.stat().st_size > 1 << 20:
            return []
        data = manifest.read_bytes()
        if b"gazebo_model_path" not in data:  # most packages: no XML parse
            return []
        parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False)
        root = etree.fromstring(data, parser)
    except (OSError, ValueError, etree.XMLSyntaxError):
        return []
    found = []
    real_share = share.resolve()
    for export in root.iterfind("export/gazebo_ros"):
        raw = export.get("gazebo_model_path")
        if not raw:
            continue
        for part in raw.split(os.pathsep):
            folder = Path(part.replace("${prefix}", str(share))).resolve()
            if (folder == real_share or real_share in folder.parents) and folder.is_dir():
                found.append(folder)
    return found


PACKAGE_SCAN_DEPTH = 4
"""How deep below a search-path folder package.xml files are looked for (a source tree's src/repo/pkg)."""
PACKAGE_SCAN_FOLDERS = 5000
"""The most folders one scan looks into."""
_NAME = re.compile(rb"<name>\s*([A-Za-z0-9_]+)\s*</name>")


def packages_by_name(folder: Path) -> dict[str, Path]:
    """Package name -> folder, for every ``package.xml`` below ``folder`` (not below a package, as ROS's
    crawl stops there; hidden folders skipped; at most :data:`PACKAGE_SCAN_DEPTH` deep and
    :data:`PACKAGE_SCAN_FOLDERS` folders). Cached until the folder changes."""
    try:
        stamp = folder.stat().st_mtime
    except OSError:
        return {}
    return _scan_packages(str(folder), stamp)


@functools.lru_cache(maxsize=32)
def _scan_packages(folder: str, _stamp: float) -> dict[str, Path]:
    """The ROS packages under ``folder`` by their package.xml name (not their folder's), as colcon and ``$(find)``
    know them: a walk that stops descending at a package, skips hidden folders, and is bounded in depth and
    folders so a resource path pointed at a home folder stays quick; ``_stamp`` invalidates the cache."""
    found: dict[str, Path] = {}
    seen = 0
    for root, dirs, files in os.walk(folder, followlinks=False):
        seen += 1
        depth = root[len(folder) :].count(os.sep)
        if "package.xml" in files:
            dirs[:] = []
            try:
                with open(os.path.join(root, "package.xml"), "rb") as f:
                    head = f.read(1 << 16)
            except OSError:
                continue
            m = _NAME.search(head)
            if m is not None:
                found.setdefault(m.group(1).decode(), Path(root))
            continue
        dirs[:] = [d for d in dirs if not d.startswith(".")] if depth < PACKAGE_SCAN_DEPTH else []
        if seen >= PACKAGE_SCAN_FOLDERS:
            break
    return found


def exported_model_paths(prefixes: str) -> tuple[Path, ...]:
    """The model folders the ament index's packages export for Gazebo, as gazebo_ros adds them to
    ``GAZEBO_MODEL_PATH`` (gazebo_ros/scripts/gazebo_ros_paths.py: every package's
    ``<export><gazebo_ros gazebo_model_path=...>``, ``${prefix}`` its share folder). TurtleBot3's
    turtlebot3_gazebo exports its ``models``, where ``model://turtlebot3_world`` lives. Cached until an
    index folder changes."""
    stamp = []
    for prefix in _split(prefixes):
        try:
            stamp.append((prefix / "share" / "ament_index" / "resource_index" / "packages").stat().st_mtime)
        except OSError:
            stamp.append(0.0)
    return _exports(prefixes, tuple(stamp))


def _local_path(uri: str, base_dir: str | os.PathLike[str] | None) -> Path | None:
    """The file a ``file://`` URI or a plain path names (relative to ``base_dir``), unresolved; None for
    other schemes, or a relative path without a base."""
    uri = uri[len("file://") :] if uri.startswith("file://") else uri
    if "://" in uri:
        return None
    path = Path(uri)
    if path.is_absolute():
        return path
    return Path(base_dir) / path if base_dir is not None else None


def _in_package_source(package_root: Path, path: Path) -> bool:
    """Whether ``path`` is in the source folder of a package installed with ``--symlink-install``
    (colcon links ``share/PKG/package.xml`` and the package's files to the source tree)."""
    manifest = package_root / "package.xml"
    if not manifest.is_symlink():
        return False
    source = manifest.resolve().parent
    return path == source or source in path.parents


PACKAGE_MARKERS = ("package.xml", "model.config", "model.sdf")
"""Files that make a folder a ROS package or a Gazebo model."""


def _is_package(folder: Path) -> bool:
    return any((folder / marker).is_file() for marker in PACKAGE_MARKERS)


def _confined_folder(root: Path, folder: Path) -> bool:
    """Whether the package or model folder ``folder`` (an entry of the resource root ``root``) may be read.

    A folder whose real location stays inside the root may. One that is a symbolic link out of it (an
    ament prefix's ``share/PKG -> /src/PKG``, a models collection of links) may only where it leads to a
    package or a model (a ``package.xml``, ``model.config`` or ``model.sdf``): a link ``etcmodel -> /etc``
    in a model folder would otherwise open ``/etc`` to every ``model://etcmodel/...`` in a request."""
    real, real_root = folder.resolve(), root.resolve()
    if real == real_root or real_root in real.parents:
        return True
    return _is_package(real)


def _symlinked_source(root: Path, path: Path) -> Path | None:
    """The package under ``root`` that holds ``path`` outside ``root``, if any: the source folder of a
    package installed with ``--symlink-install`` (its ``package.xml`` links there), or the real folder of a
    package folder that is itself a link (``share/PKG -> /src/PKG``) and leads to a package or model."""
    try:
        candidates = [root, *(p for p in root.iterdir() if p.is_dir())] if root.is_dir() else []
    except OSError:
        return None
    for pkg in candidates:
        if _in_package_source(pkg, path):
            return pkg
        if pkg.is_symlink():
            real = pkg.resolve()
            if (path == real or real in path.parents) and _is_package(real):
                return pkg
    return None
