// The world userdata: creation, identity checks, item <-> handle maps, filters and responses
// that call back into Lua, and bump.lua's cell count.

#include "lua_world.hpp"

#include <cmath>
#include <new>

#include "boundary.hpp"

namespace tvlua {

// [SECTION] bump's cell count --------------------------------------------------------------------

BumpCells::Range BumpCells::of(const tv::Rect& r) const {
  return {static_cast<std::int64_t>(std::floor(r.x / size_)) + 1,
          static_cast<std::int64_t>(std::floor(r.y / size_)) + 1,
          static_cast<std::int64_t>(std::ceil((r.x + r.w) / size_)),
          static_cast<std::int64_t>(std::ceil((r.y + r.h) / size_))};
}

bool BumpCells::add(const Range& r) {
  for (std::int64_t y = r.y0; y <= r.y1; ++y) {
    for (std::int64_t x = r.x0; x <= r.x1; ++x) {
      const std::uint64_t k = key(x, y);
      if (++counts_[k] == 1) emptied_.erase(k);  // a cell still in memory is used again
    }
  }
  return false;
}

bool BumpCells::remove(const Range& r) {
  bool emptied = false;
  for (std::int64_t y = r.y0; y <= r.y1; ++y) {
    for (std::int64_t x = r.x0; x <= r.x1; ++x) {
      const std::uint64_t k = key(x, y);
      auto it = counts_.find(k);
      if (it == counts_.end()) continue;
      if (--it->second == 0) {
        counts_.erase(it);
        emptied_.insert(k);
        emptied = true;
      }
    }
  }
  return emptied;
}

// [SECTION] the userdata -------------------------------------------------------------------------

LuaWorld::~LuaWorld() { magic = 0; }

LuaWorld& checkWorld(lua_State* L, int idx) {
  auto* w = static_cast<LuaWorld*>(lua_touserdata(L, idx));
  if (w == nullptr || lua_objlen(L, idx) != sizeof(LuaWorld) || w->magic != LuaWorld::kMagic) {
    const char* v = describe(L, idx);
    luaL_error(L, "bad self: expected a world (call its methods with ':'), but got %s", v);
  }
  return *w;
}

void pushEnv(lua_State* L, int worldIdx, int slot) {
  lua_getfenv(L, worldIdx);
  lua_rawgeti(L, -1, slot);
  lua_remove(L, -2);
}

std::int64_t findSlot(lua_State* L, int mapIdx, int itemIdx) {
  lua_pushvalue(L, itemIdx);
  lua_rawget(L, mapIdx);
  const std::int64_t slot =
      lua_type(L, -1) == LUA_TNUMBER ? static_cast<std::int64_t>(lua_tonumber(L, -1)) : -1;
  lua_pop(L, 1);
  return slot;
}

void checkItem(lua_State* L, int idx) {
  if (lua_isnoneornil(L, idx)) luaL_error(L, "item must not be nil");
  if (lua_type(L, idx) == LUA_TNUMBER && std::isnan(lua_tonumber(L, idx))) {
    luaL_error(L, "item must not be NaN");
  }
}

tv::ItemId requireItem(lua_State* L, LuaWorld& w, int worldIdx, int itemIdx, const char* doing) {
  pushEnv(L, worldIdx, kItemToSlot);
  const std::int64_t slot = findSlot(L, lua_gettop(L), itemIdx);
  lua_pop(L, 1);
  if (slot < 0) {
    const char* v = describe(L, itemIdx, false);
    luaL_error(L,
               "Item %s must be added to the world before %s. Use world:add(item, x,y,w,h) to add "
               "it first.",
               v, doing);
  }
  return w.world.idAt(static_cast<std::uint32_t>(slot));
}

void checkNotBusy(lua_State* L, LuaWorld& w, const char* what) {
  if (w.busy > 0) {
    luaL_error(L, "world:%s cannot be called while one of this world's filters or responses runs",
               what);
  }
}

namespace {
// Is the sentinel of the last emptying still alive? When it is gone a collection ran since:
// every cell emptied before it is gone too.
bool sentinelAlive(lua_State* L, int worldIdx) {
  pushEnv(L, worldIdx, kSentinel);
  lua_rawgeti(L, -1, 1);
  const bool alive = !lua_isnil(L, -1);
  lua_pop(L, 2);
  return alive;
}
}  // namespace

void moveCells(lua_State* L, int worldIdx, LuaWorld& w, std::uint32_t slot, const tv::Rect* to) {
  if (slot >= w.ranges.size()) w.ranges.resize(slot + 1);
  BumpCells::Range& from = w.ranges[slot];
  const BumpCells::Range b = to ? w.cells.of(*to) : BumpCells::Range{};
  if (to && from == b) return;  // the usual small move: nothing to do
  if (to) w.cells.add(b);       // first, so that shared cells never empty
  if (from.x0 <= from.x1 && from.y0 <= from.y1) {
    // Cells emptied before a collection that has run since are gone, as in bump.
    if (!sentinelAlive(L, worldIdx)) w.cells.collect();
    if (w.cells.remove(from)) {
      pushEnv(L, worldIdx, kSentinel);
      lua_rawgeti(L, -1, 1);
      if (lua_isnil(L, -1)) {
        lua_newtable(L);  // referenced only by the weak table: dies at the next collection
        lua_rawseti(L, -3, 1);
      }
      lua_pop(L, 2);
    }
  }
  from = b;
}

std::size_t countBumpCells(lua_State* L, int worldIdx, LuaWorld& w) {
  if (!sentinelAlive(L, worldIdx)) w.cells.collect();
  return w.cells.occupied() + w.cells.pending();
}

// [SECTION] responses by name --------------------------------------------------------------------

void pushResponseName(lua_State* L, int worldIdx, tv::ResponseId id) {
  pushEnv(L, worldIdx, kIdToName);
  lua_rawgeti(L, -1, id);
  lua_remove(L, -2);
}

tv::ResponseId answerToResponse(lua_State* L, LuaWorld& w, int worldIdx) {
  if (!lua_toboolean(L, -1)) {
    lua_pop(L, 1);
    return tv::response::ignore;
  }
  pushEnv(L, worldIdx, kNameToId);
  lua_pushvalue(L, -2);
  lua_rawget(L, -2);
  if (lua_type(L, -1) != LUA_TNUMBER) {
    // As bump.lua says it: "Unknown collision type: <name> (<type>)". Raised as a C++ error: we
    // are inside the core's call, which must unwind first.
    lua_pop(L, 2);
    lua_getglobal(L, "tostring");
    lua_pushvalue(L, -2);
    const std::string name = lua_pcall(L, 1, 1, 0) == 0 && lua_isstring(L, -1) ? lua_tostring(L, -1) : "?";
    lua_pop(L, 1);
    const std::string type = luaL_typename(L, -1);
    lua_pop(L, 1);
    throw tv::Error("Unknown collision type: " + name + " (" + type + ")");
  }
  const auto id = static_cast<tv::ResponseId>(lua_tonumber(L, -1));
  lua_pop(L, 3);
  (void)w;
  return id;
}

// [SECTION] collision tables ---------------------------------------------------------------------

namespace {

const char* const kKeyNames[kKeyCount] = {nullptr, "item", "other", "type", "overlaps", "ti",
                                          "move", "normal", "touch", "itemRect", "otherRect",
                                          "slide", "bounce", "x", "y", "w", "h"};

// t[keys[k]] = v for the table on top, keys at `keys`.
inline void setNumber(lua_State* L, int keys, int k, double v) {
  lua_rawgeti(L, keys, k);
  lua_pushnumber(L, v);
  lua_rawset(L, -3);
}

void setXY(lua_State* L, int keys, int field, double x, double y) {
  lua_rawgeti(L, keys, field);
  lua_createtable(L, 0, 2);
  setNumber(L, keys, kKeyX, x);
  setNumber(L, keys, kKeyY, y);
  lua_rawset(L, -3);
}

void setRect(lua_State* L, int keys, int field, const tv::Rect& r) {
  lua_rawgeti(L, keys, field);
  lua_createtable(L, 0, 4);
  setNumber(L, keys, kKeyX, r.x);
  setNumber(L, keys, kKeyY, r.y);
  setNumber(L, keys, kKeyW, r.w);
  setNumber(L, keys, kKeyH, r.h);
  lua_rawset(L, -3);
}

}  // namespace

void pushKeys(lua_State* L) {
  lua_createtable(L, kKeyCount, 0);
  for (int k = 1; k < kKeyCount; ++k) {
    lua_pushstring(L, kKeyNames[k]);
    lua_rawseti(L, -2, k);
  }
}

void pushCollision(lua_State* L, int worldIdx, int slotToItem, int itemIdx, const tv::Collision& c,
                   bool withTarget) {
  pushEnv(L, worldIdx, kKeys);
  const int keys = lua_gettop(L);
  lua_createtable(L, 0, 12);
  if (itemIdx != 0 || c.item.valid()) {
    lua_rawgeti(L, keys, kKeyItem);
    if (itemIdx != 0) {
      lua_pushvalue(L, itemIdx);
    } else {
      lua_rawgeti(L, slotToItem, static_cast<int>(c.item.index) + 1);
    }
    lua_rawset(L, -3);
  }
  lua_rawgeti(L, keys, kKeyOther);
  lua_rawgeti(L, slotToItem, static_cast<int>(c.other.index) + 1);
  lua_rawset(L, -3);
  lua_rawgeti(L, keys, kKeyType);
  pushResponseName(L, worldIdx, c.response);
  lua_rawset(L, -3);
  lua_rawgeti(L, keys, kKeyOverlaps);
  lua_pushboolean(L, c.overlaps);
  lua_rawset(L, -3);
  setNumber(L, keys, kKeyTi, c.ti);
  setXY(L, keys, kKeyMove, c.move.x, c.move.y);
  setXY(L, keys, kKeyNormal, c.normal.x, c.normal.y);
  setXY(L, keys, kKeyTouch, c.touch.x, c.touch.y);
  setRect(L, keys, kKeyItemRect, c.itemRect);
  setRect(L, keys, kKeyOtherRect, c.otherRect);
  if (withTarget) {
    if (c.response == tv::response::slide) setXY(L, keys, kKeySlide, c.target.x, c.target.y);
    if (c.response == tv::response::bounce) setXY(L, keys, kKeyBounce, c.target.x, c.target.y);
  }
  lua_remove(L, keys);
}

// [SECTION] calls into Lua -----------------------------------------------------------------------

namespace {
thread_local CallContext* tlsCall = nullptr;
}

CallContext* currentCall() { return tlsCall; }

CallScope::CallScope(CallContext& c) {
  c.outer = tlsCall;
  tlsCall = &c;
}
CallScope::~CallScope() { tlsCall = tlsCall->outer; }

tv::ResponseId LuaFilter::operator()(tv::ItemId item, tv::ItemId other) const {
  CallContext& k = *call;
  if (k.filterIdx == 0) return k.world->slide;
  lua_State* L = k.L;
  lua_pushvalue(L, k.filterIdx);
  if (k.itemIdx != 0) {
    lua_pushvalue(L, k.itemIdx);
  } else if (item.valid()) {
    lua_rawgeti(L, k.slotToItem, static_cast<int>(item.index) + 1);  // a batch's body
  } else {
    lua_pushnil(L);
  }
  lua_rawgeti(L, k.slotToItem, static_cast<int>(other.index) + 1);
  if (lua_pcall(L, 2, 1, 0) != 0) throw LuaRaised{};
  return answerToResponse(L, *k.world, k.worldIdx);
}

tv::Leg luaResponse(const tv::Collision& c, tv::Vec2 goal) {
  CallContext* k = currentCall();
  if (k == nullptr) throw tv::Error("a response added from Lua ran outside a Lua call");
  lua_State* L = k->L;
  pushEnv(L, k->worldIdx, kIdToFn);
  lua_rawgeti(L, -1, c.response);
  lua_remove(L, -2);
  lua_pushvalue(L, k->worldIdx);
  pushCollision(L, k->worldIdx, k->slotToItem, k->itemIdx, c, false);
  if (k->savedCols != 0) {
    // The table the response saw (and may have written to, as bump's own responses write
    // col.slide) is the one the move returns.
    lua_pushvalue(L, -1);
    lua_rawseti(L, k->savedCols, k->responded + 1);
  }
  // bump hands its responses the item's rect before the move (check's x,y,w,h); the core's
  // responses see the leg's.
  const tv::Rect& r = k->bump ? k->origin : c.itemRect;
  lua_pushnumber(L, r.x);
  lua_pushnumber(L, r.y);
  lua_pushnumber(L, r.w);
  lua_pushnumber(L, r.h);
  lua_pushnumber(L, goal.x);
  lua_pushnumber(L, goal.y);
  if (k->bump) {
    pushEnv(L, k->worldIdx, kVisited);  // bump's visitedFilter
  } else if (k->filterIdx != 0) {
    lua_pushvalue(L, k->filterIdx);
  } else {
    lua_pushnil(L);
  }
  ++k->responded;
  k->inResponse = true;
  k->projected = false;
  const int status = lua_pcall(L, 9, 4, 0);
  k->inResponse = false;
  if (status != 0) throw LuaRaised{};
  if (lua_type(L, -4) != LUA_TNUMBER || lua_type(L, -3) != LUA_TNUMBER) {
    pushResponseName(L, k->worldIdx, c.response);
    const std::string name = lua_isstring(L, -1) ? lua_tostring(L, -1) : "?";
    const std::string a = luaL_typename(L, -5), b = luaL_typename(L, -4);
    lua_pop(L, 5);
    throw tv::Error("response '" + name + "' must return goalX, goalY (numbers), but returned a " +
                    a + " and a " + b);
  }
  const tv::Vec2 next{lua_tonumber(L, -4), lua_tonumber(L, -3)};
  // bump goes on while the response returns collisions (its 4th value, or its list's length).
  double more = 0;
  if (lua_type(L, -1) == LUA_TNUMBER) {
    more = lua_tonumber(L, -1);
  } else if (lua_istable(L, -2)) {
    more = static_cast<double>(lua_objlen(L, -2));
  }
  lua_pop(L, 4);
  if (k->bump) {
    // The next leg is the projection the response made (bump's `world:project` from where it
    // chose), re-made by the core with the same rules; from the contact if it made none.
    tv::Leg leg;
    leg.start = k->projected ? k->projectedFrom : c.touch;
    leg.goal = next;
    leg.stop = !(more > 0);
    return leg;
  }
  // The core's rules never meet an item twice through a response of Lua's; the next leg starts
  // at the contact.
  return {c.touch, next, /*passThrough=*/true};
}

int visitedFilter(lua_State* L) {
  LuaWorld& w = checkWorld(L, lua_upvalueindex(1));
  lua_settop(L, 2);
  pushEnv(L, lua_upvalueindex(1), kItemToSlot);  // 3
  const std::int64_t slot = lua_isnil(L, 2) ? -1 : findSlot(L, 3, 2);
  if (slot >= 0) {
    const tv::ItemId other = w.world.idAt(static_cast<std::uint32_t>(slot));
    for (const tv::ItemId met : w.world.metThisMove()) {
      if (met == other) {
        lua_pushboolean(L, 0);
        return 1;
      }
    }
  }
  pushEnv(L, lua_upvalueindex(1), kFilter);  // 4
  if (!lua_toboolean(L, 4)) {
    lua_pushliteral(L, "slide");  // bump's default filter
    return 1;
  }
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

// [SECTION] newWorld -----------------------------------------------------------------------------

namespace {

int worldGc(lua_State* L) {
  auto* w = static_cast<LuaWorld*>(lua_touserdata(L, 1));
  if (w != nullptr && lua_objlen(L, 1) == sizeof(LuaWorld) && w->magic == LuaWorld::kMagic) {
    w->~LuaWorld();
  }
  return 0;
}

int worldToString(lua_State* L) {
  auto* w = static_cast<LuaWorld*>(lua_touserdata(L, 1));
  lua_pushfstring(L, "tunnelvision.world: %p", static_cast<void*>(w));
  return 1;
}

const char* const kBuiltinNames[tv::response::kBuiltinCount] = {"touch", "cross", "slide",
                                                                 "bounce"};

}  // namespace

int newWorld(lua_State* L) {
  const double cellSize = optPositive(L, 1, "cellSize", 64.0);
  lua_settop(L, 0);
  void* mem = lua_newuserdata(L, sizeof(LuaWorld));  // 1
  new (mem) LuaWorld(cellSize);                      // throws only before it exists
  auto& w = *static_cast<LuaWorld*>(mem);
  w.bumpRules = lua_toboolean(L, lua_upvalueindex(3)) != 0;
  // The per-world field table: the methods (copied, so a method call is one table lookup),
  // world.cellSize, and whatever code (spies) assigns. Other keys go to readInternals: bump's
  // rows, rects, nonEmptyCells and responses, built when read.
  lua_createtable(L, 0, 40);  // 2: fields
  lua_pushnil(L);
  while (lua_next(L, lua_upvalueindex(1)) != 0) {
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_rawset(L, 2);
  }
  lua_pushnumber(L, cellSize);
  lua_setfield(L, 2, "cellSize");
  lua_createtable(L, 0, 1);
  lua_pushvalue(L, 1);
  lua_pushcclosure(L, guarded<readInternals>, 1);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, 2);
  lua_createtable(L, 0, 4);  // 3: the world's metatable
  lua_pushvalue(L, 2);
  lua_setfield(L, 3, "__index");
  lua_pushvalue(L, 2);
  lua_setfield(L, 3, "__newindex");
  lua_pushcfunction(L, worldGc);
  lua_setfield(L, 3, "__gc");
  lua_pushcfunction(L, worldToString);
  lua_setfield(L, 3, "__tostring");
  lua_pushvalue(L, 3);
  lua_setmetatable(L, 1);
  lua_createtable(L, kEnvSize, 0);  // 4: env
  for (int i = 1; i < kKeys; ++i) {
    lua_newtable(L);
    lua_rawseti(L, 4, i);
  }
  lua_pushvalue(L, lua_upvalueindex(2));
  lua_rawseti(L, 4, kKeys);
  lua_newtable(L);
  lua_rawseti(L, 4, kInternals);
  lua_pushboolean(L, 0);
  lua_rawseti(L, 4, kFilter);
  lua_pushvalue(L, 1);
  lua_pushcclosure(L, guarded<visitedFilter>, 1);
  lua_rawseti(L, 4, kVisited);
  lua_newtable(L);
  lua_rawseti(L, 4, kSerials);
  lua_pushvalue(L, lua_upvalueindex(4));
  lua_rawseti(L, 4, kBumpResponses);
  lua_rawgeti(L, 4, kSentinel);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "v");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
  lua_rawgeti(L, 4, kNameToId);
  lua_rawgeti(L, 4, kIdToName);
  for (int i = 0; i < tv::response::kBuiltinCount; ++i) {
    lua_pushstring(L, kBuiltinNames[i]);
    lua_pushnumber(L, i);
    lua_rawset(L, -4);
    lua_pushstring(L, kBuiltinNames[i]);
    lua_rawseti(L, -2, i);
  }
  lua_pop(L, 2);
  lua_pushvalue(L, 4);
  lua_setfenv(L, 1);
  lua_settop(L, 1);
  recordIfAsked(L, 1, w);
  lua_settop(L, 1);
  return 1;
}

}  // namespace tvlua
