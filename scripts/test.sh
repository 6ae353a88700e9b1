#!/usr/bin/env bash
# The whole test suite: builds and runs it in Release, then again under ASan + UBSan.
# Usage: scripts/test.sh [--release-only]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh all

run_preset() {
  echo "== $1: configure, build, test" >&2
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
  ctest --preset "$1"
}

run_preset release
if [ "${1:-}" != --release-only ]; then
  run_preset asan
fi
