#!/usr/bin/env bash
# Static checks, run by ./test.sh before the tests: ruff (lint + format), pyright (basic) on gazelle/ and the layer rules.
# MuJoCo ships no type stubs: pybind11-stubgen writes them to build/typings (pyright's stubPath) first.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
PY="$ROOT/.venv/bin"
"$PY/ruff" check gazelle tests bench launch launch_ros launch_xml launch_yaml scripts compat
"$PY/ruff" format --check gazelle tests bench launch launch_ros launch_xml launch_yaml scripts compat
stamp="build/typings/.mujoco-$("$PY/python" -c 'import mujoco; print(mujoco.__version__)')"
if [ ! -e "$stamp" ]; then
  rm -rf build/typings
  "$PY/pybind11-stubgen" mujoco -o build/typings --ignore-all-errors >/dev/null 2>&1
  touch "$stamp"
fi
"$PY/pyright" --warnings
# The layer rules (one-way imports, public surfaces only) are static too: a private import once reached CI unseen
"$PY/python" -m pytest -q -p no:cacheprovider tests/project/test_architecture.py
