// The C half of the fast path under LuaJIT (fast_path.lua is the Lua half): plain C functions
// that Lua calls through the FFI, which never touch the Lua state. Each returns 0 when it did the
// whole call, or -1 having changed nothing, and the Lua half then calls the C API method, which
// does the call or raises its error. Lua gets their addresses from the module (no symbol is
// exported: the same code works where a loader hides a library's symbols, as on Windows).

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "fast_path_lua.hpp"  // kFastPathLua: fast_path.lua's text, made by the build
#include "lua_world.hpp"

namespace tvlua {
namespace {

// As fast_path.lua declares it.
struct FastResult {
  double x, y;
  const FastCollision* cols;
  std::int32_t n, emptied;
};

// The registry's copy of what fast_path.lua returns (the C functions it replaced).
constexpr const char* kCapiKey = "tunnelvision.capi";

enum Flags : int { kCommit = 1, kSentinelAlive = 2, kKeepLast = 4 };

void fill(FastCollision& f, const tv::Collision& c) {
  f.ti = c.ti;
  f.moveX = c.move.x;
  f.moveY = c.move.y;
  f.normalX = c.normal.x;
  f.normalY = c.normal.y;
  f.touchX = c.touch.x;
  f.touchY = c.touch.y;
  f.itemX = c.itemRect.x;
  f.itemY = c.itemRect.y;
  f.itemW = c.itemRect.w;
  f.itemH = c.itemRect.h;
  f.otherX = c.otherRect.x;
  f.otherY = c.otherRect.y;
  f.otherW = c.otherRect.w;
  f.otherH = c.otherRect.h;
  f.targetX = c.target.x;
  f.targetY = c.target.y;
  f.other = static_cast<std::int32_t>(c.other.index);
  f.response = static_cast<std::int32_t>(c.response);
  f.overlaps = c.overlaps ? 1 : 0;
  f.unused = 0;
}

// world:move / check / go without a filter, for the item in `slot` (from the world's item ->
// slot table, so in the world): what moveOrCheck and go do, but the Lua half's.
int fastMove(void* world, double slot, double goalX, double goalY, int flags,
             FastResult* out) noexcept {
  auto& w = *static_cast<LuaWorld*>(world);
  // In use by its own filter or response (the C function raises), responses added from Lua
  // (they need the Lua state), a goal the C function refuses.
  if (w.busy > 0 || w.luaResponses || !std::isfinite(goalX) || !std::isfinite(goalY)) return -1;
  try {
    const auto index = static_cast<std::uint32_t>(slot);
    const tv::ItemId id = w.world.idAt(index);
    const tv::Vec2 goal{goalX, goalY};
    const tv::Rect before = w.world.rect(id);
    CallContext ctx;  // no filter: every pair gets what 'slide' names (LuaFilter)
    ctx.world = &w;
    ctx.bump = w.bumpRules && !w.mover;
    ctx.item = id;
    ctx.origin = before;
    tv::MoveResult r;
    {
      const Busy busy(w);
      const LuaFilter filter{&ctx};
      tv::MoveOptions options;
      if (ctx.bump) options.semantics = tv::MoveSemantics::bump;
      if ((flags & kCommit) == 0) {
        r = w.world.check(id, goal, filter, options);
      } else if (w.mover) {
        r = w.mover->move(w.world, id, goal, filter);
      } else {
        r = w.world.move(id, goal, filter, options);
      }
    }
    w.fastCols.resize(r.collisions.size());
    for (std::size_t i = 0; i < r.collisions.size(); ++i) fill(w.fastCols[i], r.collisions[i]);
    if ((flags & kKeepLast) != 0) w.last.assign(r.collisions.begin(), r.collisions.end());
    out->emptied = 0;
    if ((flags & kCommit) != 0) {
      const tv::Rect after = before.at(r.position);
      out->emptied = relocateCells(w, index, &after, [&] { return (flags & kSentinelAlive) != 0; });
      touched(w);
    }
    out->x = r.position.x;
    out->y = r.position.y;
    out->cols = w.fastCols.data();
    out->n = static_cast<std::int32_t>(r.collisions.size());
    return 0;
  } catch (...) {  // no Lua runs here, so nothing but C++ exceptions reach this
    return -1;
  }
}

// world:getRect for the item in `slot`: x, y, w, h into out[0..3].
int fastRect(void* world, double slot, double* out) noexcept {
  auto& w = *static_cast<LuaWorld*>(world);
  try {
    const tv::Rect r = w.world.rect(w.world.idAt(static_cast<std::uint32_t>(slot)));
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.w;
    out[3] = r.h;
    return 0;
  } catch (...) {
    return -1;
  }
}

// world:getCollision(i) after go: collision i (1-based) of the last go.
int fastCollision(void* world, double i, FastCollision* out) noexcept {
  auto& w = *static_cast<LuaWorld*>(world);
  if (!(i >= 1 && i <= static_cast<double>(w.last.size())) || i != std::floor(i)) return -1;
  fill(*out, w.last[static_cast<std::size_t>(i) - 1]);
  return 0;
}

// stateOf(world): the world's item -> slot, slot -> item, sentinel and response-name tables;
// nothing for anything else (the Lua half then calls the C function, which says what is wrong).
int stateOf(lua_State* L) {
  auto* w = static_cast<LuaWorld*>(lua_touserdata(L, 1));
  if (lua_type(L, 1) != LUA_TUSERDATA || w == nullptr || lua_objlen(L, 1) != sizeof(LuaWorld) ||
      w->magic != LuaWorld::kMagic) {
    return 0;
  }
  for (const int slot : {kItemToSlot, kSlotToItem, kSentinel, kIdToName}) pushEnv(L, 1, slot);
  return 4;
}

bool disabledByEnvironment() {
  const char* v = std::getenv("TV_LUA_FFI");
  return v != nullptr && (std::strcmp(v, "0") == 0 || std::strcmp(v, "off") == 0);
}

template <class F>
void pushAddress(lua_State* L, F* f) {
  lua_pushlightuserdata(L, reinterpret_cast<void*>(f));
}

}  // namespace

void installFastPath(lua_State* L, int methodsIdx) {
  if (disabledByEnvironment()) return;
  lua_getglobal(L, "require");
  lua_pushliteral(L, "ffi");
  if (lua_pcall(L, 1, 1, 0) != 0 || !lua_istable(L, -1)) {  // PUC Lua: no ffi, the C API it is
    lua_pop(L, 1);
    return;
  }
  const int ffi = lua_gettop(L);
  if (luaL_loadbuffer(L, kFastPathLua, std::strlen(kFastPathLua), "=tunnelvision/fast_path.lua") != 0) {
    lua_error(L);  // the build embedded a file that does not compile
  }
  lua_pushvalue(L, ffi);
  lua_pushvalue(L, methodsIdx);
  lua_pushcfunction(L, stateOf);
  pushAddress(L, &fastMove);
  pushAddress(L, &fastRect);
  pushAddress(L, &fastCollision);
  lua_pushnumber(L, tv::response::slide);
  lua_pushnumber(L, tv::response::bounce);
  lua_call(L, 8, 1);
  lua_setfield(L, LUA_REGISTRYINDEX, kCapiKey);
  lua_pop(L, 1);
}

void pushFastPathInfo(lua_State* L, int moduleIdx) {
  lua_getfield(L, LUA_REGISTRYINDEX, kCapiKey);
  lua_pushboolean(L, !lua_isnil(L, -1));
  lua_setfield(L, moduleIdx, "fastPath");
  lua_setfield(L, moduleIdx, "_capi");
}

}  // namespace tvlua
