#!/usr/bin/env bash
# The test command: sets everything up (see scripts/setup.sh), runs the static checks (scripts/check.sh: ruff,
# pyright), then the whole pytest suite.
# Extra arguments go to pytest, e.g. ./test.sh -k spawn (./test.sh -n 0 runs in this process, one test at a time).
# The suite runs on up to 2 workers (one per core, at most 2), each taking whole test files: most tests
# wait on subprocesses, discovery and real time (one process used 0.6 of a core), and on 2 cores 2 workers
# took the suite from 11:05 to 6:17; each worker process reserves its own ROS_DOMAIN_ID (tests/_ros_domain.py).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$ROOT/scripts/setup.sh"
cd "$ROOT"
"$ROOT/scripts/check.sh"
exec "$ROOT/.venv/bin/python" -m pytest -n auto --maxprocesses 2 --dist loadfile "$@"
