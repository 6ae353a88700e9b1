#pragma once
// The boundary between Lua and C++: no C++ exception may leave a lua_CFunction (under LuaJIT it
// turns into the message-less "C++ exception"; under PUC Lua 5.1 it calls std::terminate), and
// a Lua error is a longjmp in PUC Lua that skips C++ destructors. So every function Lua calls
// is wrapped by `guarded`, which turns a C++ exception into a Lua error only after every C++
// object of the call has been destroyed, and argument checks raise before such objects exist.

#include <cmath>
#include <cstdio>
#include <exception>

#include <lua.hpp>

namespace tvlua {

/// Thrown by C++ code that called Lua (a filter, a response) when the Lua code raised: the
/// error value is left on top of the Lua stack, and `guarded` raises it again once the core
/// has unwound (and so left the world as it was).
struct LuaRaised {};

template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
  char message[512];
  bool raised = false;
  try {
    return F(L);
  } catch (const LuaRaised&) {
    raised = true;  // the Lua error value is on top of the stack
  } catch (const std::exception& e) {
    std::snprintf(message, sizeof message, "%s", e.what());
  }
  // Raised only here, once the handler has ended: a longjmp (PUC Lua) out of a catch block
  // would leave the C++ exception alive forever. Under LuaJIT a Lua error is a foreign
  // exception: neither handler above sees it, so it propagates untouched.
  if (!raised) lua_pushstring(L, message);
  return lua_error(L);
}

/// What a value is, for error messages: "-1", "nil", "'abc'", "table: 0x5581..." (tostring,
/// with strings quoted unless `quote` is false, as bump prints items).
inline const char* describe(lua_State* L, int idx, bool quote = true) {
  idx = idx < 0 && idx > LUA_REGISTRYINDEX ? lua_gettop(L) + idx + 1 : idx;
  switch (lua_type(L, idx)) {
    case LUA_TNONE:
    case LUA_TNIL:
      return "nil";
    case LUA_TNUMBER:
      {
        char buf[64];  // as Lua's tostring prints it, but one spelling of NaN
        const double v = lua_tonumber(L, idx);
        std::snprintf(buf, sizeof buf, "%.14g", std::isnan(v) ? std::fabs(v) : v);
        return lua_pushstring(L, buf), lua_tostring(L, -1);
      }
    case LUA_TBOOLEAN:
      return lua_toboolean(L, idx) ? "true" : "false";
    case LUA_TSTRING:
      if (!quote) return lua_tostring(L, idx);
      return lua_pushfstring(L, "'%s'", lua_tostring(L, idx)), lua_tostring(L, -1);
    default:
      if (luaL_callmeta(L, idx, "__tostring") && lua_isstring(L, -1)) return lua_tostring(L, -1);
      return lua_pushfstring(L, "%s: %p", luaL_typename(L, idx), lua_topointer(L, idx)),
             lua_tostring(L, -1);
  }
}

/// A number argument: "x must be a number, but was nil (a nil)" / "... a finite number, but
/// was nan".
inline double checkFinite(lua_State* L, int idx, const char* name) {
  if (lua_type(L, idx) != LUA_TNUMBER) {
    const char* v = describe(L, idx);
    luaL_error(L, "%s must be a number, but was %s (a %s)", name, v, luaL_typename(L, idx));
  }
  const double v = lua_tonumber(L, idx);
  if (!std::isfinite(v)) luaL_error(L, "%s must be a finite number, but was %s", name, describe(L, idx));
  return v;
}

/// A size argument: "w must be a positive number, but was -1".
inline double checkPositive(lua_State* L, int idx, const char* name) {
  if (lua_type(L, idx) != LUA_TNUMBER) {
    const char* v = describe(L, idx);
    luaL_error(L, "%s must be a positive number, but was %s (a %s)", name, v, luaL_typename(L, idx));
  }
  const double v = lua_tonumber(L, idx);
  if (!(v > 0) || !std::isfinite(v)) {
    luaL_error(L, "%s must be a positive number, but was %s", name, describe(L, idx));
  }
  return v;
}

/// An optional number: `fallback` when nil or absent.
inline double optFinite(lua_State* L, int idx, const char* name, double fallback) {
  return lua_isnoneornil(L, idx) ? fallback : checkFinite(L, idx, name);
}
inline double optPositive(lua_State* L, int idx, const char* name, double fallback) {
  return lua_isnoneornil(L, idx) ? fallback : checkPositive(L, idx, name);
}

/// An optional function argument (a filter): false when nil or absent.
inline bool optFunction(lua_State* L, int idx, const char* name) {
  if (lua_isnoneornil(L, idx)) return false;
  if (lua_type(L, idx) != LUA_TFUNCTION && !luaL_getmetafield(L, idx, "__call")) {
    const char* v = describe(L, idx);
    luaL_error(L, "%s must be a function, but was %s (a %s)", name, v, luaL_typename(L, idx));
  }
  if (lua_type(L, idx) != LUA_TFUNCTION) lua_pop(L, 1);  // the __call luaL_getmetafield pushed
  return true;
}

}  // namespace tvlua
