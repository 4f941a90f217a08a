"""The files ``colcon build --symlink-install`` links into an install prefix, and the workspace they lead to.

With ``--symlink-install`` colcon does not copy a package's files into ``install/``: it links them. An
ament_cmake package's ``install(DIRECTORY models ...)`` makes real folders in ``install/PKG/share/PKG``
holding one link per file into ``src/`` (ament_cmake_symlink_install); an ament_python package's
``data_files`` become links into ``build/PKG``, which in turn link into ``src/`` (colcon-core's
``task/python/build.py``, ``_symlinks_in_build``, then its ``symlink_data`` command). Following such a link
lands outside every resource root, in the workspace the prefix was built from.

colcon marks what it made (colcon-core ``verb/__init__.py``): the install base holds
``.colcon_install_layout`` (``isolated`` or ``merged``), the build base holds ``.built_by`` (``colcon``).
Run in a workspace with the default bases, those are ``WS/install`` and ``WS/build``; so the workspace of
a prefix is the parent of the nearest install base above it, and only when that parent also holds a build
base that colcon marked. A prefix built with ``--install-base`` or ``--build-base`` elsewhere has no
workspace here, and keeps the plain confinement (add its source folder to ``GAZELLE_RESOURCE_PATH``).

Only a path that lies *in* a resource root (its folders resolved, its last component not) is followed, and
only to a file in that workspace: a ``file://`` URI that names ``WS/src/...`` directly is not read, and
neither is a link in the install tree that leads out of the workspace.
"""

from __future__ import annotations

import os
from pathlib import Path

INSTALL_MARKER = ".colcon_install_layout"
"""The file colcon writes in an install base; it reads ``isolated`` or ``merged``."""
INSTALL_LAYOUTS = ("isolated", "merged")
BUILD_MARKER = ".built_by"
"""The file colcon writes in a build base; it reads ``colcon``."""
MARKER_BYTES = 64
"""The most of a marker file that is read (colcon writes one word and a newline)."""


def _reads(marker: Path, words: tuple[str, ...]) -> bool:
    """Whether the regular file ``marker`` holds one of ``words`` (and a newline), as colcon writes it."""
    try:
        if not marker.is_file():
            return False
        with open(marker, "rb") as f:
            head = f.read(MARKER_BYTES)
    except OSError:
        return False
    return head.decode("ascii", "replace").strip() in words


def colcon_workspace(folder: Path) -> Path | None:
    """The workspace (resolved) that the colcon install base holding ``folder`` was built in, or None.

    The nearest folder at or above ``folder`` that is an install base (its ``.colcon_install_layout``)
    decides: its parent is the workspace when it also holds colcon's build base (``build/.built_by``).
    An install base without one beside it (``--install-base`` elsewhere, a copied install tree), or one
    whose parent is the file system's root, has no workspace: None, and no folder above is tried."""
    for base in (folder, *folder.parents):
        if (base / INSTALL_MARKER).exists():
            if not _reads(base / INSTALL_MARKER, INSTALL_LAYOUTS):
                return None
            workspace = base.parent.resolve()
            if workspace == Path(workspace.anchor) or not _reads(workspace / "build" / BUILD_MARKER, ("colcon",)):
                return None  # a build in / would make every link of the install tree readable
            return workspace
    return None


def colcon_linked(path: str | os.PathLike[str], roots: list[Path]) -> Path | None:
    """``path`` (absolute, made normal) when it is a link colcon made in an install prefix that lies in one of
    ``roots`` (resolved folders), and it leads to a file or folder of the workspace the prefix was built
    from; else None.

    The folders on the way are resolved and must stay in a root; the last component is the link colcon
    made (``install/PKG/share/PKG/meshes/wall.dae -> WS/src/.../wall.dae``). What is returned is that
    link, not its target: relative references in the file then resolve beside it in the install tree, as
    they do for Gazebo, which opens the link."""
    raw = Path(path)
    if not raw.is_absolute():
        return None
    lexical = Path(os.path.normpath(raw))
    if lexical.parent == lexical:
        return None
    try:
        here = lexical.parent.resolve() / lexical.name
        if not any(root in here.parents for root in roots):
            return None
        workspace = colcon_workspace(here.parent)
        if workspace is None:
            return None
        real = here.resolve()
    except (OSError, RuntimeError):  # a link loop
        return None
    return here if workspace in real.parents else None
