// Specification of the spatial hash's cell arithmetic (tv/grid.hpp).

#include "tv/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

namespace {

using tv::Cell;
using tv::CellRange;
using tv::Grid;
using tv::Rect;
using tv::Vec2;

TEST(Grid, IndexIsTheFloorOfTheCoordinateInCells) {
  const Grid g(16);
  EXPECT_EQ(g.index(0.0), 0);
  EXPECT_EQ(g.index(-0.0), 0);
  EXPECT_EQ(g.index(15.999), 0);
  EXPECT_EQ(g.index(16.0), 1);
  EXPECT_EQ(g.index(-1e-300), -1);
  EXPECT_EQ(g.index(-16.0), -1);
  EXPECT_EQ(g.index(-16.5), -2);
  EXPECT_EQ(g.index(1e9), 62500000);
}

TEST(Grid, IndexIsMonotoneForAnAwkwardCellSize) {
  // Cell size 0.1 (inexact): neighbouring doubles never map to decreasing cells.
  const Grid g(0.1);
  double v = 99.99;
  std::int64_t last = g.index(v);
  for (int i = 0; i < 100000; ++i) {
    v = std::nextafter(v, 200.0);
    const std::int64_t c = g.index(v);
    ASSERT_GE(c, last) << v;
    last = c;
  }
}

//   cell size 16; the closed rect {16,0,16,16} reaches x = 32 and y = 16: cells (1..2, 0..1)
TEST(Grid, CellsOfCoverTheClosedRect) {
  const Grid g(16);
  EXPECT_EQ(g.cellsOf({16, 0, 16, 16}), (CellRange{1, 0, 2, 1}));
  EXPECT_EQ(g.cellsOf({17, 1, 8, 8}), (CellRange{1, 0, 1, 0}));
  EXPECT_EQ(g.cellsOf({-1, -1, 2, 2}), (CellRange{-1, -1, 0, 0}));
  EXPECT_EQ(g.cellsOf({16, 0, 16, 16}).count(), 4);
  EXPECT_TRUE((CellRange{}).empty());
  EXPECT_EQ((CellRange{}).count(), 0);
}

TEST(Grid, OriginAndBoundsOfACell) {
  const Grid g(16);
  EXPECT_EQ(g.origin({-2, 3}), (Vec2{-32, 48}));
  EXPECT_EQ(g.bounds({-2, 3}), (Rect{-32, 48, 16, 16}));
  EXPECT_EQ(g.cellAt({-32, 63.9}), (Cell{-2, 3}));
}

TEST(Grid, FitsWhileCellIndicesStayBelowTwoToThe52) {
  const Grid g(1.0);
  EXPECT_TRUE(g.fits({1e15, -1e15, 1, 1}));
  EXPECT_FALSE(g.fits({5e15, 0, 1, 1}));
  EXPECT_FALSE(g.fits({0, -5e15, 1, 1}));
  const Grid coarse(1e6);
  EXPECT_TRUE(coarse.fits({1e20, 0, 1, 1}));
}

// Every cell the moving rect meets at any sampled instant is visited.
TEST(Grid, ForEachSweptCellVisitsEveryCellTheMovingRectMeets) {
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<int> coord(-200, 200), size(1, 40), cellSize(0, 3);
  const double cells[] = {4.0, 16.0, 64.0, 10.0};
  for (int trial = 0; trial < 2000; ++trial) {
    const Grid g(cells[cellSize(rng)]);
    // Quarter-pixel rects and moves: every sampled position below is exact.
    const Rect start{coord(rng) / 4.0, coord(rng) / 4.0, size(rng) / 4.0, size(rng) / 4.0};
    const Vec2 goal{coord(rng) * 1.0, coord(rng) * 1.0};
    std::set<std::pair<std::int64_t, std::int64_t>> visited;
    g.forEachSweptCell(start, goal, [&](Cell c) { visited.insert({c.x, c.y}); });
    for (int k = 0; k <= 64; ++k) {
      const double t = k / 64.0;
      const Rect r = start.at(start.position() + (goal - start.position()) * t);
      const CellRange range = g.cellsOf(r);
      for (std::int64_t cy = range.y0; cy <= range.y1; ++cy) {
        for (std::int64_t cx = range.x0; cx <= range.x1; ++cx) {
          ASSERT_TRUE(visited.count({cx, cy}))
              << "cell (" << cx << ", " << cy << ") at t " << t << " missed; trial " << trial;
        }
      }
    }
  }
}

// A long diagonal visits a band of cells along the path, not the whole bounding box.
TEST(Grid, ForEachSweptCellCostFollowsThePathNotTheBoundingBox) {
  const Grid g(16);
  long visited = 0;
  g.forEachSweptCell({0, 0, 8, 8}, {1000, 1000}, [&](Cell) { ++visited; });
  const long box = g.cellsOf({0, 0, 1008, 1008}).count();  // 64 x 64 = 4096
  EXPECT_EQ(box, 4096);
  EXPECT_LT(visited, 4 * 64);
  EXPECT_GE(visited, 63);
}

}  // namespace
