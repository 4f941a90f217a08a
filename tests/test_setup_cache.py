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


def _run(venv: Path, cache: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "GAZELLE_CACHE_DIR": str(cache), "GAZELLE_INTERFACES_NO_BUILD": "1"}
    return subprocess.run(["bash", str(SCRIPT), str(venv)], capture_output=True, text=True, env=env, timeout=300)


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


def test_a_cached_build_installs_and_a_corrupt_one_is_rebuilt_not_used(tmp_path: Path) -> None:
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    python.write_text(f'#!/bin/sh\nexec "{sys.executable}" "$@"\n')
    python.chmod(0o755)
    cache = tmp_path / "cache"
    first = _run(venv, cache)
    assert first.returncode == 3, first.stderr
    entry = Path(re.search(r"no usable cached build at (\S+)", first.stderr).group(1))  # type: ignore[union-attr]
    assert entry.parent == cache / "interfaces"

    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w") as tar:
        data = b"export PREFIX=/old/venv/share/fake_msgs\n"
        info = tarfile.TarInfo("share/fake_msgs/local_setup.sh")
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    good = _entry(buf.getvalue(), "/old/venv")
    _write(entry, good)
    ok = _run(venv, cache)
    assert ok.returncode == 0, ok.stderr
    assert "installed from the cache" in ok.stdout
    assert (venv / "share" / "fake_msgs" / "local_setup.sh").read_text() == f"export PREFIX={venv}/share/fake_msgs\n"

    for broken in ({**good, "files.tar": good["files.tar"][:700]}, {**good, "files.sha256": b"0" * 64 + b"\n"}):
        (venv / ".gazelle_interfaces.sha256").unlink(missing_ok=True)
        _write(entry, broken)
        bad = _run(venv, cache)
        assert bad.returncode == 3, bad.stdout
        assert "incomplete or corrupt; rebuilding" in bad.stderr
        assert not entry.exists()  # not trusted again
