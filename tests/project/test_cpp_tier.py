"""Issue 54: the C++ tier (scripts/build_cpp.sh) is built on first need only. Set-up writes a stub config for
each package a workspace finds, which builds the tier (or takes it from the cache) when CMake first reads it;
without a usable cache entry the never-build mode says so and compiles nothing. Run against a stand-in venv
whose python is this venv's: nothing is built or installed here (tests/integration/test_cpp_nodes.py builds)."""

from __future__ import annotations

import os
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
