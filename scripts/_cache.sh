# Content-keyed caches outside the clone (~/.cache/gazelle, GAZELLE_CACHE_DIR), shared by
# scripts/build_interfaces.sh and scripts/bytecode.sh: sourced, not run.
#
# An entry is a folder ROOT/KEY holding files.tar and files.sha256 (its checksum), made in a private
# temporary folder and moved into place whole, so a reader never sees half of one. ROOT is owner-only.
# An entry another user owns, in a ROOT others can write, or that fails its checksum, is reported and
# never used (a corrupt one is removed, so it is rebuilt); the caller also checks what it unpacked.

CACHE_HOME="${GAZELLE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/gazelle}"

# cache_dir DIR: DIR created owner-only, or an existing one checked to be ours and not writable by others.
cache_dir() {
  mkdir -p -m 700 "$1" 2>/dev/null || return 1
  [[ "$(stat -c %u "$1")" == "$(id -u)" ]] || return 1
  (( (8#$(stat -c %a "$1") & 8#022) == 0 )) || return 1
}

# cache_usable WHO ROOT ENTRY WHAT_NEXT: 0 when ENTRY exists, is ours and its files.tar matches its checksum;
# otherwise 1, having said why on stderr as "WHO: ..., WHAT_NEXT" (nothing when there is no entry).
cache_usable() {
  local who="$1" root="$2" entry="$3" next="$4"
  [[ -d "$entry" ]] || return 1
  if ! cache_dir "$root" || [[ "$(stat -c %u "$entry")" != "$(id -u)" ]]; then
    echo "$who: cache $root belongs to another user or is writable by others; not used" >&2
    return 1
  fi
  if [[ -f "$entry/files.tar" && -f "$entry/files.sha256" ]] &&
      [[ "$(sha256sum "$entry/files.tar" | cut -d' ' -f1)" == "$(cat "$entry/files.sha256")" ]]; then
    return 0
  fi
  echo "$who: cached entry $entry is incomplete or corrupt; $next" >&2
  rm -rf "$entry"
  return 1
}

# cache_unpack WHO ENTRY DEST WHAT_NEXT: files.tar unpacked into DEST; an entry that does not unpack is
# reported and removed (1).
cache_unpack() {
  local who="$1" entry="$2" dest="$3" next="$4"
  if tar -xf "$entry/files.tar" -C "$dest" --no-same-owner 2>/dev/null; then return 0; fi
  echo "$who: cached entry $entry does not unpack; $next" >&2
  rm -rf "$entry"
  return 1
}

# cache_new ROOT: prints a new private temporary folder inside ROOT to fill with files.tar (and anything
# else the entry keeps); 1 when ROOT cannot be used.
cache_new() {
  cache_dir "$1" || return 1
  # a folder a killed set-up left behind
  find "$1" -mindepth 1 -maxdepth 1 -type d -name '.tmp.*' -mmin +60 -exec rm -rf {} + 2>/dev/null || true
  local tmp="$1/.tmp.$$.$RANDOM"
  rm -rf "$tmp"
  mkdir -m 700 "$tmp" && echo "$tmp"
}

# cache_commit ROOT TMP ENTRY KEEP: TMP's files.tar checksummed and TMP moved into place as ENTRY; the KEEP
# newest entries of ROOT are kept, older ones removed.
cache_commit() {
  local root="$1" tmp="$2" entry="$3" keep="$4"
  sha256sum "$tmp/files.tar" | cut -d' ' -f1 >"$tmp/files.sha256"
  rm -rf "$entry"
  mv "$tmp" "$entry"
  find "$root" -mindepth 1 -maxdepth 1 -type d ! -name '.tmp.*' -printf '%T@ %p\n' |
    sort -rn | tail -n +$((keep + 1)) | cut -d' ' -f2- | while read -r old; do rm -rf "$old"; done
}
