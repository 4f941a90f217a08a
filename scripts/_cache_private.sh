# Sourced after scripts/_cache.sh by scripts/build_cpp.sh (the C++ tier's cache): its cache_dir replaced by
# the check docs/security.md gives gazelle's caches. A file of its own because scripts/_cache.sh is part of the
# interface tiers' cache key (scripts/build_interfaces.sh): changing it would rebuild them cold on every machine
# once; they can take this check the next time their key changes anyway.
#
# cache_dir DIR: DIR (and each missing folder above it) created owner-only, then checked, at every use, as
# gazelle's Python caches are (gazelle/_files.py, docs/security.md): DIR's real path is ours with no group or
# other write, and every folder above it is ours or root's with no group or other write unless sticky (/tmp).
# 1 otherwise, with CACHE_WHY saying why.
cache_dir() {
  local dir="$1" missing=() d uid mode me
  me="$(id -u)"
  CACHE_WHY=""
  d="$dir"
  while [[ ! -e "$d" ]]; do missing=("$d" "${missing[@]}"); d="$(dirname "$d")"; done
  for d in "${missing[@]}"; do mkdir -m 700 "$d" 2>/dev/null || [[ -d "$d" ]] || { CACHE_WHY="cannot create $d"; return 1; }; done
  d="$(cd "$dir" 2>/dev/null && pwd -P)" || { CACHE_WHY="$dir is not a folder"; return 1; }
  read -r uid mode < <(stat -c '%u %a' "$d")
  [[ "$uid" == "$me" ]] || { CACHE_WHY="$d belongs to another user (uid $uid)"; return 1; }
  (( (8#$mode & 8#022) == 0 )) || { CACHE_WHY="others may write to $d (mode $mode)"; return 1; }
  while [[ "$d" != / ]]; do
    d="$(dirname "$d")"
    read -r uid mode < <(stat -c '%u %a' "$d")
    [[ "$uid" == "$me" || "$uid" == 0 ]] || { CACHE_WHY="$d above it belongs to another user (uid $uid)"; return 1; }
    if (( (8#$mode & 8#022) != 0 && (8#$mode & 8#1000) == 0 )); then
      CACHE_WHY="others may write to $d above it (mode $mode)"
      return 1
    fi
  done
}
