#!/usr/bin/env bash
# The demo: sets everything up (see scripts/setup.sh), starts `gazelle sim` on the embedded
# default world, spawns the seed robot, drives one square with square_movement.py, prints the
# corners by ground truth and by /odom, writes out/demo/square.svg, and stops everything.
# Extra arguments go to `gazelle demo`, e.g. ./demo.sh --rtf 0
#
# The demo needs the first tier of interface packages only (scripts/build_interfaces.sh): on a cold
# machine it starts after that tier, and ros2_control's and MoveIt's interfaces are built once it is done
# (Ctrl-C skips that; the next scripts/setup.sh or ./test.sh builds them).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export GAZELLE_SETUP_INTERFACES=first
# the browser is only for --snapshot and --record
case " $* " in
  *" --snapshot "* | *" --record "*) "$ROOT/scripts/setup.sh" ;;
  *) GAZELLE_SETUP_NO_BROWSER=1 "$ROOT/scripts/setup.sh" ;;
esac
cd "$ROOT"
status=0
"$ROOT/.venv/bin/gazelle" demo "$@" || status=$?
stamp() { cat "$ROOT/.venv/.gazelle_interfaces.$1.sha256" 2>/dev/null || true; }
if [[ "$(stamp second)" != "$(stamp first)" ]]; then  # both tiers are stamped with the same content hash
  echo "[setup] the demo is done; now building ros2_control's and MoveIt's interface packages (control_msgs,"
  echo "[setup] moveit_msgs, ...: about 4 minutes on 2 cores, once; Ctrl-C skips, scripts/setup.sh builds them later)"
  start=$SECONDS
  "$ROOT/scripts/build_interfaces.sh" "$ROOT/.venv" all || status=$((status ? status : $?))
  "$ROOT/scripts/interface_bytecode.sh" "$ROOT/.venv" || true
  echo "[setup] ros2_control's and MoveIt's interfaces took $((SECONDS - start)) s"
fi
exit "$status"
