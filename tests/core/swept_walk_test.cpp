// Specification of the continuous broad phase (tv/grid.hpp, Grid::forEachSweptCell): the walk
// visits every cell the moving rect meets, whatever the ratio of the cell size to the rounding
// of the coordinates — down to cells a few ulps of the coordinates wide.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

// Cells of 7.5e-7 at y = 1e9, where a double's step is 1.2e-7: a cell is 6 ulps of the walked
// coordinate, and the walk's column boundaries (c * size) are off by a good part of a cell. The
// walk must still visit the obstacle's cells. (The issue's own case, cells of 3.1e-7, had a
// mover 4.5e-8 tall at y = 1e9: below half an ulp, so y + h == y, and such a rect is now refused
// as having no interior; this one is 1.5e-7 tall.)
//
//        |##|     the wall, 3.7e-9 wide and 4.1e-6 tall, at x ≈ 2.3e-6
//    \            the mover (1.5e-8 × 1.5e-7) moving right and up through it,
//     \           x from 1.25e-6 to 7.1e-6, y from 1e9 - 6e-7 to 1e9 - 9.3e-6
TEST(SweptWalk, CellsAFewUlpsOfTheCoordinatesWideAreStillAllVisited) {
  World w(7.4685078275118712e-07);
  (void)w.add(
      {2.2734653758344361e-06, 999999999.99999797, 3.6933845261853752e-09, 4.0978293996286454e-06});
  const ItemId m = w.add(
      {1.2512294323018248e-06, 999999999.9999994, 1.4946155242873129e-08, 1.5102090485111685e-07});
  const Vec2 g{7.0984202029503844e-06, 999999999.9999907};
  // The bounds broad phase (every cell of the bounding box) is the reference.
  const tv::MoveResult bounds = w.check(m, g, {}, {tv::BroadPhase::bounds});
  ASSERT_EQ(bounds.collisions.size(), 1u);
  const double ti = bounds.collisions[0].ti;
  const tv::MoveResult swept = w.check(m, g);
  ASSERT_EQ(swept.collisions.size(), 1u) << "the swept walk passed through";
  EXPECT_EQ(swept.collisions[0].ti, ti);
}

// The same shape at random: a thin wall (a few thousandths of a cell wide, a few cells tall)
// on the path of a mover under a cell (1 to 3 ulps tall), moving some 30 cells at y = 1e9 with
// cells of 2 to 8 ulps. Swept and bounds always agree. The opposite case, 16 px cells at the
// origin, runs in the same loop.
TEST(SweptWalk, AgreesWithTheBoundsBroadPhaseForCellsDownToAFewUlps) {
  std::mt19937_64 g(20240601);
  const auto unit = [&] { return static_cast<double>(g() >> 11) * 0x1p-53; };
  int hits = 0;
  for (int i = 0; i < 40000; ++i) {
    const bool tiny = i % 4 != 0;
    const double offset = tiny ? 1e9 : 0.0;
    const double ulp = 1.1920928955078125e-07;  // of 1e9
    const double cell = tiny ? (2 + 6 * unit()) * ulp : 16.0;
    World w(cell);
    const auto pos = [&](double spread) { return (unit() - 0.5) * spread * cell; };
    const auto size = [&](double s) { return s * cell * (0.5 + unit()); };
    // At 1e9 a rect's height must be at least an ulp to have an interior.
    const Rect mover{pos(20), offset + pos(20), size(0.016),
                     tiny ? ulp * (1 + 2 * unit()) : size(0.14)};
    const Vec2 goal{pos(40), offset + pos(40)};
    const double t = unit();
    const Vec2 on = mover.position() + (goal - mover.position()) * t;
    (void)w.add({on.x + pos(0.5), on.y + pos(0.5), size(0.0034), size(5)});
    const ItemId m = w.add(mover);
    const std::size_t expected = w.check(m, goal, {}, {tv::BroadPhase::bounds}).collisions.size();
    ASSERT_EQ(w.check(m, goal).collisions.size(), expected) << "case " << i << " cell " << cell;
    hits += static_cast<int>(expected);
  }
  EXPECT_GT(hits, 10000) << "the cases must hit often enough to mean something";
}

}  // namespace
