#!/usr/bin/env bash
# Compile the bytecode of a site-packages folder, through a cache kept by content outside the clone.
#
#   scripts/bytecode.sh PYTHON SITE_DIR KEY
#
# uv links every clone's wheels to the same files, so their bytecode is the same, and Python relocates it
# (it rewrites co_filename on import): the compiled files of a wheel set (KEY: scripts/setup.sh's hash of
# requirements.txt and pyproject.toml) are kept in ~/.cache/gazelle/bytecode (GAZELLE_CACHE_DIR), one entry
# per KEY, Python and machine, the three newest kept, and a second clone unpacks them in seconds instead of
# compiling 12,000 files (34-54 s on a 2-core machine). The folder is owner-only and each entry checksummed:
# one another user owns, or that fails its checksum or does not unpack, is reported and rebuilt, never used.
# compileall runs after an unpacked entry anyway and recompiles whatever does not match its source (a file
# uv unpacked again since), so nothing stale is imported.
# Prints "cached" when the entry was used, "compiled" otherwise.
set -euo pipefail
if [[ $# -ne 3 ]]; then
  echo "usage: $0 PYTHON SITE_DIR KEY" >&2
  exit 2
fi
PY="$1"
SITE="$(cd "$2" && pwd)"
KEY="$3"
TAG="$("$PY" -c 'import sys; print(sys.implementation.cache_tag)')"
ROOT="${GAZELLE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/gazelle}/bytecode"
ENTRY="$ROOT/$KEY-$TAG-$(uname -m)"

private_dir() {  # $1 owner-only: created so, or an existing one ours and not writable by others
  mkdir -p -m 700 "$1" 2>/dev/null || return 1
  [[ "$(stat -c %u "$1")" == "$(id -u)" ]] || return 1
  (( (8#$(stat -c %a "$1") & 8#022) == 0 )) || return 1
}

restored=""
if [[ -d "$ENTRY" ]]; then
  if ! private_dir "$ROOT" || [[ "$(stat -c %u "$ENTRY")" != "$(id -u)" ]]; then
    echo "bytecode: cache $ROOT belongs to another user or is writable by others; not used" >&2
  elif [[ -f "$ENTRY/pyc.tar" && -f "$ENTRY/pyc.sha256" ]] &&
      [[ "$(sha256sum "$ENTRY/pyc.tar" | cut -d' ' -f1)" == "$(cat "$ENTRY/pyc.sha256")" ]] &&
      tar -xf "$ENTRY/pyc.tar" -C "$SITE" --no-same-owner 2>/dev/null; then
    restored=1
  else
    echo "bytecode: cached bytecode $ENTRY is incomplete or corrupt; compiling" >&2
    rm -rf "$ENTRY"
  fi
fi
if [[ -n "$restored" ]]; then
  # one process: compileall's -j pool spends 17 s on 12,000 files that are up to date, one process 2 s
  "$PY" -m compileall -q "$SITE" >/dev/null 2>&1 || true
  echo "cached"
  exit 0
fi
"$PY" -m compileall -q -j 0 "$SITE" >/dev/null 2>&1 || true
echo "compiled"
private_dir "$ROOT" || { echo "bytecode: cannot use the cache $ROOT; not saved" >&2; exit 0; }
tmp="$ROOT/.tmp.$$"
rm -rf "$tmp"
mkdir -m 700 "$tmp"
if (cd "$SITE" && find . -path '*/__pycache__/*.pyc' -print0 | tar --null -cf "$tmp/pyc.tar" -T -) 2>/dev/null; then
  sha256sum "$tmp/pyc.tar" | cut -d' ' -f1 >"$tmp/pyc.sha256"
  rm -rf "$ENTRY"
  mv "$tmp" "$ENTRY"
  find "$ROOT" -mindepth 1 -maxdepth 1 -type d ! -name '.tmp.*' -printf '%T@ %p\n' |
    sort -rn | tail -n +4 | cut -d' ' -f2- | while read -r old; do rm -rf "$old"; done
else
  rm -rf "$tmp"
  echo "bytecode: could not cache the bytecode" >&2
fi
