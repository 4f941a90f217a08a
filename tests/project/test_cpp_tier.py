"""Issue 54: the C++ tier (scripts/build_cpp.sh) is built on first need only. Set-up writes a stub config for
each package a workspace finds, which builds the tier (or takes it from the cache) when CMake first reads it;
without a usable cache entry the never-build mode says so and compiles nothing. Run against a stand-in venv
whose python is this venv's: nothing is built or installed here (tests/integration/test_cpp_nodes.py builds)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from _paths import REPO

SCRIPT = REPO / "scripts" / "build_cpp.sh"
FOUND_BY_WORKSPACES = ("rclcpp", "rclcpp_action", "rclcpp_lifecycle", "rclcpp_components")


def _venv(tmp_path: Path) -> Path:
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    python.write_text(f'#!/bin/sh\nexec "{sys.executable}" "$@"\n')
    python.chmod(0o755)
    return venv


def _run(venv: Path, cache: Path, mode: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "GAZELLE_CACHE_DIR": str(cache), "GAZELLE_CPP_NO_BUILD": "1"}
    return subprocess.run(["bash", str(SCRIPT), str(venv), mode], capture_output=True, text=True, env=env, timeout=120)


def test_set_up_writes_stubs_that_build_the_tier_when_a_workspace_first_finds_it(tmp_path: Path) -> None:
    venv = _venv(tmp_path)
    done = _run(venv, tmp_path / "cache", "stubs")
    assert done.returncode == 0, done.stderr
    for pkg in FOUND_BY_WORKSPACES:
        stub = (venv / "share" / pkg / "cmake" / f"{pkg}Config.cmake").read_text()
        assert "gazelle: built on first need" in stub
        assert f'"{SCRIPT}" "{venv}" build' in stub  # this clone's script, this venv
        assert "FATAL_ERROR" in stub  # a failed build is one clear line, not a half-read config
    assert not (venv / "lib").exists()  # nothing built, nothing linked
    # and again: nothing else happens while the tier is not installed
    assert _run(venv, tmp_path / "cache", "stubs").returncode == 0


def test_without_a_cached_build_the_never_build_mode_says_so(tmp_path: Path) -> None:
    venv = _venv(tmp_path)
    cache = tmp_path / "cache"
    done = _run(venv, cache, "build")
    assert done.returncode == 3, done.stdout + done.stderr
    assert f"build_cpp: no usable cached build at {cache}/cpp/" in done.stderr
    assert not (venv / "lib" / "librclcpp.so").exists()


def test_a_cache_others_could_swap_is_not_used_whoever_made_it(tmp_path: Path) -> None:
    """docs/security.md: the cache folder is this user's with no group or other write, and so is every folder
    above it (or root's, or sticky as /tmp); checked at every use. An entry there is reported, never unpacked."""
    venv = _venv(tmp_path)
    shared = tmp_path / "shared"
    shared.mkdir()
    cache = shared / "cache"
    first = _run(venv, cache, "build")  # makes the cache folders, owner-only, and names the entry it looks for
    entry = Path(first.stderr.split("no usable cached build at ", 1)[1].split()[0])
    entry.mkdir(parents=True)
    (entry / "files.tar").write_bytes(b"")
    (entry / "files.sha256").write_text("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855\n")
    (entry / "prefix").write_text(str(venv))
    shared.chmod(0o777)  # a folder above the cache that anyone may write to: they could swap the cache itself
    try:
        done = _run(venv, cache, "build")
    finally:
        shared.chmod(0o755)
    assert done.returncode == 3, done.stdout + done.stderr
    assert (
        f"build_cpp: cache {cache}/cpp is not private (others may write to {shared} above it (mode 777))" in done.stderr
    )
    assert not (venv / "lib" / "librclcpp.so").exists()
    assert entry.is_dir()  # reported and left alone, not removed


def _setup_copy(tmp_path: Path, tools: dict[str, str]) -> tuple[Path, dict[str, str]]:
    """scripts/setup.sh in a stand-in clone, on a machine without console_bridge (the copy looks for it where
    nothing is), with PATH holding only the commands its first step uses and ``tools`` (name: shell script)."""
    scripts = tmp_path / "clone" / "scripts"
    scripts.mkdir(parents=True)
    text = (REPO / "scripts" / "setup.sh").read_text().replace("/usr/lib/*/console_bridge/", f"{tmp_path}/none/*/")
    (scripts / "setup.sh").write_text(text)
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    for name in ("bash", "dirname", "id", "mktemp", "tail", "rm", "cmake", "g++", "make", "chromium"):
        found = shutil.which(name) or "/bin/true"
        (bin_dir / name).symlink_to(found)
    for name, script in tools.items():
        (bin_dir / name).write_text(f"#!{shutil.which('bash')}\n{script}\n")
        (bin_dir / name).chmod(0o755)
    env = {"PATH": str(bin_dir), "HOME": str(tmp_path), "TMPDIR": str(tmp_path), "GAZELLE_SETUP_NO_BROWSER": "1"}
    return scripts / "setup.sh", env


def test_the_tiers_debian_package_comes_from_set_up_or_one_line_says_why_not(tmp_path: Path) -> None:
    """The C++ tier's one Debian package (libconsole-bridge-dev) is installed by scripts/setup.sh (--cpp, or
    --cpp-debian when the tier is first built); without apt-get, or when apt-get fails, one line says which
    package and why, and the exit status is 1."""
    setup, env = _setup_copy(tmp_path, {})
    done = subprocess.run(["bash", str(setup), "--cpp-debian"], capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 1, done.stdout + done.stderr
    assert done.stderr.splitlines() == [
        "[setup] cannot install Debian packages libconsole-bridge-dev: no apt-get here; install them and run again"
    ]
    failing_apt = (
        'echo "apt-get $*" >>"$HOME/apt.calls"; [[ $1 == update ]] || { echo "E: Unable to locate package"; exit 100; }'
    )
    setup, env = _setup_copy(tmp_path / "again", {"apt-get": failing_apt})
    done = subprocess.run(["bash", str(setup), "--cpp-debian"], capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 1, done.stdout + done.stderr
    if os.getuid() == 0:
        [line] = done.stderr.splitlines()
        assert line.startswith("[setup] apt-get could not install Debian packages libconsole-bridge-dev "), line
        assert "(E: Unable to locate package); its log: " in line
        assert "install -y -qq libconsole-bridge-dev" in (tmp_path / "again" / "apt.calls").read_text()
    else:  # no password-less sudo in this stand-in PATH
        assert "not root and no password-less sudo" in done.stderr
