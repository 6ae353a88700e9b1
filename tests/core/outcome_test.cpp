// judgeMove: what a finished move passed through or ended inside, read from where it started
// and where it ended (a tunnelling move leaves no hit to read it from).
#include <gtest/gtest.h>

#include "tv/mover.hpp"
#include "tv/outcome.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

//   x: 0    10   20   30   40
//      [b]       |##|            the bullet (2x2 at y 10) is teleported from x 0 to x 40,
//                |##|            past a 4 px wall at x 20..24: passed through it.
struct Lane {
  World world{16};
  ItemId wall = world.add({20, 0, 4, 32});
  ItemId bullet = world.add({0, 10, 2, 2});
};

TEST(JudgeMove, ATeleportPastAWallPassedThroughIt) {
  Lane l;
  const Rect start = l.world.rect(l.bullet);
  Mover naive(MoverSpec{.kind = MoverKind::discrete});
  naive.move(l.world, l.bullet, {40, 10});
  const MoveOutcome o = judgeMove(l.world, l.bullet, start, l.world.rect(l.bullet));
  EXPECT_EQ(o.passedThrough, l.wall);
  EXPECT_FALSE(o.endedInside.valid());
}

TEST(JudgeMove, ASweptMoveStoppedAtTheFacePassedNothing) {  // the negative control
  Lane l;
  const Rect start = l.world.rect(l.bullet);
  Mover exact(MoverSpec{.kind = MoverKind::continuous});
  exact.move(l.world, l.bullet, {40, 10});
  EXPECT_EQ(l.world.rect(l.bullet).right(), 20.0);
  const MoveOutcome o = judgeMove(l.world, l.bullet, start, l.world.rect(l.bullet));
  EXPECT_FALSE(o.passedThrough.valid());
  EXPECT_FALSE(o.endedInside.valid());
}

//      [b] -> ending at x 21 (inside the wall)
TEST(JudgeMove, EndingInsideASolidItDidNotStartIn) {
  Lane l;
  const Rect start = l.world.rect(l.bullet);
  l.world.update(l.bullet, {21, 10, 2, 2});  // what a game writing x += v*dt does
  const MoveOutcome o = judgeMove(l.world, l.bullet, start, l.world.rect(l.bullet));
  EXPECT_EQ(o.endedInside, l.wall);
  EXPECT_FALSE(o.passedThrough.valid());
}

TEST(JudgeMove, WhatTheFilterIgnoresOrCrossesIsNotCounted) {
  Lane l;
  const Rect start = l.world.rect(l.bullet);
  l.world.update(l.bullet, {40, 10, 2, 2});
  for (const ResponseId r : {response::ignore, response::cross}) {
    const MoveOutcome o =
        judgeMove(l.world, l.bullet, start, l.world.rect(l.bullet), Filter::all(r));
    EXPECT_FALSE(o.passedThrough.valid()) << r;
  }
}

}  // namespace
}  // namespace tv
