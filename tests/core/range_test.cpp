// Specification of the range the guarantees cover (tv/geometry.hpp): every coordinate, size and
// goal within ±2^500 (≈ 3.27e150), cell sizes in [2^-485, 2^500]. Beyond it the exact time
// comparison's products overflow (from about 3e154) and near 1e308 a displacement overflows to
// infinity, so moves tunnelled and cell indices were cast from infinity (undefined behaviour).
// Such input is refused by name; everything inside the range keeps every guarantee.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "expect_rejected.hpp"
#include "tv/error.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

// The case: World(1e154), a wall at 1e155 and a mover 1e154 wide sent to 1.5e155 passed
// through the wall. Each part of it is now refused, naming its value.
TEST(Range, ScenesBeyondTwoToThe500AreRefusedNamingTheValue) {
  EXPECT_THROW(World(1e154), tv::Error);
  EXPECT_THROW(World(1e307), tv::Error);
  World w(1e140);  // a legal cell size whose grid reaches 4.5e155
  expectRejected(w, {"tv::World::add", "x must be within ±2^500", "1e+155"}, [&] {
    (void)w.add({1e155, -1e154, 1e154, 2e154});
  });
  expectRejected(w, {"tv::World::add", "w must be within ±2^500", "1e+154"}, [&] {
    (void)w.add({0, 0, 1e154, 1e154});
  });
  const ItemId m = w.add({0, 0, 1e141, 1e141});
  expectRejected(w, {"tv::World::move", "goal.x", "1.5e+155"}, [&] {
    (void)w.move(m, {1.5e155, 0});
  });
  expectRejected(w, {"tv::World::project", "x must be within", "-1.5e+151"}, [&] {
    (void)w.project({-1.5e151, 0, 1, 1}, {0, 0});
  });
  expectRejected(w, {"tv::World::queryPoint", "-1e+151"}, [&] { (void)w.queryPoint({-1e151, 0}); });
  // A move from -1.5e308 to 1.5e308 (a displacement of infinity) cannot even be set up.
  World big(0x1p500);
  expectRejected(big, {"-1.5e+308"}, [&] { (void)big.add({-1.5e308, 0, 1, 1}); });
}

// The opposite case: the same scene scaled to fit the range stops at the wall, flush with it.
//
//   [m]------------------------>|####|      wall at 1e150, 1e149 wide and 2e149 tall
//   0, 1e149 square              1e150      goal 1.5e150: past the wall
TEST(Range, TheSameSceneInsideTheRangeStopsAtTheWall) {
  World w(1e149);
  const ItemId wall = w.add({1e150, -1e149, 1e149, 2e149});
  const ItemId m = w.add({0, 0, 1e149, 1e149});
  const tv::MoveResult r = w.move(m, {1.5e150, 0});
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].other, wall);
  EXPECT_EQ(w.rect(m).right(), 1e150);
}

// At the top of the range the exact ordering still holds: two faces an ulp apart near 3e150,
// approached from -3e150 (differences of 6e150, products near 2^1003).
TEST(Range, AtTheTopOfTheRangeHitsAreStillOrderedExactly) {
  const double F = 3e150, G = std::nextafter(F, INFINITY);
  World w(0x1p500);
  (void)w.add({G, -1e150, 1e149, 2e150});
  const ItemId near = w.add({F, -1e150, 1e149, 2e150});
  const ItemId m = w.add({-3e150, 0, 1e148, 1e148});
  tv::MoveOptions o;
  o.maxResponses = 1;
  const tv::MoveResult r = w.move(m, {0x1p500 - 1e148, 0}, {}, o);
  ASSERT_FALSE(r.collisions.empty());
  EXPECT_EQ(r.collisions[0].other, near);
  EXPECT_FALSE(tv::overlaps(w.rect(m), w.rect(near)));
}

// A response of the user's that throws the mover past 2^500 is refused by name, before anything
// moves.
tv::Leg farAway(const tv::Collision& c, Vec2) {
  return {c.touch, {1e151, 0}};
}

TEST(Range, AResponseLegBeyondTheRangeIsRefused) {
  World w(0x1p500);
  (void)w.add({1e150, -1e149, 1e149, 2e149});
  const ItemId m = w.add({0, 0, 1e148, 1e148});
  const tv::ResponseId far = w.addResponse("far", &farAway);
  expectRejected(w, {"response 'far'", "1e+151", "2^500"}, [&] {
    (void)w.move(m, {1.5e150, 0}, tv::Filter::all(far));
  });
}

}  // namespace
