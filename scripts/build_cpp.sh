#!/usr/bin/env bash
# rclcpp (Jazzy) and what C++ nodes use most (rclcpp_action, rclcpp_lifecycle, rclcpp_components), built from the released sources under cpp/ against the ROS 2
# wheels in a virtualenv and installed into it, so a workspace's `find_package(rclcpp)` finds it there.
#
#   scripts/build_cpp.sh VENV_DIR build   the tier, from the cache or built (what `setup.sh --cpp` runs)
#   scripts/build_cpp.sh VENV_DIR stubs   unless the tier is installed and up to date: VENV_DIR/share/<pkg>/cmake/
#                                         <pkg>Config.cmake for each package of the tier runs `build` when a
#                                         package first finds it (a workspace's `colcon build`), then reads
#                                         the real one
#
# Built on first need only: a team that never writes C++ never pays for it (`stubs` writes four small files).
# Cached by content outside the clone like the interface tiers (~/.cache/gazelle/cpp, scripts/_cache.sh),
# under a hash over cpp/, this script, the compiler's and Python's versions and the wheel packages it builds
# against; VENV_DIR/.gazelle_cpp.sha256 holds the hash the tier was installed with.
# Build trees live in <repo>/build/cpp/<pkg>; cmake/ninja output goes to <build dir>/build.log.
set -euo pipefail

if [[ $# -ne 2 || ! "$2" =~ ^(build|stubs)$ ]]; then
  echo "usage: $0 VENV_DIR build|stubs" >&2
  exit 2
fi
if [[ ! -x "$1/bin/python" ]]; then
  echo "build_cpp: $1 is not a virtualenv (no bin/python)" >&2
  exit 2
fi
VENV_DIR="$(cd "$1" && pwd)"
MODE="$2"
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/_cache.sh
source "$REPO_ROOT/scripts/_cache.sh"
# shellcheck source=scripts/_cache_private.sh
source "$REPO_ROOT/scripts/_cache_private.sh"  # every folder above the cache checked too, at every use
PY="$VENV_DIR/bin/python"
BUILD_ROOT="$REPO_ROOT/build/cpp"
STAMP="$VENV_DIR/.gazelle_cpp.sha256"
# In build order: the packages of a stage build side by side (each needs only earlier stages').
STAGES=("statistics_msgs composition_interfaces" "libstatistics_collector class_loader" "rclcpp"
  "rclcpp_action rclcpp_lifecycle rclcpp_components")
# shellcheck disable=SC2206  # package names are words
PKGS=(${STAGES[*]})
# What a workspace finds: these get a stub until the tier is installed.
USER_PKGS=(rclcpp rclcpp_action rclcpp_lifecycle rclcpp_components)
STUB_MARK="gazelle: built on first need"
# Wheel packages whose version change must trigger a rebuild.
DEP_PKGS=(ament_cmake ament_index_cpp builtin_interfaces rcl rcl_action rcl_interfaces rcl_lifecycle
  rcl_logging_interface rcl_yaml_param_parser rcpputils rcutils rmw rosgraph_msgs rosidl_default_generators
  rosidl_dynamic_typesupport rosidl_runtime_cpp rosidl_typesupport_cpp rosidl_typesupport_fastrtps_cpp
  tracetools action_msgs lifecycle_msgs type_description_interfaces fastrtps)

compute_hash() {
  {
    (cd "$REPO_ROOT" && find cpp -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum &&
      sha256sum scripts/build_cpp.sh scripts/_cache.sh scripts/_cache_private.sh)
    "$PY" -c 'import os, sys; print("python", sys.version.split()[0], os.path.realpath(sys.executable))'
    g++ --version 2>/dev/null | head -n1
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

installed() {  # the tier's packages are in the venv, their configs real (not stubs)
  local pkg cfg
  [[ -f "$VENV_DIR/lib/librclcpp.so" ]] || return 1
  for pkg in "${USER_PKGS[@]}"; do
    cfg="$VENV_DIR/share/$pkg/cmake/${pkg}Config.cmake"
    [[ -f "$cfg" ]] && ! grep -q "$STUB_MARK" "$cfg" || return 1
  done
}

write_stubs() {
  local pkg dir
  for pkg in "${USER_PKGS[@]}"; do
    dir="$VENV_DIR/share/$pkg/cmake"
    mkdir -p "$dir"
    cat >"$dir/${pkg}Config.cmake.tmp" <<STUB
# $STUB_MARK (scripts/build_cpp.sh stubs). The first package that finds $pkg builds gazelle's C++ tier
# (rclcpp and friends from their released sources, against the wheels), or takes it
# from the cache; the tier's real ${pkg}Config.cmake then replaces this file and is read in its place.
message(STATUS "gazelle: $pkg is built once, on first need (scripts/build_cpp.sh; cached afterwards)")
execute_process(COMMAND "$REPO_ROOT/scripts/build_cpp.sh" "$VENV_DIR" build RESULT_VARIABLE _gazelle_cpp_rc)
file(READ "\${CMAKE_CURRENT_LIST_FILE}" _gazelle_cpp_now)
if(NOT _gazelle_cpp_rc EQUAL 0 OR _gazelle_cpp_now MATCHES "$STUB_MARK")
  message(FATAL_ERROR "gazelle: building $pkg (scripts/build_cpp.sh $VENV_DIR build) failed; its log is named above")
endif()
include("\${CMAKE_CURRENT_LIST_FILE}")
STUB
    mv "$dir/${pkg}Config.cmake.tmp" "$dir/${pkg}Config.cmake"
  done
}

# The wheels as a C++ prefix. Their CMake exports name two libraries of the machine they were built on
# (fastrtps: /usr/lib64/libtinyxml2.so; tracetools: lttng-ust), which their own libraries already carry
# under hashed names in site-packages/ros_*.libs; those are linked into VENV_DIR/lib, where a C++ node's
# RPATH finds them (the wheels' own RPATH, $ORIGIN/../../../ros_*.libs, was meant for site-packages). Each
# file is rewritten (sed -i makes a new one), never edited in place: uv hard-links it to its cache.
prepare_venv() {
  local f lib
  f="$VENV_DIR/share/fastrtps/cmake/fastrtps-shared-targets.cmake"
  if [[ -f "$f" ]] && grep -q '/usr/lib64/libtinyxml2.so' "$f"; then sed -i 's|;/usr/lib64/libtinyxml2\.so;|;|' "$f"; fi
  f="$VENV_DIR/share/tracetools/cmake/tracetools_exportExport.cmake"
  if [[ -f "$f" ]] && grep -q '"lttng-ust;' "$f"; then sed -i 's|"lttng-ust;|"|' "$f"; fi
  f="$VENV_DIR/share/tracetools/cmake/ament_cmake_export_libraries-extras.cmake"
  if [[ -f "$f" ]] && grep -q '"lttng-ust;' "$f"; then sed -i 's|"lttng-ust;|"|' "$f"; fi
  for lib in "$VENV_DIR"/lib/python3*/site-packages/ros_*.libs/*.so*; do
    [[ -e "$lib" && ! -e "$VENV_DIR/lib/${lib##*/}" ]] || continue
    ln -s "${lib#"$VENV_DIR/lib/"}" "$VENV_DIR/lib/${lib##*/}"
  done
}

# class_loader (rclcpp_components' loader) logs through Debian's console_bridge: set-up installs it
# (scripts/setup.sh --cpp-debian), or says in one line why it cannot.
need_console_bridge() {
  compgen -G "/usr/lib/*/console_bridge/cmake/console_bridge-config.cmake" >/dev/null && return 0
  "$REPO_ROOT/scripts/setup.sh" --cpp-debian >&2
}

if [[ "$MODE" == stubs ]]; then
  # a tier installed from other sources or for other wheels (a pull, an upgrade) is rebuilt on next need too
  if ! installed || [[ ! -f "$STAMP" || "$(cat "$STAMP")" != "$(compute_hash)" ]]; then write_stubs; fi
  exit 0
fi

for tool in cmake g++ sha256sum flock; do
  command -v "$tool" >/dev/null || { echo "build_cpp: '$tool' not found" >&2; exit 1; }
done
# One build at a time per venv: colcon configures packages in parallel, and each may find rclcpp first.
exec 9>"$VENV_DIR/.gazelle_cpp.lock"
flock 9
prepare_venv
need_console_bridge
HASH="$(compute_hash)"
CACHE_ROOT="$CACHE_HOME/cpp"
ENTRY="$CACHE_ROOT/$HASH-$(uname -m)"

if [[ -f "$STAMP" && "$(cat "$STAMP")" == "$HASH" ]] && installed; then
  echo "cpp: the C++ tier is up to date"
  exit 0
fi

restore() {
  local start=$SECONDS old_prefix
  if ! cache_dir "$CACHE_ROOT"; then
    echo "build_cpp: cache $CACHE_ROOT is not private ($CACHE_WHY); not used" >&2
    return 1
  fi
  cache_usable build_cpp "$CACHE_ROOT" "$ENTRY" rebuilding || return 1
  if [[ ! -f "$ENTRY/prefix" ]]; then
    echo "build_cpp: cached entry $ENTRY is incomplete or corrupt; rebuilding" >&2
    rm -rf "$ENTRY"
    return 1
  fi
  old_prefix="$(cat "$ENTRY/prefix")"
  cache_unpack build_cpp "$ENTRY" "$VENV_DIR" rebuilding || return 1
  if [[ "$old_prefix" != "$VENV_DIR" ]]; then
    tar -tf "$ENTRY/files.tar" | grep -E '(local_setup\.[a-z]+|Export\.cmake|\.dsv|\.sh)$' |
      while read -r f; do
        [[ -f "$VENV_DIR/$f" ]] && sed -i "s|$old_prefix|$VENV_DIR|g" "$VENV_DIR/$f"
      done
  fi
  if ! installed; then
    echo "build_cpp: cached entry $ENTRY did not install the tier; rebuilding" >&2
    rm -rf "$ENTRY"
    return 1
  fi
  echo "cpp: the C++ tier installed from the cache ($ENTRY) in $((SECONDS - start))s"
}

save() {
  local tmp pkg
  tmp="$(cache_new "$CACHE_ROOT")" || { echo "build_cpp: cannot use the cache $CACHE_ROOT; not saved" >&2; return 0; }
  for pkg in "${PKGS[@]}"; do  # CMake writes the manifest without a final newline
    { cat "$BUILD_ROOT/$pkg/install_manifest.txt"; echo; } | sed -n "s|^$VENV_DIR/||p"
  done | LC_ALL=C sort -u >"$tmp/files.list"
  if tar -cf "$tmp/files.tar" -C "$VENV_DIR" -T "$tmp/files.list" 2>/dev/null; then
    echo "$VENV_DIR" >"$tmp/prefix"
    rm -f "$tmp/files.list"
    cache_commit "$CACHE_ROOT" "$tmp" "$ENTRY" 3
    echo "cpp: cached the C++ tier in $ENTRY"
  else
    rm -rf "$tmp"
    echo "build_cpp: could not cache the C++ tier" >&2
  fi
}

if restore; then
  echo "$HASH" >"$STAMP"
  exit 0
fi
if [[ -n "${GAZELLE_CPP_NO_BUILD:-}" ]]; then  # the cache's own test: never build
  echo "build_cpp: no usable cached build at $ENTRY" >&2
  exit 3
fi

# Build only against the venv, never against a sourced ROS installation or the workspace being built.
export PATH="$VENV_DIR/bin:$PATH"
export AMENT_PREFIX_PATH="$VENV_DIR"
export CMAKE_PREFIX_PATH="$VENV_DIR"
unset COLCON_PREFIX_PATH PYTHONPATH CMAKE_BUILD_PARALLEL_LEVEL MAKEFLAGS || true
rm -f "$STAMP"
mkdir -p "$BUILD_ROOT"
if command -v ninja >/dev/null; then GENERATOR=(-G Ninja); BUILD_TOOL=ninja; else GENERATOR=(); BUILD_TOOL=make; fi
JOBS="${GAZELLE_BUILD_JOBS:-$(nproc)}"

# What is compiled: each package's libraries (and rclcpp_components' containers), no tests. How: unity
# builds (a dozen of a library's sources compiled as one file, so rclcpp's headers are parsed 8 times, not
# 90) at -O1, as the interface packages are: rclcpp took 60-75 s on the shared 2-core machine.
# The libraries find the wheels' by RPATH $ORIGIN (they all live in VENV_DIR/lib).
build_pkg() {
  local pkg="$1" bdir="$BUILD_ROOT/$1" log="$BUILD_ROOT/$1/build.log" start=$SECONDS
  if [[ -f "$bdir/CMakeCache.txt" ]] &&
      ! { grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$VENV_DIR" "$bdir/CMakeCache.txt" &&
          grep -q "^CMAKE_MAKE_PROGRAM:FILEPATH=.*/$BUILD_TOOL\$" "$bdir/CMakeCache.txt"; }; then
    rm -rf "$bdir"
  fi
  mkdir -p "$bdir"
  : >"$log"
  if ! {
    cmake "${GENERATOR[@]}" -S "$REPO_ROOT/cpp/$pkg" -B "$bdir" \
      -DCMAKE_BUILD_TYPE=None -DCMAKE_C_FLAGS=-O1 -DCMAKE_CXX_FLAGS=-O1 \
      -DCMAKE_INSTALL_PREFIX="$VENV_DIR" -DCMAKE_INSTALL_RPATH='$ORIGIN' \
      -DCMAKE_SHARED_LINKER_FLAGS=-Wl,--disable-new-dtags -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags \
      -DPython3_EXECUTABLE="$PY" -DBUILD_TESTING=OFF &&
    cmake --build "$bdir" --target install -- -j"$JOBS"
  } >>"$log" 2>&1; then
    echo "build_cpp: building $pkg failed; last lines of $log:"
    tail -n 40 "$log"
    return 1
  fi
  echo "cpp: built $pkg in $((SECONDS - start))s"
}

echo "cpp: building ${USER_PKGS[*]} against the wheels (once; cached afterwards)"
build_started=$SECONDS
for stage in "${STAGES[@]}"; do
  pids=()
  for pkg in $stage; do
    build_pkg "$pkg" >&2 &
    pids+=($!)
  done
  failed=0
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
  ((failed == 0)) || exit 1
done
installed || { echo "build_cpp: the C++ tier built but is not complete in $VENV_DIR" >&2; exit 1; }
echo "$HASH" >"$STAMP"
echo "cpp: built the C++ tier in $((SECONDS - build_started))s"
save
