"""gazelle's compiled per-step loops, built once against the MuJoCo the bindings load.

One loop today: :func:`run_servo_groups` runs blocks of ros2_control position-servo cycles inside
MuJoCo's step loop (``_native/servo_block.c``, see its header): per step the servo commands of every
planned group, then ``mj_step``, with no Python between steps and the GIL released.

The library is built from its source with the system C compiler (the one the interface packages are
built with) into ``$GAZELLE_CACHE_DIR/native`` (default ``~/.cache/gazelle/native``), named by a hash of
the source, the MuJoCo version and the compile flags, so a new MuJoCo or a changed source builds anew.
``scripts/setup.sh`` builds it (:func:`main`); a process that finds it missing
builds it on first use (an atomic rename: concurrent builders never see half a file). Where no compiler is
found the loop is unavailable: :func:`available` says so and the callers run their Python cycles
(the same results, slower), after one warning.

Loading code from a file is running it, so what is loaded is what was checked. The folder is checked at
every start, built or not (:func:`gazelle._files.private_folder`: it and every folder above it out of other
users' reach; one that is not is refused with one warning, and the Python cycles run). The library is opened
once, without following a link, its descriptor checked (a regular file of this user's that no one else may
write) and loaded through ``/proc/self/fd/N``: the file checked is the file mapped, even if its name were
swapped between the two (a ``renameat2`` exchange in a folder others could write loaded their library in 5
starts of 20 when the check and the load each went by name).
"""

from __future__ import annotations

import ctypes
import hashlib
import logging
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import mujoco
import numpy as np

from .._files import private_folder

_log = logging.getLogger(__name__)

SOURCE = Path(__file__).with_name("_native") / "servo_block.c"
CFLAGS = ("-O2", "-fPIC", "-shared", "-ffp-contract=off", "-fno-fast-math", "-std=c11")
"""Compile flags: ``-ffp-contract=off`` keeps every rounding the Python cycle makes."""

_lock = threading.Lock()
_lib: ctypes.CDLL | None = None
_tried = False
_fd_names: set[str] = set()
"""The ``/proc/self/fd/N`` names a library was loaded under (:func:`_fd_name` never reuses one)."""


class ServoGroupStruct(ctypes.Structure):
    """``gz_servo_group`` of the C source (the field order is the source's)."""

    # pointers are numpy arrays' data (ServoPlan keeps the arrays alive while the struct is used); sizes
    # per field are in the C source's comments. The order here must be the C struct's, field for field.
    _fields_ = [
        # the servos: their actuators and joints
        ("nservo", ctypes.c_int),
        ("act", ctypes.c_void_p),
        ("qadr", ctypes.c_void_p),
        ("dadr", ctypes.c_void_p),
        # per planned cycle: the targets and velocity references; per servo: the PID and its state
        ("target", ctypes.c_void_p),
        ("velref", ctypes.c_void_p),
        ("kp", ctypes.c_void_p),
        ("ki", ctypes.c_void_p),
        ("kd", ctypes.c_void_p),
        ("offset", ctypes.c_void_p),
        ("imin", ctypes.c_void_p),
        ("imax", ctypes.c_void_p),
        ("integral", ctypes.c_void_p),
        ("last", ctypes.c_void_p),
        # the path check (NULL: none) and what it compares with
        ("tol_p", ctypes.c_void_p),
        ("tol_v", ctypes.c_void_p),
        ("desp", ctypes.c_void_p),
        ("desv", ctypes.c_void_p),
        # what each cycle records for the controllers (the joints' state before the step) and the output
        ("nrec", ctypes.c_int),
        ("rec_qadr", ctypes.c_void_p),
        ("rec_dadr", ctypes.c_void_p),
        ("rec", ctypes.c_void_p),
        ("rec_time", ctypes.c_void_p),
        ("ctrl_out", ctypes.c_void_p),
        ("cursor", ctypes.c_int),
        ("violated", ctypes.c_int),
    ]


def _mujoco_dir() -> Path:
    """The installed mujoco package's folder (its headers and shared library are inside the wheel)."""
    return Path(mujoco.__file__).resolve().parent


def _mujoco_library() -> Path | None:
    """The MuJoCo shared library the Python bindings load, which the loop must link against (one MuJoCo
    in the process, not two)."""
    found = sorted(_mujoco_dir().glob("libmujoco.so*"))
    return found[0] if found else None


def library_path() -> Path:
    """Where the built library is (or will be) for this source, MuJoCo and flags."""
    h = hashlib.sha256(SOURCE.read_bytes())
    h.update(mujoco.__version__.encode())
    h.update(" ".join(CFLAGS).encode())
    h.update(sys.platform.encode())
    env = os.environ.get("GAZELLE_CACHE_DIR")
    base = Path(env) if env else Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "gazelle"
    return base / "native" / f"servo_block-{h.hexdigest()[:20]}.so"


def build(quiet: bool = False) -> Path | None:
    """Build the library unless it is there; its path, or None (after a warning) when it cannot be built.

    The library is named by the hash of its source, the compiler flags and the MuJoCo version (see
    :func:`library_path`), so a stale build is never loaded: a change to any of them is a new file. It is
    built into a temporary file in the owner-only cache folder and renamed into place (two processes
    building at once each finish whole, and neither loads half a file). A folder another user could write
    to, or one above it, is refused whether the library is there or not: loading code from it would run
    theirs. Without a compiler the servo cycles run in Python: the same numbers (the C loop mirrors the
    Python arithmetic, ``-ffp-contract=off``), slower.
    The build is linked against the very ``libmujoco`` the Python bindings load, with its folder as the
    rpath: the loop reads the bindings' mjModel and mjData, whose layouts are that library's."""
    named = library_path()
    folder = private_folder(named.parent, "the compiled servo loop's cache")  # every time: built or not
    if folder is None:
        return None
    target = folder / named.name
    if target.is_file() and not target.is_symlink():
        return target
    lib = _mujoco_library()
    cc = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    if lib is None or cc is None:
        _log.warning(
            "no C compiler (or no libmujoco in the mujoco package): ros2_control's per-step servo cycles run "
            "in Python (the same results, slower)"
        )
        return None
    fd, tmp = tempfile.mkstemp(prefix=".build-", suffix=".so", dir=target.parent)
    os.close(fd)
    cmd = [
        cc,
        *CFLAGS,
        f"-I{_mujoco_dir() / 'include'}",
        str(SOURCE),
        "-o",
        tmp,
        str(lib),
        f"-Wl,-rpath,{lib.parent}",
        "-lm",
    ]
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as err:
        done = None
        message = str(err)
    else:
        message = done.stderr.strip()
    if done is None or done.returncode != 0:
        Path(tmp).unlink(missing_ok=True)
        _log.warning(f"building {SOURCE.name} failed ({message[-500:]}): servo cycles run in Python")
        return None
    os.chmod(tmp, 0o700)
    os.replace(tmp, target)
    if not quiet:
        _log.info(f"built {target}")
    return target


def _load() -> ctypes.CDLL | None:
    """The native servo library, built on first use and loaded once per process (None: not available, and
    the Python path runs instead). ``GAZELLE_NO_NATIVE`` turns it off."""
    global _lib, _tried
    with _lock:
        if _tried:
            return _lib
        _tried = True
        if os.environ.get("GAZELLE_NO_NATIVE"):
            return None
        path = build(quiet=True)
        if path is None:
            return None
        lib = _load_checked(path)
        if lib is None:
            return None
        lib.gz_run_servo_groups.restype = ctypes.c_int
        lib.gz_run_servo_groups.argtypes = [
            ctypes.c_void_p,
            ctypes.c_void_p,
            ctypes.c_int,
            ctypes.c_int,
            ctypes.POINTER(ServoGroupStruct),
        ]
        lib.gz_last_error.restype = ctypes.c_char_p
        _lib = lib
        return lib


def _load_checked(path: Path) -> ctypes.CDLL | None:
    """The library at ``path`` loaded from the very file that was checked; None (after a warning) when that
    file is not a regular file of this user's that no one else may write.

    Opened once (``O_NOFOLLOW``: a link is not followed), checked by ``fstat`` of the descriptor, and loaded
    through ``/proc/self/fd/N``, which names that open file and no other: a name swapped after the check
    changes nothing. The descriptor is closed once the library is mapped."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as err:
        _log.warning(f"{path} cannot be opened ({err.strerror or err}): servo cycles run in Python")
        return None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode) or info.st_uid != os.getuid() or info.st_mode & 0o022:
            _log.warning(
                f"{path} is not a regular file of this user's that no one else may write: not loaded "
                "(servo cycles run in Python)"
            )
            return None
        name, spare = _fd_name(fd)
        try:
            return ctypes.CDLL(name)
        finally:
            for extra in spare:
                os.close(extra)
    finally:
        os.close(fd)


def _fd_name(fd: int) -> tuple[str, list[int]]:
    """``/proc/self/fd/N`` for the open file ``fd``, with N a number this module has not loaded a library
    under before (and the extra descriptors, duplicates of ``fd``, to close after the load).

    glibc's ``dlopen`` returns the library it already loaded under the same name without opening the file,
    so a name reused for another file (a second load in one process: tests) would map the first one."""
    spare: list[int] = []
    name = f"/proc/self/fd/{fd}"
    while name in _fd_names:
        spare.append(os.dup(fd))
        name = f"/proc/self/fd/{spare[-1]}"
    _fd_names.add(name)
    return name, spare


def available() -> bool:
    """Whether the compiled loop can be used (built or buildable, and not switched off by
    ``GAZELLE_NO_NATIVE``, which the tests use to compare it with the Python cycle)."""
    return _load() is not None


def run_servo_groups(model: mujoco.MjModel, data: mujoco.MjData, nstep: int, groups: object, ngroup: int) -> int:
    """Run ``nstep`` steps of the ``ngroup`` groups at ``groups`` (a pointer to a struct or an array of
    them; see the C source); the steps taken, or -(taken) - 1 after a MuJoCo error (:func:`last_error`)."""
    lib = _load()
    assert lib is not None
    return int(lib.gz_run_servo_groups(model._address, data._address, nstep, ngroup, groups))


def last_error() -> str:
    """The message of the last MuJoCo error inside :func:`run_servo_groups` (this thread's)."""
    lib = _load()
    return lib.gz_last_error().decode(errors="replace") if lib is not None else ""


def pointer(array: np.ndarray | None) -> int | None:
    """The address of a C-contiguous array's data (None for None)."""
    if array is None:
        return None
    assert array.flags.c_contiguous
    return array.ctypes.data


def main() -> int:
    """Build the library now (scripts/setup.sh); 0 when it is there, 1 when it could not be built (the
    Python cycles serve then: not an error of the set-up)."""
    logging.basicConfig(level=logging.INFO, format="[setup] %(message)s")
    return 0 if build() is not None else 1
