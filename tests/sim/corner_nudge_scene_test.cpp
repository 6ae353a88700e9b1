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

// The tools draw each nudge: the simulation lists them per tick, with the ceiling and the body
// where it met the corner and where the nudge put it. At 600 px/s the jumps meet the ceilings on
// tick 4: bodies 2k and 2k + 1 clip column k's corners by k px, so those of columns 1 to 4 are
// nudged (by k px, outwards) and no other.
TEST(CornerNudge, TheSimulationListsEachNudgeAndASeekKeepsIt) {
  const SceneDef& scene = findScene("corner-nudge");
  Simulation s(scene, scene.defaults(), parseMover("continuous"));
  for (int t = 0; t < 3; ++t) s.tick();
  EXPECT_TRUE(s.cornerNudges().empty());
  s.tick();
  ASSERT_EQ(s.cornerNudges().size(), 8u);
  for (const CornerNudgeAt& n : s.cornerNudges()) {
    const double clip = static_cast<double>(n.body / 2);
    EXPECT_GE(clip, 1.0) << n.body;
    EXPECT_LE(clip, 4.0) << n.body;
    const Rect ceiling = s.world().rect(n.ceiling);
    EXPECT_EQ(n.from.y, ceiling.bottom()) << "met from below";
    if (n.body % 2 == 0) {
      EXPECT_EQ(n.to.x, n.from.x - clip) << n.body;
      EXPECT_EQ(n.to.right(), ceiling.x) << n.body;
    } else {
      EXPECT_EQ(n.to.x, n.from.x + clip) << n.body;
      EXPECT_EQ(n.to.x, ceiling.right()) << n.body;
    }
  }
  s.tick();
  s.seek(4);
  EXPECT_EQ(s.cornerNudges().size(), 8u);
  // Without correction there is nothing to list.
  Params p = scene.defaults();
  p.set("correct", 0);
  Simulation off(scene, p, parseMover("continuous"));
  for (int t = 0; t < 6; ++t) {
    off.tick();
    EXPECT_TRUE(off.cornerNudges().empty());
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
