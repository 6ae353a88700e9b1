// Specification of the world's spatial hash (core/src/spatial_hash.hpp): half-open
// registration, O(1) re-registration that keeps every cell's entries right, recycled cells, and
// a box of occupied cells that follows where items are now, not where they once were.

#include "spatial_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
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

TEST(SpatialHash, AnItemCrossingTheFourCellBoundaryBothWaysKeepsEveryCellExact) {
  // Small items (up to four cells) remember their entries; larger ones keep their range in a
  // side table whose places are reused. Item 0 goes from one kind to the other and back while
  // neighbours added after it share its cells, so every removal of its entries moves one of
  // theirs (swap-remove) and must re-point it.
  //
  //   cell 10     x: 0   10   20   30   40   50
  //               +----+----+----+----+----+
  //   y 0         |0 1 |0 2 |  3 |    |    |     0 = the item, 1..6 = neighbours
  //   y 10        |0 4 |0 5 |  6 |    |    |
  //               +----+----+----+----+----+
  SpatialHash h(10);
  std::map<std::uint32_t, Rect> items;
  const auto put = [&](std::uint32_t slot, const Rect& r) {
    if (items.count(slot) != 0) {
      h.update(slot, r);
    } else {
      h.insert(slot, slot * 7u, r);
    }
    items[slot] = r;
    expectMatches(h, items);
  };
  const auto erase = [&](std::uint32_t slot) {
    h.erase(slot);
    items.erase(slot);
    expectMatches(h, items);
  };
  put(0, {1, 1, 15, 15});  // 2×2: small
  put(1, {2, 2, 3, 3});
  put(2, {12, 2, 3, 3});
  put(3, {22, 2, 3, 3});
  put(4, {2, 12, 3, 3});
  put(5, {12, 12, 3, 3});
  put(6, {22, 12, 3, 3});
  put(0, {1, 1, 25, 15});  // 3×2: large
  put(0, {2, 2, 25, 15});  // the same cells: its rect rewritten in all six
  put(0, {11, 1, 15, 15});  // 2×2 again, one column over
  put(0, {1, 1, 45, 5});    // 5×1: large
  put(0, {1, 1, 35, 5});    // 4×1: small, at the boundary
  put(0, {1, 1, 45, 5});
  put(7, {-30, -30, 35, 35});  // 4×4, a second place in the side table
  erase(0);                    // frees its place...
  put(8, {-60, 40, 25, 25});   // ...which this one takes
  put(7, {-29, -29, 35, 35});  // 7's range is still its own
  put(8, {-60, 40, 5, 5});     // large to small: the place is free again
  put(0, {30, 30, 60, 5});     // and taken again
  put(7, {3, 3, 5, 5});
  erase(0);
  erase(7);
  put(9, {0, 0, 50, 50});
  // A copy holds the same side table and goes on independently.
  SpatialHash copy(h);
  expectMatches(copy, items);
  h.update(9, {5, 5, 5, 5});
  h.erase(8);
  std::map<std::uint32_t, Rect> copied = items;
  items[9] = {5, 5, 5, 5};
  items.erase(8);
  expectMatches(h, items);
  expectMatches(copy, copied);
  copy.update(9, {100, 100, 35, 35});
  copied[9] = {100, 100, 35, 35};
  expectMatches(copy, copied);
  expectMatches(h, items);
}

TEST(SpatialHash, AShiftThatLeavesACellEntersANewOneAndGrowsTheTableKeepsEveryCellExact) {
  // The table starts with 64 buckets and doubles when a 33rd cell is made. Item 0 (two cells)
  // steps one cell right: it leaves (0,0), which item 1 keeps occupied (and whose entry moves
  // into item 0's place there), keeps (1,0), and enters (2,0) — the 33rd cell, made mid-shift.
  //
  //   x: 0    10   20   30
  //      +----+----+----+
  //      |0  1|0   |    |   ->   |   1|   0|   0|
  //      +----+----+----+
  //   and thirty single items along y = 50, one a cell
  SpatialHash h(10);
  std::map<std::uint32_t, Rect> items;
  const auto insert = [&](std::uint32_t slot, const Rect& r) {
    h.insert(slot, slot * 7u, r);
    items[slot] = r;
  };
  insert(0, {1, 1, 15, 5});
  insert(1, {2, 2, 3, 3});
  for (std::uint32_t i = 0; i < 30; ++i) insert(2 + i, {i * 10.0 + 1, 51, 3, 3});
  ASSERT_EQ(h.occupiedCells(), 32u);
  const std::size_t before = h.memoryBytes();
  h.update(0, {11, 1, 15, 5});
  items[0] = {11, 1, 15, 5};
  EXPECT_EQ(h.occupiedCells(), 33u);
  EXPECT_GT(h.memoryBytes(), before);  // the table did grow on the way
  expectMatches(h, items);
  // And back: (2,0) empties and is freed, (0,0) is entered again, then item 1 goes too.
  h.update(0, {1, 1, 15, 5});
  items[0] = {1, 1, 15, 5};
  expectMatches(h, items);
  h.update(1, {31, 1, 3, 3});
  items[1] = {31, 1, 3, 3};
  expectMatches(h, items);
}

TEST(SpatialHash, ACrowdGatheringAndDispersingKeepsEveryCellExactAndSoDoesItsCopy) {
  // Hundreds of items crowd into a few cells (tens of entries each, buffers traded up) and spread
  // out again (buffers given back), moving mostly by small steps (shifts that free cells and take
  // freed ones in the same update); halfway, a copy takes the same steps as the original.
  SpatialHash h(10);
  std::map<std::uint32_t, Rect> items;
  Rng rng(23);
  const auto randomRect = [&](double spread) {
    const bool large = rng.uniform() < 0.1;
    const double w = large ? rng.uniform(25, 45) : rng.uniform(0.5, 12);
    const double hgt = large ? rng.uniform(12, 30) : rng.uniform(0.5, 12);
    return Rect{std::floor(rng.uniform(-spread, spread)), rng.uniform(-spread, spread), w, hgt};
  };
  std::optional<SpatialHash> copy;
  std::map<std::uint32_t, Rect> copied;
  for (int step = 0; step < 30000; ++step) {
    // Phases of 5000 steps: gathered into 40×40, spread over 400×400, and so on.
    const double spread = (step / 5000) % 2 == 0 ? 20 : 200;
    const auto slot = static_cast<std::uint32_t>(rng.below(300));
    const auto it = items.find(slot);
    const double u = rng.uniform();
    if (it == items.end()) {
      const Rect r = randomRect(spread);
      h.insert(slot, slot * 7u, r);
      items[slot] = r;
      if (copy) {
        copy->insert(slot, slot * 7u, r);
        copied[slot] = r;
      }
    } else if (u < 0.05) {
      h.erase(slot);
      items.erase(it);
      if (copy) {
        copy->erase(slot);
        copied.erase(slot);
      }
    } else {
      Rect r = it->second;
      if (u < 0.8) {
        // A step, pulled towards the phase's area.
        const Vec2 pull{r.x > spread ? -4.0 : r.x < -spread ? 4.0 : 0.0,
                        r.y > spread ? -4.0 : r.y < -spread ? 4.0 : 0.0};
        r = r.at(r.position() + pull + Vec2{rng.uniform(-3, 3), rng.uniform(-3, 3)});
      } else if (u < 0.9) {
        r = r.at({std::floor(rng.uniform(-spread, spread)), rng.uniform(-spread, spread)});
      } else {
        const Rect s = randomRect(spread);  // resized, often across four cells
        r = {r.x, r.y, s.w, s.h};
      }
      h.update(slot, r);
      it->second = r;
      if (copy) {
        copy->update(slot, r);
        copied[slot] = r;
      }
    }
    if (step == 15000) {
      copy.emplace(h);
      copied = items;
    }
    if (step % 500 == 0) {
      expectMatches(h, items);
      if (copy) expectMatches(*copy, copied);
      if (HasFailure()) return;
    }
  }
  expectMatches(h, items);
  ASSERT_TRUE(copy.has_value());
  expectMatches(*copy, copied);
  EXPECT_EQ(copied, items);  // the same steps, the same registry
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
  // Tight at once: the box's far sides were left empty, so the read finds it again.
  EXPECT_EQ(h.liveBox(), (CellRange{0, 0, 2, 0}));
  h.update(1, {48, 0, 8, 8});
  EXPECT_EQ(h.liveBox(), (CellRange{0, 0, 3, 0}));
  h.erase(1);
  EXPECT_EQ(h.liveBox(), (CellRange{0, 0, 0, 0}));
  h.erase(0);
  EXPECT_TRUE(h.liveBox().empty());
}

TEST(SpatialHash, TheBoxIsTheTightestAfterEveryStepOfARandomWalk) {
  // Items appear, move (by short steps and by jumps) and vanish; after every step the box is
  // exactly the one that holds the occupied cells — which a copy made then agrees with.
  SpatialHash h(8);
  std::uint64_t state = 12345;
  const auto next = [&](int n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  };
  std::map<std::uint32_t, Rect> items;
  for (int step = 0; step < 20000; ++step) {
    const auto slot = static_cast<std::uint32_t>(next(24));
    const bool far = next(50) == 0;
    const Rect r{static_cast<double>(next(far ? 4000 : 64) - (far ? 2000 : 32)),
                 static_cast<double>(next(far ? 4000 : 64) - (far ? 2000 : 32)),
                 1.0 + next(12), 1.0 + next(12)};
    if (!items.contains(slot)) {
      h.insert(slot, slot * 7u, r);
      items[slot] = r;
    } else if (next(8) == 0) {
      h.erase(slot);
      items.erase(slot);
    } else {
      h.update(slot, r);
      items[slot] = r;
    }
    CellRange want;
    for (const auto& [s, rect] : items) {
      const CellRange c = h.grid().cellsHolding(rect);
      want = want.empty() ? c
                          : CellRange{std::min(want.x0, c.x0), std::min(want.y0, c.y0),
                                      std::max(want.x1, c.x1), std::max(want.y1, c.y1)};
    }
    if (want.empty()) {
      ASSERT_TRUE(h.liveBox().empty()) << "step " << step;
    } else {
      ASSERT_EQ(h.liveBox(), want) << "step " << step;
    }
  }
  expectMatches(h, items);
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

// The case as a user met it: World w(1.0), two 4×4 items, a check from (0, 0) to (3000, 2000).
// The second item then visits (1e6, 1e6) and comes straight back; the same check reads the same
// cells, with no other move in between.
//
//   (0,0) ■ mover ─────────────────────────────────► (3000, 2000)
//         ■ other ···· trip to (1e6, 1e6) and back ····
TEST(WorldCells, ALongCheckReadsTheSameCellsBeforeAndAfterAFarTripWithNoMoveBetween) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out";
  World w(1.0);
  const ItemId mover = w.add({0, 0, 4, 4});
  const ItemId other = w.add({10, 10, 4, 4});
  const auto cellsRead = [&] {
    MoveTrace t;
    MoveOptions o;
    o.trace = &t;
    (void)w.check(mover, {3000, 2000}, {}, o);
    return t.cells.size();
  };
  const std::size_t before = cellsRead();
  w.update(other, Vec2{1e6, 1e6});
  w.update(other, Vec2{10, 10});
  const std::size_t after = cellsRead();
  EXPECT_EQ(after, before);
  EXPECT_LT(before, 200u);

  // Negative control: the walk clipped by a box that still spans the trip (as the box was, when
  // it was recomputed only after keys/2 + 8 cells had emptied) reads hundreds of times more.
  const Grid g(1.0);
  const CellRange near = g.cellsOf({0, 0, 14, 14});
  const CellRange stale{near.x0, near.y0, g.cellAt({1e6 + 4, 1e6 + 4}).x,
                        g.cellAt({1e6 + 4, 1e6 + 4}).y};
  std::size_t staleCells = 0;
  g.forEachSweptCell({0, 0, 4, 4}, {3000, 2000}, [&](Cell) { ++staleCells; }, stale);
  EXPECT_GT(staleCells, 100 * before);
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
