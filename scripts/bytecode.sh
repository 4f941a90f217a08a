#!/usr/bin/env bash
# Compile the bytecode of a site-packages folder, through a cache kept by content outside the clone.
#
#   scripts/bytecode.sh PYTHON SITE_DIR KEY
#
# uv links every clone's wheels to the same files, so their bytecode is the same, and Python relocates it
# (it rewrites co_filename on import): the compiled files of a wheel set (KEY: scripts/setup.sh's hash of
# requirements.txt and pyproject.toml) are kept in ~/.cache/gazelle/bytecode (scripts/_cache.sh), one entry
# per KEY, Python and machine, the three newest kept, and a second clone unpacks them in seconds instead of
# compiling 12,000 files (34-54 s on a 2-core machine). An entry that is not ours, fails its checksum or does
# not unpack is reported and rebuilt, never used. compileall runs after an unpacked entry anyway and
# recompiles whatever does not match its source (a file uv unpacked again since; drop_stale_bytecode.py
# first removes what compileall's mtime-only check would keep), so nothing stale is imported.
# Prints "cached" when the entry was used, "compiled" otherwise.
set -euo pipefail
if [[ $# -ne 3 ]]; then
  echo "usage: $0 PYTHON SITE_DIR KEY" >&2
  exit 2
fi
# shellcheck source=scripts/_cache.sh
source "$(dirname "${BASH_SOURCE[0]}")/_cache.sh"
PY="$1"
SITE="$(cd "$2" && pwd)"
KEY="$3"
TAG="$("$PY" -c 'import sys; print(sys.implementation.cache_tag)')"
ROOT="$CACHE_HOME/bytecode"
ENTRY="$ROOT/$KEY-$TAG-$(uname -m)"

if cache_usable bytecode "$ROOT" "$ENTRY" compiling && cache_unpack bytecode "$ENTRY" "$SITE" compiling; then
  # compileall checks a compiled file's source mtime alone (import: mtime and size): drop the ones whose
  # source changed since, even within the same second, so that it compiles them again
  "$PY" "$(dirname "${BASH_SOURCE[0]}")/drop_stale_bytecode.py" "$SITE" >/dev/null 2>&1 || true
  # one process: compileall's -j pool spends 17 s on 12,000 files that are up to date, one process 2 s
  "$PY" -m compileall -q "$SITE" >/dev/null 2>&1 || true
  echo "cached"
  exit 0
fi
"$PY" -m compileall -q -j 0 "$SITE" >/dev/null 2>&1 || true
echo "compiled"
tmp="$(cache_new "$ROOT")" || { echo "bytecode: cannot use the cache $ROOT; not saved" >&2; exit 0; }
if (cd "$SITE" && find . -path '*/__pycache__/*.pyc' -print0 | tar --null -cf "$tmp/files.tar" -T -) 2>/dev/null; then
  cache_commit "$ROOT" "$tmp" "$ENTRY" 3
else
  rm -rf "$tmp"
  echo "bytecode: could not cache the bytecode" >&2
fi
