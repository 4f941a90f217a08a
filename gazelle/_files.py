"""How gazelle writes a file and which folders it trusts: one way each, for every layer.

* :func:`atomic_write` writes a file whole or not at all, and never through a link: replays, checkpoints,
  the convex-decomposition cache and the sweep's shipped files all go through it. Each writer had its own
  ``<name>.<pid>.tmp`` beside the target, a name anyone could guess: a symlink planted there made
  ``gazelle sim --replay`` write through it into another file and leave the target a link.
* :func:`private_folder` is the check of a folder gazelle reads code or data back from (the compiled servo
  loop, the convex cache): the folder and every folder above it must be such that no other user can
  replace what is inside. A folder that others may write, anywhere on the way up, lets them swap a file
  between the moment it is checked and the moment it is used.
"""

from __future__ import annotations

import logging
import os
import stat
import tempfile
from pathlib import Path

_log = logging.getLogger(__name__)


def _umask() -> int:
    """The process's umask, read without changing it (``os.umask`` sets it, and another thread creating a
    file meanwhile would get the wrong mode); Linux reports it in ``/proc/self/status`` since 4.7."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    return 0o022


def atomic_write(path: str | os.PathLike[str], data: bytes | str, mode: int | None = None) -> Path:
    """Write ``data`` (text is UTF-8) to ``path``, whole or not at all, never through a link; the path.

    The bytes go to a new file that :func:`tempfile.mkstemp` creates in the target's folder (``O_EXCL``, a
    random name, owner-only until it is complete: nothing planted in advance can be opened or written
    through), get ``mode`` (default: ``0o666`` less the umask, as a plain ``open`` would give), and the file
    is renamed over the target with ``os.replace``. A reader sees the old file or the new one, never half of
    one; a symlink at the target is itself replaced (what it pointed to is never written); a failure leaves
    the target as it was and no temporary file behind. Not flushed to disk (``fsync``): a power cut may
    lose the new file, never corrupt the old one into half of each."""
    out = Path(path)
    blob = data.encode("utf-8") if isinstance(data, str) else data
    fd, tmp = tempfile.mkstemp(prefix=f".{out.name[:120]}.", suffix=".tmp", dir=out.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(blob)
            os.fchmod(f.fileno(), mode if mode is not None else 0o666 & ~_umask())
        os.replace(tmp, out)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return out


def _unsafe(folder: Path, owner_only: bool = False) -> str | None:
    """Why another user could replace what is in the real folder ``folder`` (None: nobody could), or, with
    ``owner_only``, enter it.

    The folder itself must be a folder, this user's, with no group or other write (with ``owner_only``, no group
    or other access at all: 0700); each folder above it this user's or root's, and without group or other write
    unless sticky (``/tmp``): in a sticky folder only an entry's owner may rename or remove it, and the entry
    below was checked to be this user's or root's."""
    me = os.getuid()
    info = folder.lstat()
    if not stat.S_ISDIR(info.st_mode):
        return f"{folder} is not a folder"
    if info.st_uid != me:
        return f"{folder} belongs to another user (uid {info.st_uid})"
    if info.st_mode & 0o022:
        return f"others may write to {folder} (mode {stat.S_IMODE(info.st_mode):04o})"
    if owner_only and info.st_mode & 0o077:
        return f"others may enter {folder} (mode {stat.S_IMODE(info.st_mode):04o}, not 0700)"
    for parent in folder.parents:
        info = parent.lstat()
        if info.st_uid not in (me, 0):
            return f"{parent} above it belongs to another user (uid {info.st_uid})"
        if info.st_mode & 0o022 and not info.st_mode & stat.S_ISVTX:
            return f"others may write to {parent} above it (mode {stat.S_IMODE(info.st_mode):04o})"
    return None


def checked_folder(folder: Path, *, create: bool = True, owner_only: bool = False) -> tuple[Path | None, str | None]:
    """The one check of a folder whose files no other user may replace: ``(its real path, None)`` when nobody else
    can (see :func:`_unsafe`; with ``owner_only``, nor enter it: 0700), ``(None, why)`` when someone could,
    ``(None, None)`` when it does not exist and ``create`` is false. A missing folder (and each missing folder
    above it) is made owner-only (0700) when ``create``, whatever the umask. Links are resolved: the chain checked
    is the real one, which callers use. Raises ``OSError`` when it cannot be made or read."""
    if not create and not folder.exists():
        return None, None
    for missing in [*reversed(folder.parents), folder]:  # each one made here is owner-only, whatever the umask
        if not missing.exists():
            missing.mkdir(mode=0o700, exist_ok=True)
    real = folder.resolve(strict=True)
    why = _unsafe(real, owner_only)
    if why is None:
        return real, None
    return None, why if real == folder.absolute() else f"{why} (the real folder of {folder})"


def private_folder(folder: Path, what: str) -> Path | None:
    """``folder`` created owner-only (0700) when missing, as its real path (links resolved), when no other
    user can replace what is in it (:func:`checked_folder`); else None, after one warning naming ``what`` it
    holds and why, so that nothing is read from it or written to it. Checked at each use, not once: a folder
    made writable after the first check is refused at the next.

    Callers open files under the path returned, not the one given: a link on the way that another user
    could re-point was resolved when the chain was checked."""
    try:
        real, why = checked_folder(folder)
    except OSError as err:
        _log.debug(f"cannot use {what} {folder}: {err}")
        return None
    if why is not None:
        _log.warning(
            f"{what} {folder} is not private: {why}, so another user could swap what is in it; it is not used "
            "(make it and the folders above it yours and not writable by others, e.g. mode 0700, or set "
            "GAZELLE_CACHE_DIR)"
        )
    return real
