// Specification of the World's queries: rect, point, segment and anyOverlap, on the same
// half-open, exact-edge model as moves.

#include <gtest/gtest.h>

#include <vector>

#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;
namespace response = tv::response;

// Four 16x16 tiles meeting at (16,16), added out of reading order:
//
//   (0,0) +------+------+ (32,0)
//         |  a   |  b   |        added: d, b, c, a
//         +------+------+ (32,16)
//         |  c   |  d   |
//         +------+------+ (32,32)
struct Quad {
  World world{16};
  ItemId d = world.add({16, 16, 16, 16});
  ItemId b = world.add({16, 0, 16, 16});
  ItemId c = world.add({0, 16, 16, 16});
  ItemId a = world.add({0, 0, 16, 16});
};

using Ids = std::vector<ItemId>;

// [SECTION] queryRect ---------------------------------------------------------------------------

TEST(QueryRect, TouchingNeighboursAreNotIncluded) {
  const Quad q;
  EXPECT_EQ(q.world.queryRect({0, 0, 16, 16}), Ids{q.a});
  EXPECT_EQ(q.world.queryRect({32, 0, 5, 5}), Ids{});  // touches b's right edge only
}

TEST(QueryRect, ReturnsItemsInAddOrder) {
  const Quad q;
  EXPECT_EQ(q.world.queryRect({8, 8, 16, 16}), (Ids{q.d, q.b, q.c, q.a}));
  EXPECT_EQ(q.world.queryRect({-100, -100, 300, 300}), (Ids{q.d, q.b, q.c, q.a}));
}

TEST(QueryRect, AddOrderIsNotSlotOrder) {
  World w(16);
  const ItemId first = w.add({0, 0, 8, 8});
  const ItemId second = w.add({8, 0, 8, 8});
  w.remove(first);
  const ItemId third = w.add({4, 4, 8, 8});  // reuses slot 0, yet comes after `second`
  ASSERT_EQ(third.index, first.index);
  EXPECT_EQ(w.queryRect({0, 0, 20, 20}), (Ids{second, third}));
}

TEST(QueryRect, SkipLeavesTheAskingItemOut) {
  const Quad q;
  EXPECT_EQ(q.world.queryRect({8, 8, 16, 16}, q.b), (Ids{q.d, q.c, q.a}));
  std::vector<ItemId> out{q.a, q.a, q.a};  // the out-parameter form clears first
  q.world.queryRect({20, 20, 2, 2}, out, q.a);
  EXPECT_EQ(out, Ids{q.d});
}

TEST(QueryRect, AZeroSizeRectFindsWhatHoldsItStrictly) {
  const Quad q;
  EXPECT_EQ(q.world.queryRect({8, 8, 0, 0}), Ids{q.a});
  EXPECT_EQ(q.world.queryRect({16, 8, 0, 0}), Ids{});  // on the seam: interior of neither
}

// [SECTION] queryPoint ----------------------------------------------------------------------------

TEST(QueryPoint, APointOnASharedEdgeBelongsToExactlyOneTile) {
  const Quad q;
  EXPECT_EQ(q.world.queryPoint({16, 8}), Ids{q.b});
  EXPECT_EQ(q.world.queryPoint({8, 16}), Ids{q.c});
  EXPECT_EQ(q.world.queryPoint({16, 16}), Ids{q.d});  // the corner all four share
  EXPECT_EQ(q.world.queryPoint({0, 0}), Ids{q.a});
  EXPECT_EQ(q.world.queryPoint({32, 8}), Ids{});
  EXPECT_EQ(q.world.queryPoint({8, 32}), Ids{});
}

TEST(QueryPoint, EveryPointOfAFloorBelongsToExactlyOneTile) {
  // 64 tiles of 16 px in a row (the seams fall on and off cell lines of 24): a sweep of
  // points at 1/8 px across the floor each find exactly one.
  World w(24);
  for (int i = 0; i < 64; ++i) (void)w.add({16.0 * i, 0, 16, 16});
  for (int k = 0; k < 64 * 16 * 8; ++k) {
    const Vec2 p{k / 8.0, 15.875};
    ASSERT_EQ(w.queryPoint(p).size(), 1u) << "x = " << p.x;
  }
}

TEST(QueryPoint, OverlappingItemsComeInAddOrder) {
  World w(16);
  const ItemId big = w.add({0, 0, 40, 40});
  const ItemId small = w.add({10, 10, 5, 5});
  EXPECT_EQ(w.queryPoint({12, 12}), (Ids{big, small}));
}

// [SECTION] querySegment --------------------------------------------------------------------------

//   (-16,4) ---> (48,4), 64 long, across a then b:
//   a from t 16/64 to 32/64 (x 0 to 16), b from 32/64 to 48/64 (x 16 to 32).
TEST(QuerySegment, IsSortedAlongTheSegmentWithEntryAndExitPoints) {
  const Quad q;  // b was added before a
  const std::vector<tv::SegmentHit> hits = q.world.querySegment({-16, 4}, {48, 4});
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].item, q.a);
  EXPECT_EQ(hits[0].t0, 0.25);
  EXPECT_EQ(hits[0].t1, 0.5);
  EXPECT_EQ(hits[0].entry, (Vec2{0, 4}));
  EXPECT_EQ(hits[0].exit, (Vec2{16, 4}));
  EXPECT_EQ(hits[1].item, q.b);
  EXPECT_EQ(hits[1].t0, 0.5);
  EXPECT_EQ(hits[1].t1, 0.75);
  EXPECT_EQ(hits[1].entry, (Vec2{16, 4}));
  EXPECT_EQ(hits[1].exit, (Vec2{32, 4}));
  // Backwards, b comes first and is entered from its right edge.
  const std::vector<tv::SegmentHit> back = q.world.querySegment({48, 4}, {-16, 4});
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].item, q.b);
  EXPECT_EQ(back[0].entry, (Vec2{32, 4}));
  EXPECT_EQ(back[1].item, q.a);
  EXPECT_EQ(back[1].exit, (Vec2{0, 4}));
}

TEST(QuerySegment, AlongAGridLineBetweenTilesHitsNothing) {
  const Quad q;
  EXPECT_TRUE(q.world.querySegment({-8, 16}, {40, 16}).empty());
  EXPECT_TRUE(q.world.querySegment({16, -8}, {16, 40}).empty());
  EXPECT_TRUE(q.world.querySegment({0, 0}, {32, 0}).empty());  // along the outer edge
}

//   (-8,8)
//       `.
//         `. +------+    (-8,8) -> (8,-8) passes through a's corner (0,0) and nothing else
//            |  a   |
TEST(QuerySegment, ThroughACornerPointOnlyHitsNothing) {
  const Quad q;
  EXPECT_TRUE(q.world.querySegment({-8, 8}, {8, -8}).empty());
  // Through the point all four share, along the other diagonal, crosses b and c only.
  const std::vector<tv::SegmentHit> hits = q.world.querySegment({32, 0}, {0, 32});
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].item, q.b);
  EXPECT_EQ(hits[1].item, q.c);
  EXPECT_EQ(hits[0].t1, 0.5);
  EXPECT_EQ(hits[1].t0, 0.5);
}

TEST(QuerySegment, TiesAlongTheSegmentComeInAddOrder) {
  World w(16);
  const ItemId upper = w.add({50, 0, 10, 10});
  const ItemId lower = w.add({50, 2, 10, 10});
  const std::vector<tv::SegmentHit> hits = w.querySegment({0, 5}, {100, 5});
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].item, upper);
  EXPECT_EQ(hits[1].item, lower);
  EXPECT_EQ(hits[0].t0, 0.5);
  EXPECT_EQ(hits[1].t0, 0.5);
}

TEST(QuerySegment, ALongSegmentFindsAThinItemFarAway) {
  World w(4);
  const ItemId thin = w.add({9000, -1, 0.5, 2});
  const std::vector<tv::SegmentHit> hits = w.querySegment({0, 0}, {10000, 0.5});
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].item, thin);
}

// [SECTION] anyOverlap --------------------------------------------------------------------------

TEST(AnyOverlap, IsTheCheapIsThisSpotFree) {
  const Quad q;
  EXPECT_FALSE(q.world.anyOverlap({32, 0, 10, 10}));     // touching b only
  EXPECT_FALSE(q.world.anyOverlap({-10, -10, 10, 10}));  // touching a's corner
  EXPECT_TRUE(q.world.anyOverlap({31, 31, 10, 10}));
  EXPECT_FALSE(q.world.anyOverlap({100, 100, 1, 1}));
}

TEST(AnyOverlap, SkipsTheAskingItemAndAsksTheFilter) {
  const Quad q;
  EXPECT_FALSE(q.world.anyOverlap({1, 1, 2, 2}, q.a));
  EXPECT_TRUE(q.world.anyOverlap({1, 1, 2, 2}));
  std::vector<ItemId> asked;
  auto ignoreAll = [&](ItemId self, ItemId other) {
    EXPECT_EQ(self, q.a);
    asked.push_back(other);
    return response::ignore;
  };
  EXPECT_FALSE(q.world.anyOverlap({8, 8, 16, 16}, q.a, ignoreAll));
  EXPECT_EQ(asked.size(), 3u);  // b, c, d each asked once
  auto onlyD = [&](ItemId, ItemId other) {
    return other == q.d ? response::touch : response::ignore;
  };
  EXPECT_TRUE(q.world.anyOverlap({8, 8, 16, 16}, q.a, onlyD));
  EXPECT_FALSE(q.world.anyOverlap({8, 8, 8, 8}, q.a, onlyD));
}

}  // namespace
