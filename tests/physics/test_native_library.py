"""The compiled servo loop's library is code this process runs: it is loaded only from a folder no other user
can write (the folder and every folder above it, checked at every start, built or not), and what is loaded
is the very file that was checked (issue 48, item 4: with the cache's ``native/`` folder 0777, 5 starts of 20
loaded a library another user swapped in between the check and the load).

Each test builds nothing: the library is compiled once for the module (~2 s) and copied into a fresh cache.
"""

from __future__ import annotations

import ctypes
import logging
import os
import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

CC = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")

pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler: the servo loop runs in Python, nothing to load")

SWAPPED = b"a library another user swapped in"


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The servo library compiled once, into a cache of the module's own."""
    from gazelle.physics import _native

    cache = tmp_path_factory.mktemp("native-build")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("GAZELLE_CACHE_DIR", str(cache))
        path = _native.build(quiet=True)
    assert path is not None, "the servo loop did not build"
    return path


@pytest.fixture
def native(built: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[tuple[Any, Path]]:
    """``gazelle.physics._native`` not loaded yet, with its library already built in a fresh, private cache
    (``tmp_path/cache``); yields (module, library path)."""
    from gazelle.physics import _native

    monkeypatch.setenv("GAZELLE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("GAZELLE_NO_NATIVE", raising=False)
    monkeypatch.setattr(_native, "_tried", False)
    monkeypatch.setattr(_native, "_lib", None)
    path = _native.library_path()
    path.parent.mkdir(mode=0o700, parents=True)
    shutil.copy2(built, path)
    path.chmod(0o700)
    yield _native, path


def _swapped_library(folder: Path) -> Path:
    """A library with the servo loop's two symbols whose ``gz_last_error`` says it is not gazelle's."""
    src = folder / "swapped.c"
    src.write_text(
        f'const char* gz_last_error(void) {{ return "{SWAPPED.decode()}"; }}\n'
        "int gz_run_servo_groups(void) { return 0; }\n"
    )
    out = folder / "swapped.so"
    assert CC is not None
    subprocess.run([CC, "-shared", "-fPIC", str(src), "-o", str(out)], check=True, capture_output=True, timeout=60)
    out.chmod(0o700)
    return out


def test_the_library_builds_loads_and_runs_from_a_private_cache(native) -> None:
    _native, path = native
    lib = _native._load()
    assert lib is not None
    assert lib.gz_last_error() == b""  # gazelle's own: no MuJoCo error yet on this thread
    assert path.parent.stat().st_mode & 0o777 == 0o700


@pytest.mark.parametrize("writable", ["native", "cache"], ids=["its-folder", "a-folder-above"])
def test_a_library_in_a_folder_others_may_write_is_not_loaded_though_it_is_built(
    native, writable: str, caplog: pytest.LogCaptureFixture
) -> None:
    """The library is there (``build`` used to return at once then, so the folder was never checked): a
    0777 ``native/`` folder, or a 0777 folder above it, is refused with one warning naming it, and the servo
    cycles run in Python. The folder is left as it is (refused, not repaired: whatever is in it may already
    be another user's)."""
    _native, path = native
    folder = path.parent if writable == "native" else path.parent.parent
    folder.chmod(0o777)
    with caplog.at_level(logging.WARNING):
        assert _native._load() is None
    (warning,) = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert f"others may write to {folder}" in warning and "(mode 0777)" in warning and "\n" not in warning
    assert "compiled servo loop's cache" in warning
    assert not _native.available()
    assert folder.stat().st_mode & 0o777 == 0o777


@pytest.mark.skipif(os.getuid() != 0, reason="giving a folder to another user takes root")
def test_a_native_folder_another_user_owns_is_not_loaded_from(native, caplog: pytest.LogCaptureFixture) -> None:
    _native, path = native
    os.chown(path.parent, 65534, -1)  # nobody's, mode 0700 still
    with caplog.at_level(logging.WARNING):
        assert _native._load() is None
    assert f"{path.parent} belongs to another user (uid 65534)" in caplog.text


def test_a_library_name_swapped_between_the_check_and_the_load_loads_the_checked_file(
    native, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The race, made certain: the library's name is replaced by another library (as another user's
    ``renameat2`` exchange would) at the last moment before the loader opens it. What is loaded is still
    the file that was checked (gazelle's loop, whose last error is empty), never the swapped one."""
    _native, path = native
    swapped = _swapped_library(tmp_path)
    checked = path.stat().st_ino
    real_cdll = ctypes.CDLL
    opened: list[str] = []

    def swap_then_load(name: str, *args: Any, **kwargs: Any) -> ctypes.CDLL:
        os.replace(swapped, path)  # between the check and the load
        opened.append(name)
        return real_cdll(name, *args, **kwargs)

    monkeypatch.setattr(ctypes, "CDLL", swap_then_load)
    lib = _native._load()
    assert opened, "the library was not loaded"
    assert lib is not None
    assert path.stat().st_ino != checked  # the name was swapped
    assert lib.gz_last_error() != SWAPPED, f"the swapped-in library was loaded (by the name {opened[0]})"
    assert lib.gz_last_error() == b""


def test_a_library_that_is_a_link_is_not_followed(native, tmp_path: Path) -> None:
    _native, path = native
    elsewhere = _swapped_library(tmp_path)
    path.unlink()
    path.symlink_to(elsewhere)
    lib = _native._load()  # built anew over the link: the link's target is neither loaded nor written
    assert lib is not None and lib.gz_last_error() == b""
    assert not path.is_symlink() and elsewhere.read_bytes() != path.read_bytes()
