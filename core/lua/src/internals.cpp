// bump.lua's internal tables, for the tools that read them (bump_debug.lua draws `world.rows`;
// inspectors list `world.rects`): `rows[cy][cx]` = cell {x, y, itemCount, items = {[item] =
// true}}, `nonEmptyCells` = {[cell] = true}, `rects[item]` = {x, y, w, h}, `responses[name]` =
// function. A world keeps none of them while it runs: reading one builds it from the world,
// once per change (moves and updates bump a counter; a read after one rebuilds). The tables are
// plain Lua tables, kept per world and refilled in place, so a tool holding `world.rows` sees
// the world as of the last read of `world.rows`. Writing to them changes nothing in the world.

#include <vector>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/bump.hpp"

namespace tvlua {
namespace {

// Slots of env[kInternals].
enum Internal : int { kRows = 1, kRects, kNonEmpty, kResponses, kBuiltVersion };

// Empties table t (at index t) without replacing it.
void clear(lua_State* L, int t) {
  lua_pushnil(L);
  while (lua_next(L, t) != 0) {
    lua_pop(L, 1);
    lua_pushvalue(L, -1);
    lua_pushnil(L);
    lua_rawset(L, t);
  }
}

// env[kInternals][slot], created (with metatable mode, when given) if missing; pushed.
void pushTable(lua_State* L, int internals, int slot, const char* mode) {
  lua_rawgeti(L, internals, slot);
  if (lua_istable(L, -1)) return;
  lua_pop(L, 1);
  lua_newtable(L);
  if (mode != nullptr) {
    lua_createtable(L, 0, 1);
    lua_pushstring(L, mode);
    lua_setfield(L, -2, "__mode");
    lua_setmetatable(L, -2);
  }
  lua_pushvalue(L, -1);
  lua_rawseti(L, internals, slot);
}

void setWeak(lua_State* L, const char* mode) {
  lua_createtable(L, 0, 1);
  lua_pushstring(L, mode);
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
}

// rows, nonEmptyCells and rects from the world, as bump would hold them now.
void build(lua_State* L, int worldIdx, LuaWorld& w, int internals) {
  pushTable(L, internals, kRows, nullptr);
  const int rows = lua_gettop(L);
  pushTable(L, internals, kNonEmpty, nullptr);
  const int nonEmpty = lua_gettop(L);
  pushTable(L, internals, kRects, nullptr);
  const int rects = lua_gettop(L);
  clear(L, rows);
  clear(L, nonEmpty);
  clear(L, rects);
  pushEnv(L, worldIdx, kSlotToItem);
  const int items = lua_gettop(L);
  const double size = w.world.cellSize();
  // In add order, so that rebuilding the same world gives the same tables.
  std::vector<tv::ItemId> ids;
  w.world.forEachItem([&](tv::ItemId id, const tv::Rect&) { ids.push_back(id); });
  std::sort(ids.begin(), ids.end(),
            [&](tv::ItemId a, tv::ItemId b) { return w.world.order(a) < w.world.order(b); });
  for (const tv::ItemId id : ids) {
    const tv::Rect r = w.world.rect(id);
    lua_rawgeti(L, items, static_cast<int>(id.index) + 1);
    const int item = lua_gettop(L);
    lua_pushvalue(L, item);
    lua_createtable(L, 0, 4);
    lua_pushnumber(L, r.x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, r.y);
    lua_setfield(L, -2, "y");
    lua_pushnumber(L, r.w);
    lua_setfield(L, -2, "w");
    lua_pushnumber(L, r.h);
    lua_setfield(L, -2, "h");
    lua_rawset(L, rects);
    const tv::bump::Cells c = tv::bump::cellsOf(size, r);
    for (double cy = c.top; cy <= c.bottom; ++cy) {
      lua_pushnumber(L, cy);
      lua_rawget(L, rows);
      if (lua_isnil(L, -1)) {  // a new row (weak-valued, as bump's)
        lua_pop(L, 1);
        lua_newtable(L);
        setWeak(L, "v");
        lua_pushnumber(L, cy);
        lua_pushvalue(L, -2);
        lua_rawset(L, rows);
      }
      const int row = lua_gettop(L);
      for (double cx = c.left; cx <= c.right; ++cx) {
        lua_pushnumber(L, cx);
        lua_rawget(L, row);
        if (lua_isnil(L, -1)) {
          lua_pop(L, 1);
          lua_createtable(L, 0, 4);
          lua_pushnumber(L, cx);
          lua_setfield(L, -2, "x");
          lua_pushnumber(L, cy);
          lua_setfield(L, -2, "y");
          lua_pushnumber(L, 0);
          lua_setfield(L, -2, "itemCount");
          lua_newtable(L);
          setWeak(L, "k");
          lua_setfield(L, -2, "items");
          lua_pushnumber(L, cx);
          lua_pushvalue(L, -2);
          lua_rawset(L, row);
          lua_pushvalue(L, -1);
          lua_pushboolean(L, 1);
          lua_rawset(L, nonEmpty);
        }
        lua_getfield(L, -1, "itemCount");
        lua_pushnumber(L, lua_tonumber(L, -1) + 1);
        lua_setfield(L, -3, "itemCount");
        lua_pop(L, 1);
        lua_getfield(L, -1, "items");
        lua_pushvalue(L, item);
        lua_pushboolean(L, 1);
        lua_rawset(L, -3);
        lua_pop(L, 2);
      }
      lua_pop(L, 1);
    }
    lua_settop(L, item - 1);
  }
  lua_settop(L, rows - 1);
}

// responses: name -> function, bump's own for the built-ins (module upvalue).
void buildResponses(lua_State* L, int worldIdx, int internals) {
  pushTable(L, internals, kResponses, nullptr);
  const int out = lua_gettop(L);
  clear(L, out);
  pushEnv(L, worldIdx, kNameToId);
  const int names = lua_gettop(L);
  pushEnv(L, worldIdx, kIdToFn);
  const int fns = lua_gettop(L);
  pushEnv(L, worldIdx, kBumpResponses);
  const int builtins = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, names) != 0) {
    const auto id = static_cast<int>(lua_tonumber(L, -1));
    lua_pop(L, 1);
    lua_pushvalue(L, -1);
    if (id < tv::response::kBuiltinCount) {
      lua_pushvalue(L, -1);
      lua_rawget(L, builtins);
    } else {
      lua_rawgeti(L, fns, id);
    }
    lua_rawset(L, out);
  }
  lua_settop(L, out - 1);
}

}  // namespace

int readInternals(lua_State* L) {
  const int worldIdx = lua_upvalueindex(1);
  LuaWorld& w = checkWorld(L, worldIdx);
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  const std::string_view key = lua_tostring(L, 2);
  int slot = 0;
  if (key == "rows") slot = kRows;
  if (key == "rects") slot = kRects;
  if (key == "nonEmptyCells") slot = kNonEmpty;
  if (key == "responses") slot = kResponses;
  if (slot == 0) return 0;
  pushEnv(L, worldIdx, kInternals);
  const int internals = lua_gettop(L);
  if (slot == kResponses) {
    buildResponses(L, worldIdx, internals);
  } else {
    lua_rawgeti(L, internals, kBuiltVersion);
    const bool fresh = lua_type(L, -1) == LUA_TNUMBER &&
                       static_cast<std::uint64_t>(lua_tonumber(L, -1)) == w.version;
    lua_pop(L, 1);
    if (!fresh) {
      build(L, worldIdx, w, internals);
      lua_pushnumber(L, static_cast<lua_Number>(w.version));
      lua_rawseti(L, internals, kBuiltVersion);
    }
  }
  lua_rawgeti(L, internals, slot);
  return 1;
}

}  // namespace tvlua
