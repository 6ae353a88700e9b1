#!/bin/sh
# A LÖVE game watched live with no code: TV_LIVE=127.0.0.1:PORT in its environment, and
# tv-replay --listen saving what arrives; the saved stream must validate, traced (as the
# debugger re-runs it).
#   love_live.sh TV_REPLAY LOVE GAME_DIR OUT [ARGS...]   plays GAME_DIR with ARGS
# The environment gives the rest (TV_LUA_MODULE_DIR, SDL_VIDEODRIVER=offscreen, ...).
set -eu
replay=$1 love=$2 game=$3 out=$4
shift 4
rm -f "$out" "$out.log"
"$replay" --listen 0 --out "$out" --wait 60 >"$out.log" 2>&1 &
listener=$!
i=0
while ! grep -q "listening on" "$out.log" 2>/dev/null; do
  i=$((i + 1)); [ $i -lt 500 ] || { echo "tv-replay did not start"; cat "$out.log"; exit 1; }
  sleep 0.02
done
port=$(sed -n 's/^listening on .*:\([0-9]*\)$/\1/p' "$out.log")
TV_LIVE="127.0.0.1:$port" "$love" "$game" "$@" 2>&1 | grep -v -e XDG_RUNTIME_DIR -e '^ALSA' -e '^AL lib'
wait $listener
cat "$out.log"
# The game closed its stream as it quit (love.run returned): a whole recording.
grep -q "the game closed its recording" "$out.log"
"$replay" "$out" --validate --traced
