"""Issue 28: the interface packages are cached by content outside the clone, and a corrupt entry is
reported and rebuilt, never used (scripts/build_interfaces.sh, run here in its never-build mode against a
stand-in venv whose python is this venv's, so the import check passes and nothing is compiled)."""

from __future__ import annotations

import hashlib
import io
import os
import re
import subprocess
import sys
import tarfile
from pathlib import Path

from _paths import REPO

SCRIPT = REPO / "scripts" / "build_interfaces.sh"


def _run(venv: Path, cache: Path, *tier: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "GAZELLE_CACHE_DIR": str(cache), "GAZELLE_INTERFACES_NO_BUILD": "1"}
    return subprocess.run(["bash", str(SCRIPT), str(venv), *tier], capture_output=True, text=True, env=env, timeout=300)


def _entry(tar_bytes: bytes, prefix: str) -> dict[str, bytes]:
    return {
        "files.tar": tar_bytes,
        "files.sha256": (hashlib.sha256(tar_bytes).hexdigest() + "\n").encode(),
        "prefix": (prefix + "\n").encode(),
    }


def _write(entry: Path, files: dict[str, bytes]) -> None:
    entry.mkdir(mode=0o700, parents=True, exist_ok=True)
    for name, content in files.items():
        (entry / name).write_bytes(content)


def _fake_tier(package: str, prefix: str) -> dict[str, bytes]:
    """A cache entry of one file that names the venv it was built in."""
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w") as tar:
        data = f"export PREFIX={prefix}/share/{package}\n".encode()
        info = tarfile.TarInfo(f"share/{package}/local_setup.sh")
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return _entry(buf.getvalue(), prefix)


def test_a_cached_build_installs_and_a_corrupt_one_is_rebuilt_not_used(tmp_path: Path) -> None:
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    python.write_text(f'#!/bin/sh\nexec "{sys.executable}" "$@"\n')
    python.chmod(0o755)
    cache = tmp_path / "cache"
    first = _run(venv, cache)
    assert first.returncode == 3, first.stderr
    # one entry per tier: what any world needs, then ros2_control's and MoveIt's
    entries = [Path(p) for p in re.findall(r"no usable cached build at (\S+)", first.stderr)]
    assert [e.name.split("-")[1] for e in entries] == ["first", "second"], first.stderr
    assert all(e.parent == cache / "interfaces" for e in entries)
    only_first = _run(venv, cache, "first")
    assert only_first.returncode == 3 and only_first.stderr.count("no usable cached build") == 1, only_first.stderr

    good = {e: _fake_tier(f"fake_{i}_msgs", "/old/venv") for i, e in enumerate(entries)}
    _write(entries[0], good[entries[0]])
    ok = _run(venv, cache, "first")  # the demo's set-up: the first tier alone
    assert ok.returncode == 0, ok.stderr
    assert "the first tier installed from the cache" in ok.stdout and "second" not in ok.stdout + ok.stderr
    assert (
        venv / "share" / "fake_0_msgs" / "local_setup.sh"
    ).read_text() == f"export PREFIX={venv}/share/fake_0_msgs\n"
    _write(entries[1], good[entries[1]])
    both = _run(venv, cache)
    assert both.returncode == 0, both.stderr
    assert "the first tier is up to date" in both.stdout and "the second tier installed from the cache" in both.stdout
    again = _run(venv, cache, "first")  # nothing to do
    assert again.returncode == 0 and "installed" not in again.stdout, again.stdout
    other = tmp_path / "other_venv"  # a second clone's demo takes the second tier too when it is cached
    (other / "bin").mkdir(parents=True)
    (other / "bin" / "python").write_bytes(python.read_bytes())
    (other / "bin" / "python").chmod(0o755)
    second_clone = _run(other, cache, "first")
    assert second_clone.returncode == 0, second_clone.stderr
    assert "the second tier installed from the cache" in second_clone.stdout, second_clone.stdout
    assert (other / ".gazelle_interfaces.second.sha256").read_text() == (
        venv / ".gazelle_interfaces.second.sha256"
    ).read_text()

    entry = entries[0]
    for broken in (
        {**good[entry], "files.tar": good[entry]["files.tar"][:700]},
        {**good[entry], "files.sha256": b"0" * 64 + b"\n"},
    ):
        (venv / ".gazelle_interfaces.first.sha256").unlink(missing_ok=True)
        _write(entry, broken)
        bad = _run(venv, cache)
        assert bad.returncode == 3, bad.stdout
        assert "incomplete or corrupt; rebuilding" in bad.stderr
        assert not entry.exists()  # not trusted again
        assert "the second tier is up to date" in bad.stdout  # the other tier is not touched


BYTECODE = REPO / "scripts" / "bytecode.sh"


def _bytecode(site: Path, cache: Path, key: str = "k1") -> subprocess.CompletedProcess:
    env = {**os.environ, "GAZELLE_CACHE_DIR": str(cache)}
    return subprocess.run(
        ["bash", str(BYTECODE), sys.executable, str(site), key], capture_output=True, text=True, env=env, timeout=120
    )


def _pyc_matches(source: Path) -> bool:
    """Whether the compiled file beside ``source`` was compiled from it as it is now (the header Python checks)."""
    import importlib.util

    pyc = Path(importlib.util.cache_from_source(str(source)))
    if not pyc.is_file():
        return False
    header = pyc.read_bytes()[:16]
    st = source.stat()
    return (
        header[:4] == importlib.util.MAGIC_NUMBER
        and int.from_bytes(header[8:12], "little") == int(st.st_mtime) & 0xFFFFFFFF
        and int.from_bytes(header[12:16], "little") == st.st_size & 0xFFFFFFFF
    )


def test_the_wheels_bytecode_is_cached_reused_and_a_corrupt_or_stale_entry_is_not_trusted(tmp_path: Path) -> None:
    """Issue 28: a second clone unpacks the wheels' bytecode instead of compiling 12,000 files; a corrupt entry
    is reported and rebuilt, and a compiled file that no longer matches its source is compiled again."""
    site = tmp_path / "site"
    (site / "pkg").mkdir(parents=True)
    mod = site / "pkg" / "mod.py"
    mod.write_text("VALUE = 1\n")
    cache = tmp_path / "cache"

    first = _bytecode(site, cache)
    assert first.returncode == 0 and first.stdout.strip() == "compiled", first.stderr
    (entry,) = (cache / "bytecode").iterdir()
    assert (entry / "files.tar").is_file() and (cache / "bytecode").stat().st_mode & 0o077 == 0
    assert _pyc_matches(mod)

    for pyc in site.rglob("*.pyc"):  # a new clone: the same sources, no bytecode yet
        pyc.unlink()
    again = _bytecode(site, cache)
    assert again.returncode == 0 and again.stdout.strip() == "cached", again.stderr
    assert _pyc_matches(mod)

    tar = (entry / "files.tar").read_bytes()
    for broken in ({"files.tar": tar[: len(tar) // 2]}, {"files.sha256": b"0" * 64 + b"\n"}):
        for name, content in broken.items():
            (entry / name).write_bytes(content)
        for pyc in site.rglob("*.pyc"):
            pyc.unlink()
        bad = _bytecode(site, cache)
        assert bad.returncode == 0 and bad.stdout.strip() == "compiled", bad.stdout
        assert "incomplete or corrupt; compiling" in bad.stderr
        assert (
            _pyc_matches(mod)
            and hashlib.sha256((entry / "files.tar").read_bytes()).hexdigest()
            == (entry / "files.sha256").read_text().strip()
        )  # rebuilt, whole

    for pyc in site.rglob("*.pyc"):
        pyc.unlink()
    was = mod.stat()
    mod.write_text("VALUE = 22\n")  # the source changed since the entry was made (uv unpacked it again),
    os.utime(mod, ns=(was.st_atime_ns, was.st_mtime_ns))  # within the same second: only its size tells
    stale = _bytecode(site, cache)
    assert stale.stdout.strip() == "cached" and _pyc_matches(mod)  # compiled again from the source as it is

    (cache / "bytecode").chmod(0o777)  # another user could have put anything there
    try:
        foreign = _bytecode(site, cache)
        assert "writable by others; not used" in foreign.stderr and foreign.stdout.strip() == "compiled"
    finally:
        (cache / "bytecode").chmod(0o700)


def test_the_installed_interface_packages_have_current_bytecode() -> None:
    """Every module of the interface packages the set-up installed (after it compiled the wheels') has
    bytecode compiled from it as it is now: where PYTHONDONTWRITEBYTECODE is set, Python never writes it,
    and every server and ``ros2`` command compiled ~180 of these modules at its start (1.2 s of CPU against
    0.3 s to import moveit_msgs, gazebo_msgs, simulation_interfaces and control_msgs)."""
    import sysconfig

    site = Path(sysconfig.get_paths()["purelib"])
    packages = [site / p.name for p in (REPO / "interfaces").iterdir() if (site / p.name).is_dir()]
    assert packages, f"no interface package is installed in {site}"
    sources = [py for package in packages for py in package.rglob("*.py")]
    stale = [str(py.relative_to(site)) for py in sources if not _pyc_matches(py)]
    assert not stale, f"{len(stale)} of {len(sources)} modules without current bytecode, e.g. {stale[:3]}"


def test_the_interface_bytecode_script_compiles_what_is_missing_or_stale(tmp_path: Path) -> None:
    """scripts/interface_bytecode.sh compiles an interface package's module that has no bytecode, and again
    once its source changed, even within the same second (a venv of its own, with a stand-in tf2_msgs);
    other packages are left alone."""
    import venv

    venv.create(tmp_path / "venv", with_pip=False)
    site = Path(
        subprocess.run(
            [
                str(tmp_path / "venv" / "bin" / "python"),
                "-c",
                "import sysconfig; print(sysconfig.get_paths()['purelib'])",
            ],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
    )
    (site / "tf2_msgs" / "msg").mkdir(parents=True)
    mod = site / "tf2_msgs" / "msg" / "_tf_message.py"
    mod.write_text("VALUE = 1\n")
    (site / "not_ours").mkdir()
    other = site / "not_ours" / "m.py"
    other.write_text("VALUE = 2\n")
    script = [str(REPO / "scripts" / "interface_bytecode.sh"), str(tmp_path / "venv")]
    subprocess.run(script, check=True, timeout=120)
    assert _pyc_matches(mod) and not _pyc_matches(other)
    mod.write_text("VALUE = 11\n")
    os.utime(mod, (1_000_000_000, 1_000_000_000))  # the source changed (a cached tier unpacked again)
    assert not _pyc_matches(mod)
    subprocess.run(script, check=True, timeout=120)
    assert _pyc_matches(mod)
    was = mod.stat()
    mod.write_text("VALUE = 111\n")  # changed again within the second it was compiled from: the size tells
    os.utime(mod, ns=(was.st_atime_ns, was.st_mtime_ns))
    subprocess.run(script, check=True, timeout=120)
    assert _pyc_matches(mod)


def test_a_compat_module_whose_folder_holds_only_restored_bytecode_is_installed(tmp_path: Path) -> None:
    """The wheels' bytecode cache restores `__pycache__` folders of an earlier venv, ours among them: a fresh clone
    then found `site-packages/nav2_common/` holding nothing but bytecode, took it for a real package and skipped
    ours, and `from nav2_common.launch import ParseMultiRobotPose` failed. Only Python files make a package real."""
    import importlib.util
    import sysconfig

    spec = importlib.util.spec_from_file_location("install_ros_packages", REPO / "scripts" / "install_ros_packages.py")
    assert spec is not None and spec.loader is not None
    installer = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(installer)
    venv = tmp_path / "venv"
    site = Path(sysconfig.get_paths(vars={"base": str(venv), "platbase": str(venv)})["purelib"])
    (site / "nav2_common" / "launch" / "__pycache__").mkdir(parents=True)
    (site / "real_pkg").mkdir()
    installer.install_python_modules(venv)
    assert (site / "nav2_common" / "launch" / "parse_multirobot_pose.py").is_file()
    assert (site / "nav2_common" / installer.MARKER).is_file()
