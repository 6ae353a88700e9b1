// What a platformer asks after each move, on every world (`tunnelvision` and, as an extension of
// bump's API, `tunnelvision.bump`): contact events (tv::Contacts), the ground under a body, and
// a move with corner correction (tv::moveCornered).
//
//   local x, y, cols, len, dx = world:moveCornered(player, goalX, goalY, filter [, maxNudge])
//   local events, n = world:contacts(player, filter, cols, {oneWay = {plank}, coyote = 6})
//   local kind, ground, nx, ny, vx, vy = world:ground(player)   -- 'ground', 'oneWay'...

#include <cstdint>
#include <cstring>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/contact.hpp"
#include "tv/corner.hpp"

namespace tvlua {
namespace {

const char* phaseName(tv::ContactPhase p) {
  switch (p) {
    case tv::ContactPhase::begin:
      return "begin";
    case tv::ContactPhase::persist:
      return "persist";
    case tv::ContactPhase::end:
      return "end";
  }
  return "end";
}

const char* groundName(tv::GroundKind k) {
  switch (k) {
    case tv::GroundKind::air:
      return "air";
    case tv::GroundKind::ground:
      return "ground";
    case tv::GroundKind::oneWay:
      return "oneWay";
    case tv::GroundKind::solid:
      return "solid";
    case tv::GroundKind::coyote:
      return "coyote";
  }
  return "air";
}

// Pushes the item in `slot`, or nil when the slot no longer holds it (a removed item's end).
void pushItem(lua_State* L, LuaWorld& w, int slotToItem, tv::ItemId id) {
  if (w.world.has(id)) {
    lua_rawgeti(L, slotToItem, static_cast<int>(id.index) + 1);
  } else {
    lua_pushnil(L);
  }
}

// Items of the list at `listIdx` (nil: none) into `out`, skipping what is not in the world.
void readItems(lua_State* L, LuaWorld& w, int worldIdx, int listIdx, const char* name,
               std::vector<tv::ItemId>& out) {
  out.clear();
  if (lua_isnoneornil(L, listIdx)) return;
  if (lua_type(L, listIdx) != LUA_TTABLE)
    luaL_error(L, "%s must be a list of items, but was a %s", name, luaL_typename(L, listIdx));
  pushEnv(L, worldIdx, kItemToSlot);
  const int map = lua_gettop(L);
  const int n = static_cast<int>(lua_objlen(L, listIdx));
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, listIdx, i);
    const std::int64_t slot = findSlot(L, map, lua_gettop(L));
    lua_pop(L, 1);
    if (slot >= 0) out.push_back(w.world.idAt(static_cast<std::uint32_t>(slot)));
  }
  lua_pop(L, 1);
}

// The collisions of a move as Lua saw them (bump's cols: other, normal), for what it met.
void readCols(lua_State* L, LuaWorld& w, int worldIdx, int colsIdx, tv::ItemId item,
              std::vector<tv::Collision>& out) {
  out.clear();
  if (lua_isnoneornil(L, colsIdx)) return;
  if (lua_type(L, colsIdx) != LUA_TTABLE)
    luaL_error(L, "cols must be a move's collision list, but was a %s", luaL_typename(L, colsIdx));
  pushEnv(L, worldIdx, kItemToSlot);
  const int map = lua_gettop(L);
  const int n = static_cast<int>(lua_objlen(L, colsIdx));
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, colsIdx, i);
    const int col = lua_gettop(L);
    if (lua_type(L, col) != LUA_TTABLE) luaL_error(L, "cols[%d] must be a collision table", i);
    lua_getfield(L, col, "other");
    const std::int64_t slot = findSlot(L, map, lua_gettop(L));
    lua_getfield(L, col, "normal");
    tv::Collision c;
    c.item = item;
    if (lua_type(L, -1) == LUA_TTABLE) {
      lua_getfield(L, -1, "x");
      lua_getfield(L, -2, "y");
      c.normal = {lua_tonumber(L, -2), lua_tonumber(L, -1)};
      lua_pop(L, 2);
    }
    lua_settop(L, col - 1);
    if (slot >= 0) {
      c.other = w.world.idAt(static_cast<std::uint32_t>(slot));
      out.push_back(c);
    }
  }
  lua_pop(L, 1);
}

// world:contacts(item [, filter [, cols [, options]]]) -> events, n. Each event is a table
// {other = item (nil once removed), phase = 'begin'|'persist'|'end', normal = {x, y}, met}.
// options: {oneWay = {items}, solids = {items}, coyote = updates}.
int contacts(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "reading its contacts");
  const bool hasFilter = optFunction(L, 3, "filter");
  checkNotBusy(L, w, "contacts");
  lua_settop(L, 5);
  int coyote = 0;
  if (!lua_isnil(L, 5)) {
    if (lua_type(L, 5) != LUA_TTABLE)
      luaL_error(L, "options must be a table, but was a %s", luaL_typename(L, 5));
    lua_getfield(L, 5, "oneWay");
    readItems(L, w, 1, lua_gettop(L), "options.oneWay", w.oneWayItems);
    lua_getfield(L, 5, "solids");
    readItems(L, w, 1, lua_gettop(L), "options.solids", w.solidItems);
    lua_getfield(L, 5, "coyote");
    const double c = optFinite(L, lua_gettop(L), "options.coyote", 0);
    if (c < 0 || c > (1 << 20) || c != static_cast<int>(c))
      luaL_error(L, "options.coyote must be a whole number of updates in [0, 2^20], but was %f", c);
    coyote = static_cast<int>(c);
    lua_settop(L, 5);
  } else {
    w.oneWayItems.clear();
    w.solidItems.clear();
  }
  readCols(L, w, 1, 4, id, w.metCols);
  pushEnv(L, 1, kSlotToItem);  // 6
  CallContext ctx;
  ctx.L = L;
  ctx.world = &w;
  ctx.worldIdx = 1;
  ctx.itemIdx = 2;
  ctx.filterIdx = hasFilter ? 3 : 0;
  ctx.slotToItem = 6;
  ctx.item = id;
  std::span<const tv::ContactEvent> events;
  {
    const CallScope scope(ctx);
    const Busy busy(w);
    const LuaFilter filter{&ctx};
    tv::ContactOptions o;
    o.filter = filter;
    o.oneWay = w.oneWayItems;
    o.solids = w.solidItems;
    o.coyoteUpdates = coyote;
    events = w.contacts.update(w.world, id, o, w.metCols);
  }
  lua_createtable(L, static_cast<int>(events.size()), 0);
  const int out = lua_gettop(L);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const tv::ContactEvent& e = events[i];
    lua_createtable(L, 0, 4);
    pushItem(L, w, 6, e.other);
    lua_setfield(L, -2, "other");
    lua_pushstring(L, phaseName(e.phase));
    lua_setfield(L, -2, "phase");
    lua_createtable(L, 0, 2);
    lua_pushnumber(L, e.normal.x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, e.normal.y);
    lua_setfield(L, -2, "y");
    lua_setfield(L, -2, "normal");
    lua_pushboolean(L, e.met);
    lua_setfield(L, -2, "met");
    lua_rawseti(L, out, static_cast<int>(i) + 1);
  }
  lua_pushinteger(L, static_cast<lua_Integer>(events.size()));
  return 2;
}

// world:ground(item) -> kind, ground (or nil), nx, ny, vx, vy, updatesInAir: what the item
// stood on at its last world:contacts ('air' for an item never read).
int ground(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "reading its ground");
  const tv::Ground g = w.contacts.ground(id);
  lua_pushstring(L, groundName(g.kind));
  pushEnv(L, 1, kSlotToItem);
  if (g.item.valid()) {
    pushItem(L, w, lua_gettop(L), g.item);
  } else {
    lua_pushnil(L);
  }
  lua_remove(L, -2);
  lua_pushnumber(L, g.normal.x);
  lua_pushnumber(L, g.normal.y);
  lua_pushnumber(L, g.velocity.x);
  lua_pushnumber(L, g.velocity.y);
  lua_pushinteger(L, g.updatesInAir);
  return 7;
}

// world:jumped(item): its coyote time ends.
int jumped(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  w.contacts.jumped(requireItem(L, w, 1, 2, "marking its jump"));
  return 0;
}

// world:forgetContacts(item) -> events, n: the ends of every contact it had (it may have been
// removed from the world already: then it is named by the item it was).
int forgetContacts(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  pushEnv(L, 1, kItemToSlot);
  const std::int64_t slot = findSlot(L, lua_gettop(L), 2);
  lua_pop(L, 1);
  lua_createtable(L, 0, 0);
  if (slot < 0) {
    lua_pushinteger(L, 0);
    return 2;  // never added, or removed and not tracked under its slot any more
  }
  const tv::ItemId id = w.world.idAt(static_cast<std::uint32_t>(slot));
  const std::span<const tv::ContactEvent> events = w.contacts.forget(w.world, id);
  const int out = lua_gettop(L);
  pushEnv(L, 1, kSlotToItem);
  const int slotToItem = lua_gettop(L);
  for (std::size_t i = 0; i < events.size(); ++i) {
    lua_createtable(L, 0, 2);
    pushItem(L, w, slotToItem, events[i].other);
    lua_setfield(L, -2, "other");
    lua_pushstring(L, "end");
    lua_setfield(L, -2, "phase");
    lua_rawseti(L, out, static_cast<int>(i) + 1);
  }
  lua_pop(L, 1);
  lua_pushinteger(L, static_cast<lua_Integer>(events.size()));
  return 2;
}

// world:moveCornered(item, goalX, goalY [, filter [, maxNudge = 4]]) -> x, y, cols, len, dx,
// ceiling: a move with corner correction; dx is the nudge (0: none) and ceiling the item whose
// corner it went round (nil: none). Collision tables as world:move's.
int moveCornered(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "getting its rect");
  const tv::Vec2 goal{checkFinite(L, 3, "goalX"), checkFinite(L, 4, "goalY")};
  const bool hasFilter = optFunction(L, 5, "filter");
  const double maxNudge = optFinite(L, 6, "maxNudge", 4.0);
  if (maxNudge < 0) luaL_error(L, "maxNudge must be >= 0, but was %f", maxNudge);
  checkNotBusy(L, w, "moveCornered");
  lua_settop(L, 6);
  pushEnv(L, 1, kSlotToItem);  // 7
  CallContext ctx;
  ctx.L = L;
  ctx.world = &w;
  ctx.worldIdx = 1;
  ctx.itemIdx = 2;
  ctx.filterIdx = hasFilter ? 5 : 0;
  ctx.slotToItem = 7;
  ctx.item = id;
  ctx.origin = w.world.rect(id);
  tv::CornerMove m;
  {
    const CallScope scope(ctx);
    const Busy busy(w);
    const LuaFilter filter{&ctx};
    tv::CornerOptions o;
    o.filter = filter;
    o.maxNudge = maxNudge;
    m = tv::moveCornered(w.world, id, goal, o);
  }
  const tv::Rect after = w.world.rect(id);
  moveCells(L, 1, w, id.index, &after);
  touched(w);
  lua_pushnumber(L, m.position.x);
  lua_pushnumber(L, m.position.y);
  lua_createtable(L, static_cast<int>(m.collisions.size()), 0);
  const int out = lua_gettop(L);
  for (std::size_t i = 0; i < m.collisions.size(); ++i) {
    pushCollision(L, 1, 7, 2, m.collisions[i], true);
    lua_rawseti(L, out, static_cast<int>(i) + 1);
  }
  lua_pushinteger(L, static_cast<lua_Integer>(m.collisions.size()));
  lua_pushnumber(L, m.nudged ? m.nudge.dx : 0.0);
  if (m.nudged) {
    pushItem(L, w, 7, m.nudge.hit.other);
  } else {
    lua_pushnil(L);
  }
  return 6;
}

}  // namespace

void registerPlatformMethods(lua_State* L, int methodsIdx) {
  const luaL_Reg methods[] = {
      {"contacts", guarded<contacts>},
      {"ground", guarded<ground>},
      {"jumped", guarded<jumped>},
      {"forgetContacts", guarded<forgetContacts>},
      {"moveCornered", guarded<moveCornered>},
      {nullptr, nullptr},
  };
  setFunctions(L, methodsIdx, methods);
}

}  // namespace tvlua
