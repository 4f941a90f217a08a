#!/usr/bin/env bash
# Set up everything gazelle needs, idempotently, on a Debian machine with Python >= 3.11:
# Debian build tools if missing, a virtualenv in .venv, the pinned wheels (ROS 2 Jazzy,
# MuJoCo, xacro, ...), gazelle itself (editable), and our ROS interface packages.
# Each step is skipped when what it would produce is already there and up to date.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="$ROOT/.venv"
say() { printf '[setup] %s\n' "$*"; }
# `./demo.sh` without --snapshot/--record needs no browser: GAZELLE_SETUP_NO_BROWSER=1 skips chromium;
# GAZELLE_SETUP_INTERFACES=first builds only the first tier of interface packages (step 4), what the demo needs
UV_VERSION=0.13.9
SETUP_START=$SECONDS
step_start=$SECONDS
took() { say "$1 took $((SECONDS - step_start)) s"; step_start=$SECONDS; }

# 1. Debian packages: a C/C++ toolchain and CMake build our interface packages.
missing=()
command -v cmake >/dev/null || missing+=(cmake)
command -v g++ >/dev/null || missing+=(g++)
command -v make >/dev/null || missing+=(make)
# the viewer's browser tests and `gazelle snapshot` use Debian's chromium (Playwright never downloads one)
[[ -x /usr/bin/chromium || -n "${GAZELLE_SETUP_NO_BROWSER:-}" ]] || missing+=(chromium)
# cameras render offscreen with MuJoCo through EGL on Mesa (llvmpipe on a CPU; a GPU driver where present)
if ! compgen -G "/usr/lib/*/libEGL.so.1" >/dev/null || ! compgen -G "/usr/lib/*/libEGL_mesa.so.0" >/dev/null; then
  missing+=(libegl1 libegl-mesa0 libgl1-mesa-dri)
fi
if ((${#missing[@]})); then
  if [[ $(id -u) -eq 0 ]]; then SUDO=""; else SUDO="sudo"; fi
  say "installing Debian packages: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
  took "Debian packages"
fi

# 2. The virtualenv, with a Python >= 3.11.
PY=""
for cand in python3.11 python3.12 python3.13 python3; do
  if command -v "$cand" >/dev/null && "$cand" -c 'import sys; sys.exit(sys.version_info < (3, 11))'; then
    PY="$cand"; break
  fi
done
[[ -n "$PY" ]] || { echo "[setup] need Python >= 3.11" >&2; exit 1; }
if [[ ! -x "$VENV/bin/python" ]]; then
  if ! "$PY" -m venv "$VENV" 2>/dev/null; then
    say "installing python3-venv"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null
    "$PY" -m venv "$VENV"
  fi
  say "created $VENV"
fi

# 3. Pinned wheels, then gazelle itself (only when requirements or pyproject changed).
want="$(cat "$ROOT/requirements.txt" "$ROOT/pyproject.toml" | sha256sum | cut -d' ' -f1)"
stamp="$VENV/.gazelle_requirements.sha256"
if [[ ! -f "$stamp" || "$(cat "$stamp")" != "$want" ]]; then
  say "installing wheels (ROS 2 Jazzy, MuJoCo, xacro, ...); log: $VENV/pip-install.log"
  pip_install() {
    if ! "$VENV/bin/python" -m pip install --disable-pip-version-check "$@" >>"$VENV/pip-install.log" 2>&1; then
      tail -n 40 "$VENV/pip-install.log" >&2
      echo "[setup] pip install failed (full log: $VENV/pip-install.log)" >&2
      exit 1
    fi
  }
  : > "$VENV/pip-install.log"
  # uv installs the pinned wheels from its cache in seconds where pip takes a minute and a half (measured
  # on a warm cache: 4 s against 85 s); pip remains the way when uv cannot be had. Hard links into uv's
  # cache (uv's own default on Linux; a copy where the cache is on another file system): copying the 2 GB
  # took 33-57 s of every fresh clone's set-up, linking 7 s. The trade, as with uv anywhere: editing a file
  # inside .venv/lib edits uv's cached copy too (`uv cache clean` starts it afresh).
  if [[ ! -x "$VENV/bin/uv" ]]; then pip_install "uv==$UV_VERSION" || true; fi
  if [[ -x "$VENV/bin/uv" ]]; then
    uv_install() {
      if ! "$VENV/bin/uv" pip install --link-mode hardlink --python "$VENV/bin/python" "$@" \
          >>"$VENV/pip-install.log" 2>&1; then
        tail -n 40 "$VENV/pip-install.log" >&2
        echo "[setup] uv pip install failed (full log: $VENV/pip-install.log)" >&2
        exit 1
      fi
    }
    uv_install -r "$ROOT/requirements.txt"
    uv_install --no-deps --no-build-isolation -e "$ROOT"
  else
    pip_install -r "$ROOT/requirements.txt"
    pip_install --no-deps --no-build-isolation -e "$ROOT"
  fi
  echo "$want" > "$stamp"
  took "the wheels"
fi

# 3b. Bytecode, compiled once here: uv installs none, and where PYTHONDONTWRITEBYTECODE is set (as in many
#     CI images and containers) Python never writes it at import either, so every process compiled MuJoCo's,
#     numpy's, rclpy's and gazelle's modules from source at each start: 1.35 s to import what `gazelle sim`
#     needs, 0.52 s compiled; a fresh clone's suite took 3 minutes longer than a used working tree's.
#     gazelle's own sources are checked every time (compileall skips what is up to date).
#     The compiled files are kept by content outside the clone (scripts/bytecode.sh): a second clone
#     unpacks them in seconds.
bytecode="$VENV/.gazelle_bytecode.sha256"
if [[ ! -f "$bytecode" || "$(cat "$bytecode")" != "$want" ]]; then
  step_start=$SECONDS
  site="$("$VENV/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
  if [[ "$("$ROOT/scripts/bytecode.sh" "$VENV/bin/python" "$site" "$want")" == cached ]]; then
    took "the wheels' bytecode from the cache"
  else
    took "compiling the wheels' bytecode"
  fi
  echo "$want" > "$bytecode"
fi
own=("$ROOT/gazelle" "$ROOT/launch" "$ROOT/launch_ros" "$ROOT/launch_xml" "$ROOT/launch_yaml" "$ROOT/compat/python")
"$VENV/bin/python" "$ROOT/scripts/drop_stale_bytecode.py" "${own[@]}" >/dev/null 2>&1 || true
"$VENV/bin/python" -m compileall -q -j 0 "${own[@]}" >/dev/null 2>&1 || true

# 3c. gazelle's compiled per-step loop (gazelle/physics/_native: ros2_control's servo cycles inside MuJoCo's
#     steps), built once per source and MuJoCo version into the owner-only cache; without a compiler the
#     same cycles run in Python.
"$VENV/bin/python" -c 'from gazelle.physics import _native; _native.main()' || true

# 4. Our interface packages, rebuilt only on change: the first tier (tf2_msgs, simulation_interfaces,
#    gazebo_msgs, ros_gz_interfaces), then ros2_control's and MoveIt's (scripts/build_interfaces.sh).
step_start=$SECONDS
"$ROOT/scripts/build_interfaces.sh" "$VENV" "${GAZELLE_SETUP_INTERFACES:-all}"
"$ROOT/scripts/interface_bytecode.sh" "$VENV"  # installed after 3b: their bytecode too
took "the interface packages"

# 5. The venv is a ROS prefix: gazelle's stand-ins for gazebo_ros, robot_state_publisher,
#    controller_manager and xacro in its ament index, and AMENT_PREFIX_PATH set by `activate`
#    (after a sourced workspace's), so `ros2 launch/run` and get_package_share_directory find them.
"$VENV/bin/python" "$ROOT/scripts/install_ros_packages.py" "$VENV"
if ! grep -q "gazelle: the venv is a ROS prefix" "$VENV/bin/activate"; then
  cat >>"$VENV/bin/activate" <<'ACTIVATE'
# gazelle: the venv is a ROS prefix (our interface packages and compat/ros_packages)
case ":${AMENT_PREFIX_PATH:-}:" in
  *":$VIRTUAL_ENV:"*) ;;
  *) export AMENT_PREFIX_PATH="${AMENT_PREFIX_PATH:+$AMENT_PREFIX_PATH:}$VIRTUAL_ENV" ;;
esac
ACTIVATE
fi
if ! grep -q "gazelle: what /opt/ros/jazzy/setup.bash gives a shell" "$VENV/bin/activate"; then
  cat >>"$VENV/bin/activate" <<'ACTIVATE'
# gazelle: what /opt/ros/jazzy/setup.bash gives a shell, besides the prefix: ros_environment's variables
# (unless a sourced ROS set them), and ament's shell functions, which the environment hooks of a workspace's
# packages call (ament_prepend_unique_value, ament_append_unique_value)
: "${ROS_DISTRO:=jazzy}" "${ROS_VERSION:=2}" "${ROS_PYTHON_VERSION:=3}"
export ROS_DISTRO ROS_VERSION ROS_PYTHON_VERSION
. "$VIRTUAL_ENV/local_setup.sh"
ACTIVATE
fi
say "ready in $((SECONDS - SETUP_START)) s"
