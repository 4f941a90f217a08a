#!/usr/bin/env bash
# The test command: sets everything up (see scripts/setup.sh), runs the static checks (scripts/check.sh: ruff,
# pyright), then the whole pytest suite.
# Extra arguments go to both pytest runs, e.g. ./test.sh -k spawn (./test.sh -n 0 runs the second one in one
# process too).
# Two runs: first the load and real-time tests (marked serial: the concurrent-client, soak and signal tests,
# the demo's and the square's real-time drives, the real-time video), alone, as they are timed; then all
# the others on up to 2 workers (one per core, at most 2), each taking whole test files: most tests wait on
# subprocesses, discovery and real time (one process used 0.6 of a core), and on 2 cores 2 workers took
# the suite from 11:05 to about 6 minutes; each worker process reserves its own ROS_DOMAIN_ID
# (tests/_ros_domain.py). The exit status is the first failing run's (a run that selects no test is fine
# when the other one ran some).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$ROOT/scripts/setup.sh"
cd "$ROOT"
"$ROOT/scripts/check.sh"
PY="$ROOT/.venv/bin/python"
serial=0
"$PY" -m pytest --phase serial -n 0 "$@" || serial=$?
parallel=0
"$PY" -m pytest --phase parallel -n auto --maxprocesses 2 --dist loadfile "$@" || parallel=$?
# 5 is pytest's "no test selected": fine for one run when the other ran tests
if [[ $serial -eq 5 && $parallel -eq 5 ]]; then exit 5; fi
if [[ $serial -eq 5 ]]; then serial=0; fi
if [[ $parallel -eq 5 ]]; then parallel=0; fi
if [[ $serial -ne 0 ]]; then exit "$serial"; fi
exit "$parallel"
