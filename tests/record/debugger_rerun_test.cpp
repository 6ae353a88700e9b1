// Specification of "what the debugger shows is what the game got": a game recorded untraced,
// then opened as the debugger opens it — seek to a frame (from the nearest keyframe, a world
// rebuilt from a snapshot), then step the frame's calls with a trace — replays every call bit for
// bit, down to the filter's questions. Before this held, a level with many candidates the filter
// ignores (smoke around a player sliding on blocks) validated untraced while one in forty of its
// moves, re-run traced from a keyframe, asked the filter about a pair the game was never asked
// about and then ended elsewhere.

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

#include "core/smoky_level.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

// The smoky level played for `frames` frames with a recorder attached once the level is built
// (so the replay starts from a snapshot, not from an empty world).
std::vector<std::uint8_t> recordSmokyLevel(int frames, std::uint32_t keyframeEvery) {
  World world(test::SmokyLevel::kCell);
  test::SmokyLevel level(19);
  std::vector<Collision> last;
  test::Calls c;
  c.add = [&](const Rect& r) { return world.add(r); };
  c.remove = [&](ItemId id) { world.remove(id); };
  c.update = [&](ItemId id, const Rect& r) { world.update(id, r); };
  c.move = [&](ItemId id, Vec2 goal, Filter f) { return world.move(id, goal, f); };
  level.build(c);
  Recorder rec(RecorderOptions{keyframeEvery});
  world.attach(rec);
  for (int f = 0; f < frames; ++f) {
    level.frame(c);
    rec.frame();
  }
  world.detach();
  EXPECT_TRUE(rec.ok()) << rec.error();
  return rec.bytes();
}

TEST(DebuggerReRun, ASmokyLevelValidatesUntracedAndTraced) {
  Replay replay = Replay::fromBytes(recordSmokyLevel(600, 16));
  const std::optional<Divergence> d = replay.validate();
  EXPECT_FALSE(d) << d->report();
  const std::optional<Divergence> traced = replay.validate({}, Replay::Tracing::on);
  EXPECT_FALSE(traced) << traced->report();
}

// Every frame, as the debugger shows it: seek to its first call, then step each call traced.
TEST(DebuggerReRun, EveryFrameSeekedFromItsKeyframeAndSteppedTracedReplaysBitForBit) {
  Replay replay = Replay::fromBytes(recordSmokyLevel(600, 16));
  MoveTrace trace;
  int diverged = 0, calls = 0;
  std::string first;
  for (std::uint64_t f = 1; f < replay.frames(); ++f) {
    replay.seek(f, 0);
    while (replay.frame() == f && replay.call() < replay.callCount(f)) {
      trace.clear();
      ++calls;
      if (const std::optional<Divergence> d = replay.step(&trace)) {
        if (first.empty()) first = d->report();
        ++diverged;
      }
    }
  }
  EXPECT_EQ(diverged, 0) << diverged << " of " << calls << " calls diverged; the first:\n"
                         << first;
}

}  // namespace
}  // namespace tv
