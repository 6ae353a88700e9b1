// Recording a game without touching its code: `TV_RECORD=game.tvrec love mygame`, or
// `require('tunnelvision').record('game.tvrec')` once. Every world created from then on (and
// every one alive at `record`) records into its own file — the first into the path given, the
// n-th into the path with ".n" before its extension (game.tvrec, game.2.tvrec, ...) — because a
// recording holds one world. Under LÖVE a frame is marked after each step of `love.run` (one
// `love.update` and `love.draw`), and every file is closed when the game quits or its error
// handler runs; elsewhere `tunnelvision.frame()` marks one, and a file is closed when its world
// is collected or the interpreter exits.
//
// Watching a game live without touching its code: `TV_LIVE=HOST:PORT love mygame` streams the
// world the game made last to a receiver listening there (tv-debugger --listen, tv-replay
// --listen), which may pause the game and step it a frame at a time: LÖVE's step then waits in
// its frame mark. One stream per game, because a receiver watches one game: a world made while
// another streams takes the stream over — a level reloaded is a new run in the debugger — and
// the older world's recording ends (its file too, with TV_RECORD). The game never waits for a
// receiver that is not there (tv/record/live.hpp).

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/record/live.hpp"

namespace tvlua {
namespace {

// registry: {path, count, live, hooked, env, worlds, all, streaming}
constexpr const char* kState = "tunnelvision.autorecord";

// The registry table of this module's recording state, created on first use.
void pushState(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kState);
  if (lua_istable(L, -1)) return;
  lua_pop(L, 1);
  lua_createtable(L, 0, 4);
  // Worlds recording automatically; every world; the one streaming live (at most one).
  for (const char* weak : {"worlds", "all", "streaming"}) {
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

// state[field] = a fresh weak-keyed table.
void resetSet(lua_State* L, int state, const char* field) {
  lua_newtable(L);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "k");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_setfield(L, state, field);
}

// Starts recording the world at `worldIdx` automatically: into the next file when a path is
// set (TV_RECORD, `record`), and streaming to the TV_LIVE receiver when `stream` is true. False
// (and a message on top of the stack) when the file cannot be written or the stream not made.
bool startAuto(lua_State* L, int worldIdx, LuaWorld& w, int state, bool stream) {
  lua_getfield(L, state, "path");
  const bool toFile = lua_isstring(L, -1) != 0;
  const std::string path = toFile ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  lua_getfield(L, state, "live");
  const std::string live = stream && lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  if (!toFile && live.empty()) return true;  // nothing asked
  lua_getfield(L, state, "count");
  const int n = toFile ? static_cast<int>(lua_tonumber(L, -1)) + 1 : 0;
  lua_pop(L, 1);
  std::string error;
  {
    const std::string file = toFile ? numbered(path, n) : "";
    try {
      std::optional<tv::LiveOptions> options;
      if (!live.empty()) {
        options.emplace();
        options->address = live;
        options->control = true;  // the receiver may pause the game at LÖVE's frame marks
      }
      if (toFile) {
        w.recorder = std::make_unique<tv::Recorder>(file);
        if (options) w.recorder->stream(*options);
      } else {
        w.recorder = std::make_unique<tv::Recorder>(*options);  // copies nothing while nobody listens
      }
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
  if (toFile) {
    lua_pushnumber(L, n);
    lua_setfield(L, state, "count");
  }
  w.recordNumber = n;
  w.streaming = !live.empty();
  lua_getfield(L, state, "hooked");
  w.framesByLove = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  const auto join = [&](const char* set) {
    lua_getfield(L, state, set);
    lua_pushvalue(L, worldIdx);
    lua_pushboolean(L, 1);
    lua_rawset(L, -3);
    lua_pop(L, 1);
  };
  join("worlds");
  if (w.streaming) join("streaming");
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

// Ends a world's automatic recording: the file's end mark, the stream's "closed" to its
// receiver; an I/O error met on the way is said on stderr.
void stopAuto(LuaWorld& w) {
  if (!w.recorder) return;
  w.recorder->close();
  if (!w.recorder->ok()) {
    if (w.recordNumber > 0) {
      std::fprintf(stderr, "tunnelvision: recording %d: %s\n", w.recordNumber,
                   w.recorder->error().c_str());
    } else {
      std::fprintf(stderr, "tunnelvision: live stream: %s\n", w.recorder->error().c_str());
    }
  }
  w.recorder.reset();
  w.framesByLove = false;
  w.streaming = false;
  w.recordNumber = 0;
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
// later record again into the next numbered file (and stream, with TV_LIVE).
int closeAll(lua_State* L) {
  pushState(L);
  const int state = lua_gettop(L);
  forEachWorld(L, state, "worlds", [](int, LuaWorld& w) { stopAuto(w); });
  resetSet(L, state, "worlds");
  resetSet(L, state, "streaming");
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
    // A world that only streams gets a recorder that writes the file too (its receiver sees a
    // new run): one recorder per world.
    const bool streaming = w.recorder && w.streaming && w.recordNumber == 0;
    if (streaming) stopAuto(w);
    if (!w.recorder && !startAuto(L, idx, w, state, streaming)) {
      std::fprintf(stderr, "tunnelvision: not recording a world: %s\n", lua_tostring(L, -1));
      lua_pop(L, 1);
    }
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

// tunnelvision.stopRecording(): closes every automatic recording and records no new world
// into a file. With TV_LIVE the world that streamed streams on (a new run for its receiver).
int stopAll(lua_State* L) {
  pushState(L);
  const int state = lua_gettop(L);
  lua_getfield(L, state, "streaming");
  lua_pushnil(L);
  const bool streamed = lua_next(L, -2) != 0;
  if (streamed) {
    lua_pop(L, 1);  // the value; the world stays, at state + 2
  } else {
    lua_pushnil(L);
  }
  const int streamer = lua_gettop(L);
  closeAll(L);
  lua_pushnil(L);
  lua_setfield(L, state, "path");
  if (streamed) {
    auto* w = static_cast<LuaWorld*>(lua_touserdata(L, streamer));
    const bool world = w != nullptr && lua_objlen(L, streamer) == sizeof(LuaWorld) &&
                       w->magic == LuaWorld::kMagic;
    if (world && !w->recorder && !startAuto(L, streamer, *w, state, true)) {
      std::fprintf(stderr, "tunnelvision: not streaming a world: %s\n", lua_tostring(L, -1));
    }
  }
  lua_settop(L, state - 1);
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
  lua_getfield(L, state, "live");
  const bool live = lua_isstring(L, -1) != 0;
  lua_pop(L, 1);
  if (live) {
    // The stream goes to the newest world: the one before it ends its recording (see above).
    forEachWorld(L, state, "streaming", [](int, LuaWorld& old) { stopAuto(old); });
    resetSet(L, state, "streaming");
  }
  if (!startAuto(L, worldIdx, w, state, live)) {
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
  // TV_RECORD and TV_LIVE: once per Lua state (the module may be opened again, e.g. by busted).
  pushState(L);
  const int state = lua_gettop(L);
  lua_getfield(L, state, "env");
  const bool seen = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (!seen) {
    lua_pushboolean(L, 1);
    lua_setfield(L, state, "env");
    std::string live, bad;
    try {
      if (const std::optional<tv::LiveOptions> o = tv::liveFromEnvironment("TV_LIVE")) live = o->address;
    } catch (const std::exception& e) {
      bad = e.what();  // names the variable and its value
    }
    if (!bad.empty()) {
      // One clear line, and the game runs on without the stream.
      std::fprintf(stderr, "tunnelvision: %s; the game runs without streaming\n", bad.c_str());
    } else if (!live.empty()) {
      lua_pushlstring(L, live.data(), live.size());
      lua_setfield(L, state, "live");
      hookLove(L, state);  // frames at LÖVE's steps: where a pause holds the game
    }
    const char* path = std::getenv("TV_RECORD");
    if (path != nullptr && !enable(L, path)) {
      // One clear line, and the game runs on unrecorded.
      std::fprintf(stderr, "tunnelvision: TV_RECORD=%s: %s; the game runs without recording\n",
                   path, lua_tostring(L, -1));
      lua_pop(L, 1);
    }
  }
  lua_settop(L, state - 1);
}

}  // namespace tvlua
