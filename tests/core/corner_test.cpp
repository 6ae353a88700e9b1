// Specification of corner correction (tv/corner.hpp): a body jumping into the corner of a ceiling
// by at most maxNudge is nudged round it and goes on up — exactly beside the ceiling, never
// inside it — with World::move (no correction) as the negative control: it stops dead.

#include "tv/corner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "tv/error.hpp"
#include "tv/world.hpp"

namespace {

using tv::CornerMove;
using tv::CornerOptions;
using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

// A ceiling 32 wide and a body 8 x 12 below its left end, jumping 40 px straight up:
//
//          +------------------------------+
//          |        ceiling {16, 0, 32, 8}  |
//       +--+-----------------------------+
//       |b |      body {10 + shift, 40, 8, 12}: its right 2 + shift px under the ceiling
//       |  |
//       +--+
struct Jump {
  static constexpr Rect kCeiling{16, 0, 32, 8};
  explicit Jump(double x) : body(world.add({x, 40, 8, 12})) {}
  World world{16};
  ItemId ceiling = world.add(kCeiling);
  ItemId body;
};

TEST(CornerCorrection, AJumpClippingACeilingCornerBy2pxIsNudgedRoundItAndGoesOnUp) {
  Jump s(10);
  const CornerMove m = tv::moveCornered(s.world, s.body, {10, 0});
  ASSERT_TRUE(m.nudged);
  EXPECT_EQ(m.nudge.dx, -2.0);
  EXPECT_EQ(m.nudge.hit.other, s.ceiling);
  EXPECT_EQ(m.nudge.hit.touch, (Vec2{10, 8})) << "where it clipped the corner";
  EXPECT_EQ(m.position, (Vec2{8, 0}));
  EXPECT_EQ(s.world.rect(s.body).right(), 16.0) << "beside the ceiling, edge on edge";
  EXPECT_TRUE(m.collisions.empty()) << "the corner is reported as the nudge, not as a stop";
}

TEST(CornerCorrection, NegativeControlWithoutItTheJumpStopsDeadOnTheCorner) {
  Jump s(10);
  const tv::MoveResult r = s.world.move(s.body, {10, 0});
  EXPECT_EQ(r.position, (Vec2{10, 8})) << "stopped under the ceiling: 2 px of it ended the jump";
  Jump off(10);
  CornerOptions o;
  o.maxNudge = 0;
  const CornerMove m = tv::moveCornered(off.world, off.body, {10, 0}, o);
  EXPECT_FALSE(m.nudged);
  EXPECT_EQ(m.position, (Vec2{10, 8}));
}

TEST(CornerCorrection, TheRightEndToo) {
  //   +----------+
  //   | ceiling  |        body {46, 40, 8, 12}: its left 2 px under the ceiling's right end (48)
  //   +--------+-+--+
  //            |  b |
  Jump s(46);
  const CornerMove m = tv::moveCornered(s.world, s.body, {46, 0});
  ASSERT_TRUE(m.nudged);
  EXPECT_EQ(m.nudge.dx, 2.0);
  EXPECT_EQ(m.position, (Vec2{48, 0}));
}

TEST(CornerCorrection, AClipDeeperThanMaxNudgeStops) {
  // Clipped by 5 px: more than Celeste's 4, not nudged; with maxNudge 6, nudged by 5.
  Jump s(13);
  const CornerMove m = tv::moveCornered(s.world, s.body, {13, 0});
  EXPECT_FALSE(m.nudged);
  EXPECT_EQ(m.position, (Vec2{13, 8}));
  Jump t(13);
  CornerOptions o;
  o.maxNudge = 6;
  const CornerMove n = tv::moveCornered(t.world, t.body, {13, 0}, o);
  ASSERT_TRUE(n.nudged);
  EXPECT_EQ(n.nudge.dx, -5.0);
}

TEST(CornerCorrection, NeverAgainstTheMovesHorizontalDirection) {
  // Moving up and right, clipping the left end: a nudge left would undo the player's input.
  Jump s(10);
  const CornerMove m = tv::moveCornered(s.world, s.body, {14, 0});
  EXPECT_FALSE(m.nudged);
  EXPECT_EQ(s.world.rect(s.body).y, 8.0) << "stopped by the ceiling (and slid along it)";
}

TEST(CornerCorrection, NotWhenTheStripBesideTheCornerIsTaken) {
  //   +--+-----------+
  //   |w |  ceiling  |    a wall {0, 0, 9, 60} reaches into the strip the body would slide
  //   |  |+--+-------+    through (x 8..10): no nudge, the jump stops as World::move's
  //   |  ||b |
  Jump s(10);
  s.world.add({0, 0, 9, 60});
  const CornerMove m = tv::moveCornered(s.world, s.body, {10, 0});
  EXPECT_FALSE(m.nudged);
  EXPECT_EQ(m.position, (Vec2{10, 8}));
  // A wall the filter crosses (a ghost) does not take the strip.
  Jump g(10);
  const ItemId ghost = g.world.add({0, 0, 9, 60});
  const auto filter = [&](ItemId, ItemId other) {
    return other == ghost ? tv::response::cross : tv::response::slide;
  };
  CornerOptions o;
  o.filter = filter;
  EXPECT_TRUE(tv::moveCornered(g.world, g.body, {10, 0}, o).nudged);
}

TEST(CornerCorrection, ExactAtOddPositionsAndSizes) {
  // Sizes and positions off the pixel grid: the nudged body ends edge on edge beside the
  // ceiling (placeBefore: bit for bit, or one rounding step short), never inside it.
  for (int i = 0; i < 200; ++i) {
    World w(16);
    const double cx = 16.1 + i * 0.0731, bw = 7.3 + i * 0.013, clip = 0.01 + (i % 40) * 0.0997;
    const ItemId ceiling = w.add({cx, 0.3, 30.7, 7.9});
    const double bx = cx - bw + clip;
    const ItemId body = w.add({bx, 40.17, bw, 12.2});
    const CornerMove m = tv::moveCornered(w, body, {bx, -3.3});
    ASSERT_TRUE(m.nudged) << i;
    const Rect b = w.rect(body), c = w.rect(ceiling);
    EXPECT_LE(b.right(), c.x) << i;
    EXPECT_EQ(b.x, tv::placeBefore(c.x, bw)) << i;
    EXPECT_EQ(b.y, -3.3) << i;
    EXPECT_FALSE(tv::overlaps(b, c)) << i;
  }
}

TEST(CornerCorrection, BadInputIsRefusedNamingTheValueAndChangesNothing) {
  Jump s(10);
  const std::uint64_t before = s.world.stateHash();
  for (const double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    CornerOptions o;
    o.maxNudge = bad;
    try {
      (void)tv::moveCornered(s.world, s.body, {10, 0}, o);
      FAIL() << "maxNudge " << bad << " was accepted";
    } catch (const tv::Error& e) {
      EXPECT_NE(std::string(e.what()).find("maxNudge"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)tv::moveCornered(s.world, s.body, {std::nan(""), 0}), tv::Error);
  EXPECT_THROW((void)tv::moveCornered(s.world, tv::ItemId{}, {10, 0}), tv::Error);
  EXPECT_EQ(s.world.stateHash(), before);
}

}  // namespace
