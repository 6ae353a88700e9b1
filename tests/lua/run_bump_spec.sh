#!/bin/bash
# bump.lua's own spec suite (fetched by games/fetch.sh, never part of this repository) run
# against tunnelvision.bump: run_bump_spec.sh BUSTED VM GAMES_DIR. Exit 77 (skip) without it.
busted=$1 vm=$2 games=$3
if [ ! -f "$games/bump.lua/spec/World_spec.lua" ]; then
  echo "SKIP: bump.lua's spec suite is not in $games: run tests/lua/games/fetch.sh $games (needs the network)"
  exit 77
fi
spec=$(cd "$games/bump.lua/spec" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
export TV_LUA_MODULE_DIR=$(cd "$TV_LUA_MODULE_DIR" && pwd)
cd "$(mktemp -d)" || exit 1   # a directory without a bump.lua in it
exec "$busted" --lua="$vm" --helper="$here/bump_spec_helper.lua" --output=TAP "$spec"
