// bump.lua 3.1.7's World API on a tv::World: the same names, arguments, return values and
// errors. Moves go through the core (exact contact, no seam snags, never tunnelling); `project`
// lists a leg's collisions as bump's does, from the core's exact sweep.

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/bump.hpp"
#include "tv/sweep.hpp"

namespace tvlua {
namespace {

// Calls the Lua function below its `nargs` arguments; a raising one becomes LuaRaised.
void callLua(lua_State* L, int nargs, int nresults) {
  if (lua_pcall(L, nargs, nresults, 0) != 0) throw LuaRaised{};
}

// A query filter's verdict on one item: filter(item) truthy (true when there is no filter).
bool queryAccepts(lua_State* L, int filterIdx, int slotToItem, tv::ItemId id) {
  if (filterIdx == 0) return true;
  lua_pushvalue(L, filterIdx);
  lua_rawgeti(L, slotToItem, static_cast<int>(id.index) + 1);
  callLua(L, 1, 1);
  const bool yes = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return yes;
}

tv::Rect checkRect(lua_State* L, int first) {
  const double x = checkFinite(L, first, "x");
  const double y = checkFinite(L, first + 1, "y");
  const double w = checkPositive(L, first + 2, "w");
  const double h = checkPositive(L, first + 3, "h");
  return {x, y, w, h};
}

// [SECTION] items --------------------------------------------------------------------------------

int add(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  pushEnv(L, 1, kItemToSlot);
  const int map = lua_gettop(L);
  if (findSlot(L, map, 2) >= 0) {
    const char* v = describe(L, 2, false);
    luaL_error(L, "Item %s added to the world twice.", v);
  }
  const tv::Rect r = checkRect(L, 3);
  checkNotBusy(L, w, "add");
  pushEnv(L, 1, kSlotToItem);
  const tv::ItemId id = w.world.add(r);
  // Lua's side after the core's: an add the core refused changed nothing.
  lua_pushvalue(L, 2);
  lua_pushnumber(L, id.index);
  lua_rawset(L, map);
  lua_pushvalue(L, 2);
  lua_rawseti(L, -2, static_cast<int>(id.index) + 1);
  moveCells(L, 1, w, id.index, &r);
  touched(w);
  if (w.recorder) labelItem(L, 1, w, 2, id);
  lua_settop(L, 2);
  return 1;
}

int remove(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "getting its rect");
  checkNotBusy(L, w, "remove");
  w.world.remove(id);
  pushEnv(L, 1, kItemToSlot);
  lua_pushvalue(L, 2);
  lua_pushnil(L);
  lua_rawset(L, -3);
  pushEnv(L, 1, kSlotToItem);
  lua_pushnil(L);
  lua_rawseti(L, -2, static_cast<int>(id.index) + 1);
  moveCells(L, 1, w, id.index, nullptr);
  touched(w);
  return 0;
}

int update(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "getting its rect");
  const tv::Rect old = w.world.rect(id);
  const tv::Rect r{checkFinite(L, 3, "x"), checkFinite(L, 4, "y"), optPositive(L, 5, "w", old.w),
                   optPositive(L, 6, "h", old.h)};
  checkNotBusy(L, w, "update");
  if (r == old) return 0;
  w.world.update(id, r);
  moveCells(L, 1, w, id.index, &r);
  touched(w);
  return 0;
}

int getRect(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::Rect r = w.world.rect(requireItem(L, w, 1, 2, "getting its rect"));
  lua_pushnumber(L, r.x);
  lua_pushnumber(L, r.y);
  lua_pushnumber(L, r.w);
  lua_pushnumber(L, r.h);
  return 4;
}

int hasItem(lua_State* L) {
  checkWorld(L, 1);
  if (lua_isnoneornil(L, 2)) {
    lua_pushboolean(L, 0);
    return 1;
  }
  pushEnv(L, 1, kItemToSlot);
  lua_pushboolean(L, findSlot(L, lua_gettop(L), 2) >= 0);
  return 1;
}

int getItems(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  pushEnv(L, 1, kSlotToItem);
  const int items = lua_gettop(L);
  lua_createtable(L, static_cast<int>(w.world.count()), 0);
  int n = 0;
  // In add order, as every list this module returns.
  Lease s(w);
  w.world.forEachItem([&](tv::ItemId id, const tv::Rect&) { s->items.push_back(id); });
  std::sort(s->items.begin(), s->items.end(),
            [&](tv::ItemId a, tv::ItemId b) { return w.world.order(a) < w.world.order(b); });
  for (const tv::ItemId id : s->items) {
    lua_rawgeti(L, items, static_cast<int>(id.index) + 1);
    lua_rawseti(L, -2, ++n);
  }
  lua_pushinteger(L, n);
  return 2;
}

int countItems(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(checkWorld(L, 1).world.count()));
  return 1;
}

int countCells(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  lua_pushinteger(L, static_cast<lua_Integer>(countBumpCells(L, 1, w)));
  return 1;
}

int toWorld(lua_State* L) {
  const double size = checkWorld(L, 1).world.cellSize();
  const double cx = checkFinite(L, 2, "cx"), cy = checkFinite(L, 3, "cy");
  lua_pushnumber(L, (cx - 1) * size);
  lua_pushnumber(L, (cy - 1) * size);
  return 2;
}

int toCell(lua_State* L) {
  const double size = checkWorld(L, 1).world.cellSize();
  const double x = checkFinite(L, 2, "x"), y = checkFinite(L, 3, "y");
  lua_pushnumber(L, std::floor(x / size) + 1);
  lua_pushnumber(L, std::floor(y / size) + 1);
  return 2;
}

// [SECTION] moving -------------------------------------------------------------------------------

// The shared part of move and check: arguments 2..5 are item, goalX, goalY, filter.
struct MoveCall {
  LuaWorld* w;
  tv::ItemId id;
  tv::Vec2 goal;
  CallContext ctx;
};

MoveCall prepareMove(lua_State* L, const char* what) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "getting its rect");
  const tv::Vec2 goal{checkFinite(L, 3, "goalX"), checkFinite(L, 4, "goalY")};
  const bool hasFilter = optFunction(L, 5, "filter");
  checkNotBusy(L, w, what);
  lua_settop(L, 5);
  pushEnv(L, 1, kSlotToItem);  // 6
  lua_pushnil(L);              // 7: collision tables Lua responses saw, made on demand
  MoveCall m{&w, id, goal, {}};
  m.ctx.L = L;
  m.ctx.world = &w;
  m.ctx.worldIdx = 1;
  m.ctx.itemIdx = 2;
  m.ctx.filterIdx = hasFilter ? 5 : 0;
  m.ctx.slotToItem = 6;
  m.ctx.bump = w.bumpRules && !w.mover;
  m.ctx.origin = w.world.rect(id);
  m.ctx.item = id;
  if (m.ctx.bump && w.luaResponses) {
    // bump's visitedFilter, which responses added from Lua receive, calls this move's filter.
    lua_getfenv(L, 1);
    if (hasFilter) {
      lua_pushvalue(L, 5);
    } else {
      lua_pushboolean(L, 0);
    }
    lua_rawseti(L, -2, kFilter);
    lua_pop(L, 1);
  }
  return m;
}

// Pushes bump's `cols, len` for a move's collisions (tables Lua responses saw are reused).
int pushCollisions(lua_State* L, const MoveCall& m, std::span<const tv::Collision> cols) {
  lua_createtable(L, static_cast<int>(cols.size()), 0);
  const int out = lua_gettop(L);
  for (std::size_t i = 0; i < cols.size(); ++i) {
    bool reused = false;
    if (m.ctx.savedCols != 0) {
      lua_rawgeti(L, m.ctx.savedCols, static_cast<int>(i) + 1);
      reused = !lua_isnil(L, -1);
      if (!reused) lua_pop(L, 1);
    }
    if (!reused) pushCollision(L, 1, m.ctx.slotToItem, 2, cols[i], true);
    lua_rawseti(L, out, static_cast<int>(i) + 1);
  }
  lua_pushinteger(L, static_cast<lua_Integer>(cols.size()));
  return 2;
}

void makeSavedCols(lua_State* L, MoveCall& m) {
  // Only responses added from Lua see collision tables, and only a plain move keeps one
  // collision per response (a substep mover's pieces do not).
  if (!m.w->luaResponses || m.w->mover) return;
  lua_newtable(L);
  lua_replace(L, 7);
  m.ctx.savedCols = 7;
}

int moveOrCheck(lua_State* L, bool commit) {
  MoveCall m = prepareMove(L, commit ? "move" : "check");
  makeSavedCols(L, m);
  LuaWorld& w = *m.w;
  const tv::Rect before = w.world.rect(m.id);
  tv::MoveResult r;
  {
    const CallScope scope(m.ctx);
    const Busy busy(w);
    const LuaFilter filter{&m.ctx};
    tv::MoveOptions options;
    if (m.ctx.bump) options.semantics = tv::MoveSemantics::bump;
    if (!commit) {
      r = w.world.check(m.id, m.goal, filter, options);
    } else if (w.mover) {
      r = w.mover->move(w.world, m.id, m.goal, filter);
    } else {
      r = w.world.move(m.id, m.goal, filter, options);
    }
  }
  if (commit) {
    const tv::Rect after = before.at(r.position);
    moveCells(L, 1, w, m.id.index, &after);
    touched(w);
  }
  lua_pushnumber(L, r.position.x);
  lua_pushnumber(L, r.position.y);
  return 2 + pushCollisions(L, m, r.collisions);
}

int move(lua_State* L) { return moveOrCheck(L, true); }
int check(lua_State* L) { return moveOrCheck(L, false); }

// world:project(item, x,y,w,h, goalX, goalY, filter) -> cols, len: every collision of the
// straight leg, as the core's World::hitsAlong lists them — in the order the world's own moves
// take them (exact times of impact, then ordinary hits before exact corner hits, then add
// order; under bump's rules, bump's order).
int project(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const tv::Rect r = checkRect(L, 3);
  const tv::Vec2 goal{optFinite(L, 7, "goalX", r.x), optFinite(L, 8, "goalY", r.y)};
  const bool hasFilter = optFunction(L, 9, "filter");
  lua_settop(L, 9);
  pushEnv(L, 1, kSlotToItem);  // 10
  tv::ItemId self;
  if (!lua_isnil(L, 2) && !(lua_type(L, 2) == LUA_TNUMBER && std::isnan(lua_tonumber(L, 2)))) {
    pushEnv(L, 1, kItemToSlot);
    const std::int64_t slot = findSlot(L, lua_gettop(L), 2);
    lua_pop(L, 1);
    if (slot >= 0) self = w.world.idAt(static_cast<std::uint32_t>(slot));
  }
  CallContext ctx;
  ctx.L = L;
  ctx.world = &w;
  ctx.worldIdx = 1;
  ctx.itemIdx = lua_isnil(L, 2) ? 0 : 2;
  ctx.filterIdx = hasFilter ? 9 : 0;
  ctx.slotToItem = 10;
  if (w.bumpRules) {
    // A response added from Lua, projecting its item inside a move: where it projects from is
    // where the move's next leg starts.
    CallContext* outer = w.current;
    if (outer != nullptr && outer->inResponse && self.valid() && self == outer->item) {
      outer->projected = true;
      outer->projectedFrom = r.position();
    }
  }
  Lease s(w);
  {
    const CallScope scope(ctx);
    const Busy busy(w);
    const LuaFilter filter{&ctx};
    tv::MoveOptions options;
    if (w.bumpRules) options.semantics = tv::MoveSemantics::bump;
    w.world.hitsAlong(self, r, goal, filter, s->cols, options);
  }
  lua_createtable(L, static_cast<int>(s->cols.size()), 0);
  int n = 0;
  for (const tv::Collision& c : s->cols) {
    pushCollision(L, 1, 10, ctx.itemIdx, c, false);
    lua_rawseti(L, -2, ++n);
  }
  lua_pushinteger(L, n);
  return 2;
}

// [SECTION] queries ------------------------------------------------------------------------------

int queryRect(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const tv::Rect r = checkRect(L, 2);
  const int filterIdx = optFunction(L, 6, "filter") ? 6 : 0;
  lua_settop(L, 6);
  pushEnv(L, 1, kSlotToItem);  // 7
  lua_newtable(L);             // 8
  int n = 0;
  {
    Lease s(w);
    w.world.queryRect(r, s->items);
    for (const tv::ItemId id : s->items) {
      if (!queryAccepts(L, filterIdx, 7, id)) continue;
      lua_rawgeti(L, 7, static_cast<int>(id.index) + 1);
      lua_rawseti(L, 8, ++n);
    }
  }
  lua_pushinteger(L, n);
  return 2;
}

int queryPoint(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const tv::Vec2 p{checkFinite(L, 2, "x"), checkFinite(L, 3, "y")};
  const int filterIdx = optFunction(L, 4, "filter") ? 4 : 0;
  lua_settop(L, 4);
  pushEnv(L, 1, kSlotToItem);  // 5
  lua_newtable(L);             // 6
  int n = 0;
  {
    std::vector<tv::ItemId> found;
    if (w.bumpRules) {
      tv::bump::queryPoint(w.world, p, found);
    } else {
      found = w.world.queryPoint(p);
    }
    for (const tv::ItemId id : found) {
      if (!queryAccepts(L, filterIdx, 5, id)) continue;
      lua_rawgeti(L, 5, static_cast<int>(id.index) + 1);
      lua_rawseti(L, 6, ++n);
    }
  }
  lua_pushinteger(L, n);
  return 2;
}

int querySegmentImpl(lua_State* L, bool withCoords) {
  LuaWorld& w = checkWorld(L, 1);
  const tv::Vec2 a{checkFinite(L, 2, "x1"), checkFinite(L, 3, "y1")};
  const tv::Vec2 b{checkFinite(L, 4, "x2"), checkFinite(L, 5, "y2")};
  const int filterIdx = optFunction(L, 6, "filter") ? 6 : 0;
  lua_settop(L, 6);
  pushEnv(L, 1, kSlotToItem);  // 7
  lua_newtable(L);             // 8
  int n = 0;
  {
    std::vector<tv::SegmentHit> hits;
    if (w.bumpRules) {
      tv::bump::querySegment(w.world, a, b, hits);
    } else {
      hits = w.world.querySegment(a, b);
    }
    for (const tv::SegmentHit& h : hits) {
      if (!queryAccepts(L, filterIdx, 7, h.item)) continue;
      if (!withCoords) {
        lua_rawgeti(L, 7, static_cast<int>(h.item.index) + 1);
      } else {
        lua_createtable(L, 0, 7);
        lua_rawgeti(L, 7, static_cast<int>(h.item.index) + 1);
        lua_setfield(L, -2, "item");
        lua_pushnumber(L, h.t0);
        lua_setfield(L, -2, "ti1");
        lua_pushnumber(L, h.t1);
        lua_setfield(L, -2, "ti2");
        lua_pushnumber(L, h.entry.x);
        lua_setfield(L, -2, "x1");
        lua_pushnumber(L, h.entry.y);
        lua_setfield(L, -2, "y1");
        lua_pushnumber(L, h.exit.x);
        lua_setfield(L, -2, "x2");
        lua_pushnumber(L, h.exit.y);
        lua_setfield(L, -2, "y2");
      }
      lua_rawseti(L, 8, ++n);
    }
  }
  lua_pushinteger(L, n);
  return 2;
}

int querySegment(lua_State* L) { return querySegmentImpl(L, false); }
int querySegmentWithCoords(lua_State* L) { return querySegmentImpl(L, true); }

// [SECTION] responses ----------------------------------------------------------------------------

// world:addResponse(name, fn): fn(world, col, x,y,w,h, goalX, goalY, filter) -> goalX, goalY
// [, cols, len]. Re-adding a name replaces its function, as in bump.
int addResponse(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  if (lua_type(L, 2) != LUA_TSTRING) {
    const char* v = describe(L, 2);
    luaL_error(L, "name must be a string, but was %s (a %s)", v, luaL_typename(L, 2));
  }
  if (lua_type(L, 3) != LUA_TFUNCTION) {
    const char* v = describe(L, 3);
    luaL_error(L, "response must be a function, but was %s (a %s)", v, luaL_typename(L, 3));
  }
  checkNotBusy(L, w, "addResponse");
  lua_settop(L, 3);
  pushEnv(L, 1, kNameToId);  // 4
  pushEnv(L, 1, kIdToFn);    // 5
  pushEnv(L, 1, kIdToName);  // 6
  lua_pushvalue(L, 2);
  lua_rawget(L, 4);
  const bool known = lua_type(L, -1) == LUA_TNUMBER;
  const auto id = known ? static_cast<tv::ResponseId>(lua_tonumber(L, -1)) : tv::ResponseId{0};
  lua_pop(L, 1);
  tv::ResponseId builtin = 0;
  const bool isBuiltinFn = isBuiltinResponse(lua_tocfunction(L, 3), builtin);
  if (known && id < tv::response::kBuiltinCount && isBuiltinFn && builtin == id) {
    return 0;  // re-adding a built-in under its own name
  }
  if (known && id >= tv::response::kBuiltinCount && isBuiltinFn &&
      std::string_view(lua_tostring(L, 2)) == tv::kBuiltinResponses[builtin].name) {
    // A built-in given back its own name: the core's built-in again.
    lua_pushvalue(L, 2);
    lua_pushnumber(L, builtin);
    lua_rawset(L, 4);
    if (builtin == tv::response::slide) w.slide = builtin;
    return 0;
  }
  if (known && id >= tv::response::kBuiltinCount) {
    lua_pushvalue(L, 3);
    lua_rawseti(L, 5, id);  // a new function for a response added from Lua
    return 0;
  }
  // A new name, or a built-in's name given a function of the user's: a core response that
  // calls the Lua function. The core's names are unique; a replaced built-in keeps its own.
  std::string coreName = lua_tostring(L, 2);
  if (known) coreName += " (from Lua)";
  const tv::ResponseId fresh = w.world.addResponse(coreName, luaResponse, &w);
  lua_pushvalue(L, 3);
  lua_rawseti(L, 5, fresh);
  lua_pushvalue(L, 2);
  lua_rawseti(L, 6, fresh);
  lua_pushvalue(L, 2);
  lua_pushnumber(L, fresh);
  lua_rawset(L, 4);
  w.luaResponses = true;
  if (std::string_view(lua_tostring(L, 2)) == "slide") w.slide = fresh;
  return 0;
}

}  // namespace

void registerWorldMethods(lua_State* L, int methodsIdx) {
  const luaL_Reg methods[] = {
      {"add", guarded<add>},
      {"remove", guarded<remove>},
      {"update", guarded<update>},
      {"move", guarded<move>},
      {"check", guarded<check>},
      {"project", guarded<project>},
      {"getRect", guarded<getRect>},
      {"hasItem", guarded<hasItem>},
      {"getItems", guarded<getItems>},
      {"countItems", guarded<countItems>},
      {"countCells", guarded<countCells>},
      {"toWorld", guarded<toWorld>},
      {"toCell", guarded<toCell>},
      {"queryRect", guarded<queryRect>},
      {"queryPoint", guarded<queryPoint>},
      {"querySegment", guarded<querySegment>},
      {"querySegmentWithCoords", guarded<querySegmentWithCoords>},
      {"addResponse", guarded<addResponse>},
      {nullptr, nullptr},
  };
  setFunctions(L, methodsIdx, methods);
}

}  // namespace tvlua
