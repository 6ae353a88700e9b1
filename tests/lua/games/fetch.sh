#!/bin/bash
# Fetches what the game tests compare against — public repositories, never part of this one —
# into DIR, each at a pinned commit:
#   DIR/bump.lua            kikito/bump.lua 3.1.7 (its spec suite, and the file TV_BUMP_LUA names)
#   DIR/bump-demo           kikito/bump.lua's `demo` branch: the bump.lua demo game
#   DIR/love2d-platformer   marclurr/love2d-platformer ("Mushroom Massacre")
# Needs git and the network; what cannot be fetched is said and left out (its tests skip).
#
#   tests/lua/games/fetch.sh DIR      (ctest looks in build/<preset>/games, or $TV_GAMES_DIR)
set -u
dir=${1:?usage: fetch.sh DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
status=0

# get NAME REPOSITORY COMMIT: DIR/NAME holds the repository's files at COMMIT.
get() {
  local name=$1 url=$2 commit=$3
  if [ -f "$dir/$name/.tv-commit" ] && [ "$(cat "$dir/$name/.tv-commit")" = "$commit" ]; then
    echo "$name: already at ${commit:0:12}"
    return
  fi
  local src=$dir/.git-cache/$(basename "$url")
  if [ ! -d "$src" ]; then
    git clone --quiet --bare "$url" "$src" 2>/dev/null || {
      echo "$name: could not clone $url (offline?): its tests will skip"
      rm -rf "$src"
      status=1
      return
    }
  fi
  if ! git -C "$src" cat-file -e "$commit^{commit}" 2>/dev/null; then
    git -C "$src" fetch --quiet origin '+refs/heads/*:refs/heads/*' 2>/dev/null
  fi
  rm -rf "$dir/$name" && mkdir -p "$dir/$name"
  if git -C "$src" archive "$commit" | tar -x -C "$dir/$name"; then
    echo "$commit" > "$dir/$name/.tv-commit"
    echo "$name: ${commit:0:12} from $url"
  else
    echo "$name: $url has no commit $commit: its tests will skip"
    rm -rf "$dir/$name"
    status=1
  fi
}

get bump.lua https://github.com/kikito/bump.lua 95d9e40b8aee295fc9d9b78ca214a829d6c21555
get bump-demo https://github.com/kikito/bump.lua 2f3692cb45beec3ff2dcc0bba8e9f34f2fb4b209
get love2d-platformer https://github.com/marclurr/love2d-platformer 9e5a87f971d43498b5516a7db8d95a81149473e2
exit $status
