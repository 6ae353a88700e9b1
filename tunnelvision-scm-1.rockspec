-- `luarocks make` from the repository builds and installs the native module for Lua 5.1 /
-- LuaJIT: tunnelvision.so (`require 'tunnelvision'`) into the rock's lib directory and
-- tunnelvision/bump.lua (`require 'tunnelvision.bump'`) into its Lua directory.
rockspec_format = "3.0"
package = "tunnelvision"
version = "scm-1"
source = {
  url = "git+file://.",  -- luarocks make builds the checkout it is run in
}
description = {
  summary = "A swept-AABB collision world with bump.lua's API that never tunnels or snags",
  detailed = [[
    tunnelvision.bump is a drop-in for bump.lua 3.1.7 (same names, arguments, results and
    errors) on Tunnelvision's C++ core: exact contact, no seam snags, no tunnelling.
    tunnelvision adds movers by name, a batch step for moving versus moving and a move that
    makes no garbage.
  ]],
  license = "MIT",
}
dependencies = {
  "lua >= 5.1, < 5.2",
}
build = {
  type = "cmake",
  variables = {
    CMAKE_BUILD_TYPE = "Release",
    TV_BUILD_APP = "OFF",
    TV_BUILD_TESTS = "OFF",
    TV_LUA_INCDIR = "$(LUA_INCDIR)",
    TV_LUA_INSTALL_CMOD = "$(LIBDIR)",
    TV_LUA_INSTALL_LMOD = "$(LUADIR)",
  },
}
