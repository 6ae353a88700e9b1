// Specification of the edges of the accepted input: calls that would loop forever, fill memory
// or half-finish are refused up front, or undone, with a tv::Error that names the value, and
// the world is left as it was (stateHash() bit for bit).

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>

#include "expect_rejected.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/timestep.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Mover;
using tv::Rect;
using tv::ResponseId;
using tv::Vec2;
using tv::World;

// [SECTION] moves that would never end -----------------------------------------------------------

// One query per pixel: 1e9 px would take half a minute, 1e17 px years (and a double step count
// never reaches 0 past 2^53). Refused before the first step.
TEST(Limits, ThePixelMoverRefusesMovesOverTwoToThe24Pixels) {
  World w(16);
  const ItemId p = w.add({0, 0, 8, 8});
  Mover pixel(tv::parseMover("pixel"));
  expectRejected(w, {"pixel move of", "1e+09", "2^24"}, [&] { (void)pixel.move(w, p, {1e9, 0}); });
  // 10^5 px is fine: a bullet at 6e6 px/s.
  EXPECT_EQ(pixel.move(w, p, {1e5, 0}).position, (Vec2{1e5, 0}));
}

// A frame of 0.5 s at a step of 1e-10 s would be 5e9 ticks (an int overflow), and at 1e-20 s
// accumulator - step == accumulator: the loop would never end.
TEST(Limits, AFixedStepRefusesMoreThanTwoToThe20TicksPerFrame) {
  for (const double step : {1e-10, 1e-20}) {
    try {
      const tv::FixedStep f(step, 0.5);
      ADD_FAILURE() << "step " << step << " was accepted";
    } catch (const tv::Error& e) {
      EXPECT_NE(std::string(e.what()).find("2^20"), std::string::npos) << e.what();
    }
  }
  tv::FixedStep ok(0.5 / (1 << 20), 0.5);
  EXPECT_EQ(ok.advance(0.5), 1 << 20);
}

// A 1e9 px diagonal in a world whose items span a few cells: the walk is clipped to the cells
// that ever held an item, so it visits a handful, not the 6e7 cells of the path.
TEST(Limits, ALongMoveThroughEmptySpaceVisitsOnlyUsedCells) {
  World w(16);
  const ItemId p = w.add({0, 0, 8, 8});
  (void)w.add({64, 64, 16, 16});
  tv::MoveTrace trace;
  const tv::MoveResult r = w.move(p, {1e9, 1e9}, {}, {tv::BroadPhase::swept, &trace});
  ASSERT_EQ(r.collisions.size(), 1u) << "it still meets the tile on its way";
  if constexpr (tv::kTraceCompiledIn) {
    EXPECT_LT(trace.cells.size(), 64u);
  }
}

// [SECTION] items that would fill memory ---------------------------------------------------------

// Each item is registered in every cell it meets: 4e15 px square at cell size 1 is 1.6e31 cells.
TEST(Limits, ARectMeetingMoreThanTwoToThe24CellsIsRefused) {
  World w(1);
  expectRejected(w, {"tv::World::add", "cells of size 1", "2^24", "larger cell size"},
                 [&] { (void)w.add({-2e15, -2e15, 4e15, 4e15}); });
  expectRejected(w, {"tv::World::add", "spans"}, [&] { (void)w.add({0, 0, 1e5, 1e5}); });
  EXPECT_EQ(w.count(), 0u);
}

// [SECTION] moves that would half-finish ---------------------------------------------------------

//   [p]--->--->--->|###|      substep-sweep, 8 px pieces; the filter answers 77 (not a
//   0              100        response) once the pieces reach the wall, 12 pieces in.
TEST(Limits, ASubstepMoveThatFailsPartWayPutsTheItemBack) {
  for (const char* name : {"substep-sweep", "substep-discrete"}) {
    World w(16);
    (void)w.add({100, 0, 16, 16});
    const ItemId p = w.add({0, 0, 8, 8});
    tv::MoverSpec spec = tv::parseMover(name);
    spec.maxStep = 8;
    Mover m(spec);
    expectRejected(w, {"77"}, [&] {
      (void)m.move(w, p, {200, 0}, [](ItemId, ItemId) -> ResponseId { return 77; });
    });
    EXPECT_EQ(w.rect(p), (Rect{0, 0, 8, 8})) << name;
  }
}

//   [p]   |###|    the pixel mover steps 5.3 px towards the wall; at x = 3 it meets it and the
//   0     10       filter answers 77. The throw must leave the sub-pixel remainder as it was
//                  (0), not the 0.3 the half-done move had set: a later 0.3 px move stays put.
TEST(Limits, APixelMoveThatFailsPartWayKeepsTheRemainder) {
  World w(16);
  (void)w.add({10, 0, 16, 16});
  const ItemId p = w.add({0, 0, 8, 8});
  Mover pixel(tv::parseMover("pixel"));
  expectRejected(w, {"77"}, [&] {
    (void)pixel.move(w, p, {5.3, 0}, [](ItemId, ItemId) -> ResponseId { return 77; });
  });
  EXPECT_EQ(pixel.move(w, p, {0.3, 0}).position, (Vec2{0, 0})) << "0 + 0.3 rounds to 0";
}

// A response of the user's that hands back a leg the world cannot sweep (NaN, or too far out)
// is refused by name before anything moves.
tv::Leg toNowhere(const tv::Collision& c, Vec2) { return {c.touch, {std::nan(""), 1e300}}; }

TEST(Limits, AUserResponseReturningABadLegIsRefusedByName) {
  World w(16);
  (void)w.add({20, 0, 16, 16});
  const ItemId p = w.add({0, 0, 8, 8});
  const ResponseId nowhere = w.addResponse("nowhere", &toNowhere);
  expectRejected(w, {"response 'nowhere'", "nan", "1e+300"}, [&] {
    (void)w.move(p, {40, 0}, tv::Filter::all(nowhere));
  });
  EXPECT_EQ(w.rect(p), (Rect{0, 0, 8, 8}));
}

// [SECTION] running out of responses ------------------------------------------------------------
//
//   B  +----+  y = -16       a body spawned 1 px into A: pushed up out of A it lands in B,
//      |    |                pushed down out of B it lands in A again... Out of responses, it
//   A  +-[]-+  y = 0         must not stop in B, which it did not start in: it stays where
//      +----+  y = 16        the move began (still in A, where it started).
TEST(Limits, OutOfResponsesAfterPushOutsTheItemStaysWhereItWasSafe) {
  for (const int budget : {63, 64}) {
    World w(16);
    const ItemId a = w.add({0, 0, 16, 16});
    const ItemId b = w.add({0, -16, 16, 16});
    const ItemId p = w.add({4, 1, 8, 8});
    tv::MoveOptions o;
    o.maxResponses = budget;
    const tv::MoveResult r = w.move(p, {4, 1}, {}, o);
    EXPECT_EQ(r.collisions.size(), static_cast<std::size_t>(budget));
    EXPECT_FALSE(tv::overlaps(w.rect(p), w.rect(b))) << budget << ": ended inside B";
    EXPECT_EQ(w.rect(p).position(), (Vec2{4, 1})) << budget;
    (void)a;
  }
}

// [SECTION] handles --------------------------------------------------------------------------------

// The pixel mover keeps a sub-pixel remainder per item; a new item in a removed item's slot
// starts from zero, not from what the old one left.
TEST(Limits, APixelRemainderDoesNotPassToTheNextItemInTheSlot) {
  World w(16);
  Mover pixel(tv::parseMover("pixel"));
  const ItemId old = w.add({0, 0, 8, 8});
  (void)pixel.move(w, old, {0.4, 0});  // 0.4 px left over
  w.remove(old);
  const ItemId fresh = w.add({0, 0, 8, 8});
  ASSERT_EQ(fresh.index, old.index) << "precondition: the slot is reused";
  EXPECT_EQ(pixel.move(w, fresh, {0.4, 0}).position, (Vec2{0, 0})) << "0.4 + 0.4 rounded to 1";
}

}  // namespace
