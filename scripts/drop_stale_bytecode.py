"""Remove the compiled files (``__pycache__/*.pyc`` of this Python) that no longer match their source.

    python scripts/drop_stale_bytecode.py DIR...

Python's import takes a timestamp-based .pyc as current when the source's mtime (whole seconds) *and size*
match the ones in its header; ``compileall`` compares the mtime alone. A source rewritten within the second
its bytecode was compiled from (a cached entry unpacked, then the file changed in the same second; a test
that edits a file quickly) therefore stays stale to compileall, and every import compiles it again in memory
(and, under PYTHONDONTWRITEBYTECODE, never saves it). Run before ``compileall`` so that it compiles these
again. Hash-based .pyc files (PEP 552) are left to compileall. Prints how many were removed.
"""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

FLAGS_TIMESTAMP = 0
"""PEP 552: a .pyc header's flags word; 0 means it is checked by the source's mtime and size."""


def stale(source: Path, pyc: Path) -> bool:
    """Whether ``pyc`` is a timestamp-based compile of this Python that does not match ``source`` now."""
    try:
        header = pyc.read_bytes()[:16]
        st = source.stat()
    except OSError:
        return False
    if len(header) < 16 or header[:4] != importlib.util.MAGIC_NUMBER:
        return False  # another Python's, or not a .pyc: compileall's business
    if int.from_bytes(header[4:8], "little") != FLAGS_TIMESTAMP:
        return False
    mtime = int.from_bytes(header[8:12], "little")
    size = int.from_bytes(header[12:16], "little")
    return mtime != int(st.st_mtime) & 0xFFFFFFFF or size != st.st_size & 0xFFFFFFFF


def drop(roots: list[str]) -> int:
    """Remove the stale compiled files below ``roots``; returns how many."""
    tag = sys.implementation.cache_tag
    removed = 0
    for root in roots:
        for folder, _dirs, files in os.walk(root):
            if os.path.basename(folder) != "__pycache__":
                continue
            for name in files:
                parts = name.split(".")
                # mod.cpython-311.pyc and mod.cpython-311.opt-1.pyc both come from ../mod.py
                if len(parts) < 3 or parts[-1] != "pyc" or parts[1] != tag:
                    continue
                pyc = Path(folder, name)
                if stale(pyc.parent.parent / f"{parts[0]}.py", pyc):
                    pyc.unlink(missing_ok=True)
                    removed += 1
    return removed


if __name__ == "__main__":
    print(drop(sys.argv[1:]))
