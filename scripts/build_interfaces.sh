#!/usr/bin/env bash
# Build gazelle's own ROS 2 interface packages (interfaces/: tf2_msgs,
# simulation_interfaces, gazebo_msgs, control_msgs, controller_manager_msgs, ros_gz_interfaces,
# octomap_msgs, object_recognition_msgs, moveit_msgs) with the ROS 2 Jazzy rosidl/ament CMake
# tooling from the PyPI wheels, and install them into a Python virtualenv.
#
#   scripts/build_interfaces.sh VENV_DIR
#
# Idempotent: a hash over everything under interfaces/, this script and the
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
PKGS=(tf2_msgs simulation_interfaces gazebo_msgs control_msgs controller_manager_msgs ros_gz_interfaces
  octomap_msgs object_recognition_msgs moveit_msgs)
# Wheel packages whose version change must trigger a rebuild.
DEP_PKGS=(ament_cmake rosidl_default_generators rosidl_generator_py
  rosidl_typesupport_fastrtps_c builtin_interfaces std_msgs geometry_msgs
  action_msgs service_msgs unique_identifier_msgs trajectory_msgs sensor_msgs lifecycle_msgs shape_msgs)

for tool in cmake make g++ sha256sum; do
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
if [[ -f "$STAMP" && "$(cat "$STAMP")" == "$HASH" ]] && imports_ok; then
  echo "interfaces up to date"
  exit 0
fi

# Build only against the venv, never against a sourced ROS installation.
export PATH="$VENV_DIR/bin:$PATH"
export AMENT_PREFIX_PATH="$VENV_DIR"
export CMAKE_PREFIX_PATH="$VENV_DIR"
unset COLCON_PREFIX_PATH PYTHONPATH || true

rm -f "$STAMP"
mkdir -p "$BUILD_ROOT"

build_pkg() {
  local pkg="$1" bdir="$BUILD_ROOT/$1" log="$BUILD_ROOT/$1/build.log"
  local start=$SECONDS
  # A build tree configured for another prefix cannot be reused.
  if [[ -f "$bdir/CMakeCache.txt" ]] &&
      ! grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$VENV_DIR" "$bdir/CMakeCache.txt"; then
    rm -rf "$bdir"
  fi
  mkdir -p "$bdir"
  : >"$log"
  if ! {
    cmake -S "$REPO_ROOT/interfaces/$pkg" -B "$bdir" \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_INSTALL_PREFIX="$VENV_DIR" \
      -DPython3_EXECUTABLE="$PY" \
      -DBUILD_TESTING=OFF &&
    make -C "$bdir" -j2 install
  } >>"$log" 2>&1; then
    echo "build_interfaces: building $pkg failed; last lines of $log:" >&2
    tail -n 60 "$log" >&2
    exit 1
  fi
  echo "built $pkg in $((SECONDS - start))s"
}

for pkg in "${PKGS[@]}"; do
  build_pkg "$pkg"
done

if ! imports_ok; then
  echo "build_interfaces: packages built but do not import with $PY" >&2
  exit 1
fi
echo "$HASH" >"$STAMP"
