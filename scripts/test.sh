#!/usr/bin/env bash
# The whole test suite: builds and runs it in Release, then again under ASan + UBSan.
# Usage: scripts/test.sh [--release-only] [--keep-going]
#   --release-only  stop after the Release half.
#   --keep-going    run the ASan + UBSan half even when the Release half failed: a crash or a wrong
#                   result in Release is often a memory error that the sanitizers name. The run
#                   still ends in failure. Without it a red Release half stops here, so that its
#                   failures are what you read first.
set -euo pipefail
cd "$(dirname "$0")/.."

release_only=0 keep_going=0
for arg in "$@"; do
  case "$arg" in
    --release-only) release_only=1 ;;
    --keep-going) keep_going=1 ;;
    *) echo "scripts/test.sh: unknown flag '$arg' (flags: --release-only, --keep-going)" >&2; exit 2 ;;
  esac
done

scripts/deps.sh all

# Says which tests of a preset failed and where their pictures are.
report_failures() {
  local preset=$1 dir=build/$1
  local log=$dir/Testing/Temporary/LastTestsFailed.log
  echo >&2
  echo "== $preset: FAILED" >&2
  if [ -s "$log" ]; then
    echo "   $(wc -l < "$log") test(s) failed:" >&2
    sed 's/^[0-9]*:/     /' "$log" >&2
  fi
  local diffs
  # golden-output/negative/ holds the negative controls' pictures: they differ on purpose.
  diffs=$(find "$dir/tests" -name '*.diff.png' -not -path '*/negative/*' 2>/dev/null | sort || true)
  if [ -n "$diffs" ]; then
    echo "   Pictures that differ from their golden (yellow: beyond the tolerance, red: within it;" >&2
    echo "   the rendered picture is beside each, without .diff):" >&2
    echo "$diffs" | sed 's/^/     /' >&2
  fi
  echo "   Again, with their output: ctest --preset $preset --rerun-failed --output-on-failure" >&2
}

run_preset() {
  echo "== $1: configure, build, test" >&2
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
  find "build/$1/tests" -name '*.diff.png' -delete 2>/dev/null || true
  if ! ctest --preset "$1"; then
    report_failures "$1"
    return 1
  fi
}

status=0
run_preset release || status=1
if [ "$release_only" = 1 ]; then exit $status; fi
if [ $status != 0 ] && [ "$keep_going" = 0 ]; then
  echo "   (the ASan + UBSan half did not run: scripts/test.sh --keep-going runs it anyway)" >&2
  exit $status
fi
run_preset asan || status=1
exit $status
