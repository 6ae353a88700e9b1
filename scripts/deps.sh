#!/usr/bin/env bash
# Installs the Debian 12 packages Tunnelvision builds with, if any are missing.
# Usage: scripts/deps.sh [core|all]   (core: library, tools and tests; all: also the GUI/headless
#        renderer and the MinGW cross-compiler for the Lua module's Windows build)
set -euo pipefail

core=(g++ cmake ninja-build pkg-config googletest libgtest-dev libgmock-dev libgmp-dev libbenchmark-dev
      nlohmann-json3-dev zlib1g-dev liblua5.1-0-dev lua5.1 luajit lua-busted doxygen)
gui=(libimgui-dev libglfw3-dev libosmesa6-dev libstb-dev libgl-dev xvfb xauth
     love libegl1 libgl1-mesa-dri)  # love headless: SDL's offscreen driver (EGL, llvmpipe)

# The Lua module cross-compiled for Windows (tests/lua: lua.windows_dll).
cross=(g++-mingw-w64-x86-64 libz-mingw-w64-dev)

want=("${core[@]}")
if [ "${1:-all}" = all ]; then want+=("${gui[@]}" "${cross[@]}"); fi

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing packages: ${missing[*]}" >&2
sudo=()
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
