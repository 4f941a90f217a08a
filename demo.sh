#!/usr/bin/env bash
# The demo: sets everything up (see scripts/setup.sh), starts `gazelle sim` on the embedded
# default world, spawns the seed robot, drives one square with square_movement.py, prints the
# corners by ground truth and by /odom, writes out/demo/square.svg, and stops everything.
# Extra arguments go to `gazelle demo`, e.g. ./demo.sh --rtf 0
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# the browser is only for --snapshot and --record
case " $* " in
  *" --snapshot "* | *" --record "*) "$ROOT/scripts/setup.sh" ;;
  *) GAZELLE_SETUP_NO_BROWSER=1 "$ROOT/scripts/setup.sh" ;;
esac
cd "$ROOT"
exec "$ROOT/.venv/bin/gazelle" demo "$@"
