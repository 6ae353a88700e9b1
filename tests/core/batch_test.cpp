// Moving versus moving: items that cross during a tick must meet.
#include <gtest/gtest.h>

#include <span>
#include <utility>

#include "tv/batch.hpp"
#include "tv/error.hpp"

namespace tv {
namespace {

// A bullet flies right along y = 0..4 while an enemy drops through its path during the tick:
//
//            enemy (18..22) falls from y = -20 to y = 20
//              ##
//              ##
//   [bullet] -------------------->   x: 0 -> 40
//              ||
//              vv
//
// Halfway through the tick both are at x ~ 18..22, y ~ 0..4. Frozen one at a time, neither is
// ever where the other is.
struct Crossing {
  World world{32};
  ItemId bullet = world.add({0, 0, 4, 4});
  ItemId enemy = world.add({18, -20, 4, 4});
};

TEST(Batch, MoversThatCrossDuringATickCollide) {
  Crossing s;
  Batch batch;
  const BatchMove moves[] = {{s.bullet, {40, 0}}, {s.enemy, {18, 20}}};
  batch.step(s.world, moves, [](ItemId, ItemId) { return response::touch; });
  ASSERT_EQ(batch.size(), 2u);
  ASSERT_EQ(batch.outcome(0).collisions.size(), 1u);
  ASSERT_EQ(batch.outcome(1).collisions.size(), 1u);
  const Collision& hit = batch.outcome(0).collisions[0];
  EXPECT_EQ(hit.other, s.enemy);
  EXPECT_EQ(batch.outcome(1).collisions[0].other, s.bullet);
  // Both stopped where they met, touching, not overlapping.
  EXPECT_FALSE(overlaps(s.world.rect(s.bullet), s.world.rect(s.enemy)));
  EXPECT_TRUE(touches(s.world.rect(s.bullet), s.world.rect(s.enemy)));
  EXPECT_LT(s.world.rect(s.bullet).x, 40.0);
}

TEST(Batch, AStepOfNoBodiesDoesNothingOnANewBatchAsOnAUsedOne) {
  // A new Batch's grid had no cell yet: a step of no bodies read one that did not exist (found
  // by the recording reader's mutation fuzz, replaying a batch call whose body count was 0).
  Crossing s;
  const std::uint64_t before = s.world.stateHash();
  Batch fresh;
  fresh.step(s.world, std::span<const BatchMove>{});
  EXPECT_EQ(fresh.size(), 0u);
  Batch used;
  const BatchMove moves[] = {{s.bullet, {40, 0}}};
  used.step(s.world, moves);
  used.step(s.world, std::span<const BatchMove>{});
  EXPECT_EQ(used.size(), 0u);
  EXPECT_NE(s.world.stateHash(), before);  // the one real step moved the bullet
}

TEST(Batch, OneAtATimeMovesMissTheSameCrossing) {
  // The negative control for the test above.
  Crossing s;
  const auto touch = [](ItemId, ItemId) { return response::touch; };
  EXPECT_TRUE(s.world.move(s.bullet, {40, 0}, touch).collisions.empty());
  EXPECT_TRUE(s.world.move(s.enemy, {18, 20}, touch).collisions.empty());
}

TEST(Batch, StaticObstaclesStopMoversExactlyAsAMoveDoes) {
  World w(32);
  w.add({100, -50, 16, 100});
  const ItemId a = w.add({0, 0, 8, 8});
  Batch batch;
  const BatchMove moves[] = {{a, {200, 30}}};
  batch.step(w, moves);
  EXPECT_EQ(w.rect(a).right(), 100.0);  // slid down the wall's face
  EXPECT_EQ(w.rect(a).y, 30.0);
}

TEST(Batch, HeadOnSlidersEndTouching) {
  World w(32);
  const ItemId a = w.add({0, 0, 8, 8});
  const ItemId b = w.add({30, 0, 8, 8});
  Batch batch;
  const BatchMove moves[] = {{a, {30, 0}}, {b, {0, 0}}};
  batch.step(w, moves);
  EXPECT_FALSE(overlaps(w.rect(a), w.rect(b)));
  EXPECT_EQ(w.rect(a).right(), w.rect(b).x);
}

TEST(Batch, CrossingMoversReportAndPassThrough) {
  Crossing s;
  Batch batch;
  const BatchMove moves[] = {{s.bullet, {40, 0}}, {s.enemy, {18, 20}}};
  batch.step(s.world, moves, [](ItemId, ItemId) { return response::cross; });
  EXPECT_EQ(batch.outcome(0).collisions.size(), 1u);
  EXPECT_EQ(s.world.rect(s.bullet).position(), (Vec2{40, 0}));
  EXPECT_EQ(s.world.rect(s.enemy).position(), (Vec2{18, 20}));
}

TEST(Batch, BadInputThrowsAndChangesNothing) {
  Crossing s;
  Batch batch;
  const std::uint64_t before = s.world.stateHash();
  const BatchMove twice[] = {{s.bullet, {40, 0}}, {s.bullet, {0, 40}}};
  EXPECT_THROW(batch.step(s.world, twice), Error);
  const BatchMove nan[] = {{s.bullet, {NAN, 0}}};
  EXPECT_THROW(batch.step(s.world, nan), Error);
  const BatchMove unknown[] = {{ItemId{99, 0}, {0, 0}}};
  EXPECT_THROW(batch.step(s.world, unknown), Error);
  EXPECT_EQ(s.world.stateHash(), before);
}

// The order the moves are listed in is not an input: a pair is swept from its earlier-added
// side and same-instant events run in add order, so listing a, b or b, a lands every body on
// the same doubles. (Sweeping from the first-listed side rounded a.x to 10.826996197718628 one
// way and 10.82699619771863 the other.)
TEST(Batch, TheOutcomeDoesNotDependOnTheOrderOfTheMoves) {
  const auto run = [](bool reversed) {
    World w(32);
    const ItemId a = w.add({0.3, 0.7, 8, 8});
    const ItemId b = w.add({30.1, 3.3, 8, 8});
    const BatchMove ab[] = {{a, {25.7, 9.1}}, {b, {2.9, 0.2}}};
    const BatchMove ba[] = {ab[1], ab[0]};
    Batch batch;
    batch.step(w, reversed ? std::span<const BatchMove>(ba) : std::span<const BatchMove>(ab),
               Filter::all(response::slide));
    return std::pair{w.rect(a), w.rect(b)};
  };
  const auto forward = run(false), backward = run(true);
  EXPECT_EQ(forward.first, backward.first);
  EXPECT_EQ(forward.second, backward.second);
  EXPECT_NE(forward.first.position(), (Vec2{25.7, 9.1})) << "precondition: a and b did meet";
}

// A filter answer that is not a response is found part way through the tick, after other
// bodies have advanced: every body goes back where it began.
TEST(Batch, AStepThatThrowsPartWayPutsEveryBodyBack) {
  Crossing s;
  const ItemId bystander = s.world.add({0, 100, 4, 4});
  const std::uint64_t before = s.world.stateHash();
  Batch batch;
  const BatchMove moves[] = {{s.bullet, {40, 0}}, {s.enemy, {18, 20}}, {bystander, {50, 100}}};
  EXPECT_THROW(batch.step(s.world, moves,
                          [&](ItemId, ItemId other) -> ResponseId {
                            return other == s.enemy ? ResponseId{77} : response::touch;
                          }),
               Error);
  EXPECT_EQ(s.world.stateHash(), before);
  EXPECT_EQ(s.world.rect(bystander), (Rect{0, 100, 4, 4}));
}

// A body's path is re-based only by events it takes part in. While a and b meet at t = 1/4,
// c flies on untouched and reaches the wall at t = 3/4: its collision describes the leg from
// where it began the tick, not from where it was at the others' event.
//
//   [a]-> <-[b]                 (meet at t = 1/4)
//
//   [c] ------------------->|wall|   (c.right 8 -> 40 crosses the wall's face at 32: t = 3/4)
TEST(Batch, ABodyIsReBasedOnlyByItsOwnEvents) {
  World w(32);
  const ItemId a = w.add({0, 0, 8, 8});
  const ItemId b = w.add({24, 0, 8, 8});
  const ItemId c = w.add({0, 40, 8, 8});
  w.add({32, 32, 8, 32});
  Batch batch;
  const BatchMove moves[] = {{a, {32, 0}}, {b, {-8, 0}}, {c, {32, 40}}};
  batch.step(w, moves, Filter::all(response::touch));
  ASSERT_EQ(batch.outcome(0).collisions.size(), 1u);
  ASSERT_EQ(batch.outcome(2).collisions.size(), 1u);
  const Collision& hit = batch.outcome(2).collisions[0];
  EXPECT_EQ(hit.itemRect, (Rect{0, 40, 8, 8}));
  EXPECT_EQ(hit.move, (Vec2{32, 0}));
  EXPECT_EQ(hit.ti, 0.75);
  EXPECT_EQ(w.rect(c).right(), 32.0);
  EXPECT_EQ(w.rect(a).right(), w.rect(b).x);
}

// maxEvents bounds the events a tick may run; a tick whose events all fit ends as if there
// were no bound, and one that has more stops every body at the instant of the last it ran.
//
//   |wall|          [a] slides down the wall's face to y = 30 (one event);
//   [d]-->|wall2|   and d, meanwhile, would hit a second wall at t = 1/2.
TEST(Batch, MaxEventsStopsTheTickOnlyWhenAnotherEventIsDue) {
  World w(32);
  w.add({100, -50, 16, 100});
  const ItemId a = w.add({0, 0, 8, 8});
  Batch batch;
  const BatchMove one[] = {{a, {200, 30}}};
  World once = w;
  batch.step(once, one, {}, 1);
  EXPECT_EQ(once.rect(a).right(), 100.0);
  EXPECT_EQ(once.rect(a).y, 30.0) << "its one event ran and it slid on to its goal";

  w.add({300, 200, 16, 16});
  const ItemId d = w.add({200, 200, 8, 8});
  const BatchMove two[] = {{a, {200, 30}},
                           {d, {384, 200}}};  // d's face 208 -> 392 meets 300 at 1/2
  World cut = w;
  batch.step(cut, two, {}, 1);
  // a hit the wall at t = 92/200 and ran that event; d's hit at t = 1/2 did not run, so both
  // stop where they were at t = 0.46: a where it touched, d short of its wall.
  ASSERT_EQ(batch.outcome(0).collisions.size(), 1u);
  EXPECT_EQ(cut.rect(a).position(), batch.outcome(0).collisions[0].touch);
  EXPECT_EQ(cut.rect(a).right(), 100.0);
  EXPECT_GT(cut.rect(d).x, 200.0);
  EXPECT_LT(cut.rect(d).right(), 300.0);
  World all = w;
  batch.step(all, two, {}, 2);
  EXPECT_EQ(all.rect(a).y, 30.0);
  EXPECT_EQ(all.rect(d).right(), 300.0);
}

}  // namespace
}  // namespace tv
