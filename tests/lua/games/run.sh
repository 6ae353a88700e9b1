#!/bin/bash
# Plays a real public LÖVE game (fetched by fetch.sh, never part of this repository) unchanged,
# headless, with the scripted input of its profile, and compares tunnelvision.bump with bump.lua
# frame by frame:
#   1. twice on the game's own bump.lua: the game must repeat itself (else nothing compares);
#   2. on tunnelvision.bump (only `require 'bump'` answered by the harness), recording itself
#      through TV_RECORD — no code — into one .tvrec per world;
#   3. the per-frame states of 1 and 2 compared; at the first difference both runs are played
#      again to that frame and the items that differ are printed;
#   4. every recording validated with tv-replay (bit for bit, traced when it can).
#
#   run.sh PROFILE GAMES_DIR MODULE_DIR OUT_DIR [TV_REPLAY]
#
# Exit 0: every check held; 1: one failed (said why); 77: the game is not in GAMES_DIR (skip).
# TV_GAME_LIVE=1 instead plays the game once on tunnelvision.bump watched live with no code
# (TV_LIVE=127.0.0.1:PORT, tv-replay --listen saving the stream), and validates the saved
# stream traced. TV_GAME_FRAMES overrides the profile's frame count; TV_GAME_AS_SHIPPED=1 also reports how far
# bump.lua as shipped (its hash orders left as they fall) repeats itself; TV_GAME_TIMING=N also
# times love.update in N rounds of three runs taking turns — bump.lua, tunnelvision.bump through
# the FFI (LÖVE's LuaJIT: the module's fast path), and through the C API (TV_LUA_FFI=0) — none
# recording, and prints the best of each.
set -u
profile=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
games=$2
moduledir=$(cd "$3" && pwd)
out=$4
replay=${5:-}
here=$(cd "$(dirname "$0")" && pwd)

field() { luajit -e "local v = dofile('$profile').$1; io.write(type(v) == 'table' and table.concat(v, ' ') or tostring(v))"; }
name=$(field name)
game=$games/$name
if [ ! -f "$game/main.lua" ]; then
  echo "SKIP: $name is not in $games: run tests/lua/games/fetch.sh $games (needs the network)"
  exit 77
fi
game=$(cd "$game" && pwd)
frames=${TV_GAME_FRAMES:-$(field frames)}
work=$(mkdir -p "$out/$name" && cd "$out/$name" && pwd)
rundir=$work/game
rm -rf "$rundir" && mkdir -p "$rundir"
# The game's files, linked (not copied, not changed); its main.lua and conf.lua under other
# names, so that the harness's run first.
for f in "$game"/* "$game"/.[!.]*; do
  [ -e "$f" ] || continue
  base=$(basename "$f")
  case $base in
    main.lua) ln -s "$f" "$rundir/tv_game_main.lua" ;;
    conf.lua) ln -s "$f" "$rundir/tv_game_conf.lua" ;;
    .git) ;;
    *) ln -s "$f" "$rundir/$base" ;;
  esac
done
cp "$here/harness/main.lua" "$here/harness/conf.lua" "$rundir/"

failed=0
fail() { echo "FAIL: $*"; failed=1; }

# play MODE TAG [DUMP_FRAMES...]: one run; its log is $work/TAG.log
play() {
  local mode=$1 tag=$2
  shift 2
  local dump=""
  for f in "$@"; do dump="$dump$f, "; done
  cat > "$work/$tag.config.lua" <<EOF
return { mode = '$mode', profile = '$profile', frames = $frames, log = '$work/$tag.log',
         moduleDir = '$moduledir', reference = '$here/../reference/ordered_bump.lua',
         dump = { $dump} }
EOF
  local record=()
  if [ "$mode" = tunnelvision ] && [ "$tag" = tunnelvision ]; then
    rm -f "$work"/recording*.tvrec
    record=(TV_RECORD="$work/recording.tvrec")
  fi
  [ "${TV_LUA_FFI_RUN:-}" = 0 ] && record+=(TV_LUA_FFI=0)
  [ -n "${TV_LIVE_TO:-}" ] && record+=(TV_LIVE="$TV_LIVE_TO")
  env "${record[@]}" TV_HARNESS="$work/$tag.config.lua" SDL_VIDEODRIVER=offscreen \
    SDL_AUDIODRIVER=dummy ALSOFT_DRIVERS=null timeout 1200 love "$rundir" \
    > "$work/$tag.out" 2>&1
  local rc=$?
  if ! tail -n 1 "$work/$tag.log" 2>/dev/null | grep -q '^end done'; then
    fail "$name on $mode ($tag) did not finish $frames frames (rc $rc):"
    grep -v -e XDG_RUNTIME_DIR -e '^ALSA' -e '^AL lib' "$work/$tag.out" | tail -n 20
    tail -n 2 "$work/$tag.log" 2>/dev/null
    return 1
  fi
  return 0
}

echo "== $name: $frames frames, scripted input, headless"
if [ "${TV_GAME_LIVE:-}" = 1 ]; then
  [ -n "$replay" ] || { echo "SKIP: watching $name live needs tv-replay"; exit 77; }
  stream=$work/live.tvrec
  rm -f "$stream" "$stream.log"
  "$replay" --listen 0 --out "$stream" --wait 60 > "$stream.log" 2>&1 &
  listener=$!
  for _ in $(seq 500); do grep -q "listening on" "$stream.log" 2>/dev/null && break; sleep 0.02; done
  port=$(sed -n 's/^listening on .*:\([0-9]*\)$/\1/p' "$stream.log")
  [ -n "$port" ] || { cat "$stream.log"; fail "tv-replay --listen did not start"; exit 1; }
  TV_LIVE_TO=127.0.0.1:$port play tunnelvision live
  played=$?
  wait $listener
  cat "$stream.log"
  [ $played = 0 ] || exit 1
  grep -q "the game closed its recording" "$stream.log" || fail "$name: the stream did not end closed"
  if "$replay" "$stream" --validate --traced > "$work/validate.txt" 2>&1; then
    echo "tv-replay --validate --traced live.tvrec: $(tail -n 1 "$work/validate.txt")"
  else
    fail "$name: tv-replay --validate --traced live.tvrec:"
    cat "$work/validate.txt"
  fi
  exit $failed
fi
if [ -n "${TV_GAME_AS_SHIPPED:-}" ]; then
  # How far bump.lua as shipped repeats itself: its pairs over tables keyed by tables follow
  # memory addresses, which change from run to run.
  play bump-as-shipped shipped && play bump-as-shipped shipped.again &&
    luajit "$here/harness/compare.lua" "$work/shipped.log" "$work/shipped.again.log" |
    sed 's/^/bump.lua as shipped, run against run: /'
fi
play bump bump || exit 1
play bump bump.again || exit 1
if ! luajit "$here/harness/compare.lua" "$work/bump.log" "$work/bump.again.log" > "$work/repeat.txt"; then
  fail "$name does not repeat itself on bump.lua, so no comparison means anything:"
  cat "$work/repeat.txt"
  exit 1
fi
echo "bump.lua: the game repeats itself run to run ($frames frames)"
play tunnelvision tunnelvision || exit 1

luajit "$here/harness/compare.lua" "$work/bump.log" "$work/tunnelvision.log" > "$work/compare.txt"
verdict=$?
cat "$work/compare.txt"
# explain FRAME: play both to FRAME again and print the items that differ there.
explain() {
  local f=$1
  play bump bump.dump "$((f - 1))" "$f" && play tunnelvision tunnelvision.dump "$((f - 1))" "$f" &&
    luajit "$here/harness/compare.lua" --items "$work/bump.dump.log" "$work/tunnelvision.dump.log" "$f"
}
case $verdict in
  0) ;;
  2) # Within rounding: where bump's contact lands a step inside what it touched, ours does not
     # (core/lua/README.md); show the first such place.
     explain "$(sed -n 's/^first difference at frame \([0-9]*\).*/\1/p' "$work/compare.txt")" ;;
  *) explain "$(sed -n 's/^first difference beyond rounding at frame \([0-9]*\).*/\1/p' "$work/compare.txt")"
     fail "$name: tunnelvision.bump and bump.lua differ beyond rounding (see above)" ;;
esac

# No body wedged: the most collisions a single move returned, and moves with more than 16.
grep '^end' "$work/tunnelvision.log" | sed 's/^end done/tunnelvision.bump:/'
grep '^end' "$work/bump.log" | sed 's/^end done/bump.lua:         /'
most=$(sed -n 's/^end done .* mostCollisions \([0-9]*\).*/\1/p' "$work/tunnelvision.log")
[ "${most:-99}" -lt 64 ] || fail "$name: a move returned $most collisions (a wedged body)"

# love.update's CPU time, the three ways taking turns (the runs above recorded or dumped).
if [ -n "${TV_GAME_TIMING:-}" ]; then
  best() { sed -n 's/^end done .* update \([0-9.]*\).*/\1/p' "$work/$1.log"; }
  declare -A fastest=()
  for round in $(seq 1 "$TV_GAME_TIMING"); do
    for way in bump ffi capi; do
      case $way in
        bump) play bump-as-shipped "time.$way" || exit 1 ;;
        ffi) play tunnelvision-timing "time.$way" || exit 1 ;;
        capi) TV_LUA_FFI_RUN=0 play tunnelvision-timing "time.$way" || exit 1 ;;
      esac
      t=$(best "time.$way")
      if [ -z "${fastest[$way]:-}" ] || awk "BEGIN{exit !($t < ${fastest[$way]})}"; then fastest[$way]=$t; fi
    done
  done
  awk -v b="${fastest[bump]}" -v f="${fastest[ffi]}" -v c="${fastest[capi]}" -v n="$frames" 'BEGIN{
    printf "love.update, best of %s rounds, %d frames: bump.lua %.3f s, tunnelvision.bump FFI %.3f s (%.2fx), C API %.3f s (%.2fx)\n", ENVIRON["TV_GAME_TIMING"], n, b, f, b / f, c, b / c }'
fi

# The recordings TV_RECORD made, with no code in the game.
shopt -s nullglob
recordings=("$work"/recording*.tvrec)
if [ ${#recordings[@]} -eq 0 ]; then
  fail "$name: TV_RECORD made no recording"
elif [ -n "$replay" ]; then
  for r in "${recordings[@]}"; do
    if "$replay" "$r" --validate > "$work/validate.txt" 2>&1; then
      echo "tv-replay --validate $(basename "$r"): $(tail -n 1 "$work/validate.txt")"
    else
      fail "$name: tv-replay --validate $(basename "$r"):"
      cat "$work/validate.txt"
    fi
  done
  "$replay" "${recordings[0]}" --stats 2>/dev/null | head -n 12
fi
exit $failed
