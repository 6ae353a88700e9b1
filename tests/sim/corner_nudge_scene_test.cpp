// The corner-nudge scene as a table: bodies jumping straight up into the corners of a ceiling,
// clipping it by 0, 1, ... 8 px (one column per clip, a body under each end), at 600 to 4800 px/s,
// for every mover — with corner correction (tv::moveCornered, Celeste's 4 px) and, as the
// negative control, without (the mover alone).
//
//     ################################   roof: stops every jump
//          +---------------+             ceiling
//       [a]|               |[b]          a's right edge k px under its left end, b's left edge
//        ^                   ^           k px under its right end
//     ################################   floor: a body that lands jumps again from its start
//
// Counted per jump: snags (stopped by a clip of at most 4 px, which the game wants nudged round),
// hits (stopped by a deeper clip: as it should be), tunnelled (ended above the ceiling still
// under its end: through the corner, not round it), overlaps (ended a move inside a solid).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

constexpr std::uint64_t kTicks = 240;

Counters run(std::string_view mover, bool correct, double speed, double nudge = 4) {
  const SceneDef& scene = findScene("corner-nudge");
  Params p = scene.defaults();
  p.set("correct", correct ? 1 : 0);
  p.set("speed", speed);
  p.set("nudge", nudge);
  Simulation s(scene, p, parseMover(mover));
  for (std::uint64_t t = 0; t < kTicks; ++t) s.tick();
  return s.counters();
}

std::string where(std::string_view mover, double speed) {
  return std::string(mover) + " at " + std::to_string(static_cast<int>(speed)) + " px/s";
}

TEST(CornerNudge, WithCorrectionNoJumpIsSnaggedOrPassesThroughACornerAtAnySpeed) {
  for (const std::string_view m : moverNames()) {
    for (const double speed : {600.0, 1200.0, 2400.0, 4800.0}) {
      const Counters c = run(m, true, speed);
      const std::string at = where(m, speed);
      EXPECT_EQ(c.snags, 0u) << at;
      EXPECT_EQ(c.tunnelled, 0u) << at;
      EXPECT_EQ(c.misses, 0u) << at;
      EXPECT_EQ(c.escapes, 0u) << at;
      EXPECT_EQ(c.overlaps, 0u) << at;
      // Clips of 5 to 8 px are more than the nudge: those jumps still stop, every time.
      EXPECT_GT(c.hits, 0u) << at;
      EXPECT_GT(c.jumps, 18u) << at;  // every body lands and jumps again
    }
  }
}

TEST(CornerNudge, ANudgeAsLargeAsTheDeepestClipLetsEveryJumpThrough) {
  for (const std::string_view m : moverNames()) {
    const Counters c = run(m, true, 600, 8);
    EXPECT_EQ(c.snags + c.hits + c.tunnelled + c.misses + c.overlaps, 0u) << m;
  }
}

TEST(CornerNudgeNegativeControl, WithoutCorrectionEveryMoverFailsAtTheCornersAtEverySpeed) {
  // The movers that sweep stop dead under every clip, 1 px included: 4 of the 8 clipped jumps
  // per end snag. The movers that teleport (discrete, substep-discrete) land in the corner and
  // are pushed out of it: sideways for a shallow clip (a nudge by accident), but also for a
  // clip deeper than the nudge (missed: round a corner it should stop on), through the ceiling
  // (tunnelled) or the roof (escaped) when fast.
  for (const std::string_view m : moverNames()) {
    const bool teleports = m == "discrete" || m == "substep-discrete";
    for (const double speed : {600.0, 1200.0, 2400.0, 4800.0}) {
      const Counters c = run(m, false, speed);
      if (teleports) {
        EXPECT_GT(c.snags + c.misses + c.tunnelled + c.escapes, 0u) << where(m, speed);
      } else {
        EXPECT_GT(c.snags, 0u) << where(m, speed);
        EXPECT_EQ(c.snags, c.hits) << where(m, speed) << ": 4 clips should pass, 4 should stop";
      }
    }
  }
}

TEST(CornerNudge, TheSameTicksGiveTheSameHash) {
  const SceneDef& scene = findScene("corner-nudge");
  Simulation a(scene, scene.defaults(), parseMover("continuous"));
  Simulation b(scene, scene.defaults(), parseMover("continuous"));
  for (int t = 0; t < 100; ++t) {
    a.tick();
    b.tick();
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_EQ(a.world().stateHash(), b.world().stateHash());
}

}  // namespace
}  // namespace tv::sim
