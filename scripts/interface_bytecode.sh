#!/usr/bin/env bash
# Compile the bytecode of the interface packages scripts/build_interfaces.sh installed into a venv:
#
#   scripts/interface_bytecode.sh VENV_DIR
#
# The set-up compiles the wheels' bytecode (scripts/bytecode.sh) before these packages are installed, and
# where PYTHONDONTWRITEBYTECODE is set (CI images, containers) Python never writes it at import: every
# process that imported them compiled their modules from source again (measured: importing moveit_msgs,
# gazebo_msgs, simulation_interfaces and control_msgs took 1.2 s of CPU so, 0.3 s compiled; a `gazelle sim`
# server imports ~180 of their modules). compileall skips what is up to date, so a run with nothing new
# takes a fraction of a second. Kept apart from build_interfaces.sh, whose text is part of its cache key.
set -euo pipefail
PY="$1/bin/python"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
site="$("$PY" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
dirs=()
for pkg in "$ROOT"/interfaces/*/; do
  pkg="$(basename "$pkg")"
  if [[ -d "$site/$pkg" ]]; then dirs+=("$site/$pkg"); fi
done
if ((${#dirs[@]})); then
  "$PY" "$ROOT/scripts/drop_stale_bytecode.py" "${dirs[@]}" >/dev/null 2>&1 || true  # see that script
  "$PY" -m compileall -q "${dirs[@]}" >/dev/null 2>&1 || true
fi
