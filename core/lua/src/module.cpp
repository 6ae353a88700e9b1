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

// Pushes the methods every world has (bump's API, our additions, recording).
void pushMethods(lua_State* L) {
  lua_newtable(L);
  const int methods = lua_gettop(L);
  tvlua::registerWorldMethods(L, methods);
  tvlua::registerExtraMethods(L, methods);
  tvlua::registerPlatformMethods(L, methods);
  tvlua::registerRecordingMethods(L, methods);
  tvlua::installFastPath(L, methods);
}

// Pushes newWorld over `methods`: worlds with bump.lua's rules or the core's; `responses` is
// the module's bump.responses.
void pushNewWorld(lua_State* L, int methods, bool bumpRules, int responses) {
  lua_pushvalue(L, methods);
  tvlua::pushKeys(L);
  lua_pushboolean(L, bumpRules);
  lua_pushvalue(L, responses);
  lua_pushcclosure(L, tvlua::guarded<tvlua::newWorld>, 4);
}

// Pushes the bump module table: bump.lua 3.1.7's face.
void pushBump(lua_State* L) {
  pushMethods(L);
  const int methods = lua_gettop(L);
  lua_createtable(L, 0, 8);
  const int bump = lua_gettop(L);
  tvlua::pushResponseFunctions(L);
  const int responses = lua_gettop(L);
  pushNewWorld(L, methods, true, responses);
  lua_setfield(L, bump, "newWorld");
  tvlua::pushRectFunctions(L);
  lua_setfield(L, bump, "rect");
  lua_setfield(L, bump, "responses");
  lua_pushliteral(L, "bump v3.1.7 (tunnelvision)");
  lua_setfield(L, -2, "_VERSION");
  lua_pushliteral(L, "bump.lua's API and rules on Tunnelvision's swept-AABB core");
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
  tvlua::recordFromEnvironment(L);
  return 1;
}

TV_LUA_EXPORT int luaopen_tunnelvision(lua_State* L) {
  if (!pushLoaded(L, "tunnelvision.bump", nullptr)) pushBump(L);
  const int bump = lua_gettop(L);
  lua_createtable(L, 0, 10);
  const int tv = lua_gettop(L);
  // Our own worlds: the core's rules (exact sweep, any number of visits); the same methods.
  pushMethods(L);
  lua_getfield(L, bump, "responses");
  pushNewWorld(L, lua_gettop(L) - 1, false, lua_gettop(L));
  lua_setfield(L, tv, "newWorld");
  lua_pop(L, 2);
  lua_pushvalue(L, bump);
  lua_setfield(L, tv, "bump");
  lua_newtable(L);
  int i = 0;
  for (const std::string_view name : tv::moverNames()) {
    lua_pushlstring(L, name.data(), name.size());
    lua_rawseti(L, -2, ++i);
  }
  lua_pushliteral(L, "bump");
  lua_rawseti(L, -2, ++i);
  lua_setfield(L, tv, "movers");
  tvlua::pushValidateRecording(L);
  lua_setfield(L, tv, "validateRecording");
  tvlua::pushRecordingItems(L);
  lua_setfield(L, tv, "recordingItems");
  tvlua::pushRecordingNudges(L);
  lua_setfield(L, tv, "recordingNudges");
  tvlua::pushAutoRecord(L, tv);
  tvlua::pushFastPathInfo(L, tv);
  lua_pushliteral(L, "tunnelvision 0.2");
  lua_setfield(L, tv, "_VERSION");
  // So that `require 'tunnelvision.bump'` after `require 'tunnelvision'` finds this module even
  // where no loader would find tunnelvision.so by that name.
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
  tvlua::recordFromEnvironment(L);
  lua_settop(L, tv);
  return 1;
}
