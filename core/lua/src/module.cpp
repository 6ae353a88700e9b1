// The entry points: `require 'tunnelvision.bump'` (bump.lua 3.1.7's API) and
// `require 'tunnelvision'` (the same worlds with our additions). Both are re-entrant: every
// open builds fresh tables (busted reloads modules once per spec file).

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/mover.hpp"

#ifdef _WIN32
#define TV_LUA_EXPORT extern "C" __declspec(dllexport)  // only these leave the DLL
#else
#define TV_LUA_EXPORT extern "C" __attribute__((visibility("default")))
#endif

namespace {

// Pushes the bump module table.
void pushBump(lua_State* L) {
  lua_newtable(L);  // methods
  const int methods = lua_gettop(L);
  tvlua::registerWorldMethods(L, methods);
  tvlua::registerExtraMethods(L, methods);
  tvlua::registerRecordingMethods(L, methods);
  lua_createtable(L, 0, 1);  // the metatable of each world's field table
  lua_pushvalue(L, methods);
  lua_setfield(L, -2, "__index");

  lua_createtable(L, 0, 8);
  lua_pushvalue(L, -2);
  tvlua::pushKeys(L);
  lua_pushcclosure(L, tvlua::guarded<tvlua::newWorld>, 2);
  lua_setfield(L, -2, "newWorld");
  tvlua::pushRectFunctions(L);
  lua_setfield(L, -2, "rect");
  tvlua::pushResponseFunctions(L);
  lua_setfield(L, -2, "responses");
  lua_pushliteral(L, "bump v3.1.7 (tunnelvision)");
  lua_setfield(L, -2, "_VERSION");
  lua_pushliteral(L, "bump.lua's API on Tunnelvision's swept-AABB core");
  lua_setfield(L, -2, "_DESCRIPTION");
  lua_replace(L, methods);
  lua_settop(L, methods);
}

}  // namespace

namespace {
// package.loaded[name][field] when both exist (pushed), else nothing pushed and false.
bool pushLoaded(lua_State* L, const char* name, const char* field) {
  lua_getglobal(L, "package");
  if (!lua_istable(L, -1)) return lua_pop(L, 1), false;
  lua_getfield(L, -1, "loaded");
  lua_remove(L, -2);
  if (!lua_istable(L, -1)) return lua_pop(L, 1), false;
  lua_getfield(L, -1, name);
  lua_remove(L, -2);
  if (field != nullptr && lua_istable(L, -1)) {
    lua_getfield(L, -1, field);
    lua_remove(L, -2);
  }
  if (lua_istable(L, -1)) return true;
  lua_pop(L, 1);
  return false;
}
}  // namespace

// Either order of require gives one module table: tunnelvision.bump is tunnelvision's `bump`.
TV_LUA_EXPORT int luaopen_tunnelvision_bump(lua_State* L) {
  if (!pushLoaded(L, "tunnelvision", "bump")) pushBump(L);
  return 1;
}

TV_LUA_EXPORT int luaopen_tunnelvision(lua_State* L) {
  if (!pushLoaded(L, "tunnelvision.bump", nullptr)) pushBump(L);
  const int bump = lua_gettop(L);
  lua_createtable(L, 0, 6);
  lua_getfield(L, bump, "newWorld");
  lua_setfield(L, -2, "newWorld");
  lua_pushvalue(L, bump);
  lua_setfield(L, -2, "bump");
  lua_newtable(L);
  int i = 0;
  for (const std::string_view name : tv::moverNames()) {
    lua_pushlstring(L, name.data(), name.size());
    lua_rawseti(L, -2, ++i);
  }
  lua_setfield(L, -2, "movers");
  tvlua::pushValidateRecording(L);
  lua_setfield(L, -2, "validateRecording");
  lua_pushliteral(L, "tunnelvision 0.1");
  lua_setfield(L, -2, "_VERSION");
  // So that a LÖVE game whose C loader finds only tunnelvision.so can also require
  // 'tunnelvision.bump' once 'tunnelvision' is loaded.
  lua_getglobal(L, "package");
  if (lua_istable(L, -1)) {
    lua_getfield(L, -1, "loaded");
    if (lua_istable(L, -1)) {
      lua_getfield(L, -1, "tunnelvision.bump");
      const bool loaded = !lua_isnil(L, -1);
      lua_pop(L, 1);
      if (!loaded) {
        lua_pushvalue(L, bump);
        lua_setfield(L, -2, "tunnelvision.bump");
      }
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return 1;
}
