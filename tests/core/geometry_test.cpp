// Specification of the tolerance model in tv/geometry.hpp: overlap, touch and containment
// compare the rounded edge doubles exactly; placeBefore puts a far edge on an obstacle's edge
// bit for bit.

#include "tv/geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace {

using tv::Rect;
using tv::Vec2;

constexpr double kInf = std::numeric_limits<double>::infinity();

// [SECTION] overlaps and touches ------------------------------------------------------------

//   a: [0,10)x[0,10)    b: [10,20)x[0,10)
//   +----------+----------+
//   |    a     |    b     |
//   +----------+----------+
TEST(Overlap, SharingAnEdgeIsTouchingNotOverlapping) {
  const Rect a{0, 0, 10, 10}, b{10, 0, 10, 10};
  EXPECT_FALSE(tv::overlaps(a, b));
  EXPECT_FALSE(tv::overlaps(b, a));
  EXPECT_TRUE(tv::touches(a, b));
  EXPECT_TRUE(tv::touches(b, a));
}

//   +-----+
//   |  a  |
//   +-----+-----+
//         |  b  |
//         +-----+
TEST(Overlap, SharingOnlyACornerPointIsTouching) {
  const Rect a{0, 0, 10, 10}, b{10, 10, 5, 5};
  EXPECT_FALSE(tv::overlaps(a, b));
  EXPECT_TRUE(tv::touches(a, b));
}

TEST(Overlap, InteriorsMeetingByAnyAmountIsOverlappingAndNotTouching) {
  const Rect a{0, 0, 10, 10};
  const Rect b{std::nextafter(10.0, 0.0), 0, 10, 10};  // one ulp inside a's right edge
  EXPECT_TRUE(tv::overlaps(a, b));
  EXPECT_TRUE(tv::overlaps(b, a));
  EXPECT_FALSE(tv::touches(a, b));
}

TEST(Overlap, AGapOfOneUlpIsNeitherOverlapNorTouch) {
  const Rect a{0, 0, 10, 10};
  const Rect b{std::nextafter(10.0, kInf), 0, 10, 10};
  EXPECT_FALSE(tv::overlaps(a, b));
  EXPECT_FALSE(tv::touches(a, b));
}

TEST(Overlap, ARectInsideAnotherOverlapsIt) {
  const Rect outer{0, 0, 100, 100}, inner{40, 40, 1, 1};
  EXPECT_TRUE(tv::overlaps(outer, inner));
  EXPECT_TRUE(tv::overlaps(inner, outer));
}

TEST(Overlap, TheRulesMeanTheSameAtABillion) {
  // No epsilon: at 1e9 (ulp 1.2e-7) an edge shared bit for bit still only touches.
  const double e = 1e9 + 8.1;
  const Rect a{1e9, 1e9, e - 1e9, 16}, b{e, 1e9, 16, 16};
  ASSERT_EQ(a.right(), b.x);
  EXPECT_FALSE(tv::overlaps(a, b));
  EXPECT_TRUE(tv::touches(a, b));
}

// [SECTION] contains (half-open) --------------------------------------------------------------

//   (0,0) +--------+--------+ (32,0)
//         |   a    |   b    |
//         +--------+--------+ (32,16)
//   the point (16, 8) lies on the seam: it belongs to b only.
TEST(Contains, APointOnASharedEdgeBelongsToExactlyOneTile) {
  const Rect a{0, 0, 16, 16}, b{16, 0, 16, 16}, c{0, 16, 16, 16};
  EXPECT_FALSE(tv::contains(a, {16, 8}));
  EXPECT_TRUE(tv::contains(b, {16, 8}));
  EXPECT_FALSE(tv::contains(a, {8, 16}));
  EXPECT_TRUE(tv::contains(c, {8, 16}));
}

TEST(Contains, IncludesTheTopLeftCornerAndExcludesTheOthers) {
  const Rect r{0, 0, 16, 16};
  EXPECT_TRUE(tv::contains(r, {0, 0}));
  EXPECT_FALSE(tv::contains(r, {16, 0}));
  EXPECT_FALSE(tv::contains(r, {0, 16}));
  EXPECT_FALSE(tv::contains(r, {16, 16}));
  EXPECT_TRUE(tv::contains(r, {std::nextafter(16.0, 0.0), std::nextafter(16.0, 0.0)}));
  EXPECT_FALSE(tv::contains(r, {std::nextafter(0.0, -1.0), 8}));
}

// [SECTION] unite -------------------------------------------------------------------------------

//   +----+               a = {0,0,10,10}
//   | a  |      +--+     b = {20,5,5,20}
//   +----+      |b |     unite = {0,0,25,25}
//               +--+
TEST(Unite, IsTheSmallestRectHoldingBoth) {
  const Rect u = tv::unite({0, 0, 10, 10}, {20, 5, 5, 20});
  EXPECT_EQ(u, (Rect{0, 0, 25, 25}));
  EXPECT_EQ(tv::unite({20, 5, 5, 20}, {0, 0, 10, 10}), u);
}

TEST(Unite, WithNegativeCoordinatesAndContainment) {
  EXPECT_EQ(tv::unite({-10, -20, 5, 5}, {0, 0, 1, 1}), (Rect{-10, -20, 11, 21}));
  EXPECT_EQ(tv::unite({0, 0, 100, 100}, {10, 10, 1, 1}), (Rect{0, 0, 100, 100}));
}

// x0 + (x1 - x0) can round below x1. a {21, -12, 12, 2}, b {35, 9.0000000000000018, 12, 2}:
// b.bottom() is 11.000000000000002, one ulp above 11, and y1 - y0 = 23.0000000000000018 is a tie
// that rounds to 23. The world pre-rejects candidates with this hull, so a hull short of its
// rects lets a move end inside an obstacle (World.AGoalEndingAnUlpInsideAnObstacleIsStopped...).
TEST(Unite, HoldsBothRectsEvenWhenTheSizeRounds) {
  const Rect a{21, -12, 12, 2}, b{35, 9.0000000000000018, 12, 2};
  const Rect u = tv::unite(a, b);
  EXPECT_LE(u.x, a.x);
  EXPECT_LE(u.y, a.y);
  EXPECT_GE(u.right(), b.right());
  EXPECT_GE(u.bottom(), b.bottom()) << "unite's far edge rounded below b's";
}

// [SECTION] placeBefore -----------------------------------------------------------------------

// When some coordinate lands the far edge exactly on `edge`, placeBefore returns the landing
// coordinate nearest to edge - size: the rounded difference itself when it lands, otherwise the
// first landing double met going from it towards the landing ones.
void expectPlacedOnTheEdge(double edge, double size) {
  const double c = tv::placeBefore(edge, size);
  ASSERT_EQ(c + size, edge) << "edge " << edge << " size " << size;
  const double naive = edge - size;
  if (naive + size == edge) {
    EXPECT_EQ(c, naive) << "edge " << edge << " size " << size;
  } else {
    EXPECT_NE(std::nextafter(c, naive) + size, edge) << "edge " << edge << " size " << size;
  }
}

// When no coordinate lands exactly: short of the edge, and the next double up would pass it.
void expectShortByOneStep(double edge, double size) {
  const double c = tv::placeBefore(edge, size);
  EXPECT_LT(c + size, edge) << "edge " << edge << " size " << size;
  EXPECT_GT(std::nextafter(c, kInf) + size, edge) << "edge " << edge << " size " << size;
}

TEST(PlaceBefore, PutsTheFarEdgeExactlyOnTheEdgeForDecimalSizes) {
  const double sizes[] = {8.1, 13.7, 0.1, 0.3, 1.1, 16.0, 99.99, 0.7, 1234.56};
  // Hand-picked edges: small, decimal, powers of ten up to a billion.
  std::vector<double> edges = {0.0, 1.0, 16.0, 100.0, 100.1, 1234.5, 65536.3};
  edges.insert(edges.end(), {999999.9, 1e6, 123456789.123, 5e8, 999999999.9, 1e9});
  // Tile-grid edges: whole numbers (and halves) from 1 to 1e9.
  for (double e = 1.0; e <= 1e9; e *= 1.37) {
    edges.push_back(std::round(e));
    edges.push_back(std::round(e) + 0.5);
  }
  for (double e = 1e9; e > 1e9 - 1000; e -= 16.0) edges.push_back(e);
  for (const double size : sizes) {
    for (const double edge : edges) {
      if (edge != 0.0 && edge < size) continue;  // coordinate would be negative: see below
      expectPlacedOnTheEdge(edge, size);
    }
  }
}

TEST(PlaceBefore, IsExactForRandomTileEdgesUpToABillion) {
  const std::uint64_t seed = 20240611;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> sixteenths(0, std::int64_t{16'000'000'000});
  std::uniform_int_distribution<int> tenths(1, 2400);  // 0.1 .. 240.0
  for (int i = 0; i < 100000; ++i) {
    const double size = tenths(rng) / 10.0;
    const double edge = static_cast<double>(sixteenths(rng)) / 16.0 + 240.0;  // 0 .. 1e9 + 240
    const double c = tv::placeBefore(edge, size);
    ASSERT_EQ(c + size, edge) << "edge " << edge << " size " << size << " seed " << seed;
  }
}

TEST(PlaceBefore, IsTheRoundedDifferenceWhenThatLands) {
  EXPECT_EQ(tv::placeBefore(20.0, 8.0), 12.0);
  EXPECT_EQ(tv::placeBefore(16.0, 10.0), 6.0);
  EXPECT_EQ(tv::placeBefore(-16.0, 10.0), -26.0);
  EXPECT_EQ(tv::placeBefore(1e9, 16.0), 1e9 - 16.0);
  EXPECT_EQ(tv::placeBefore(0.0, 8.1), -8.1);
}

// edge 100, size 99.99: the coordinate is about 0.01, whose ulp (1.7e-18) is ~8000 times finer
// than the edge's (1.4e-14), so thousands of coordinates land the far edge on 100 exactly.
// placeBefore returns the one nearest to 100 - 99.99 (here the exact difference), and it lands.
TEST(PlaceBefore, WhenTheCoordinatesUlpIsFarFinerThanTheEdgesStillLandsNearestTheDifference) {
  const double edge = 100.0, size = 99.99;
  const double c = tv::placeBefore(edge, size);
  EXPECT_EQ(c + size, edge);
  EXPECT_EQ(c, edge - size);
  // Many larger coordinates land too: the choice among them is the nearest, not the largest.
  double up = c;
  for (int i = 0; i < 1000; ++i) up = std::nextafter(up, kInf);
  EXPECT_EQ(up + size, edge);
  // Same regime with a far edge of 1e9 and a coordinate below 1.
  expectPlacedOnTheEdge(1e9, 1e9 - 0.75);
  expectPlacedOnTheEdge(1e9 + 0.5, 999999999.9);
}

// Even a coordinate smaller than the edge cannot always land. Edge 0.9, size 0.2, coordinate
// about 0.7: coordinate and edge share the binade [0.5, 1) (ulp 2^-53); 0.2 is
// 7205759403792794 * 2^-55, which is 2 mod 4 in units of 2^-55, so every exact sum c + 0.2 lies
// halfway between two doubles of that binade and rounds to the even one. 0.9 has an odd
// mantissa: no double c has c + 0.2 == 0.9, and placeBefore stops one step short. Whole and half
// edges (even mantissas) and tile grids of dyadic sizes never hit this.
TEST(PlaceBefore, CannotLandOnAnOddMantissaEdgeWhenTheSumIsAlwaysATie) {
  for (const auto& [edge, size] : {std::pair{0.9, 0.2}, std::pair{1.7, 0.4}}) {
    const double c = tv::placeBefore(edge, size);
    EXPECT_LT(c + size, edge);
    EXPECT_GT(std::nextafter(c, kInf) + size, edge) << "no coordinate between lands either";
  }
}

TEST(PlaceBefore, NeverPastTheEdgeEvenWhenNoCoordinateReachesIt) {
  expectShortByOneStep(0.9, 0.2);  // see the odd-mantissa test above
  expectShortByOneStep(2.9, 0.7);
  // The coordinate (about -1e6, ulp 1.2e-10) is far coarser than the edge 1e-3: the far edge
  // c + 1e6 is always a multiple of 2^-33, which 1e-3 is not, so it stops short by one step.
  expectShortByOneStep(1e-3, 1e6);
  expectShortByOneStep(0.1, 1e9);
  expectShortByOneStep(1e-300, 3.0);
}

TEST(PlaceBefore, NeverPastTheEdgeForRandomEdgesAndSizes) {
  const std::uint64_t seed = 77;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mag(-12.0, 9.0);
  std::uniform_int_distribution<int> sign(0, 1);
  for (int i = 0; i < 100000; ++i) {
    const double edge = (sign(rng) ? 1.0 : -1.0) * std::pow(10.0, mag(rng));
    const double size = std::pow(10.0, mag(rng));
    const double c = tv::placeBefore(edge, size);
    ASSERT_LE(c + size, edge) << "edge " << edge << " size " << size << " seed " << seed;
    // Either it lands, or no double does: the next one up passes the edge.
    if (c + size != edge) {
      ASSERT_GT(std::nextafter(c, kInf) + size, edge) << "edge " << edge << " size " << size;
    }
  }
}

}  // namespace
