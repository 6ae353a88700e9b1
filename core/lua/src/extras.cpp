// What `tunnelvision` adds to a bump world: a move that makes no garbage, the core's movers by
// name, and the batch step that moves many items through one tick together (moving versus
// moving).

#include <cinttypes>
#include <cstdio>
#include <string>
#include <string_view>

#include "boundary.hpp"
#include "lua_world.hpp"

namespace tvlua {
namespace {

// world:go(item, goalX, goalY [, filter]) -> x, y, n. The collisions stay in the world for
// getCollision(i); nothing is allocated on the Lua side.
int go(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "getting its rect");
  const tv::Vec2 goal{checkFinite(L, 3, "goalX"), checkFinite(L, 4, "goalY")};
  const bool hasFilter = optFunction(L, 5, "filter");
  checkNotBusy(L, w, "go");
  lua_settop(L, 5);
  pushEnv(L, 1, kSlotToItem);  // 6
  CallContext ctx;
  ctx.L = L;
  ctx.world = &w;
  ctx.worldIdx = 1;
  ctx.itemIdx = 2;
  ctx.filterIdx = hasFilter ? 5 : 0;
  ctx.slotToItem = 6;
  const tv::Rect before = w.world.rect(id);
  ctx.bump = w.bumpRules && !w.mover;
  ctx.item = id;
  ctx.origin = before;
  if (ctx.bump && w.luaResponses) {
    lua_getfenv(L, 1);
    if (hasFilter) {
      lua_pushvalue(L, 5);
    } else {
      lua_pushboolean(L, 0);
    }
    lua_rawseti(L, -2, kFilter);
    lua_pop(L, 1);
  }
  tv::MoveResult r;
  {
    const CallScope scope(ctx);
    const Busy busy(w);
    const LuaFilter filter{&ctx};
    tv::MoveOptions options;
    if (ctx.bump) options.semantics = tv::MoveSemantics::bump;
    r = w.mover ? w.mover->move(w.world, id, goal, filter) : w.world.move(id, goal, filter, options);
  }
  w.last.assign(r.collisions.begin(), r.collisions.end());
  const tv::Rect after = before.at(r.position);
  moveCells(L, 1, w, id.index, &after);
  touched(w);
  lua_pushnumber(L, r.position.x);
  lua_pushnumber(L, r.position.y);
  lua_pushinteger(L, static_cast<lua_Integer>(w.last.size()));
  return 3;
}

// Pushes other, type, nx, ny, ti, touchX, touchY, overlaps, targetX, targetY.
int pushFlat(lua_State* L, int slotToItem, const tv::Collision& c) {
  lua_rawgeti(L, slotToItem, static_cast<int>(c.other.index) + 1);
  pushResponseName(L, 1, c.response);
  lua_pushnumber(L, c.normal.x);
  lua_pushnumber(L, c.normal.y);
  lua_pushnumber(L, c.ti);
  lua_pushnumber(L, c.touch.x);
  lua_pushnumber(L, c.touch.y);
  lua_pushboolean(L, c.overlaps);
  lua_pushnumber(L, c.target.x);
  lua_pushnumber(L, c.target.y);
  return 10;
}

std::size_t checkIndex(lua_State* L, int idx, const char* name, std::size_t n) {
  const double i = checkFinite(L, idx, name);
  if (i < 1 || i > static_cast<double>(n) || i != static_cast<double>(static_cast<std::size_t>(i))) {
    const char* v = describe(L, idx);
    luaL_error(L, "%s must be an integer in [1, %d], but was %s", name, static_cast<int>(n), v);
  }
  return static_cast<std::size_t>(i) - 1;
}

int getCollision(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const std::size_t i = checkIndex(L, 2, "i", w.last.size());
  pushEnv(L, 1, kSlotToItem);
  return pushFlat(L, lua_gettop(L), w.last[i]);
}

// world:setMover(name): "bump" (bump.lua's rules: a `tunnelvision.bump` world's own) or one
// of the core's movers (tunnelvision.movers).
int setMover(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const char* name = luaL_checkstring(L, 2);
  checkNotBusy(L, w, "setMover");
  if (std::string_view(name) == "bump") {
    w.mover.reset();
    w.bumpRules = true;
    return 0;
  }
  const tv::MoverSpec spec = tv::parseMover(name);  // tv::Error lists the names
  if (spec.kind == tv::MoverKind::continuous) {
    w.mover.reset();  // World::move is the continuous mover, without the indirection
  } else {
    w.mover = std::make_unique<tv::Mover>(spec);
  }
  w.bumpRules = false;
  return 0;
}

int getMover(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const std::string name = w.bumpRules ? std::string("bump")
                           : w.mover   ? w.mover->spec().name()
                                       : std::string("continuous");
  lua_pushlstring(L, name.data(), name.size());
  return 1;
}

// world:step(moves [, filter]) -> n: moves = { item1, goalX1, goalY1, item2, ... }, moved
// through one tick together so that bodies whose paths cross meet (tv::Batch).
int step(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  luaL_checktype(L, 2, LUA_TTABLE);
  const bool hasFilter = optFunction(L, 3, "filter");
  checkNotBusy(L, w, "step");
  lua_settop(L, 3);
  pushEnv(L, 1, kSlotToItem);  // 4
  pushEnv(L, 1, kItemToSlot);  // 5
  const int len = static_cast<int>(lua_objlen(L, 2));
  if (len % 3 != 0) luaL_error(L, "moves must hold item, goalX, goalY triples, but has %d values", len);
  w.moves.clear();
  w.starts.clear();
  for (int i = 1; i <= len; i += 3) {
    lua_rawgeti(L, 2, i);
    const std::int64_t slot = lua_isnil(L, -1) ? -1 : findSlot(L, 5, -1);
    if (slot < 0) {
      const char* v = describe(L, -1);
      luaL_error(L, "moves[%d] must be an item of this world, but was %s", i, v);
    }
    lua_pop(L, 1);
    char name[32];
    std::snprintf(name, sizeof name, "moves[%d]", i + 1);
    lua_rawgeti(L, 2, i + 1);
    const double gx = checkFinite(L, -1, name);
    std::snprintf(name, sizeof name, "moves[%d]", i + 2);
    lua_rawgeti(L, 2, i + 2);
    const double gy = checkFinite(L, -1, name);
    lua_pop(L, 2);
    const tv::ItemId id = w.world.idAt(static_cast<std::uint32_t>(slot));
    w.moves.push_back({id, {gx, gy}});
    w.starts.push_back(w.world.rect(id));
  }
  CallContext ctx;
  ctx.L = L;
  ctx.world = &w;
  ctx.worldIdx = 1;
  ctx.filterIdx = hasFilter ? 3 : 0;
  ctx.slotToItem = 4;
  {
    const CallScope scope(ctx);
    const Busy busy(w);
    const LuaFilter filter{&ctx};
    w.batch.step(w.world, w.moves, filter);
  }
  for (std::size_t i = 0; i < w.moves.size(); ++i) {
    const tv::Rect after = w.starts[i].at(w.batch.outcome(i).position);
    moveCells(L, 1, w, w.moves[i].item.index, &after);
  }
  touched(w);
  lua_pushinteger(L, static_cast<lua_Integer>(w.batch.size()));
  return 1;
}

// world:stepResult(i) -> item, x, y, n (its collisions in the last step)
int stepResult(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const std::size_t i = checkIndex(L, 2, "i", w.batch.size());
  const tv::BatchOutcome o = w.batch.outcome(i);
  pushEnv(L, 1, kSlotToItem);
  lua_rawgeti(L, -1, static_cast<int>(w.moves[i].item.index) + 1);
  lua_pushnumber(L, o.position.x);
  lua_pushnumber(L, o.position.y);
  lua_pushinteger(L, static_cast<lua_Integer>(o.collisions.size()));
  return 4;
}

// world:stepCollision(i, j) -> other, type, nx, ny, ti, touchX, touchY, overlaps, targetX, targetY
int stepCollision(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const std::size_t i = checkIndex(L, 2, "i", w.batch.size());
  const tv::BatchOutcome o = w.batch.outcome(i);
  const std::size_t j = checkIndex(L, 3, "j", o.collisions.size());
  pushEnv(L, 1, kSlotToItem);
  return pushFlat(L, lua_gettop(L), o.collisions[j]);
}

// world:stateHash() -> a 16-digit hex string: equal for worlds that behave the same.
int stateHash(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, w.world.stateHash());
  lua_pushstring(L, hex);
  return 1;
}

}  // namespace

void registerExtraMethods(lua_State* L, int methodsIdx) {
  const luaL_Reg methods[] = {
      {"go", guarded<go>},
      {"getCollision", guarded<getCollision>},
      {"setMover", guarded<setMover>},
      {"getMover", guarded<getMover>},
      {"step", guarded<step>},
      {"stepResult", guarded<stepResult>},
      {"stepCollision", guarded<stepCollision>},
      {"stateHash", guarded<stateHash>},
      {nullptr, nullptr},
  };
  setFunctions(L, methodsIdx, methods);
}

}  // namespace tvlua
