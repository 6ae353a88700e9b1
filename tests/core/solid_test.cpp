// Specification of moving solids (tv/solid.hpp): lifts carry their riders at any speed without
// dropping or popping them, solids push what is in their way and stop where a body is squished,
// one-way platforms carry riders and let bodies below through — each with the naive way (move
// the solid, then the bodies) as a negative control.

#include "tv/solid.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "tv/error.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::SolidMove;
using tv::SolidOptions;
using tv::Vec2;
using tv::World;

constexpr double kTile = 16.0;

// A lift 48 wide, 8 thick, with a rider 8 x 12 standing on it:
//
//          +--+
//          |r |        rider {20, 88, 8, 12}: its bottom (100) is the lift's top
//   +------+--+-----+
//   |      lift     |  lift {0, 100, 48, 8}
//   +---------------+
struct Lift {
  World world{32};
  ItemId lift = world.add({0, 100, 48, 8});
  ItemId rider = world.add({20, 88, 8, 12});
  std::vector<ItemId> bodies{rider};
  [[nodiscard]] SolidOptions options() const {
    SolidOptions o;
    o.bodies = bodies;
    return o;
  }
};

// On the top: where the core's contact puts a body (tv::placeBefore: its bottom edge on the top
// bit for bit whenever a double allows it, else the nearest position short of it), never inside.
bool onTop(const World& w, ItemId body, ItemId solid) {
  const Rect b = w.rect(body), s = w.rect(solid);
  return b.y == tv::placeBefore(s.y, b.h) && b.bottom() <= s.y;
}

// [SECTION] carrying ------------------------------------------------------------------------------

TEST(Lift, CarriesItsRiderUpAndDownAtOneToTenTilesATickExactlyOnItsTop) {
  for (int tiles = 1; tiles <= 10; ++tiles) {
    for (const double dir : {-1.0, 1.0}) {
      Lift s;
      const SolidOptions o = s.options();
      // Odd speeds: 0.37 of a pixel more than the tiles, so that rounding has every chance.
      const double step = dir * (tiles * kTile + 0.37);
      for (int tick = 0; tick < 20; ++tick) {
        const Rect l = s.world.rect(s.lift);
        const SolidMove m = tv::moveSolid(s.world, s.lift, {l.x, l.y + step}, o);
        ASSERT_EQ(m.position, (Vec2{l.x, l.y + step}));
        ASSERT_TRUE(onTop(s.world, s.rider, s.lift))
            << tiles << " tiles a tick, direction " << dir << ", tick " << tick << ": rider bottom "
            << s.world.rect(s.rider).bottom() << ", lift top " << s.world.rect(s.lift).y;
        ASSERT_TRUE(m.squished.empty());
      }
      EXPECT_EQ(s.world.rect(s.rider).x, 20.0)
          << "a vertical lift does not move its rider sideways";
    }
  }
}

TEST(Lift, CarriesItsRiderSidewaysAndStopsItAtAWall) {
  //   wall {60, 0, 8, 100} stands on the right; the lift goes right 40 px, its rider would too
  //   but meets the wall at x 52 (rider right edge 60).
  Lift s;
  const ItemId wall = s.world.add({60, 0, 8, 100});
  const SolidMove m = tv::moveSolid(s.world, s.lift, {40, 100}, s.options());
  EXPECT_EQ(m.position, (Vec2{40, 100}));
  EXPECT_EQ(s.world.rect(s.rider), (Rect{52, 88, 8, 12}));
  EXPECT_EQ(m.carried, std::vector<ItemId>{s.rider});
  EXPECT_TRUE(m.squished.empty()) << "a rider stopped by a wall is left on the lift, not squished";
  (void)wall;
}

TEST(LiftNegativeControl, TeleportingARisingLiftThenMovingItsRiderDropsItThroughTheLift) {
  // The naive order a game writes: teleport the lift up, then move the rider up by the same
  // amount. The rider's move starts inside the lift; the sweep pushes it out of the overlap the
  // short way — downwards — and it ends under the lift, at every speed. moveSolid (above) never
  // does.
  int dropped = 0;
  for (int tiles = 1; tiles <= 10; ++tiles) {
    Lift s;
    const double step = -(tiles * kTile + 0.37);
    const Rect l = s.world.rect(s.lift);
    s.world.update(s.lift, Vec2{l.x, l.y + step});
    const Rect r = s.world.rect(s.rider);
    (void)s.world.move(s.rider, {r.x, r.y + step});
    EXPECT_FALSE(onTop(s.world, s.rider, s.lift));
    if (s.world.rect(s.rider).y >= s.world.rect(s.lift).bottom()) ++dropped;
  }
  EXPECT_EQ(dropped, 10);
}

// [SECTION] pushing and squishing ---------------------------------------------------------------

//   ceiling {0, 40, 48, 8}: bottom at 48
//   the lift rises 60 px: its rider reaches the ceiling when the lift's top is at 60
TEST(Lift, CrushingItsRiderIntoACeilingStopsWithTheRiderPressedBetween) {
  Lift s;
  const ItemId ceiling = s.world.add({0, 40, 48, 8});
  const SolidMove m = tv::moveSolid(s.world, s.lift, {0, 40}, s.options());
  EXPECT_EQ(s.world.rect(s.rider), (Rect{20, 48, 8, 12}));  // against the ceiling
  EXPECT_EQ(m.position, (Vec2{0, 60}));                     // the lift stopped under it
  ASSERT_EQ(m.squished.size(), 1u);
  EXPECT_EQ(m.squished[0].body, s.rider);
  EXPECT_EQ(m.squished[0].against, ceiling);
  EXPECT_EQ(m.squished[0].normal, (Vec2{0, -1}));
  EXPECT_FALSE(tv::overlaps(s.world.rect(s.rider), s.world.rect(s.lift)));
}

//   a door {0, 0, 8, 32} slides right 100 px into a row of three boxes 8 wide at x 20, 30, 40,
//   which block each other; a wall at x 70 stops the row: boxes end at 46, 54, 62, the door at 38.
TEST(Door, PushesARowOfBodiesAndStopsWhereTheRowMeetsAWall) {
  World w(32);
  const ItemId door = w.add({0, 0, 8, 32});
  const ItemId wall = w.add({70, 0, 8, 32});
  const std::vector<ItemId> boxes{w.add({40, 10, 8, 8}), w.add({20, 10, 8, 8}),
                                  w.add({30, 10, 8, 8})};
  SolidOptions o;
  o.bodies = boxes;
  const SolidMove m = tv::moveSolid(w, door, {100, 0}, o);
  EXPECT_EQ(w.rect(boxes[0]).x, 62.0);
  EXPECT_EQ(w.rect(boxes[2]).x, 54.0);
  EXPECT_EQ(w.rect(boxes[1]).x, 46.0);
  EXPECT_EQ(m.position, (Vec2{38, 0}));
  // The box at the wall first, then each behind the one in front of it.
  ASSERT_EQ(m.squished.size(), 3u);
  EXPECT_EQ(m.squished[0].body, boxes[0]);
  EXPECT_EQ(m.squished[0].against, wall);
  EXPECT_EQ(m.squished[1].body, boxes[2]);
  EXPECT_EQ(m.squished[1].against, boxes[0]);
  EXPECT_EQ(m.squished[2].body, boxes[1]);
  EXPECT_EQ(m.squished[2].against, boxes[2]);
  EXPECT_EQ(m.squished[0].normal, (Vec2{1, 0}));
  for (const ItemId b : boxes) EXPECT_FALSE(tv::overlaps(w.rect(b), w.rect(door)));
}

TEST(Door, PushesABodyItWouldOtherwiseJumpOverAtAnySpeed) {
  // A door 8 wide moving 1000 px in one call: a body 4 wide 50 px ahead is pushed, not skipped.
  World w(32);
  const ItemId door = w.add({0, 0, 8, 32});
  const ItemId box = w.add({50, 10, 4, 4});
  const std::vector<ItemId> bodies{box};
  SolidOptions o;
  o.bodies = bodies;
  const SolidMove m = tv::moveSolid(w, door, {1000, 0}, o);
  EXPECT_EQ(m.position, (Vec2{1000, 0}));
  EXPECT_EQ(w.rect(box).x, 1008.0);
  EXPECT_EQ(m.pushed, bodies);
}

// [SECTION] one-way platforms -----------------------------------------------------------------

//   platform {0, 100, 48, 4}, one-way; rider on top; a jumper {30, 110, 8, 8} just under it
TEST(OneWayPlatform, CarriesItsRiderAndPassesThroughTheBodyBelow) {
  for (int tiles = 1; tiles <= 10; ++tiles) {
    World w(32);
    const ItemId platform = w.add({0, 100, 48, 4});
    const ItemId rider = w.add({10, 92, 8, 8});
    const ItemId below = w.add({30, 110, 8, 8});
    const std::vector<ItemId> bodies{rider, below};
    SolidOptions o;
    o.bodies = bodies;
    o.oneWay = true;
    const double step = -(tiles * kTile + 0.37);
    const SolidMove m = tv::moveSolid(w, platform, {0, 100 + step}, o);
    EXPECT_EQ(m.position, (Vec2{0, 100 + step}));
    EXPECT_TRUE(onTop(w, rider, platform)) << tiles;
    EXPECT_EQ(w.rect(below), (Rect{30, 110, 8, 8})) << "not pushed: it was below";
    EXPECT_TRUE(m.squished.empty());
    // And down again: carried exactly, at every speed.
    (void)tv::moveSolid(w, platform, {0, 100 + 3 * step}, o);
    EXPECT_TRUE(onTop(w, rider, platform)) << tiles;
  }
}

// [SECTION] bad input
// ------------------------------------------------------------------------------

TEST(MoveSolid, BadInputIsRefusedNamingItAndChangesNothing) {
  Lift s;
  const std::uint64_t before = s.world.stateHash();
  EXPECT_THROW((void)tv::moveSolid(s.world, s.lift, {0, std::nan("")}, s.options()), tv::Error);
  const std::vector<ItemId> self{s.rider, s.lift};
  SolidOptions o;
  o.bodies = self;
  try {
    (void)tv::moveSolid(s.world, s.lift, {0, 0}, o);
    ADD_FAILURE() << "the solid among its bodies was accepted";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[1] is the solid itself"), std::string::npos);
  }
  const std::vector<ItemId> twice{s.rider, s.rider};
  o.bodies = twice;
  EXPECT_THROW((void)tv::moveSolid(s.world, s.lift, {0, 0}, o), tv::Error);
  EXPECT_EQ(s.world.stateHash(), before);
}

TEST(MoveSolid, ASolidMovedIntoAnotherSolidPassesThroughItUnlessItListsItAsABody) {
  //   +---------+            a door {0, 0, 8, 40} moved right 30 px into a block
  //   |door|  |block|        {20, 0, 8, 40} that is a solid too (the game moves it by moveSolid)
  World w(16);
  const ItemId door = w.add({0, 0, 8, 40});
  const ItemId block = w.add({20, 0, 8, 40});
  const SolidMove through = tv::moveSolid(w, door, {30, 0});
  EXPECT_EQ(through.position, (Vec2{30, 0})) << "solids do not stop solids (as Celeste's)";
  EXPECT_EQ(w.rect(block), (Rect{20, 0, 8, 40}));
  // Listed among the door's bodies, the block is pushed like any body.
  w.update(door, Vec2{0, 0});
  const std::vector<ItemId> bodies{block};
  SolidOptions o;
  o.bodies = bodies;
  const SolidMove push = tv::moveSolid(w, door, {30, 0}, o);
  EXPECT_EQ(push.pushed, bodies);
  EXPECT_EQ(w.rect(block).x, 38.0);
}

TEST(MoveSolid, ARiderThatIsAlsoASolidRidesAndWhatStandsOnItIsNeverLeftInside) {
  //        +-+
  //        |r|           r {20, 80, 6, 8} stands on the platform b
  //      +-----+
  //      |  b  |         b {12, 88, 24, 4}: a solid of its own (a smaller lift), riding a
  //   +-----------+
  //   |     a     |      a {0, 92, 48, 8}, moved up, then down, 5 px
  World w(16);
  const ItemId a = w.add({0, 92, 48, 8});
  const ItemId b = w.add({12, 88, 24, 4});
  const ItemId r = w.add({20, 80, 6, 8});
  const std::vector<ItemId> bodies{b, r};
  SolidOptions o;
  o.bodies = bodies;
  (void)tv::moveSolid(w, a, {0, 87}, o);  // up: b is carried, r is pushed by b in turn
  EXPECT_TRUE(onTop(w, b, a));
  EXPECT_TRUE(onTop(w, r, b));
  (void)tv::moveSolid(w, a, {0, 92}, o);  // down: b is carried; r stood on b, not on a
  EXPECT_TRUE(onTop(w, b, a));
  EXPECT_FALSE(tv::overlaps(w.rect(r), w.rect(b)));
  EXPECT_EQ(w.rect(r).bottom(), 83.0) << "left where it was, to fall by its own gravity";
  // b moved as a solid itself carries r.
  const std::vector<ItemId> riders{r};
  o.bodies = riders;
  (void)tv::moveSolid(w, b, {12, 83}, o);
  EXPECT_TRUE(onTop(w, r, b));
}

TEST(MoveSolid, SquishesAreResultsSoTheGameReactsOnceTheWorldIsWhole) {
  // No callback runs inside moveSolid but the filter: a squished body is reported, and the game
  // removes it (or moves it) afterwards, when every item is where moveSolid left it.
  Lift s;
  const ItemId ceiling = s.world.add({0, 70, 48, 8});
  const SolidMove m = tv::moveSolid(s.world, s.lift, {0, 60}, s.options());
  ASSERT_EQ(m.squished.size(), 1u);
  EXPECT_EQ(m.squished[0].against, ceiling);
  EXPECT_FALSE(tv::overlaps(s.world.rect(s.rider), s.world.rect(s.lift)));
  EXPECT_FALSE(tv::overlaps(s.world.rect(s.rider), s.world.rect(ceiling)));
  s.world.remove(m.squished[0].body);
  EXPECT_EQ(s.world.count(), 2u);
}

TEST(MoveSolid, AFilterThatThrowsLeavesEveryItemWhereItWas) {
  Lift s;
  const ItemId ceiling = s.world.add({0, 40, 48, 8});
  const std::uint64_t before = s.world.stateHash();
  SolidOptions o = s.options();
  const auto throwing = [&](ItemId, ItemId other) -> tv::ResponseId {
    if (other == ceiling) throw std::runtime_error("game error");
    return tv::response::slide;
  };
  o.filter = throwing;
  EXPECT_THROW((void)tv::moveSolid(s.world, s.lift, {0, 0}, o), std::runtime_error);
  EXPECT_EQ(s.world.stateHash(), before);
}

}  // namespace
