#!/bin/sh
# The live stream through the programs, as a user runs them:
#   live_cli.sh stream   TV_REPLAY TV_EXAMPLE DIR  a game streamed to tv-replay --listen; the
#                                                   saved file validates
#   live_cli.sh frames   TV_REPLAY TV_EXAMPLE DIR  --frames N stops after N frames, file closed
#   live_cli.sh in-use   TV_REPLAY DIR             a second listener on the same port: one message
#   live_cli.sh refused  TV_EXAMPLE                 nobody listens: one message, the game runs on
set -eu
mode=$1

# Starts tv-replay --listen on a free port in the background; sets PORT and LISTENER.
listen() {
  "$1" --listen 0 --out "$2" --wait 60 $3 >"$2.log" 2>&1 &
  LISTENER=$!
  i=0
  while ! grep -q "listening on" "$2.log" 2>/dev/null; do
    i=$((i + 1)); [ $i -lt 500 ] || { echo "tv-replay did not start"; cat "$2.log"; exit 1; }
    sleep 0.02
  done
  PORT=$(sed -n 's/^listening on .*:\([0-9]*\)$/\1/p' "$2.log")
}

case $mode in
  stream)
    replay=$2 example=$3 dir=$4
    listen "$replay" "$dir/live_stream.tvrec" ""
    "$example" --frames 90 --live "127.0.0.1:$PORT" >/dev/null
    wait $LISTENER
    cat "$dir/live_stream.tvrec.log"
    grep -q "the game closed its recording" "$dir/live_stream.tvrec.log"
    "$replay" "$dir/live_stream.tvrec" --validate
    ;;
  frames)
    replay=$2 example=$3 dir=$4
    listen "$replay" "$dir/live_frames.tvrec" "--frames 20"
    "$example" --frames 90 --live "127.0.0.1:$PORT" >/dev/null 2>&1
    wait $LISTENER
    grep -q "saved 20 frames" "$dir/live_frames.tvrec.log"
    "$replay" "$dir/live_frames.tvrec" --validate 2>"$dir/live_frames.err"
    # Closed by the receiver at frame 20: a whole recording, not one cut short.
    if [ -s "$dir/live_frames.err" ]; then cat "$dir/live_frames.err"; exit 1; fi
    ;;
  in-use)
    replay=$2 dir=$3
    listen "$replay" "$dir/live_first.tvrec" ""
    if "$replay" --listen "$PORT" --out "$dir/live_second.tvrec" 2>"$dir/live_second.err"; then
      echo "a second listener on port $PORT was not refused"; exit 1
    fi
    kill $LISTENER
    cat "$dir/live_second.err"
    grep -q "127.0.0.1:$PORT is in use by another program" "$dir/live_second.err"
    ;;
  refused)
    example=$2
    # Port 1: nobody listens there, and a connect is refused at once.
    err=$("$example" --frames 40 --live 127.0.0.1:1 2>&1 >/dev/null)
    echo "$err"
    [ "$(echo "$err" | grep -c "no receiver at 127.0.0.1:1 (connection refused)")" = 1 ]
    ;;
esac
