#!/usr/bin/env bash
# The main job: builds Release and runs the comparison of every mover on the bullets scene
# (extra arguments go to tv-run, e.g. --list, or --scene crowd --mover continuous).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh all
cmake --preset release >/dev/null
cmake --build --preset release --target tv-run >&2
exec build/release/app/cli/tv-run "$@"
