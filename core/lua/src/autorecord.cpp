// Recording a game without touching its code: `TV_RECORD=game.tvrec love mygame`, or
// `require('tunnelvision').record('game.tvrec')` once. Every world created from then on (and
// every one alive at `record`) records into its own file — the first into the path given, the
// n-th into the path with ".n" before its extension (game.tvrec, game.2.tvrec, ...) — because a
// recording holds one world. Under LÖVE a frame is marked after each step of `love.run` (one
// `love.update` and `love.draw`), and every file is closed when the game quits or its error
// handler runs; elsewhere `tunnelvision.frame()` marks one, and a file is closed when its world
// is collected or the interpreter exits.

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "lua_world.hpp"

namespace tvlua {
namespace {

constexpr const char* kState = "tunnelvision.autorecord";  // registry: {path, count, worlds, all}

// The registry table of this module's recording state, created on first use.
void pushState(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kState);
  if (lua_istable(L, -1)) return;
  lua_pop(L, 1);
  lua_createtable(L, 0, 4);
  for (const char* weak : {"worlds", "all"}) {  // worlds recording automatically; every world
    lua_newtable(L);
    lua_createtable(L, 0, 1);
    lua_pushliteral(L, "k");
    lua_setfield(L, -2, "__mode");
    lua_setmetatable(L, -2);
    lua_setfield(L, -2, weak);
  }
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, kState);
}

// "game.tvrec", n -> "game.n.tvrec" (n > 1); "game" -> "game.n".
std::string numbered(const std::string& path, int n) {
  if (n <= 1) return path;
  const std::size_t slash = path.find_last_of('/');
  std::size_t dot = path.find_last_of('.');
  const std::size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
  if (dot == std::string::npos || dot <= nameStart) dot = path.size();  // no extension
  std::string out(path, 0, dot);
  out.push_back('.');
  out.append(std::to_string(n));
  out.append(path, dot, std::string::npos);
  return out;
}

// Starts recording the world at `worldIdx` into the next file; false (and a message on top of
// the stack) when the file cannot be written.
bool startAuto(lua_State* L, int worldIdx, LuaWorld& w, int state) {
  lua_getfield(L, state, "path");
  const std::string path = lua_tostring(L, -1);
  lua_pop(L, 1);
  lua_getfield(L, state, "count");
  const int n = static_cast<int>(lua_tonumber(L, -1)) + 1;
  lua_pop(L, 1);
  std::string error;
  {
    const std::string file = numbered(path, n);
    try {
      w.recorder = std::make_unique<tv::Recorder>(file);
      w.world.attach(*w.recorder);
    } catch (const std::exception& e) {
      w.recorder.reset();
      error = e.what();
    }
  }
  if (!error.empty()) {
    lua_pushlstring(L, error.data(), error.size());
    return false;
  }
  lua_pushnumber(L, n);
  lua_setfield(L, state, "count");
  w.recordNumber = n;
  lua_getfield(L, state, "hooked");
  w.framesByLove = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  lua_getfield(L, state, "worlds");
  lua_pushvalue(L, worldIdx);
  lua_pushboolean(L, 1);
  lua_rawset(L, -3);
  lua_pop(L, 1);
  // Name what is in it already, in add order.
  pushEnv(L, worldIdx, kSlotToItem);
  const int items = lua_gettop(L);
  std::vector<tv::ItemId> ids;
  w.world.forEachItem([&](tv::ItemId id, const tv::Rect&) { ids.push_back(id); });
  std::sort(ids.begin(), ids.end(),
            [&](tv::ItemId a, tv::ItemId b) { return w.world.order(a) < w.world.order(b); });
  for (const tv::ItemId id : ids) {
    lua_rawgeti(L, items, static_cast<int>(id.index) + 1);
    labelItem(L, worldIdx, w, lua_gettop(L), id);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return true;
}

// Calls f(worldIdx, LuaWorld&) for each world in state[field], the world pushed at worldIdx.
template <class F>
void forEachWorld(lua_State* L, int state, const char* field, F&& f) {
  lua_getfield(L, state, field);
  const int set = lua_gettop(L);
  // Collect first: f may change the set.
  std::vector<int> refs;
  lua_newtable(L);
  const int list = lua_gettop(L);
  int n = 0;
  lua_pushnil(L);
  while (lua_next(L, set) != 0) {
    lua_pop(L, 1);
    lua_pushvalue(L, -1);
    lua_rawseti(L, list, ++n);
  }
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, list, i);
    auto* w = static_cast<LuaWorld*>(lua_touserdata(L, -1));
    if (w != nullptr && lua_objlen(L, -1) == sizeof(LuaWorld) && w->magic == LuaWorld::kMagic) {
      f(lua_gettop(L), *w);
    }
    lua_pop(L, 1);
  }
  lua_settop(L, set - 1);
}

// tunnelvision.frame(): ends a frame in every world recording automatically.
int frameAll(lua_State* L) {
  pushState(L);
  forEachWorld(L, lua_gettop(L), "worlds", [](int, LuaWorld& w) {
    if (w.recorder) w.recorder->frame();
  });
  return 0;
}

// Closes every automatic recording (the game quits, or its error handler runs). Worlds created
// later record again into the next numbered file.
int closeAll(lua_State* L) {
  pushState(L);
  const int state = lua_gettop(L);
  forEachWorld(L, state, "worlds", [](int, LuaWorld& w) {
    if (!w.recorder) return;
    w.recorder->close();
    if (!w.recorder->ok()) {
      std::fprintf(stderr, "tunnelvision: recording %d: %s\n", w.recordNumber,
                   w.recorder->error().c_str());
    }
    w.recorder.reset();
    w.framesByLove = false;
  });
  lua_newtable(L);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "k");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_setfield(L, state, "worlds");
  return 0;
}

// Under LÖVE: a frame after each step of love.run, and everything closed when it returns (the
// game quits) or when the error handler runs. love.run and the handlers are read when LÖVE
// calls them, so a game may define them after this runs (or never: LÖVE's own are wrapped).
// Our own code, compiled at load; arguments: love, frame, close.
constexpr const char* kLoveHook = R"lua(
local love, frame, close = ...
local hooked = { run = true, errorhandler = true, errhand = true }
local set = {}
for k in pairs(hooked) do set[k] = rawget(love, k); rawset(love, k, nil) end
local function wrapRun(run)
  return function(...)
    local step = run(...)
    if type(step) ~= 'function' then close(); return step end
    return function(...)
      local result = step(...)
      frame()
      if result ~= nil then close() end
      return result
    end
  end
end
local function wrapHandler(handler)
  return function(...) close(); return handler(...) end
end
local mt = getmetatable(love)
if mt == nil then mt = {}; setmetatable(love, mt) end
local index, newindex = mt.__index, mt.__newindex
mt.__index = function(t, k)
  if hooked[k] then
    local f = set[k]
    if f == nil then return nil end
    if k == 'run' then return wrapRun(f) end
    return wrapHandler(f)
  end
  if type(index) == 'function' then return index(t, k) end
  if index ~= nil then return index[k] end
end
mt.__newindex = function(t, k, v)
  if hooked[k] then set[k] = v; return end
  if type(newindex) == 'function' then return newindex(t, k, v) end
  if newindex ~= nil then newindex[k] = v; return end
  rawset(t, k, v)
end
)lua";

void hookLove(lua_State* L, int state) {
  lua_getfield(L, state, "hooked");
  const bool done = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (done) return;
  lua_getglobal(L, "love");
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    return;
  }
  if (luaL_loadbuffer(L, kLoveHook, std::char_traits<char>::length(kLoveHook), "=tunnelvision.record") != 0) {
    lua_error(L);
  }
  lua_insert(L, -2);
  lua_pushcfunction(L, guarded<frameAll>);
  lua_pushcfunction(L, guarded<closeAll>);
  lua_call(L, 3, 0);
  lua_pushboolean(L, 1);
  lua_setfield(L, state, "hooked");
}

// Can `path` be written? Opens it for appending (which creates nothing that was not there
// once removed again) and reports the system's reason when not.
bool writable(const std::string& path, std::string& why) {
  std::FILE* probe = std::fopen(path.c_str(), "rb");
  const bool existed = probe != nullptr;
  if (probe) std::fclose(probe);
  std::FILE* f = std::fopen(path.c_str(), "ab");
  if (f == nullptr) {
    why = std::strerror(errno);
    return false;
  }
  std::fclose(f);
  if (!existed) std::remove(path.c_str());
  return true;
}

// Turns automatic recording on into `path`: records every world alive now and created later.
// On failure pushes a message and returns false, changing nothing.
bool enable(lua_State* L, const std::string& path) {
  std::string why;
  if (path.empty()) {
    lua_pushliteral(L, "the path is empty");
    return false;
  }
  if (!writable(path, why)) {
    lua_pushfstring(L, "cannot write '%s': %s", path.c_str(), why.c_str());
    return false;
  }
  pushState(L);
  const int state = lua_gettop(L);
  lua_pushlstring(L, path.data(), path.size());
  lua_setfield(L, state, "path");
  lua_pushnumber(L, 0);
  lua_setfield(L, state, "count");
  hookLove(L, state);
  forEachWorld(L, state, "all", [&](int idx, LuaWorld& w) {
    if (!w.recorder && !startAuto(L, idx, w, state)) lua_pop(L, 1);
  });
  lua_settop(L, state - 1);
  return true;
}

// tunnelvision.record(path): records every world of the game (see above).
int record(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  if (!enable(L, path)) return luaL_error(L, "tunnelvision.record: %s", lua_tostring(L, -1));
  return 0;
}

// tunnelvision.stopRecording(): closes every automatic recording and records no new world.
int stopAll(lua_State* L) {
  closeAll(L);
  pushState(L);
  lua_pushnil(L);
  lua_setfield(L, -2, "path");
  return 0;
}

}  // namespace

void recordIfAsked(lua_State* L, int worldIdx, LuaWorld& w) {
  pushState(L);
  const int state = lua_gettop(L);
  lua_getfield(L, state, "all");
  lua_pushvalue(L, worldIdx);
  lua_pushboolean(L, 1);
  lua_rawset(L, -3);
  lua_pop(L, 1);
  lua_getfield(L, state, "path");
  const bool asked = lua_isstring(L, -1);
  lua_pop(L, 1);
  if (asked && !startAuto(L, worldIdx, w, state)) {
    // The directory went away since `record` checked it: say so once per world, play on.
    std::fprintf(stderr, "tunnelvision: not recording a world: %s\n", lua_tostring(L, -1));
    lua_pop(L, 1);
  }
  lua_settop(L, state - 1);
}

void pushAutoRecord(lua_State* L, int moduleIdx) {
  lua_pushcfunction(L, guarded<record>);
  lua_setfield(L, moduleIdx, "record");
  lua_pushcfunction(L, guarded<frameAll>);
  lua_setfield(L, moduleIdx, "frame");
  lua_pushcfunction(L, guarded<stopAll>);
  lua_setfield(L, moduleIdx, "stopRecording");
}

void recordFromEnvironment(lua_State* L) {
  // TV_RECORD: once per Lua state (the module may be opened again, e.g. by busted).
  pushState(L);
  lua_getfield(L, -1, "env");
  const bool seen = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (!seen) {
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, "env");
    const char* path = std::getenv("TV_RECORD");
    if (path != nullptr && !enable(L, path)) {
      // One clear line, and the game runs on unrecorded.
      std::fprintf(stderr, "tunnelvision: TV_RECORD=%s: %s; the game runs without recording\n",
                   path, lua_tostring(L, -1));
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
}

}  // namespace tvlua
