// Tracing records what a move did, and never changes what it does.
#include <gtest/gtest.h>

#include <random>

#include "tv/mover.hpp"

namespace tv {
namespace {

std::uint64_t randomScene(std::string_view mover, bool traced) {
  World w(32);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<> pos(0, 320), vel(-20, 20);
  for (int i = 0; i < 40; ++i) w.add({std::floor(pos(rng) / 16) * 16, std::floor(pos(rng) / 16) * 16, 16, 16});
  std::vector<ItemId> movers;
  for (int i = 0; i < 20; ++i) {
    const Rect r{pos(rng), pos(rng), 5, 7};
    if (!w.anyOverlap(r)) movers.push_back(w.add(r));
  }
  Mover m(parseMover(mover));
  MoveTrace trace;
  for (int t = 0; t < 200; ++t) {
    for (const ItemId id : movers) {
      const Vec2 goal = w.rect(id).position() + Vec2{vel(rng), vel(rng)};
      m.move(w, id, goal, [](ItemId, ItemId) { return response::bounce; }, traced ? &trace : nullptr);
    }
  }
  return w.stateHash();
}

TEST(Trace, RecordingNeverChangesResults) {
  for (const std::string_view name : moverNames()) {
    EXPECT_EQ(randomScene(name, true), randomScene(name, false)) << name;
  }
}

// A mover sliding into a wall:
//
//   [m] ---->  |wall|
//   0..8       20..36
TEST(Trace, RecordsCellsCandidatesLegsAndHits) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out";
  World w(16);
  const ItemId wall = w.add({20, -20, 16, 60});
  const ItemId m = w.add({0, 0, 8, 8});
  Mover mover(parseMover("continuous"));
  MoveTrace t;
  const MoveResult r = mover.move(w, m, {30, 10}, {}, &t);
  EXPECT_EQ(t.item, m);
  EXPECT_EQ(t.mover, "continuous");
  EXPECT_EQ(t.start, (Rect{0, 0, 8, 8}));
  EXPECT_EQ(t.goal, (Vec2{30, 10}));
  EXPECT_EQ(t.final, r.position);
  EXPECT_FALSE(t.cells.empty());
  ASSERT_FALSE(t.candidates.empty());
  EXPECT_EQ(t.candidates[0], wall);
  ASSERT_EQ(t.legs.size(), 2u);  // the swept leg, then the slide along the wall
  ASSERT_EQ(t.hits.size(), 1u);
  EXPECT_EQ(t.hits[0].other, wall);
  EXPECT_EQ(t.hits[0].normal, (Vec2{-1, 0}));
  EXPECT_EQ(t.hits[0].target, (Vec2{12, 10}));
}

TEST(Trace, SubstepMoversRecordTheirPieceBoundaries) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out";
  World w(16);
  const ItemId m = w.add({0, 0, 8, 8});
  Mover mover({MoverKind::substep, 4.0, MoverKind::sweep});
  MoveTrace t;
  mover.move(w, m, {18, 0}, {}, &t);
  ASSERT_EQ(t.substeps.size(), 5u);  // ceil(18 / 4) pieces of 3.6
  EXPECT_EQ(t.substeps.back().x, w.rect(m).x);
  EXPECT_EQ(t.final, w.rect(m).position());
}

// The filter is user code: the trace keeps each answer it gave, so the debugger can show why a
// candidate was passed through. A mover heading right through a ghost into a wall:
//
//   [m] ---->  |ghost|  |wall|
//   0..8       12..16   20..36
TEST(Trace, RecordsTheFiltersAnswers) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out";
  for (const std::string_view name : moverNames()) {
    World w(16);
    const ItemId ghost = w.add({12, -20, 4, 60});
    const ItemId wall = w.add({20, -20, 16, 60});
    const ItemId m = w.add({0, 0, 8, 8});
    Mover mover(parseMover(name));
    MoveTrace t;
    (void)mover.move(w, m, {30, 0}, [&](ItemId, ItemId other) {
      return other == ghost ? response::ignore : response::slide;
    }, &t);
    bool ignoredGhost = false, slidWall = false;
    for (const TraceAnswer& a : t.answers) {
      ignoredGhost |= a.other == ghost && a.response == response::ignore;
      slidWall |= a.other == wall && a.response == response::slide;
    }
    // discrete teleports past both and is asked about what it overlaps at the goal (the wall).
    if (name != "discrete") {
      EXPECT_TRUE(ignoredGhost) << name;
    }
    EXPECT_TRUE(slidWall) << name;
    t.clear();
    EXPECT_TRUE(t.answers.empty());
  }
}

}  // namespace
}  // namespace tv
