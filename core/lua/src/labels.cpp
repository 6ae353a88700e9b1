// What the debugger calls an item: a name a person recognises, never a memory address. A game
// written against bump.lua rarely names its items, but its objects usually say what they are:
// a `name` field, a class (middleclass, 30log...: `item.class.name`), or a `type`, `kind` or
// `class` string. Items without any of these get their Lua type and a serial ("table 17"). A
// label given twice in a world gets a serial from the second on ("Stone", "Stone 2"), so that
// each item has its own. The category is the class, or the first of those string fields, or
// the name.

#include <string>

#include "boundary.hpp"
#include "lua_world.hpp"

namespace tvlua {
namespace {

// t[field] when it is a string (pushed), else nothing pushed and false. Reads through __index
// (a class's fields live there), but only on tables.
bool stringField(lua_State* L, int t, const char* field) {
  lua_getfield(L, t, field);
  if (lua_type(L, -1) == LUA_TSTRING) return true;
  lua_pop(L, 1);
  return false;
}

// (item, serials) -> label, category; run protected (fields may have metamethods).
int computeLabel(lua_State* L) {
  lua_settop(L, 2);
  const int type = lua_type(L, 1);
  if (type == LUA_TSTRING) {  // bump's examples use strings: the string is the name
    lua_pushvalue(L, 1);
    lua_pushliteral(L, "");
    return 2;
  }
  if (type == LUA_TNUMBER || type == LUA_TBOOLEAN) {
    lua_getglobal(L, "tostring");
    lua_pushvalue(L, 1);
    lua_call(L, 1, 1);
    lua_pushliteral(L, "");
    return 2;
  }
  int base = 0;      // stack index of the label's base (a class or field name)
  int category = 0;  // stack index of the category
  int name = 0;
  if (type == LUA_TTABLE) {
    if (stringField(L, 1, "name")) name = lua_gettop(L);
    lua_getfield(L, 1, "class");
    if (lua_istable(L, -1) && stringField(L, lua_gettop(L), "name")) {
      base = category = lua_gettop(L);
    }
    for (const char* field : {"type", "kind", "class"}) {
      if (category != 0) break;
      if (stringField(L, 1, field)) base = category = lua_gettop(L);
    }
  }
  if (name != 0) {
    // A name is the label; a name already given in this world gets a serial ("Stone 2").
    lua_pushvalue(L, name);
    lua_rawget(L, 2);
    const lua_Number n = lua_tonumber(L, -1) + 1;
    lua_pop(L, 1);
    lua_pushvalue(L, name);
    lua_pushnumber(L, n);
    lua_rawset(L, 2);
    if (n > 1) {
      lua_pushfstring(L, "%s %d", lua_tostring(L, name), static_cast<int>(n));
    } else {
      lua_pushvalue(L, name);
    }
    if (category == 0) category = name;  // the name says what it is, when nothing else does
  } else {
    if (base == 0) {
      lua_pushstring(L, lua_typename(L, type));
      base = lua_gettop(L);
    }
    // The serial counts the items of this world that got this base so far: "Guardian 3".
    lua_pushvalue(L, base);
    lua_rawget(L, 2);
    const lua_Number n = lua_tonumber(L, -1) + 1;
    lua_pop(L, 1);
    lua_pushvalue(L, base);
    lua_pushnumber(L, n);
    lua_rawset(L, 2);
    lua_pushfstring(L, "%s %d", lua_tostring(L, base), static_cast<int>(n));
  }
  if (category != 0) {
    lua_pushvalue(L, category);
  } else {
    lua_pushliteral(L, "");
  }
  return 2;
}

}  // namespace

void labelItem(lua_State* L, int worldIdx, LuaWorld& w, int itemIdx, tv::ItemId id) {
  const int top = lua_gettop(L);
  lua_pushcfunction(L, computeLabel);
  lua_pushvalue(L, itemIdx);
  pushEnv(L, worldIdx, kSerials);
  const bool ok = lua_pcall(L, 2, 2, 0) == 0 && lua_isstring(L, -2) && lua_isstring(L, -1);
  // A label is for the debugger's eyes: an item whose fields raise is recorded unlabelled.
  if (ok) w.recorder->label(id, lua_tostring(L, -2), lua_tostring(L, -1));
  lua_settop(L, top);
}

}  // namespace tvlua
