#!/usr/bin/env bash
# Build gazelle's own ROS 2 interface packages (interfaces/: tf2_msgs,
# simulation_interfaces, gazebo_msgs, control_msgs, controller_manager_msgs, ros_gz_interfaces,
# octomap_msgs, object_recognition_msgs, moveit_msgs) with the ROS 2 Jazzy rosidl/ament CMake
# tooling from the PyPI wheels, and install them into a Python virtualenv.
#
#   scripts/build_interfaces.sh VENV_DIR
#
# A build is cached by content outside the clone (~/.cache/gazelle/interfaces, GAZELLE_CACHE_DIR): see
# restore_from_cache below. Idempotent: a hash over everything under interfaces/, this script and the
# versions of the wheel packages the build depends on is kept in
# VENV_DIR/.gazelle_interfaces.sha256. When it matches and the packages import,
# nothing is rebuilt. Build trees live in <repo>/build/interfaces/<pkg>;
# cmake/make output goes to <build dir>/build.log.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 VENV_DIR" >&2
  exit 2
fi
if [[ ! -x "$1/bin/python" ]]; then
  echo "build_interfaces: $1 is not a virtualenv (no bin/python)" >&2
  exit 2
fi

VENV_DIR="$(cd "$1" && pwd)"
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SCRIPT_REL="scripts/$(basename "${BASH_SOURCE[0]}")"
PY="$VENV_DIR/bin/python"
STAMP="$VENV_DIR/.gazelle_interfaces.sha256"
BUILD_ROOT="$REPO_ROOT/build/interfaces"
# Build order: each depends on wheel packages and on packages built before it (installed into the
# venv, which is the prefix cmake searches): moveit_msgs needs octomap_msgs and object_recognition_msgs.
# moveit_msgs' two go first, so that the largest package builds beside the others, not after them.
PKGS=(octomap_msgs object_recognition_msgs tf2_msgs simulation_interfaces gazebo_msgs control_msgs
  controller_manager_msgs ros_gz_interfaces moveit_msgs)
# Wheel packages whose version change must trigger a rebuild.
DEP_PKGS=(ament_cmake rosidl_default_generators rosidl_generator_py
  rosidl_typesupport_fastrtps_c builtin_interfaces std_msgs geometry_msgs
  action_msgs service_msgs unique_identifier_msgs trajectory_msgs sensor_msgs lifecycle_msgs shape_msgs)

for tool in cmake g++ sha256sum; do
  command -v "$tool" >/dev/null || { echo "build_interfaces: '$tool' not found" >&2; exit 1; }
done

compute_hash() {
  {
    (cd "$REPO_ROOT" &&
      find interfaces -type f ! -name '*.pyc' ! -path '*/__pycache__/*' -print0 |
      LC_ALL=C sort -z | xargs -0 sha256sum &&
      sha256sum "$SCRIPT_REL")
    "$PY" -c 'import sys; print("python", sys.version.split()[0])'
    local d xml
    for d in "${DEP_PKGS[@]}"; do
      xml="$VENV_DIR/share/$d/package.xml"
      if [[ -f "$xml" ]]; then
        echo "$d $(sed -n 's:.*<version>\(.*\)</version>.*:\1:p' "$xml" | head -n1)"
      else
        echo "$d absent"
      fi
    done
  } | sha256sum | cut -d' ' -f1
}

# Import every package and load its C type support (msg, srv and action).
imports_ok() {
  "$PY" - <<'EOF' >/dev/null 2>&1
from tf2_msgs.msg import TFMessage
from tf2_msgs.action import LookupTransform
from simulation_interfaces.msg import Result
from simulation_interfaces.srv import SpawnEntity
from simulation_interfaces.action import SimulateSteps
from gazebo_msgs.msg import ModelStates
from gazebo_msgs.srv import SpawnEntity as GzSpawnEntity
from control_msgs.action import FollowJointTrajectory
from control_msgs.msg import DynamicJointState
from controller_manager_msgs.srv import SwitchController
from ros_gz_interfaces.msg import Altimeter
from octomap_msgs.srv import GetOctomap
from object_recognition_msgs.action import ObjectRecognition
from moveit_msgs.action import MoveGroup
from moveit_msgs.srv import GetPositionIK
for t in (TFMessage, LookupTransform, Result, SpawnEntity, SimulateSteps,
          ModelStates, GzSpawnEntity, FollowJointTrajectory, DynamicJointState,
          SwitchController, Altimeter, GetOctomap, ObjectRecognition, MoveGroup, GetPositionIK):
    type(t).__import_type_support__()
EOF
}

HASH="$(compute_hash)"

# The built packages are cached by content outside the clone, so a second clone or a new venv on the
# same machine installs them in seconds: CACHE/<hash>/files.tar holds every file their `make install`
# wrote (CMake's install_manifest.txt), relative to the venv; files.sha256 its checksum; prefix the venv
# it was built in (two kinds of text file name it: rewritten to this venv on the way in). The folder is
# owner-only; an entry that another user owns, that fails its checksum, or whose packages then do not
# import, is reported and rebuilt, never trusted.
CACHE_ROOT="${GAZELLE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/gazelle}/interfaces"
ENTRY="$CACHE_ROOT/$HASH-$(uname -m)"

private_dir() {  # create $1 owner-only, or check that an existing one is ours and not writable by others
  mkdir -p -m 700 "$1" 2>/dev/null || return 1
  [[ "$(stat -c %u "$1")" == "$(id -u)" ]] || return 1
  (( (8#$(stat -c %a "$1") & 8#022) == 0 )) || return 1
}

restore_from_cache() {
  [[ -d "$ENTRY" ]] || return 1
  local start=$SECONDS
  if ! private_dir "$CACHE_ROOT" || [[ "$(stat -c %u "$ENTRY")" != "$(id -u)" ]]; then
    echo "build_interfaces: cache $CACHE_ROOT belongs to another user or is writable by others; not used" >&2
    return 1
  fi
  if ! [[ -f "$ENTRY/files.tar" && -f "$ENTRY/files.sha256" && -f "$ENTRY/prefix" ]] ||
      [[ "$(sha256sum "$ENTRY/files.tar" | cut -d' ' -f1)" != "$(cat "$ENTRY/files.sha256")" ]]; then
    echo "build_interfaces: cached build $ENTRY is incomplete or corrupt; rebuilding" >&2
    rm -rf "$ENTRY"
    return 1
  fi
  local old_prefix
  old_prefix="$(cat "$ENTRY/prefix")"
  if ! tar -xf "$ENTRY/files.tar" -C "$VENV_DIR" --no-same-owner 2>/dev/null; then
    echo "build_interfaces: cached build $ENTRY does not unpack; rebuilding" >&2
    rm -rf "$ENTRY"
    return 1
  fi
  if [[ "$old_prefix" != "$VENV_DIR" ]]; then
    tar -tf "$ENTRY/files.tar" | grep -E '(local_setup\.[a-z]+|Export\.cmake|\.dsv|\.sh)$' |
      while read -r f; do
        [[ -f "$VENV_DIR/$f" ]] && sed -i "s|$old_prefix|$VENV_DIR|g" "$VENV_DIR/$f"
      done
  fi
  if ! imports_ok; then
    echo "build_interfaces: cached build $ENTRY does not import here; rebuilding" >&2
    rm -rf "$ENTRY"
    return 1
  fi
  echo "interfaces installed from the cache ($ENTRY) in $((SECONDS - start))s"
}

save_to_cache() {
  private_dir "$CACHE_ROOT" || { echo "build_interfaces: cannot use the cache $CACHE_ROOT; not saved" >&2; return 0; }
  local tmp="$CACHE_ROOT/.tmp.$$"
  rm -rf "$tmp"
  mkdir -m 700 "$tmp"
  local pkg
  for pkg in "${PKGS[@]}"; do  # CMake writes the manifest without a final newline
    { cat "$BUILD_ROOT/$pkg/install_manifest.txt"; echo; } | sed -n "s|^$VENV_DIR/||p"
  done | LC_ALL=C sort -u >"$tmp/files.list"
  if tar -cf "$tmp/files.tar" -C "$VENV_DIR" -T "$tmp/files.list" 2>/dev/null; then
    sha256sum "$tmp/files.tar" | cut -d' ' -f1 >"$tmp/files.sha256"
    echo "$VENV_DIR" >"$tmp/prefix"
    rm -f "$tmp/files.list"
    rm -rf "$ENTRY"
    mv "$tmp" "$ENTRY" && echo "cached the interface build in $ENTRY"
    # keep the three newest builds (each ~100 MB)
    find "$CACHE_ROOT" -mindepth 1 -maxdepth 1 -type d ! -name '.tmp.*' -printf '%T@ %p\n' |
      sort -rn | tail -n +4 | cut -d' ' -f2- | while read -r old; do rm -rf "$old"; done
  else
    rm -rf "$tmp"
    echo "build_interfaces: could not cache the build" >&2
  fi
}

if [[ -f "$STAMP" && "$(cat "$STAMP")" == "$HASH" ]] && imports_ok; then
  echo "interfaces up to date"
  # built here before the cache existed: keep it for the next clone
  if [[ ! -d "$ENTRY" && -f "$BUILD_ROOT/moveit_msgs/install_manifest.txt" ]]; then save_to_cache; fi
  exit 0
fi

if restore_from_cache; then
  echo "$HASH" >"$STAMP"
  exit 0
fi
if [[ -n "${GAZELLE_INTERFACES_NO_BUILD:-}" ]]; then  # the cache's own test: never build
  echo "build_interfaces: no usable cached build at $ENTRY" >&2
  exit 3
fi

# Build only against the venv, never against a sourced ROS installation.
export PATH="$VENV_DIR/bin:$PATH"
export AMENT_PREFIX_PATH="$VENV_DIR"
export CMAKE_PREFIX_PATH="$VENV_DIR"
unset COLCON_PREFIX_PATH PYTHONPATH || true

rm -f "$STAMP"
mkdir -p "$BUILD_ROOT"

# Ninja (the pinned wheel in the venv) when there is one, else make. These are message structs and
# their (de)serialisers, not hot code: -O1 instead of Release's -O3 (measured on 2 cores, gazebo_msgs:
# 45 s against 52 s, C++ generators already left out by interfaces/cmake/python_generators.cmake).
if command -v ninja >/dev/null; then GENERATOR=(-G Ninja); BUILD_TOOL=ninja; else GENERATOR=(); BUILD_TOOL=make; fi
JOBS="${GAZELLE_BUILD_JOBS:-$(nproc)}"

build_pkg() {
  local pkg="$1" bdir="$BUILD_ROOT/$1" log="$BUILD_ROOT/$1/build.log"
  local start=$SECONDS
  # A build tree configured for another prefix, flags or build tool cannot be reused.
  if [[ -f "$bdir/CMakeCache.txt" ]] &&
      ! { grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$VENV_DIR" "$bdir/CMakeCache.txt" &&
          grep -qxF "CMAKE_C_FLAGS:STRING=-O1" "$bdir/CMakeCache.txt" &&
          grep -q "^CMAKE_MAKE_PROGRAM:FILEPATH=.*/$BUILD_TOOL\$" "$bdir/CMakeCache.txt"; }; then
    rm -rf "$bdir"
  fi
  mkdir -p "$bdir"
  : >"$log"
  if ! {
    cmake "${GENERATOR[@]}" -S "$REPO_ROOT/interfaces/$pkg" -B "$bdir" \
      -DCMAKE_BUILD_TYPE=None -DCMAKE_C_FLAGS=-O1 -DCMAKE_CXX_FLAGS=-O1 \
      -DCMAKE_INSTALL_PREFIX="$VENV_DIR" \
      -DPython3_EXECUTABLE="$PY" \
      -DBUILD_TESTING=OFF &&
    cmake --build "$bdir" --target install -- -j"$JOBS"
  } >>"$log" 2>&1; then
    echo "build_interfaces: building $pkg failed; last lines of $log:"
    tail -n 60 "$log"
    return 1
  fi
  echo "built $pkg in $((SECONDS - start))s"
}

# Two packages at a time (a package's code generators are single-threaded Python, so a second build
# fills the cores they leave idle); moveit_msgs starts once the two it depends on are installed.
declare -A PID_OF=() DONE=()
LAST="moveit_msgs"
QUEUE=()
for pkg in "${PKGS[@]}"; do [[ "$pkg" == "$LAST" ]] || QUEUE+=("$pkg"); done
running=0
build_started=$SECONDS
while ((${#QUEUE[@]} || running)) || [[ -z "${DONE[$LAST]:-}${PID_OF[$LAST]:-}" ]]; do
  if [[ -z "${PID_OF[$LAST]:-}" && -n "${DONE[octomap_msgs]:-}" && -n "${DONE[object_recognition_msgs]:-}" ]]; then
    next="$LAST"
  elif ((${#QUEUE[@]})) && ((running < 2)); then
    next="${QUEUE[0]}"; QUEUE=("${QUEUE[@]:1}")
  else
    next=""
  fi
  if [[ -n "$next" ]]; then
    mkdir -p "$BUILD_ROOT/$next"
    build_pkg "$next" >"$BUILD_ROOT/$next.out" 2>&1 &
    PID_OF[$next]=$!
    running=$((running + 1))
    continue
  fi
  finished=""
  if wait -n -p finished; then rc=0; else rc=$?; fi
  running=$((running - 1))
  for pkg in "${!PID_OF[@]}"; do
    if [[ "${PID_OF[$pkg]}" == "$finished" ]]; then
      cat "$BUILD_ROOT/$pkg.out"
      if ((rc)); then
        for other in "${PID_OF[@]}"; do kill "$other" 2>/dev/null || true; done
        wait || true
        exit 1
      fi
      DONE[$pkg]=1
    fi
  done
done
echo "built ${#PKGS[@]} interface packages in $((SECONDS - build_started))s"

if ! imports_ok; then
  echo "build_interfaces: packages built but do not import with $PY" >&2
  exit 1
fi
echo "$HASH" >"$STAMP"
save_to_cache
