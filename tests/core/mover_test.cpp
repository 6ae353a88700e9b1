// Movers: the same world, moved by different policies. Every "does not tunnel" stands beside
// the naive mover that does.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "tv/error.hpp"
#include "tv/mover.hpp"

namespace tv {
namespace {

constexpr auto kTouch = [](ItemId, ItemId) { return response::touch; };

// A 2x2 bullet at x = 80 flying right at a 16 px wall at x = 100:
//
//   bullet          wall
//   [][]  ------>  |################|
//   80 82         100              116
struct BulletAndWall {
  World world{32};
  ItemId wall = world.add({100, 0, 16, 16});
  ItemId bullet = world.add({80, 7, 2, 2});
};

TEST(Discrete, TunnelsWhenOneStepCarriesItPastTheWall) {
  BulletAndWall s;
  Mover naive(parseMover("discrete"));
  const MoveResult r = naive.move(s.world, s.bullet, {120, 7}, kTouch);
  EXPECT_EQ(r.position, (Vec2{120, 7}));  // straight through: the negative control
  EXPECT_TRUE(r.collisions.empty());
}

TEST(Discrete, IsPushedOutOfTheFarSideWhenItLandsPastTheMiddle) {
  // Lands at 110..112: 12 px past the near face, 6 px from the far one.
  BulletAndWall s;
  Mover naive(parseMover("discrete"));
  const MoveResult r = naive.move(s.world, s.bullet, {110, 7}, kTouch);
  EXPECT_EQ(r.position, (Vec2{116, 7}));
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].normal, (Vec2{1, 0}));
}

TEST(Movers, EveryMoverButDiscreteStopsAtTheNearFace) {
  for (const std::string_view name : moverNames()) {
    if (name == "discrete") continue;
    BulletAndWall s;
    MoverSpec spec = parseMover(name);
    spec.maxStep = 8;  // tile / 2
    Mover mover(spec);
    const MoveResult r = mover.move(s.world, s.bullet, {120, 7}, kTouch);
    EXPECT_EQ(s.world.rect(s.bullet).right(), 100.0) << name;
    EXPECT_EQ(r.position.x, 98.0) << name;
  }
}

TEST(Movers, NoneButDiscreteTunnelsAtAnySpeed) {
  // Thin wall (4 px), 1x1 bullets from 240 to 1e6 px/s at 60 Hz, with a random phase.
  std::mt19937_64 rng(7);
  for (const double speed : {240.0, 960.0, 1920.0, 7680.0, 1e6}) {
    const double step = speed / 60.0;
    for (const std::string_view name : moverNames()) {
      if (name == "pixel" && speed > 10000) continue;  // one query per pixel: far too slow
      MoverSpec spec = parseMover(name);
      spec.maxStep = 2;  // half the wall
      Mover mover(spec);
      int passed = 0;
      for (int k = 0; k < 50; ++k) {
        World w(16);
        w.add({1000, -8, 4, 16});
        const double phase = std::uniform_real_distribution<>(0, step)(rng);
        const ItemId b = w.add({1000 - 1 - step * 3 - phase, 0, 1, 1});
        for (int t = 0; t < 8; ++t) {
          const Rect r = w.rect(b);
          if (!mover.move(w, b, {r.x + step, r.y}, kTouch).collisions.empty()) break;
        }
        if (w.rect(b).x >= 1004) ++passed;
      }
      if (name == "discrete" && speed >= 960) {
        EXPECT_GT(passed, 0) << name << " at " << speed;  // the negative control
      } else if (name != "discrete") {
        EXPECT_EQ(passed, 0) << name << " at " << speed;
      }
    }
  }
}

TEST(Substep, DiscreteInnerStopsTunnellingOnlyWhilePiecesAreShorterThanTheWall) {
  for (const double maxStep : {8.0, 40.0}) {
    BulletAndWall s;
    Mover mover({MoverKind::substep, maxStep, MoverKind::discrete});
    mover.move(s.world, s.bullet, {160, 7}, kTouch);
    if (maxStep == 8.0) {
      EXPECT_EQ(s.world.rect(s.bullet).x, 98.0);  // caught in the wall, pushed back out
    } else {
      EXPECT_EQ(s.world.rect(s.bullet).x, 160.0);  // 40 px pieces skip the 16 px wall
    }
  }
}

TEST(Substep, DefaultsToHalfTheSmallestExtent) {
  World w(32);
  w.add({0, 100, 16, 16});
  const ItemId b = w.add({0, 0, 4, 4});  // smallest extent 4: pieces of 2
  MoveTrace trace;
  Mover mover(parseMover("substep-sweep"));
  mover.move(w, b, {20, 0}, {}, &trace);
  if constexpr (kTraceCompiledIn) {
    EXPECT_EQ(trace.substeps.size(), 10u);
  }
  EXPECT_EQ(w.rect(b).x, 20.0);
}

TEST(Pixel, MovesWholePixelsAndCarriesTheRemainder) {
  // 7.3 px a tick: 7 (0.3 left), 8 (-0.4 left), 7 (-0.1 left) = 22 after three ticks.
  World w(32);
  const ItemId b = w.add({0, 0, 10, 10});
  Mover mover(parseMover("pixel"));
  for (int t = 0; t < 3; ++t) mover.move(w, b, w.rect(b).position() + Vec2{7.3, 0});
  EXPECT_EQ(w.rect(b).x, 22.0);
}

TEST(Pixel, StopsOnThePixelBeforeAWall) {
  World w(32);
  w.add({50, 0, 16, 16});
  const ItemId b = w.add({0, 0, 10, 10});
  Mover mover(parseMover("pixel"));
  for (int t = 0; t < 10; ++t) mover.move(w, b, w.rect(b).position() + Vec2{7.3, 0});
  EXPECT_EQ(w.rect(b).x, 40.0);
}

TEST(Adaptive, GivesExactlyWhatContinuousGives) {
  // Same random walk among tiles, slow and fast: positions equal bit for bit.
  const auto walk = [](std::string_view name) {
    World w(32);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<> pos(0, 480), vel(-12, 12);
    for (int i = 0; i < 60; ++i) w.add({std::floor(pos(rng) / 16) * 16, std::floor(pos(rng) / 16) * 16, 16, 16});
    std::vector<ItemId> movers;
    for (int i = 0; i < 30; ++i) {
      const Rect r{pos(rng), pos(rng), 6.5, 9.25};
      if (w.anyOverlap(r)) continue;
      movers.push_back(w.add(r));
    }
    Mover m(parseMover(name));
    for (int t = 0; t < 300; ++t) {
      for (const ItemId id : movers) {
        const double scale = t % 50 < 40 ? 0.1 : 3.0;  // mostly slow, sometimes fast
        m.move(w, id, w.rect(id).position() + Vec2{vel(rng) * scale, vel(rng) * scale});
      }
    }
    return w.stateHash();
  };
  EXPECT_EQ(walk("adaptive"), walk("continuous"));
}

TEST(Movers, ContinuousVisitsFarFewerCellsThanSweepOnALongDiagonal) {
  // A 1900 px diagonal: the bounding box holds ~440 cells of 64; the path crosses ~60. Two
  // tiles off the path, at the box's other corners, put the whole box among used cells (the
  // world skips cells that never held anything).
  World w(64);
  const ItemId b = w.add({0, 0, 8, 8});
  (void)w.add({1400, 0, 16, 16});
  (void)w.add({0, 1400, 16, 16});
  MoveTrace sweepTrace, exactTrace;
  Mover sweep(parseMover("sweep")), exact(parseMover("continuous"));
  (void)w.check(b, {1343, 1343}, {}, {BroadPhase::bounds, &sweepTrace});
  (void)w.check(b, {1343, 1343}, {}, {BroadPhase::swept, &exactTrace});
  if constexpr (kTraceCompiledIn) {
    EXPECT_GT(sweepTrace.cells.size(), 400u);
    EXPECT_LT(exactTrace.cells.size() * 4, sweepTrace.cells.size());
  }
}

TEST(Movers, NamesRoundTripAndUnknownNamesListTheKnownOnes) {
  for (const std::string_view name : moverNames()) {
    EXPECT_EQ(parseMover(name).name(), name);
    EXPECT_FALSE(moverDescription(name).empty());
  }
  try {
    (void)parseMover("teleport");
    FAIL() << "expected tv::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'teleport'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("continuous"), std::string::npos) << e.what();
  }
}

TEST(Movers, TheTableIsTheOneListOfNamesSpecsAndDescriptions) {
  ASSERT_EQ(moverTable().size(), moverNames().size());
  for (std::size_t i = 0; i < moverTable().size(); ++i) {
    const MoverEntry& e = moverTable()[i];
    EXPECT_EQ(e.name, moverNames()[i]);
    EXPECT_EQ(e.spec.name(), e.name);           // the spec names itself as the table does
    EXPECT_EQ(parseMover(e.name).kind, e.spec.kind);
    EXPECT_EQ(parseMover(e.name).inner, e.spec.inner);
    EXPECT_EQ(moverDescription(e.name), e.description);
    EXPECT_FALSE(e.description.empty()) << e.name;
  }
  EXPECT_EQ(parseMover("substep").name(), "substep-discrete");  // the older name
}

TEST(Movers, RejectBadSpecsNamingTheValue) {
  const auto message = [](MoverSpec s) {
    try {
      Mover m(s);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({MoverKind::substep, -1.0}).find("maxStep"), std::string::npos);
  EXPECT_NE(message({MoverKind::substep, NAN}).find("nan"), std::string::npos);
  EXPECT_NE(message({MoverKind::adaptive, 0, MoverKind::discrete, 0.0}).find("safetyFraction"),
            std::string::npos);
  EXPECT_NE(message({MoverKind::substep, 4, MoverKind::pixel}).find("inner"), std::string::npos);
}

TEST(Movers, BadGoalsThrowAndLeaveTheWorldUnchanged) {
  for (const std::string_view name : moverNames()) {
    BulletAndWall s;
    Mover mover(parseMover(name));
    const std::uint64_t before = s.world.stateHash();
    for (const Vec2 goal : {Vec2{NAN, 0}, Vec2{0, INFINITY}, Vec2{1e300, 0}}) {
      EXPECT_THROW(mover.move(s.world, s.bullet, goal), Error) << name;
      EXPECT_EQ(s.world.stateHash(), before) << name;
    }
    World other(32);
    EXPECT_THROW(mover.move(other, s.bullet, {0, 0}), Error) << name;  // not in that world
  }
}

}  // namespace
}  // namespace tv
