#!/usr/bin/env bash
# The test command: sets everything up (see scripts/setup.sh), then runs the whole pytest suite.
# Extra arguments go to pytest, e.g. ./test.sh -k spawn
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$ROOT/scripts/setup.sh"
cd "$ROOT"
exec "$ROOT/.venv/bin/python" -m pytest "$@"
