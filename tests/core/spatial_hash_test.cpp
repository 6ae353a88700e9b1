// Specification of the world's spatial hash (core/src/spatial_hash.hpp): half-open
// registration, O(1) re-registration that keeps every cell's entries right, recycled cells, and
// a box of occupied cells that follows where items are now, not where they once were.

#include "spatial_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "tv/sim/rng.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv::detail {
namespace {

using Rng = sim::Rng;  // the scenes' SplitMix64: the same scenes on every standard library

std::vector<std::uint32_t> slotsIn(const SpatialHash& h, Cell c) {
  std::vector<std::uint32_t> v;
  for (const HashEntry& e : h.items(c)) v.push_back(e.slot());
  std::sort(v.begin(), v.end());
  return v;
}

// Everything the hash holds, against what a brute-force registry of the same rects says:
// each item in exactly the cells of Grid::cellsHolding, with its current rect and generation.
void expectMatches(const SpatialHash& h, const std::map<std::uint32_t, Rect>& items) {
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>> expected;
  for (const auto& [slot, r] : items) {
    Grid::forEachCell(h.grid().cellsHolding(r), [&](Cell c) {
      expected[{c.x, c.y}].push_back(slot);
    });
  }
  std::size_t cells = 0;
  h.forEachOccupiedCell([&](Cell c, std::size_t n) {
    ++cells;
    ASSERT_TRUE(h.liveBox().contains(c));
    auto want = expected[{c.x, c.y}];
    std::sort(want.begin(), want.end());
    EXPECT_EQ(slotsIn(h, c), want) << "cell " << c.x << "," << c.y;
    EXPECT_EQ(n, want.size());
    for (const HashEntry& e : h.items(c)) {
      EXPECT_EQ(e.rect, items.at(e.slot()));
      EXPECT_EQ(e.generation, e.slot() * 7u);
      EXPECT_EQ(e.shared(), h.grid().cellsHolding(e.rect).count() > 1);
    }
  });
  EXPECT_EQ(cells, expected.size());
  EXPECT_EQ(h.occupiedCells(), expected.size());
}

TEST(SpatialHash, RegistersTheHalfOpenExtent) {
  //   cell 32: a 16 px tile at (16, 16) ends on the cell line x = y = 32: one cell, not four.
  SpatialHash h(32);
  h.insert(0, 0, {16, 16, 16, 16});
  EXPECT_EQ(h.occupiedCells(), 1u);
  EXPECT_EQ(slotsIn(h, {0, 0}), std::vector<std::uint32_t>{0});
  EXPECT_FALSE(h.items({0, 0})[0].shared());
  // One ulp further it reaches into the next cells.
  const Rect wider{16, 16, std::nextafter(32.0, 64.0) - 16.0, 16};
  ASSERT_GT(wider.right(), 32.0);
  h.insert(1, 0, wider);
  ASSERT_EQ(slotsIn(h, {1, 0}), std::vector<std::uint32_t>{1});
  EXPECT_TRUE(h.items({1, 0})[0].shared());
  EXPECT_EQ(h.occupiedCells(), 2u);
}

TEST(SpatialHash, ARectNarrowerThanItsRoundingStillHasItsCornersCell) {
  // right() == x when w is far below the ulp of x: the item still lives in x's cell.
  SpatialHash h(16);
  const Rect r{1e9, 5, 1e-30, 1};
  ASSERT_EQ(r.right(), r.x);
  h.insert(3, 21, r);
  EXPECT_EQ(h.occupiedCells(), 1u);
  EXPECT_EQ(slotsIn(h, h.grid().cellAt(r.position())), std::vector<std::uint32_t>{3});
}

TEST(SpatialHash, RandomInsertsUpdatesAndErasesKeepEveryCellExact) {
  // Items of every size (small ones remember their entries' indices, large ones scan), moved
  // within a cell, across cells and far away, at awkward coordinates; after each step the hash
  // equals a brute-force registry of the same rects.
  SpatialHash h(10);
  std::map<std::uint32_t, Rect> items;
  Rng rng(7);
  const auto randomRect = [&] {
    const double w = rng.uniform() < 0.2 ? rng.uniform(10, 45) : rng.uniform(0.5, 12);
    const double x = std::floor(rng.uniform(-60, 60)) * (rng.uniform() < 0.5 ? 1.0 : 0.5);
    return Rect{x, rng.uniform(-60, 60), w, rng.uniform(0.5, 12)};
  };
  for (int step = 0; step < 4000; ++step) {
    const auto slot = static_cast<std::uint32_t>(rng.below(48));
    const auto it = items.find(slot);
    const double u = rng.uniform();
    if (it == items.end()) {
      const Rect r = randomRect();
      h.insert(slot, slot * 7u, r);
      items[slot] = r;
    } else if (u < 0.15) {
      h.erase(slot);
      items.erase(it);
    } else {
      Rect r = it->second;
      if (u < 0.6) {
        r = r.at(r.position() + Vec2{rng.uniform(-2, 2), rng.uniform(-2, 2)});  // nearby
      } else if (u < 0.9) {
        r = randomRect();
      } else {
        r = r.at({rng.uniform(-5e4, 5e4), rng.uniform(-5e4, 5e4)});  // far away
      }
      h.update(slot, r);
      it->second = r;
    }
    if (step % 50 == 0) expectMatches(h, items);
  }
  expectMatches(h, items);
  // A copy is equal, and independent of the original.
  SpatialHash copy(h);
  expectMatches(copy, items);
  for (const auto& [slot, r] : items) h.erase(slot);
  EXPECT_EQ(h.occupiedCells(), 0u);
  expectMatches(copy, items);
}

TEST(SpatialHash, CellsAreRecycledSoMemoryFollowsTheCellsOccupiedNow) {
  // One 8×8 body crosses 10^6 empty 16 px cells, 4 px a step: memory ends where it began.
  SpatialHash h(16);
  h.insert(0, 0, {0, 0, 16, 16});  // a tile at home
  h.insert(1, 0, {2, 40, 8, 8});   // the body
  const std::size_t baseline = h.memoryBytes();
  Rect body{2, 40, 8, 8};
  for (int i = 0; i < 4000000; ++i) {
    body = body.at({body.x + 4, body.y});
    h.update(1, body);
  }
  EXPECT_GE(body.x, 16.0 * 1e6);
  EXPECT_LE(h.occupiedCells(), 3u);
  EXPECT_LE(h.memoryBytes(), baseline + 1024);
  // Negative control of the measure: holding the cells it crossed (one item per 16 cells
  // left behind) costs memory in proportion.
  for (std::uint32_t k = 0; k < 1000; ++k) h.insert(2 + k, 0, {k * 256.0, 80, 8, 8});
  EXPECT_GT(h.memoryBytes(), baseline + 1000 * sizeof(HashEntry));
}

TEST(SpatialHash, TheBoxOfOccupiedCellsShrinksWhenItemsLeave) {
  // An item visits (1e6, 1e6) and comes back: the box no longer spans the trip.
  SpatialHash h(16);
  h.insert(0, 0, {0, 0, 16, 16});
  h.insert(1, 0, {32, 0, 8, 8});
  h.update(1, {1e6, 1e6, 8, 8});
  EXPECT_TRUE(h.liveBox().contains(h.grid().cellAt({1e6, 1e6})));
  h.update(1, {32, 0, 8, 8});
  // Tightened once enough cells emptied (amortized): a few more moves in place do it.
  for (int i = 0; i < 64; ++i) h.update(1, {32.0 + 16 * (i % 2), 0, 8, 8});
  EXPECT_EQ(h.liveBox(), (CellRange{0, 0, 3, 0}));
}

}  // namespace
}  // namespace tv::detail

namespace tv {
namespace {

// The cost of a move does not depend on where items used to be: after an item visited
// (1e6, 1e6) and came back, a long move through empty ground reads as few cells as before.
TEST(WorldCells, ALongMoveCostsTheSameAfterAnItemVisitedFarAway) {
  const auto cellsRead = [](bool visitFirst) {
    World w(16);
    w.add({0, 0, 16, 16});
    const ItemId far = w.add({32, 0, 8, 8});
    const ItemId m = w.add({0, 64, 8, 8});
    if (visitFirst) w.update(far, Vec2{1e6, 1e6});
    for (int i = 0; i < 64; ++i) w.update(far, Vec2{32.0 + 16 * (i % 2), 0});
    MoveTrace t;
    MoveOptions o;
    o.trace = &t;
    (void)w.check(m, {2546, 2610}, {}, o);  // a 3600 px diagonal through empty ground
    return t.cells.size();
  };
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out";
  EXPECT_EQ(cellsRead(true), cellsRead(false));
  EXPECT_LT(cellsRead(true), 16u);
}

TEST(WorldCells, MemoryReturnsToBaselineAfterABodyCrossesAMillionEmptyCells) {
  World w(16);
  for (int i = 0; i < 100; ++i) w.add({i * 16.0, 0, 16, 16});
  const ItemId body = w.add({0, 32, 8, 8});
  (void)w.move(body, {4, 32});  // the move path's scratch, once
  const std::size_t baseline = w.memoryBytes();
  for (int i = 1; i <= 1000000; ++i) (void)w.move(body, {4 + 16.0 * i, 32});
  EXPECT_EQ(w.countCells(), 100u + 1u);
  EXPECT_LE(w.memoryBytes(), baseline + 1024);
}

TEST(WorldCells, ACopyIsDeepAndMovesExactlyAsTheOriginal) {
  World a(16);
  for (int i = 0; i < 20; ++i) a.add({i * 16.0, 64, 16, 16});
  const ItemId m = a.add({0, 0, 8, 8});
  World b = a;
  const MoveResult ra = a.move(m, {100, 70});
  const Vec2 pa = ra.position;
  const MoveResult rb = b.move(m, {100, 70});
  EXPECT_EQ(pa, rb.position);
  EXPECT_EQ(a.stateHash(), b.stateHash());
  // Changing one leaves the other alone, cells included.
  b.remove(m);
  EXPECT_TRUE(a.has(m));
  EXPECT_EQ(a.queryRect({0, 0, 400, 200}, {}).size(), 20u + 1u);
  World c(32);
  c = std::move(b);
  b = a;  // a moved-from world can be assigned again
  EXPECT_EQ(b.stateHash(), a.stateHash());
  EXPECT_EQ(c.countCells(), 20u);
}

}  // namespace
}  // namespace tv
