#!/usr/bin/env bash
# The test command: sets everything up (see scripts/setup.sh), runs the static checks (scripts/check.sh: ruff,
# pyright), then the whole pytest suite.
# Extra arguments go to pytest, e.g. ./test.sh -k spawn
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$ROOT/scripts/setup.sh"
cd "$ROOT"
"$ROOT/scripts/check.sh"
exec "$ROOT/.venv/bin/python" -m pytest "$@"
