// world:startRecording(path) ... world:stopRecording(): the game's calls on this world go into
// a .tvrec file (tv::Recorder) that tv-debugger opens and tv-replay validates. Items are
// labelled from their `name` field (or tostring), with their `kind` as the category.

#include <optional>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/record/replay.hpp"

namespace tvlua {
namespace {

// world:startRecording(path [, keyframeEvery])
int startRecording(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  const char* path = luaL_checkstring(L, 2);
  const double every = optFinite(L, 3, "keyframeEvery", 64);
  if (every < 1 || every > 1048576 || every != static_cast<double>(static_cast<std::uint32_t>(every))) {
    const char* v = describe(L, 3);
    luaL_error(L, "keyframeEvery must be an integer in [1, 1048576], but was %s", v);
  }
  checkNotBusy(L, w, "startRecording");
  if (w.recorder) luaL_error(L, "world:startRecording: this world is recording already");
  pushEnv(L, 1, kSlotToItem);
  const int items = lua_gettop(L);
  {
    tv::RecorderOptions options;
    options.keyframeEvery = static_cast<std::uint32_t>(every);
    w.recorder = std::make_unique<tv::Recorder>(std::string(path), options);  // tv::Error names the path
  }
  w.world.attach(*w.recorder);
  // Label what is in the world already.
  std::vector<tv::ItemId> ids;
  w.world.forEachItem([&](tv::ItemId id, const tv::Rect&) { ids.push_back(id); });
  for (const tv::ItemId id : ids) {
    lua_rawgeti(L, items, static_cast<int>(id.index) + 1);
    labelItem(L, 1, w, lua_gettop(L), id);
    lua_pop(L, 1);
  }
  return 0;
}

// world:stopRecording() -> frames, calls, bytes; or nil, message when writing failed.
int stopRecording(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkNotBusy(L, w, "stopRecording");
  if (!w.recorder) luaL_error(L, "world:stopRecording: this world is not recording");
  w.recorder->close();
  const bool ok = w.recorder->ok();
  const std::string error = w.recorder->error();
  const double frames = static_cast<double>(w.recorder->frames());
  const double calls = static_cast<double>(w.recorder->calls());
  const double size = static_cast<double>(w.recorder->size());
  w.recorder.reset();
  w.framesByLove = false;
  if (!ok) {
    lua_pushnil(L);
    lua_pushlstring(L, error.data(), error.size());
    return 2;
  }
  lua_pushnumber(L, frames);
  lua_pushnumber(L, calls);
  lua_pushnumber(L, size);
  return 3;
}

// world:frame(): one rendered frame ends (a no-op when not recording, so games call it always;
// and under LÖVE with TV_RECORD, where each step of love.run ends one already).
int frame(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  if (w.recorder && !w.framesByLove) w.recorder->frame();
  return 0;
}

int isRecording(lua_State* L) {
  lua_pushboolean(L, checkWorld(L, 1).recorder != nullptr);
  return 1;
}

// world:label(item, label [, category]): a name for the debugger other than the automatic one.
int label(lua_State* L) {
  LuaWorld& w = checkWorld(L, 1);
  checkItem(L, 2);
  const tv::ItemId id = requireItem(L, w, 1, 2, "being labelled");
  const char* text = luaL_checkstring(L, 3);
  const char* category = luaL_optstring(L, 4, "");
  if (w.recorder) w.recorder->label(id, text, category);
  return 0;
}

// tunnelvision.validateRecording(path) -> true, summary | false, report: replays the file on
// a fresh world and compares every call's result with the recorded one, bit for bit, then again
// traced from every keyframe, as the debugger re-runs it (what tv-replay --validate and
// --validate --traced do, from Lua).
int validateRecording(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  std::string report;
  bool ok = false;
  {
    tv::Replay replay = tv::Replay::open(path);  // tv::Error names the byte offset
    std::optional<tv::Divergence> d = replay.validate();
    if (!d) {
      d = replay.validate({}, tv::Replay::Tracing::on);
      if (d) report = "traced (as the debugger re-runs it): ";
    }
    ok = !d;
    if (d) {
      report += d->report();
    } else {
      const tv::ReplaySummary& s = replay.summary();
      report = std::to_string(s.frames) + " frames, " + std::to_string(s.calls) + " calls, " +
               std::to_string(s.moves) + " moves: every result replayed bit for bit, untraced and "
               "traced";
    }
  }
  lua_pushboolean(L, ok);
  lua_pushlstring(L, report.data(), report.size());
  return 2;
}

// tunnelvision.recordingItems(path) -> { {label=, category=, moves=, hits=, nudges=}, ... }: the
// items a recording names, in the order they appear (what tv-debugger lists); `nudges` counts
// the corner corrections world:moveCornered gave the item.
int recordingItems(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  struct Item {
    std::string label, category;
    double moves, hits, nudges;
  };
  std::vector<Item> items;
  {
    const tv::Replay replay = tv::Replay::open(path);  // tv::Error names the byte offset
    for (const tv::RecordedItem& i : replay.items()) {
      items.push_back({i.label, i.category, static_cast<double>(i.moves),
                       static_cast<double>(i.hits), static_cast<double>(i.nudges)});
    }
  }
  lua_createtable(L, static_cast<int>(items.size()), 0);
  int n = 0;
  for (const Item& i : items) {
    lua_createtable(L, 0, 4);
    lua_pushlstring(L, i.label.data(), i.label.size());
    lua_setfield(L, -2, "label");
    lua_pushlstring(L, i.category.data(), i.category.size());
    lua_setfield(L, -2, "category");
    lua_pushnumber(L, i.moves);
    lua_setfield(L, -2, "moves");
    lua_pushnumber(L, i.hits);
    lua_setfield(L, -2, "hits");
    lua_pushnumber(L, i.nudges);
    lua_setfield(L, -2, "nudges");
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

// tunnelvision.recordingNudges(path) -> { {frame=, item=, ceiling=, x=, y=, dx=}, ... }: every
// corner correction in a recording, as its replay reads it (frames 0-based; item and ceiling by
// their labels; x, y where the body met the corner; dx how far it was nudged).
int recordingNudges(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  struct Nudge {
    double frame;
    std::string item, ceiling;
    double x, y, dx;
  };
  std::vector<Nudge> nudges;
  {
    const tv::Replay replay = tv::Replay::open(path);  // tv::Error names the byte offset
    for (std::uint64_t f = 0; f < replay.frames(); ++f) {
      for (const tv::CallInfo& c : replay.calls(f)) {
        if (c.kind != tv::CallKind::cornerNudge) continue;
        nudges.push_back({static_cast<double>(f), replay.label(c.item),
                          replay.label(c.nudge.hit.other), c.nudge.hit.touch.x,
                          c.nudge.hit.touch.y, c.nudge.dx});
      }
    }
  }
  lua_createtable(L, static_cast<int>(nudges.size()), 0);
  int n = 0;
  for (const Nudge& u : nudges) {
    lua_createtable(L, 0, 6);
    lua_pushnumber(L, u.frame);
    lua_setfield(L, -2, "frame");
    lua_pushlstring(L, u.item.data(), u.item.size());
    lua_setfield(L, -2, "item");
    lua_pushlstring(L, u.ceiling.data(), u.ceiling.size());
    lua_setfield(L, -2, "ceiling");
    lua_pushnumber(L, u.x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, u.y);
    lua_setfield(L, -2, "y");
    lua_pushnumber(L, u.dx);
    lua_setfield(L, -2, "dx");
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

}  // namespace

void pushValidateRecording(lua_State* L) { lua_pushcfunction(L, guarded<validateRecording>); }
void pushRecordingItems(lua_State* L) { lua_pushcfunction(L, guarded<recordingItems>); }
void pushRecordingNudges(lua_State* L) { lua_pushcfunction(L, guarded<recordingNudges>); }

void registerRecordingMethods(lua_State* L, int methodsIdx) {
  const luaL_Reg methods[] = {
      {"startRecording", guarded<startRecording>},
      {"stopRecording", guarded<stopRecording>},
      {"frame", guarded<frame>},
      {"isRecording", guarded<isRecording>},
      {"label", guarded<label>},
      {nullptr, nullptr},
  };
  setFunctions(L, methodsIdx, methods);
}

}  // namespace tvlua
