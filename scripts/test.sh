#!/usr/bin/env bash
# One command: set everything up and run the test suite on the real data in ../shared/data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export MUJOCO_GL="${MUJOCO_GL:-egl}"
export MENAGERIE_ROOT="${MENAGERIE_ROOT:-$(cd .. && pwd)/shared/data}"
export REALSIM_CACHE="${REALSIM_CACHE:-$(mktemp -d)}"
.venv/bin/ruff check realsim cli.py tests bench  # lint: unused names, import order, errors
.venv/bin/mypy  # types: the strictly typed modules listed in pyproject.toml
# Two workers (pytest-xdist), whole files to each: module fixtures are built once, and the
# conversions shared across modules once per run (tests/conftest.py: built_once).
# REALSIM_TEST_WORKERS=0 runs the tests in one process.
exec .venv/bin/python -m pytest -q -n "${REALSIM_TEST_WORKERS:-2}" --dist loadfile "$@"
