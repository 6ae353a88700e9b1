#!/usr/bin/env bash
# The main job. Builds Release, then:
# - with a display: records the example platformer and opens its recording in the debugger,
#   re-run under the naive mover beside it, at the first bullet that re-run lets through the
#   wall, followed (extra arguments go to tv-debugger instead);
# - without one (or with --headless): renders the before/after comparison images into
#   out/comparisons/, records the sample game and validates its recording, and prints the
#   tunnelling table, measured.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh all
cmake --preset release >/dev/null
build=build/release

headless=0
if [ "${1:-}" = --headless ]; then
  headless=1
  shift
fi
if [ $headless = 0 ] && { [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; }; then
  if cmake --build --preset release --target tv-debugger tv-example-platformer >&2; then
    if [ $# = 0 ]; then
      mkdir -p out/recordings
      "$build/app/examples/tv-example-platformer" --frames 600 \
        --record out/recordings/platformer.tvrec >&2
      exec "$build/app/debugger/tv-debugger" out/recordings/platformer.tvrec \
        --what-if discrete --first-failure
    fi
    exec "$build/app/debugger/tv-debugger" "$@"
  fi
  echo "run.sh: the debugger did not build (above); rendering the comparison images instead" >&2
fi

cmake --build --preset release --target tv-render tv-run >&2
if cmake --build --preset release --target tv-bench >/dev/null 2>&1; then bench=1; else bench=0; fi

# Each line: file name | tv-render arguments. The moment each naive mover fails, beside the fix.
out=out/comparisons
rm -rf "$out"
mkdir -p "$out"
while IFS='|' read -r name args; do
  # Words before --caption are flags; everything after it is the caption, one argument.
  caption="${args#* --caption }"
  flags="${args%% --caption *}"
  # shellcheck disable=SC2086  # the flags are words by design
  "$build/app/render/tv-render" $flags --caption "$caption" --out "$out/$name.png" >/dev/null
  echo "  $out/$name.png"
done <<'LIST' > "$out/index.txt"
tunnel-1920|--scene bullets-wall --compare discrete,substep-discrete,continuous --tick 2 --body 2 --view follow --caption Tunnelling at 1920 px/s: 1000 bullets into a one-tile wall. The naive mover teleports past it, the substep patch and the exact sweep stop at its face.
cells-diagonal|--scene bullets-wall --angle 45 --cell 16 --compare sweep,substep-sweep,continuous --tick 2 --body 2 --view follow --caption Cells visited by one 45 degree move (yellow): sweep tests its whole bounding box, continuous only the cells the rect crosses, substeps revisit cells. None tunnels.
bounce-gap|--scene bounce-gap --compare discrete,substep-discrete,continuous --tick 1 --body 0 --view follow --caption A ball in a slot narrower than its step. Escapes: the ball ends outside its box (discrete is pushed out of the far wall); continuous bounces wall to wall inside one tick.
seam-snag|--scene seam-walk --speed 250 --compare discrete,continuous --tick 18 --body 0 --view follow --caption The seam snag at tick 18: the teleported walker lands in the next floor tile and is pushed back sideways (snags 1, red normal); the sweep slides over the seam.
LIST
echo "Comparison images (before/after, side by side), in $out/:"
cat "$out/index.txt"
echo

# A game that records itself, its recording summarised and validated (tv-replay).
if cmake --build --preset release --target tv-example-platformer tv-replay >&2; then
  mkdir -p out/recordings
  echo "The sample platformer, recorded (out/recordings/platformer.tvrec):"
  "$build/app/examples/tv-example-platformer" --frames 600 --record out/recordings/platformer.tvrec
  "$build/app/replay/tv-replay" out/recordings/platformer.tvrec
  "$build/app/replay/tv-replay" out/recordings/platformer.tvrec --validate
  "$build/app/replay/tv-replay" out/recordings/platformer.tvrec --validate --traced
  echo
fi

if [ $bench = 1 ]; then
  exec "$build/app/bench/tv-bench" tunnel --out out/bench
fi
exec "$build/app/run/tv-run"
