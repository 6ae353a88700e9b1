#!/usr/bin/env bash
# Tracing compiled in but off, against tracing compiled out: the same crowd (10^4 movers,
# continuous) timed by two builds of tv-bench, alternately, so that drift of the machine hits
# both alike; the best run of each is compared.
#
#   app/bench/trace_overhead.sh TV_BENCH_TRACE_ON TV_BENCH_TRACE_OFF [ROUNDS]
#
# Build them with e.g.
#   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release && cmake --build build/bench --target tv-bench
#   cmake -S . -B build/bench-notrace -G Ninja -DCMAKE_BUILD_TYPE=Release -DTV_TRACE=OFF -DTV_BUILD_TESTS=OFF
#   cmake --build build/bench-notrace --target tv-bench
set -euo pipefail
on=${1:?usage: trace_overhead.sh TV_BENCH_TRACE_ON TV_BENCH_TRACE_OFF [ROUNDS]}
off=${2:?usage: trace_overhead.sh TV_BENCH_TRACE_ON TV_BENCH_TRACE_OFF [ROUNDS]}
rounds=${3:-7}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

args=(scale --crowd-only --counts 10000 --movers continuous,adaptive --ticks 200)
best() {  # best ms/tick of a mover in the CSV written by one run
  awk -F, -v m="$2" 'NR > 1 && $2 == m { print $3 }' "$1/scale_crowd.csv"
}
declare -A min
for ((r = 1; r <= rounds; ++r)); do
  for build in on off; do
    bin=$on
    [ "$build" = off ] && bin=$off
    "$bin" "${args[@]}" --out "$tmp/$build" >/dev/null
    for m in continuous adaptive; do
      v=$(best "$tmp/$build" "$m")
      key=$build.$m
      if [ -z "${min[$key]:-}" ] || awk -v a="$v" -v b="${min[$key]}" 'BEGIN { exit !(a < b) }'; then
        min[$key]=$v
      fi
    done
  done
done
echo "| mover | tracing compiled in, off: ms/tick | compiled out: ms/tick | overhead |"
echo "|---|---:|---:|---:|"
for m in continuous adaptive; do
  awk -v m="$m" -v a="${min[on.$m]}" -v b="${min[off.$m]}" \
    'BEGIN { printf "| %s | %.3f | %.3f | %+.1f%% |\n", m, a, b, 100 * (a / b - 1) }'
done
echo
echo "crowd of 10^4, best of $rounds alternating runs of 200 ticks each"
