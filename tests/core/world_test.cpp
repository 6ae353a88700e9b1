// Specification of the World's item bookkeeping: handles, add order, cells, extents, state hash.

#include "tv/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tv/error.hpp"

namespace {

using tv::Cell;
using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

std::vector<std::uint32_t> itemsIn(const World& w, Cell c) {
  const auto span = w.cellItems(c);
  std::vector<std::uint32_t> v(span.begin(), span.end());
  std::sort(v.begin(), v.end());
  return v;
}

// [SECTION] items -----------------------------------------------------------------------------

TEST(World, StartsEmptyWithTheDefaultCellSize) {
  const World w;
  EXPECT_EQ(w.cellSize(), 64.0);
  EXPECT_EQ(w.count(), 0u);
  EXPECT_EQ(w.countCells(), 0u);
  EXPECT_EQ(w.minExtent(), 0.0);
}

TEST(World, AddStoresTheRectExactly) {
  World w(16);
  const Rect r{1e6 + 0.1, -3.7, 8.1, 13.7};
  const ItemId id = w.add(r);
  EXPECT_TRUE(id.valid());
  EXPECT_TRUE(w.has(id));
  EXPECT_EQ(w.rect(id), r);
  EXPECT_EQ(w.count(), 1u);
}

TEST(World, RemoveForgetsTheItemAndItsCells) {
  World w(16);
  const ItemId a = w.add({0, 0, 8, 8});
  const ItemId b = w.add({100, 100, 8, 8});
  w.remove(a);
  EXPECT_FALSE(w.has(a));
  EXPECT_TRUE(w.has(b));
  EXPECT_EQ(w.count(), 1u);
  EXPECT_EQ(w.countCells(), 1u);
  EXPECT_TRUE(w.cellItems({0, 0}).empty());
  EXPECT_THROW((void)w.rect(a), tv::Error);
}

TEST(World, AHandleStaysStaleAfterItsSlotIsReused) {
  World w(16);
  const ItemId a = w.add({0, 0, 8, 8});
  w.remove(a);
  const ItemId b = w.add({32, 32, 8, 8});
  EXPECT_EQ(b.index, a.index);            // storage reused ...
  EXPECT_NE(b.generation, a.generation);  // ... under a new generation
  EXPECT_FALSE(w.has(a));
  EXPECT_TRUE(w.has(b));
  EXPECT_THROW((void)w.rect(a), tv::Error);
  EXPECT_THROW(w.remove(a), tv::Error);
  EXPECT_THROW(w.update(a, Vec2{1, 1}), tv::Error);
  EXPECT_EQ(w.rect(b), (Rect{32, 32, 8, 8}));
}

// Free slots are reused last-in first-out, so one slot can cycle through all 2^32 generations
// (add, remove, add, remove...). Were the generation to wrap, the first handle of that slot would
// name a new item. The slot starts 2 removes short of the wrap instead of 2^32 cycles in.
TEST(World, AHandleNeverBecomesValidAgainWhenItsSlotsGenerationsRunOut) {
  World w(16);
  const ItemId first = w.addAtGenerationForTesting({0, 0, 1, 1}, 0xFFFFFFFEu);
  w.remove(first);
  const ItemId last = w.add({0, 0, 1, 1});
  EXPECT_EQ(last.index, first.index) << "below the wrap the slot is still reused";
  EXPECT_EQ(last.generation, 0xFFFFFFFFu);
  w.remove(last);  // its generations are used up: the slot is retired
  const ItemId fresh = w.add({7, 7, 2, 2});
  EXPECT_NE(fresh.index, first.index);
  for (const ItemId stale : {first, last, ItemId{first.index, 0}, ItemId{first.index, 1}}) {
    EXPECT_FALSE(w.has(stale)) << stale.index << "/" << stale.generation;
    EXPECT_THROW((void)w.rect(stale), tv::Error);
  }
  EXPECT_EQ(w.rect(fresh), (Rect{7, 7, 2, 2}));
  EXPECT_EQ(w.count(), 1u);
  // A retired slot stays out of every later add.
  for (int i = 0; i < 8; ++i) EXPECT_NE(w.add({0, 0, 1, 1}).index, first.index);
}

TEST(World, DefaultAndForeignHandlesAreNotInTheWorld) {
  World w;
  (void)w.add({0, 0, 1, 1});
  EXPECT_FALSE(w.has(ItemId{}));
  EXPECT_FALSE(w.has(ItemId{7, 0}));
  EXPECT_FALSE(w.has(ItemId{0, 1}));
}

TEST(World, UpdateTeleportsWithoutCheckingCollisions) {
  World w(16);
  const ItemId wall = w.add({20, 0, 10, 100});
  const ItemId m = w.add({0, 0, 10, 10});
  w.update(m, Vec2{22, 5});  // straight into the wall: allowed, no collision check
  EXPECT_EQ(w.rect(m), (Rect{22, 5, 10, 10}));
  w.update(m, Rect{-40, -40, 3, 4});
  EXPECT_EQ(w.rect(m), (Rect{-40, -40, 3, 4}));
  EXPECT_EQ(w.rect(wall), (Rect{20, 0, 10, 100}));
  EXPECT_EQ(itemsIn(w, {-3, -3}), std::vector<std::uint32_t>{m.index});
}

TEST(World, OrderIsTheAddOrderAndANewItemAlwaysComesLast) {
  World w;
  const ItemId a = w.add({0, 0, 1, 1});
  const ItemId b = w.add({0, 0, 1, 1});
  const ItemId c = w.add({0, 0, 1, 1});
  EXPECT_LT(w.order(a), w.order(b));
  EXPECT_LT(w.order(b), w.order(c));
  w.remove(a);
  const ItemId d = w.add({0, 0, 1, 1});  // reuses a's slot, but is added after c
  EXPECT_EQ(d.index, a.index);
  EXPECT_GT(w.order(d), w.order(c));
  // Update and move keep the order.
  const std::uint64_t before = w.order(b);
  w.update(b, Vec2{50, 50});
  (void)w.move(b, {60, 60});
  EXPECT_EQ(w.order(b), before);
}

TEST(World, MinExtentFollowsAddUpdateAndRemove) {
  World w;
  const ItemId a = w.add({0, 0, 10, 4});
  EXPECT_EQ(w.minExtent(), 4.0);
  const ItemId b = w.add({0, 0, 2.5, 30});
  EXPECT_EQ(w.minExtent(), 2.5);
  w.update(b, Rect{0, 0, 8, 8});
  EXPECT_EQ(w.minExtent(), 4.0);
  w.remove(a);
  EXPECT_EQ(w.minExtent(), 8.0);
  w.remove(b);
  EXPECT_EQ(w.minExtent(), 0.0);
}

TEST(World, MinExtentCountsDuplicates) {
  World w;
  const ItemId a = w.add({0, 0, 3, 3});
  (void)w.add({10, 0, 3, 3});
  (void)w.add({20, 0, 5, 5});
  w.remove(a);
  EXPECT_EQ(w.minExtent(), 3.0);  // the other 3x3 is still there
}

// [SECTION] grid --------------------------------------------------------------------------------

//   cell size 16: cell (cx, cy) covers [16cx, 16cx+16) x [16cy, 16cy+16)
TEST(WorldGrid, ToCellAndToWorldAreFloorAndOrigin) {
  const World w(16);
  EXPECT_EQ(w.toCell({0, 0}), (Cell{0, 0}));
  EXPECT_EQ(w.toCell({15.99, 16}), (Cell{0, 1}));
  EXPECT_EQ(w.toCell({-0.5, -16}), (Cell{-1, -1}));
  EXPECT_EQ(w.toCell({-16.5, 1e6}), (Cell{-2, 62500}));
  EXPECT_EQ(w.toWorld({-1, 2}), (Vec2{-16, 32}));
  EXPECT_EQ(w.toWorld(w.toCell({37, -5})), (Vec2{32, -16}));
}

//   cell size 16, items registered in every cell their half-open rect [x, right) × [y, bottom)
//   meets:
//   a {2,2,8,8}    -> cell (0,0)
//   b {8,8,16,16}  -> cells (0..1, 0..1)
//   c {32,0,16,16} -> exactly cell (2,0): its right edge 48 and bottom edge 16 lie on cell
//                     lines, and an edge on a line does not reach into the next cell
//
//        x: 0    16   32   48   64
//   y:  0   +----+----+----+----+
//           |a b | b  |cccc|    |
//       16  +----+----+----+----+
//           | b  | b  |    |    |
//       32  +----+----+----+----+
TEST(WorldGrid, AnItemIsInEveryCellItsHalfOpenRectMeets) {
  World w(16);
  const ItemId a = w.add({2, 2, 8, 8});
  EXPECT_EQ(w.countCells(), 1u);
  const ItemId b = w.add({8, 8, 16, 16});
  EXPECT_EQ(w.countCells(), 4u);
  const ItemId c = w.add({32, 0, 16, 16});
  EXPECT_EQ(w.countCells(), 5u);
  EXPECT_EQ(itemsIn(w, {0, 0}), (std::vector<std::uint32_t>{a.index, b.index}));
  EXPECT_EQ(itemsIn(w, {1, 1}), std::vector<std::uint32_t>{b.index});
  EXPECT_EQ(itemsIn(w, {2, 0}), std::vector<std::uint32_t>{c.index});
  EXPECT_TRUE(w.cellItems({3, 0}).empty());  // c's right edge lies on x = 48
  EXPECT_TRUE(w.cellItems({2, 1}).empty());  // c's bottom edge lies on y = 16
  EXPECT_TRUE(w.cellItems({2, 2}).empty());
  EXPECT_TRUE(w.cellItems({-100, 7}).empty());  // never used
  EXPECT_EQ(w.idAt(b.index), b);
}

TEST(WorldGrid, ATileOnCellLinesIsInOneCellYetEveryQueryAndMoveStillFindsIt) {
  // A 16 px tile exactly on the 16 px cell (1,1); a mover pushed into it from each side, and
  // queries that only touch its edges from the neighbouring cells.
  World w(16);
  const ItemId tile = w.add({16, 16, 16, 16});
  EXPECT_EQ(w.countCells(), 1u);
  EXPECT_EQ(itemsIn(w, {1, 1}), std::vector<std::uint32_t>{tile.index});
  const ItemId m = w.add({40, 20, 8, 8});  // right of the tile, in cells (2..2, 1..1)
  const tv::MoveResult left = w.check(m, {0, 20});
  ASSERT_EQ(left.collisions.size(), 1u);
  EXPECT_EQ(left.collisions[0].other, tile);
  EXPECT_EQ(left.position.x, 32.0);  // flush with the tile's right edge
  w.update(m, Rect{20, 40, 8, 8});   // below it
  const tv::MoveResult up = w.check(m, {20, 0});
  ASSERT_EQ(up.collisions.size(), 1u);
  EXPECT_EQ(up.position.y, 32.0);
  // Touching the right edge from cell (2,1) is not an overlap; reaching 1 ulp inside is.
  EXPECT_TRUE(w.queryRect({32, 16, 8, 8}).empty());
  EXPECT_EQ(w.queryRect({std::nextafter(32.0, 0.0), 16, 8, 8}), std::vector<ItemId>{tile});
  EXPECT_EQ(w.queryPoint({std::nextafter(32.0, 0.0), 31.5}), std::vector<ItemId>{tile});
  EXPECT_TRUE(w.queryPoint({32, 20}).empty());
}

TEST(WorldGrid, UpdateMovesTheItemBetweenCells) {
  World w(16);
  const ItemId a = w.add({2, 2, 8, 8});
  w.update(a, Vec2{100, 2});  // {100,2,8,8}: cell (6,0)
  EXPECT_TRUE(w.cellItems({0, 0}).empty());
  EXPECT_EQ(itemsIn(w, {6, 0}), std::vector<std::uint32_t>{a.index});
  EXPECT_EQ(w.countCells(), 1u);
  w.update(a, Vec2{92, 2});  // {92,2,8,8}: cells (5..6, 0)
  EXPECT_EQ(w.countCells(), 2u);
  (void)w.move(a, {2, 2});  // nothing in the way
  EXPECT_EQ(w.countCells(), 1u);
  EXPECT_EQ(itemsIn(w, {0, 0}), std::vector<std::uint32_t>{a.index});
}

TEST(WorldGrid, ForEachOccupiedCellAndForEachItemSeeEverything) {
  World w(16);
  const ItemId a = w.add({2, 2, 8, 8});
  const ItemId b = w.add({8, 8, 16, 16});
  std::size_t cells = 0, entries = 0;
  w.forEachOccupiedCell([&](Cell, std::size_t n) {
    ++cells;
    entries += n;
  });
  EXPECT_EQ(cells, 4u);
  EXPECT_EQ(entries, 5u);  // a in 1 cell, b in 4
  std::vector<ItemId> seen;
  w.forEachItem([&](ItemId id, const Rect&) { seen.push_back(id); });
  EXPECT_EQ(seen, (std::vector<ItemId>{a, b}));
}

// [SECTION] stateHash ---------------------------------------------------------------------------

World threeTiles() {
  World w(32);
  (void)w.add({0, 0, 16, 16});
  (void)w.add({16, 0, 16, 16});
  (void)w.add({32, 0, 16, 16});
  return w;
}

TEST(StateHash, IsEqualForWorldsBuiltTheSameWay) {
  EXPECT_EQ(threeTiles().stateHash(), threeTiles().stateHash());
}

TEST(StateHash, ChangesWithEveryKindOfStateChange) {
  World w = threeTiles();
  std::vector<std::uint64_t> seen{w.stateHash()};
  const auto changed = [&](const char* what) {
    const std::uint64_t h = w.stateHash();
    EXPECT_EQ(std::find(seen.begin(), seen.end(), h), seen.end()) << what;
    seen.push_back(h);
  };
  const ItemId m = w.add({0, -20, 8, 8});
  changed("add");
  w.update(m, Vec2{std::nextafter(0.0, 1.0), -20});  // a single ulp
  changed("update by one ulp");
  w.update(m, Rect{0, -20, 8, 9});
  changed("resize");
  (void)w.move(m, {5, -1});
  changed("move");
  (void)w.addResponse("stick", &tv::touchResponse);
  changed("addResponse");
  w.remove(m);
  changed("remove");
  EXPECT_NE(World(32).stateHash(), World(16).stateHash()) << "cell size";
}

// "Two worlds that compare equal here behave the same" covers what the next add returns. World A
// adds two tiles; world B adds the same two plus a third and removes it. Their live items are
// identical, but A's next add gets {index 2, generation 0} and add order 2, B's gets
// {index 2, generation 1} and add order 3: the hashes must tell them apart.
TEST(StateHash, CoversTheHandleAndOrderTheNextAddWillGet) {
  World a(32), b(32);
  for (World* w : {&a, &b}) {
    (void)w->add({0, 0, 16, 16});
    (void)w->add({16, 0, 16, 16});
  }
  b.remove(b.add({32, 0, 16, 16}));
  EXPECT_NE(a.stateHash(), b.stateHash());
  const ItemId fromA = a.add({64, 0, 8, 8});
  const ItemId fromB = b.add({64, 0, 8, 8});
  EXPECT_NE(fromA.generation, fromB.generation) << "precondition: the next adds do differ";
  EXPECT_NE(a.order(fromA), b.order(fromB));
  EXPECT_NE(a.stateHash(), b.stateHash());
}

TEST(StateHash, DoesNotChangeOnQueriesOrChecks) {
  World w = threeTiles();
  const ItemId m = w.add({0, -20, 8, 8});
  const std::uint64_t h = w.stateHash();
  (void)w.check(m, {40, 10});
  (void)w.project({0, -40, 8, 8}, {40, 10});
  (void)w.queryRect({0, 0, 100, 100});
  (void)w.queryPoint({1, 1});
  (void)w.querySegment({-10, 8}, {100, 8});
  (void)w.anyOverlap({0, 0, 5, 5});
  EXPECT_EQ(w.stateHash(), h);
}

// [SECTION] check and project -------------------------------------------------------------------

TEST(World, CheckReportsWhatMoveWouldDoWithoutDoingIt) {
  World w(16);
  (void)w.add({20, -50, 10, 100});
  const ItemId m = w.add({0, 0, 10, 10});
  const tv::MoveResult c = w.check(m, {40, 20});
  const Vec2 checked = c.position;
  const std::size_t hits = c.collisions.size();
  EXPECT_EQ(w.rect(m), (Rect{0, 0, 10, 10}));
  const tv::MoveResult r = w.move(m, {40, 20});
  EXPECT_EQ(r.position, checked);
  EXPECT_EQ(r.collisions.size(), hits);
  EXPECT_EQ(w.rect(m).position(), checked);
  EXPECT_EQ(checked, (Vec2{10, 20}));
}

TEST(World, MoveWithNothingInTheWayReachesTheGoal) {
  World w(16);
  const ItemId m = w.add({0, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {1000.5, -333.25});
  EXPECT_EQ(r.position, (Vec2{1000.5, -333.25}));
  EXPECT_TRUE(r.collisions.empty());
  EXPECT_EQ(w.rect(m), (Rect{1000.5, -333.25, 10, 10}));
}

TEST(World, AMoveFarFasterThanTheCellsNeverTunnels) {
  // A 1-px wall at x = 5000 and a mover crossing 10^4 px in one move, diagonally.
  World w(8);
  (void)w.add({5000, -10000, 1, 20000});
  const ItemId m = w.add({0, 0, 2, 2});
  const tv::MoveResult r = w.move(m, {10000, 777});
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.position.x, 4998.0);
  EXPECT_EQ(r.position.y, 777.0);
}

// Candidates are pre-rejected against the move's hull, unite(start, goal rect); a hull whose far
// edge rounded below the goal rect's (Unite.HoldsBothRectsEvenWhenTheSizeRounds) would skip an
// obstacle that the goal overlaps by an ulp, and the move would end inside it.
//
//   mover {21,-12,12,2} -> goal (35, 9.0000000000000018): its bottom ends at 11.000000000000002,
//   one ulp inside the obstacle {38,11,6,12}, whose top is 11.
//   Expected: one collision (sweepRect reports a hit), the mover's bottom on y = 11.
TEST(World, AGoalEndingAnUlpInsideAnObstacleIsStoppedAtItsEdge) {
  World w(16);
  const ItemId wall = w.add({38, 11, 6, 12});
  const ItemId m = w.add({21, -12, 12, 2});
  const Vec2 goal{35, 9.0000000000000018};
  ASSERT_EQ(tv::sweepRect(w.rect(m), goal, w.rect(wall)).kind, tv::SweepKind::hit);
  const tv::MoveResult r = w.move(m, goal);
  EXPECT_EQ(r.collisions.size(), 1u);
  EXPECT_FALSE(tv::overlaps(w.rect(m), w.rect(wall))) << "the mover ended inside the obstacle";
  EXPECT_EQ(w.rect(m).bottom(), 11.0);
}

}  // namespace
