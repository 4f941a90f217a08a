#!/usr/bin/env bash
# Build gazelle's own ROS 2 interface packages (interfaces/) with the ROS 2 Jazzy rosidl/ament CMake
# tooling from the PyPI wheels, and install them into a Python virtualenv.
#
#   scripts/build_interfaces.sh VENV_DIR [first|all]
#
# Two tiers. The first is what any world needs: tf2_msgs, simulation_interfaces, gazebo_msgs and
# ros_gz_interfaces. The second is ros2_control's and MoveIt's: control_msgs, controller_manager_msgs,
# octomap_msgs, object_recognition_msgs and moveit_msgs (gazelle imports them only when a robot needs
# them: gazelle/ros/_convert.py ARM_PACKAGES). `first` builds the first tier only, and takes the second
# from the cache when it is there (./demo.sh starts the demo after it and builds the second after the demo);
# `all` (the default) both, scheduled together.
#
# Each tier is cached by content outside the clone (~/.cache/gazelle/interfaces, scripts/_cache.sh; see
# restore_tier below) under a hash over everything under interfaces/, this script, Python's version and the
# versions of the wheel packages the build depends on; VENV_DIR/.gazelle_interfaces.<tier>.sha256 holds the
# hash a tier was installed with. When it matches and the tier's packages import, nothing is done.
# Build trees live in <repo>/build/interfaces/<pkg>; cmake/ninja output goes to <build dir>/build.log.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 || ! "${2:-all}" =~ ^(first|all)$ ]]; then
  echo "usage: $0 VENV_DIR [first|all]" >&2
  exit 2
fi
if [[ ! -x "$1/bin/python" ]]; then
  echo "build_interfaces: $1 is not a virtualenv (no bin/python)" >&2
  exit 2
fi

VENV_DIR="$(cd "$1" && pwd)"
WANT="${2:-all}"
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SCRIPT_REL="scripts/$(basename "${BASH_SOURCE[0]}")"
# shellcheck source=scripts/_cache.sh
source "$REPO_ROOT/scripts/_cache.sh"
PY="$VENV_DIR/bin/python"
BUILD_ROOT="$REPO_ROOT/build/interfaces"
# Each package depends on wheel packages and on packages built before it (installed into the venv, which is
# the prefix cmake searches): moveit_msgs needs octomap_msgs and object_recognition_msgs.
declare -A TIER_PKGS=(
  [first]="tf2_msgs simulation_interfaces gazebo_msgs ros_gz_interfaces"
  [second]="octomap_msgs object_recognition_msgs control_msgs controller_manager_msgs moveit_msgs"
)
# What proves a tier installed: these import and load their C type support (a msg, srv and action of each
# package where it has them).
declare -A TIER_PROBES=(
  [first]="tf2_msgs.msg.TFMessage tf2_msgs.action.LookupTransform simulation_interfaces.msg.Result
    simulation_interfaces.srv.SpawnEntity simulation_interfaces.action.SimulateSteps gazebo_msgs.msg.ModelStates
    gazebo_msgs.srv.SpawnEntity ros_gz_interfaces.msg.Altimeter ros_gz_interfaces.msg.Contacts"
  [second]="control_msgs.action.FollowJointTrajectory control_msgs.msg.DynamicJointState
    controller_manager_msgs.srv.SwitchController octomap_msgs.srv.GetOctomap
    object_recognition_msgs.action.ObjectRecognition moveit_msgs.action.MoveGroup moveit_msgs.srv.GetPositionIK"
)
if [[ "$WANT" == first ]]; then TIERS=(first); else TIERS=(first second); fi
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
      sha256sum "$SCRIPT_REL" scripts/_cache.sh)
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

imports_ok() {  # imports_ok TIER
  # shellcheck disable=SC2086  # the probes are words
  "$PY" -c '
import importlib, sys
for name in sys.argv[1:]:
    module, _, cls = name.rpartition(".")
    type(getattr(importlib.import_module(module), cls)).__import_type_support__()
' ${TIER_PROBES[$1]} >/dev/null 2>&1
}

HASH="$(compute_hash)"

# Each tier's built packages are cached by content outside the clone, so a second clone or a new venv on the
# same machine installs them in seconds: CACHE/<hash>-<tier>-<machine>/files.tar holds every file the tier's
# `cmake --install` wrote (CMake's install_manifest.txt), relative to the venv; files.sha256 its checksum;
# prefix the venv it was built in (two kinds of text file name it: rewritten to this venv on the way in). An
# entry that is not ours, fails its checksum or does not unpack (scripts/_cache.sh), or whose packages then
# do not import, is reported and rebuilt, never trusted.
CACHE_ROOT="$CACHE_HOME/interfaces"
entry_of() { echo "$CACHE_ROOT/$HASH-$1-$(uname -m)"; }
stamp_of() { echo "$VENV_DIR/.gazelle_interfaces.$1.sha256"; }

restore_tier() {  # restore_tier TIER
  local tier="$1" entry start=$SECONDS old_prefix
  entry="$(entry_of "$tier")"
  cache_usable build_interfaces "$CACHE_ROOT" "$entry" rebuilding || return 1
  if [[ ! -f "$entry/prefix" ]]; then
    echo "build_interfaces: cached entry $entry is incomplete or corrupt; rebuilding" >&2
    rm -rf "$entry"
    return 1
  fi
  old_prefix="$(cat "$entry/prefix")"
  cache_unpack build_interfaces "$entry" "$VENV_DIR" rebuilding || return 1
  if [[ "$old_prefix" != "$VENV_DIR" ]]; then
    tar -tf "$entry/files.tar" | grep -E '(local_setup\.[a-z]+|Export\.cmake|\.dsv|\.sh)$' |
      while read -r f; do
        [[ -f "$VENV_DIR/$f" ]] && sed -i "s|$old_prefix|$VENV_DIR|g" "$VENV_DIR/$f"
      done
  fi
  if ! imports_ok "$tier"; then
    echo "build_interfaces: cached entry $entry does not import here; rebuilding" >&2
    rm -rf "$entry"
    return 1
  fi
  echo "interfaces: the $tier tier installed from the cache ($entry) in $((SECONDS - start))s"
}

save_tier() {  # save_tier TIER
  local tier="$1" tmp pkg
  tmp="$(cache_new "$CACHE_ROOT")" || { echo "build_interfaces: cannot use the cache $CACHE_ROOT; not saved" >&2; return 0; }
  for pkg in ${TIER_PKGS[$tier]}; do  # CMake writes the manifest without a final newline
    { cat "$BUILD_ROOT/$pkg/install_manifest.txt"; echo; } | sed -n "s|^$VENV_DIR/||p"
  done | LC_ALL=C sort -u >"$tmp/files.list"
  if tar -cf "$tmp/files.tar" -C "$VENV_DIR" -T "$tmp/files.list" 2>/dev/null; then
    echo "$VENV_DIR" >"$tmp/prefix"
    rm -f "$tmp/files.list"
    cache_commit "$CACHE_ROOT" "$tmp" "$(entry_of "$tier")" 6  # three builds of each tier (~50 MB each)
    echo "interfaces: cached the $tier tier in $(entry_of "$tier")"
  else
    rm -rf "$tmp"
    echo "build_interfaces: could not cache the $tier tier" >&2
  fi
}

BUILD_TIERS=()
for tier in "${TIERS[@]}"; do
  stamp="$(stamp_of "$tier")"
  if [[ -f "$stamp" && "$(cat "$stamp")" == "$HASH" ]] && imports_ok "$tier"; then
    echo "interfaces: the $tier tier is up to date"
  elif restore_tier "$tier"; then
    echo "$HASH" >"$stamp"
  else
    BUILD_TIERS+=("$tier")
  fi
done
# `first` takes the second tier too when the cache has it (seconds), never building it
if [[ "$WANT" == first && ! ( -f "$(stamp_of second)" && "$(cat "$(stamp_of second)")" == "$HASH" ) ]] &&
    [[ -d "$(entry_of second)" ]] && restore_tier second; then
  echo "$HASH" >"$(stamp_of second)"
fi
((${#BUILD_TIERS[@]})) || exit 0
if [[ -n "${GAZELLE_INTERFACES_NO_BUILD:-}" ]]; then  # the cache's own test: never build
  for tier in "${BUILD_TIERS[@]}"; do echo "build_interfaces: no usable cached build at $(entry_of "$tier")" >&2; done
  exit 3
fi

# Build only against the venv, never against a sourced ROS installation.
export PATH="$VENV_DIR/bin:$PATH"
export AMENT_PREFIX_PATH="$VENV_DIR"
export CMAKE_PREFIX_PATH="$VENV_DIR"
unset COLCON_PREFIX_PATH PYTHONPATH || true

PKGS=()
for tier in "${BUILD_TIERS[@]}"; do
  rm -f "$(stamp_of "$tier")"
  # shellcheck disable=SC2206  # package names are words
  PKGS+=(${TIER_PKGS[$tier]})
done
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

# Two packages at a time (a package's code generators are single-threaded Python, so a second build fills
# the cores they leave idle). moveit_msgs, the largest, starts once the two it depends on are installed;
# they go first, so that it builds beside the others, not after them.
declare -A PID_OF=() DONE=()
LAST="moveit_msgs"
QUEUE=()
for pkg in octomap_msgs object_recognition_msgs "${PKGS[@]}"; do
  if [[ "$pkg" != "$LAST" && " ${PKGS[*]} " == *" $pkg "* && " ${QUEUE[*]} " != *" $pkg "* ]]; then
    QUEUE+=("$pkg")
  fi
done
[[ " ${PKGS[*]} " == *" $LAST "* ]] || DONE[$LAST]=1  # not asked for
running=0
build_started=$SECONDS
while ((${#QUEUE[@]} || running)) || [[ -z "${DONE[$LAST]:-}${PID_OF[$LAST]:-}" ]]; do
  if [[ -z "${PID_OF[$LAST]:-}${DONE[$LAST]:-}" && -n "${DONE[octomap_msgs]:-}" && -n "${DONE[object_recognition_msgs]:-}" ]]; then
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
echo "built ${#PKGS[@]} interface packages (tiers: ${BUILD_TIERS[*]}) in $((SECONDS - build_started))s"

for tier in "${BUILD_TIERS[@]}"; do
  if ! imports_ok "$tier"; then
    echo "build_interfaces: the $tier tier's packages built but do not import with $PY" >&2
    exit 1
  fi
  echo "$HASH" >"$(stamp_of "$tier")"
  save_tier "$tier"
done
