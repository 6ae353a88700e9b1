// Specification of the exact narrow phase (tv/sweep.hpp): a mover's edges travel linearly from
// start to goal against a static obstacle; entry times compare exactly.

#include "tv/sweep.hpp"

#include <gtest/gtest.h>

namespace {

using tv::Rect;
using tv::SweepKind;
using tv::Vec2;

// [SECTION] sweepRect: hits and misses ---------------------------------------------------------

//   mover {0,0,10,10} -> goal (20,0)      obstacle {15,0,10,10}
//   +----+    +----+
//   | m  | -> | o  |     right edge 10 reaches 15 after 5 of 20: ti = 0.25
//   +----+    +----+     placed at x = 15 - 10 = 5, normal points back at the mover: (-1, 0)
TEST(Sweep, HeadOnHitStopsAtTheObstaclesEdge) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {20, 0}, {15, 0, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_EQ(s.ti, 0.25);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{5, 0}));
  EXPECT_FALSE(s.corner);
}

TEST(Sweep, HitWhileMovingLeftAndUpPlacesAtTheFarEdges) {
  // Moving up into a ceiling {0,-30,40,10} (bottom at -20) from y = 0, goal y = -40:
  // top edge 0 reaches -20 after 20 of 40: ti = 0.5, placed at the ceiling's bottom, normal down.
  const tv::Sweep up = tv::sweepRect({5, 0, 10, 10}, {5, -40}, {0, -30, 40, 10});
  EXPECT_EQ(up.kind, SweepKind::hit);
  EXPECT_EQ(up.ti, 0.5);
  EXPECT_EQ(up.normal, (Vec2{0, 1}));
  EXPECT_EQ(up.touch, (Vec2{5, -20}));
  // Moving left into a wall {-20,-50,10,100} (right at -10) from x = 0 to x = -40: ti = 0.25.
  const tv::Sweep left = tv::sweepRect({0, 0, 10, 10}, {-40, 0}, {-20, -50, 10, 100});
  EXPECT_EQ(left.kind, SweepKind::hit);
  EXPECT_EQ(left.ti, 0.25);
  EXPECT_EQ(left.normal, (Vec2{1, 0}));
  EXPECT_EQ(left.touch, (Vec2{-10, 0}));
}

//   mover {0,0,10,10} -> goal (20,20)     obstacle {15,5,10,10}
//   On y the mover already spans the obstacle's rows; on x its right edge reaches 15 at 0.25.
//   x is entered last: normal (-1, 0); y is interpolated: 0 + 0.25 * 20 = 5.
TEST(Sweep, DiagonalHitTakesTheNormalOfTheAxisEnteredLast) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {20, 20}, {15, 5, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_EQ(s.ti, 0.25);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{5, 5}));
  EXPECT_FALSE(s.corner);
}

//   mover {0,0,10,10} -> goal (20,30)     obstacle {15,10,10,40}
//   x entered at (15-10)/20 = 0.25, y at (10-10)/30 = 0  ->  x last: normal (-1,0),
//   touch y = 0 + 0.25 * 30 = 7.5.
TEST(Sweep, EntryOnBothAxesAtDifferentTimesUsesTheLater) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {20, 30}, {15, 10, 10, 40});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_EQ(s.ti, 0.25);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{5, 7.5}));
  // Same obstacle lower down, {15,25,10,40}: y entered at (25-10)/30 = 0.5 after x: y normal.
  const tv::Sweep t = tv::sweepRect({0, 0, 10, 10}, {20, 30}, {15, 25, 10, 40});
  EXPECT_EQ(t.kind, SweepKind::hit);
  EXPECT_EQ(t.ti, 0.5);
  EXPECT_EQ(t.normal, (Vec2{0, -1}));
  EXPECT_EQ(t.touch, (Vec2{10, 15}));
}

//   +----+
//   | m  |  \            mover {0,0,10,10} -> goal (20,20)
//   +----+   \           obstacle {15,15,10,10}: both axes entered at exactly 0.25
//            +----+      -> corner, normal on x (as bump.lua), both coordinates from edges.
//            | o  |
//            +----+
TEST(Sweep, ExactCornerHitIsFlaggedAndTakesTheXNormal) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {20, 20}, {15, 15, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_TRUE(s.corner);
  EXPECT_EQ(s.ti, 0.25);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{5, 5}));
}

TEST(Sweep, ExactCornerHitWithUnequalSpeedsPerAxis) {
  // mover {0,0,4,4} -> (30,10); obstacle {10,6,5,5}: x enters at (10-4)/30 = 0.2,
  // y at (6-4)/10 = 0.2. Both exact: a corner.
  const tv::Sweep s = tv::sweepRect({0, 0, 4, 4}, {30, 10}, {10, 6, 5, 5});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_TRUE(s.corner);
  EXPECT_EQ(s.ti, 0.2);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{6, 2}));
}

//            +----+      obstacle {15,-5,10,10} (bottom edge at y = 5)
//            | o  |
//   +----+   +----+      mover {0,0,10,10} -> goal (20,20): its right edge reaches x = 15 at
//   | m  |  /            0.25, the moment its top edge leaves y = 5. The corners pass through
//   +----+ /             each other exactly: a graze, not a hit.
TEST(Sweep, GrazingPastACornerExactlyIsAMiss) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {20, 20}, {15, -5, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::miss);
  // One unit lower and the corners do meet: a hit.
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {20, 20}, {15, -4, 10, 10}).kind, SweepKind::hit);
}

TEST(Sweep, PassingWellClearIsAMiss) {
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {20, 0}, {15, 20, 10, 10}).kind, SweepKind::miss);
  // Stopping short: the goal's right edge is 14 < 15.
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {4, 0}, {15, 0, 10, 10}).kind, SweepKind::miss);
  // Arriving exactly at the obstacle's edge at the goal only touches.
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {5, 0}, {15, 0, 10, 10}).kind, SweepKind::miss);
  // Moving away from it.
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {-5, 0}, {15, 0, 10, 10}).kind, SweepKind::miss);
}

// [SECTION] sweepRect: touching contacts --------------------------------------------------------

//   +----+----+
//   | m  | o  |   mover {0,0,10,10} touches obstacle {10,0,10,10} and pushes right: hit at
//   +----+----+   ti 0, placed where it stands.
TEST(Sweep, TouchingAndPushingInHitsAtTimeZero) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {5, 0}, {10, 0, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::hit);
  EXPECT_EQ(s.ti, 0.0);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{0, 0}));
  // Resting on a floor and pushed down by gravity while walking: the same, on y.
  const tv::Sweep g = tv::sweepRect({3, 0, 10, 10}, {5.5, 0.3}, {0, 10, 100, 16});
  EXPECT_EQ(g.kind, SweepKind::hit);
  EXPECT_EQ(g.ti, 0.0);
  EXPECT_EQ(g.normal, (Vec2{0, -1}));
  EXPECT_EQ(g.touch, (Vec2{3, 0}));
}

TEST(Sweep, TouchingAndMovingAwayIsAMiss) {
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {-5, 0}, {10, 0, 10, 10}).kind, SweepKind::miss);
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {-5, -3}, {0, 10, 10, 10}).kind, SweepKind::miss);
}

//   +----+ ->          mover {0,0,10,10} -> (30,0) slides along the top of {5,10,10,10}:
//   | m  |             sharing the edge y = 10 the whole way never overlaps.
//   +--+-+--+
//      |  o |
//      +----+
TEST(Sweep, MovingAlongAnEdgeIsAMiss) {
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {30, 0}, {5, 10, 10, 10}).kind, SweepKind::miss);
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {0, 30}, {10, 5, 10, 10}).kind, SweepKind::miss);
  // Also past a tile's corner point when the edges line up: {10,10,..} only shares a corner.
  EXPECT_EQ(tv::sweepRect({0, 0, 10, 10}, {0, 30}, {10, 10, 10, 10}).kind, SweepKind::miss);
}

// [SECTION] sweepRect: starting inside ----------------------------------------------------------

//   mover {0,0,10,10}, obstacle {8,2,10,10}: intersection 2 x 8, so ti = -16.
//   Pushes: up 8, left 2, right 18, down 12 -> left is smallest: x = 8 - 10 = -2.
TEST(Sweep, StartingInsidePushesOutTheShallowestWayWithMinusTheAreaAsTi) {
  const tv::Sweep s = tv::sweepRect({0, 0, 10, 10}, {30, 0}, {8, 2, 10, 10});
  EXPECT_EQ(s.kind, SweepKind::overlap);
  EXPECT_EQ(s.ti, -16.0);
  EXPECT_EQ(s.normal, (Vec2{-1, 0}));
  EXPECT_EQ(s.touch, (Vec2{-2, 0}));
}

TEST(Sweep, StartingInsidePushesInEachOfTheFourDirections) {
  const Rect o{0, 0, 20, 20};
  // Overlapping the top by 1: up.
  tv::Sweep s = tv::sweepRect({5, -9, 10, 10}, {5, -9}, o);
  EXPECT_EQ(s.normal, (Vec2{0, -1}));
  EXPECT_EQ(s.touch, (Vec2{5, -10}));
  EXPECT_EQ(s.ti, -10.0);
  // Overlapping the right side by 2: right, to x = 20.
  s = tv::sweepRect({18, 5, 10, 10}, {18, 5}, o);
  EXPECT_EQ(s.normal, (Vec2{1, 0}));
  EXPECT_EQ(s.touch, (Vec2{20, 5}));
  EXPECT_EQ(s.ti, -20.0);
  // Overlapping the bottom by 3: down, to y = 20.
  s = tv::sweepRect({5, 17, 10, 10}, {5, 17}, o);
  EXPECT_EQ(s.normal, (Vec2{0, 1}));
  EXPECT_EQ(s.touch, (Vec2{5, 20}));
  EXPECT_EQ(s.ti, -30.0);
  // Equal depths: up wins over the others.
  s = tv::sweepRect({5, 5, 10, 10}, {5, 5}, o);
  EXPECT_EQ(s.normal, (Vec2{0, -1}));
  EXPECT_EQ(s.touch, (Vec2{5, -10}));
}

// [SECTION] clipSegment -------------------------------------------------------------------------

//   (0,5) ----[####]----> (20,5)     rect {5,0,10,10}: enters at 5/20, leaves at 15/20
TEST(ClipSegment, ThroughTheInteriorGivesEntryAndExit) {
  const tv::SegmentClip c = tv::clipSegment({0, 5}, {20, 5}, {5, 0, 10, 10});
  EXPECT_TRUE(c.hit);
  EXPECT_EQ(c.t0, 0.25);
  EXPECT_EQ(c.t1, 0.75);
  // Backwards: enters at the right edge.
  const tv::SegmentClip b = tv::clipSegment({20, 5}, {0, 5}, {5, 0, 10, 10});
  EXPECT_TRUE(b.hit);
  EXPECT_EQ(b.t0, 0.25);
  EXPECT_EQ(b.t1, 0.75);
}

TEST(ClipSegment, StartingOrEndingInsideClampsToTheSegment) {
  const tv::SegmentClip c = tv::clipSegment({10, 5}, {30, 5}, {5, 0, 10, 10});
  EXPECT_TRUE(c.hit);
  EXPECT_EQ(c.t0, 0.0);
  EXPECT_EQ(c.t1, 0.25);
  const tv::SegmentClip d = tv::clipSegment({0, 5}, {10, 5}, {5, 0, 10, 10});
  EXPECT_TRUE(d.hit);
  EXPECT_EQ(d.t0, 0.5);
  EXPECT_EQ(d.t1, 1.0);
}

TEST(ClipSegment, AlongAnEdgeIsAMiss) {
  EXPECT_FALSE(tv::clipSegment({0, 0}, {20, 0}, {5, 0, 10, 10}).hit);
  EXPECT_FALSE(tv::clipSegment({0, 10}, {20, 10}, {5, 0, 10, 10}).hit);
  EXPECT_FALSE(tv::clipSegment({5, -5}, {5, 20}, {5, 0, 10, 10}).hit);
}

//   (0,10)
//      \      +------+     the segment (0,10) -> (10,0) passes through (5,5), the rect's
//       \     |      |     top-left corner, and nowhere else of it.
//        \    |      |
//         `-> +------+  (rect {5,5,10,10})
TEST(ClipSegment, ThroughACornerPointOnlyIsAMiss) {
  EXPECT_FALSE(tv::clipSegment({0, 10}, {10, 0}, {5, 5, 10, 10}).hit);
  // A diagonal through two opposite corners of a square does cross its interior.
  const tv::SegmentClip d = tv::clipSegment({0, 0}, {20, 20}, {5, 5, 10, 10});
  EXPECT_TRUE(d.hit);
  EXPECT_EQ(d.t0, 0.25);
  EXPECT_EQ(d.t1, 0.75);
}

TEST(ClipSegment, ZeroLengthHitsOnlyStrictlyInside) {
  const Rect r{5, 5, 10, 10};
  const tv::SegmentClip in = tv::clipSegment({8, 8}, {8, 8}, r);
  EXPECT_TRUE(in.hit);
  EXPECT_EQ(in.t0, 0.0);
  EXPECT_EQ(in.t1, 0.0);
  EXPECT_FALSE(tv::clipSegment({1, 1}, {1, 1}, r).hit);
  EXPECT_FALSE(tv::clipSegment({5, 8}, {5, 8}, r).hit);  // on an edge
  EXPECT_FALSE(tv::clipSegment({5, 5}, {5, 5}, r).hit);  // on a corner
}

TEST(ClipSegment, StoppingShortOrStoppingOnTheEdgeIsAMiss) {
  EXPECT_FALSE(tv::clipSegment({0, 5}, {4, 5}, {5, 0, 10, 10}).hit);
  EXPECT_FALSE(tv::clipSegment({0, 5}, {5, 5}, {5, 0, 10, 10}).hit);
}

}  // namespace
