// Specification of exact contact (tv/world.hpp): after touch or slide the mover's edge equals
// the obstacle's edge bit for bit, at any offset, and a body resting under gravity never drifts.

#include <gtest/gtest.h>

#include <cmath>

#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;
namespace response = tv::response;

constexpr double kOffsets[] = {0.0, 1e6, 1e9};
constexpr double kSizes[] = {8.1, 13.7, 0.3, 16.0, 24.0, 9.9, 99.99, 1.1};

// Around (o, o), a box of four walls, each 16 thick, with 400 px of room inside:
//
//   o+0 ....... +----------------------+  ceiling {o, o, 432, 16}   (bottom o+16)
//               |                      |
//   left wall   |        room          |  right wall {o+416, o, 16, 432} (left o+416)
//   {o,o,16,432}|                      |
//   o+416 ..... +----------------------+  floor {o, o+416, 432, 16}  (top o+416)
struct Box {
  explicit Box(double o) : offset(o) {}
  double offset;
  World world{64};
  ItemId ceiling = world.add({offset, offset, 432, 16});
  ItemId floor = world.add({offset, offset + 416, 432, 16});
  ItemId left = world.add({offset, offset, 16, 432});
  ItemId right = world.add({offset + 416, offset, 16, 432});
  double top() const { return world.rect(ceiling).bottom(); }
  double bottom() const { return world.rect(floor).y; }
  double leftEdge() const { return world.rect(left).right(); }
  double rightEdge() const { return world.rect(right).x; }
};

TEST(ExactContact, LandingOnAFloorPutsTheBottomEdgeOnItsTopBitForBit) {
  for (const double o : kOffsets) {
    for (const double h : kSizes) {
      for (const tv::ResponseId resp : {response::touch, response::slide}) {
        Box box(o);
        const ItemId m = box.world.add({o + 100.25, o + 50.5, 8.1, h});
        // Fall 1000 px (far past the floor) while drifting right a little.
        (void)box.world.move(m, {o + 103.5, o + 1050.5}, tv::Filter::all(resp));
        const Rect r = box.world.rect(m);
        EXPECT_EQ(r.y + r.h, box.bottom()) << "offset " << o << " h " << h << " resp " << resp;
      }
    }
  }
}

TEST(ExactContact, HittingACeilingPutsTheTopEdgeOnItsBottomBitForBit) {
  for (const double o : kOffsets) {
    for (const double h : kSizes) {
      Box box(o);
      const ItemId m = box.world.add({o + 200.7, o + 300.3, 13.7, h});
      (void)box.world.move(m, {o + 190.1, o - 700.0});
      EXPECT_EQ(box.world.rect(m).y, box.top()) << "offset " << o << " h " << h;
    }
  }
}

TEST(ExactContact, SlidingIntoEitherWallPutsTheSideEdgeOnTheWallBitForBit) {
  for (const double o : kOffsets) {
    for (const double w : kSizes) {
      Box box(o);
      const ItemId m = box.world.add({o + 150.1, o + 150.9, w, 8.1});
      (void)box.world.move(m, {o + 1150.1, o + 170.2});
      Rect r = box.world.rect(m);
      EXPECT_EQ(r.x + r.w, box.rightEdge()) << "offset " << o << " w " << w;
      EXPECT_EQ(r.y, o + 170.2) << "slide keeps the motion along the wall";
      (void)box.world.move(m, {o - 850.3, o + 160.0});
      r = box.world.rect(m);
      EXPECT_EQ(r.x, box.leftEdge()) << "offset " << o << " w " << w;
    }
  }
}

TEST(ExactContact, SlidingIntoACornerRestsOnBothEdges) {
  for (const double o : kOffsets) {
    Box box(o);
    const ItemId m = box.world.add({o + 100.1, o + 100.2, 13.7, 8.1});
    (void)box.world.move(m, {o + 2000.3, o + 1500.7});
    const Rect r = box.world.rect(m);
    EXPECT_EQ(r.x + r.w, box.rightEdge()) << "offset " << o;
    EXPECT_EQ(r.y + r.h, box.bottom()) << "offset " << o;
  }
}

TEST(ExactContact, AFloorOfTilesAtDecimalPositionsIsMetExactly) {
  // Tiles whose tops are decimal numbers (the level editor's grid is 0.5, the offset 1e6):
  // landing on each of them puts the bottom edge on that tile's top.
  World w(64);
  const double o = 1e6;
  for (int i = 0; i < 40; ++i) {
    const double top = o + 200.0 + 0.5 * (i % 7);
    const ItemId tile = w.add({o + 16.0 * i, top, 16, 16});
    const ItemId m = w.add({o + 16.0 * i + 3.3, o, 9.9, 13.7});
    (void)w.move(m, {o + 16.0 * i + 3.3, o + 500.0}, tv::Filter::all(response::touch));
    EXPECT_EQ(w.rect(m).bottom(), w.rect(tile).y) << "tile " << i;
    w.remove(m);
  }
}

// A body resting on a floor under gravity: every tick it is asked to move (0, +g) into the
// floor. For 10^6 ticks the position never changes — not by an ulp — so neither does floor()
// of it (no flicker between pixel rows).
TEST(ExactContact, ABodyRestingUnderGravityNeverDriftsInAMillionTicks) {
  const double g = 0.3;
  for (const double o : kOffsets) {
    World w(64);
    const ItemId floor = w.add({o, o + 100, 1600, 16});
    const ItemId body = w.add({o + 37.7, o + 60.1, 8.1, 13.7});
    // Fall onto the floor first.
    for (int t = 0; t < 1000 && w.rect(body).bottom() != w.rect(floor).y; ++t) {
      const Vec2 p = w.rect(body).position();
      (void)w.move(body, {p.x, p.y + g});
    }
    ASSERT_EQ(w.rect(body).bottom(), w.rect(floor).y) << "offset " << o;
    const Vec2 rest = w.rect(body).position();
    const double row = std::floor(rest.y);
    long drifted = 0, rowChanged = 0;
    for (int t = 0; t < 1'000'000; ++t) {
      const Vec2 p = w.rect(body).position();
      const Vec2 end = w.move(body, {p.x, p.y + g}).position;
      drifted += end != rest;
      rowChanged += std::floor(end.y) != row;
    }
    EXPECT_EQ(drifted, 0) << "offset " << o;
    EXPECT_EQ(rowChanged, 0) << "offset " << o;
    EXPECT_EQ(w.rect(body).position(), rest);
  }
}

// A floor whose top is just above a power of two (512 + 2 ulps) under a body whose y is just
// below 511, in the binade below: there an ulp of y is half an ulp of the top, so two positions,
// 511 - 2^-44 and 511, both rest on the top (y + h rounds to it). Gravity of 6e-14 px a tick,
// below an ulp of the top, moved the body from the one to the other (no overlap: a free move),
// and the next tick's hit placed it back at the first (the one nearest top - h): it toggled for
// ever and floor(y) flickered between rows 510 and 511. A body already on the face now stays
// where it is, so after at most one settling step of an ulp it rests.
//
//   y = 511 - 2^-44 or 511   +--+  body, h = top - 511 + 4e-14
//                            |  |
//   top = 512 + 2^-42 =====================  floor
TEST(ExactContact, ABodyUnderASubUlpGravityOnAFloorJustAboveAPowerOfTwoRests) {
  const double top = 512.0 + 0x1p-42;
  const double h = (top - 511) + 4e-14;
  World w(64);
  (void)w.add({0, top, 100, 16});
  const ItemId body = w.add({10, tv::placeBefore(top, h), 8, h});
  // The premise: both positions rest exactly on the top.
  ASSERT_EQ(w.rect(body).y, 511 - 0x1p-44);
  ASSERT_EQ((511 - 0x1p-44) + h, top);
  ASSERT_EQ(511 + h, top);
  const double g = 6e-14;
  (void)w.move(body, {10, w.rect(body).y + g});  // may settle once, by an ulp
  const Vec2 rest = w.rect(body).position();
  long moved = 0;
  for (int t = 0; t < 1000; ++t) {
    const Vec2 end = w.move(body, {10, w.rect(body).y + g}).position;
    moved += end != rest;
    EXPECT_EQ(w.rect(body).bottom(), top);
  }
  EXPECT_EQ(moved, 0) << "toggled between " << rest.y << " and another position";
  EXPECT_EQ(std::floor(w.rect(body).y), std::floor(rest.y));
}

// Pressing sideways into a wall every tick (a player holding "right") is the same.
TEST(ExactContact, ABodyPressingIntoAWallNeverDrifts) {
  World w(64);
  const double o = 1e9;
  const ItemId wall = w.add({o + 500, o, 16, 1600});
  const ItemId body = w.add({o + 37.7, o + 60.1, 13.7, 8.1});
  (void)w.move(body, {o + 1000.0, o + 60.1});
  ASSERT_EQ(w.rect(body).right(), w.rect(wall).x);
  const Vec2 rest = w.rect(body).position();
  long drifted = 0;
  for (int t = 0; t < 100'000; ++t) {
    const Vec2 p = w.rect(body).position();
    drifted += w.move(body, {p.x + 2.5, p.y}).position != rest;
  }
  EXPECT_EQ(drifted, 0);
}

}  // namespace
