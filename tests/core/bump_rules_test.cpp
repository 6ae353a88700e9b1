// Specification of MoveSemantics::bump: bump.lua 3.1.7's rules as its source defines them
// (tv/bump.hpp), and the three places where they decide what bump leaves to rounding or to
// hash order. Expected values marked "bump.lua:" were printed by bump.lua itself.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tv/bump.hpp"
#include "tv/world.hpp"

namespace {

using tv::Collision;
using tv::ItemId;
using tv::MoveOptions;
using tv::MoveSemantics;
using tv::Rect;
using tv::SweepKind;
using tv::Vec2;
using tv::World;
namespace response = tv::response;

MoveOptions bumpRules() {
  MoveOptions o;
  o.semantics = MoveSemantics::bump;
  return o;
}

tv::Filter all(tv::ResponseId r) { return tv::Filter::all(r); }

// -- the collision of two rects ------------------------------------------------------------------

//   item (0,0 7x6) already holds other (5,5 1x1) in its corner:
//   +-------+
//   |       |      the Minkowski difference's nearest corner is (-2, -1): bump's ti is
//   |     # |      minus wi * hi = min(7, 2) * min(6, 1) = -2 (the area of the minimum
//   +-------+      displacement), not the overlap's -1
TEST(BumpDetect, AnOverlapsTiIsMinusTheAreaOfTheMinimumDisplacement) {
  const tv::Sweep s = tv::bump::detect({0, 0, 7, 6}, {0, 0}, {5, 5, 1, 1});
  EXPECT_EQ(s.kind, SweepKind::overlap);
  EXPECT_EQ(s.ti, -2.0);
}

//   a 2x2 item centred in an 8x8 one:   0 1 2 3 4 5 6 7 8
//   four ways out of equal length;      . . . +-+ . . . .
//   bump's tie goes down (0, 1) when    . . . |i| . . . .
//   still, and back against the move   . . . +-+ . . . .
//   when moving
TEST(BumpDetect, AStillOverlapGoesOutTheVerticalWayOnATieAMovingOneBackAgainstItsMove) {
  const tv::Sweep still = tv::bump::detect({3, 3, 2, 2}, {3, 3}, {0, 0, 8, 8});
  EXPECT_EQ(still.touch, (Vec2{3, 8}));
  EXPECT_EQ(still.normal, (Vec2{0, 1}));
  const tv::Sweep right = tv::bump::detect({3, 3, 2, 2}, {4, 3}, {0, 0, 8, 8});
  EXPECT_EQ(right.touch, (Vec2{-2, 3}));
  EXPECT_EQ(right.normal, (Vec2{-1, 0}));
  const tv::Sweep up = tv::bump::detect({3, 3, 2, 2}, {3, 2}, {0, 0, 8, 8});
  EXPECT_EQ(up.touch, (Vec2{3, 8}));
  EXPECT_EQ(up.normal, (Vec2{0, 1}));
}

TEST(BumpDetect, ARectThroughACornerPointOnlyAndAMissAreNotCollisions) {
  // Diagonally past the corner of (10,10 8x8): touches it at one point only.
  EXPECT_EQ(tv::bump::detect({0, 0, 10, 10}, {20, 20}, {20, 0, 8, 8}).kind, SweepKind::miss);
  EXPECT_EQ(tv::bump::detect({0, 0, 10, 10}, {0, 5}, {20, 0, 8, 8}).kind, SweepKind::miss);
}

//   a body 13.7 tall falls from y 64.589 by 32.82 onto a floor at y 100:
//   bump.lua: ti = 0.6615173674588668, touch.y = 86.300000000000011, whose bottom
//   (+ 13.7) is past 100: a step inside the floor. Here the same ti, and the bottom on 100.
TEST(BumpDetect, TheContactIsNeverInsideTheOtherWhereBumpsRoundingPutsItThere) {
  const double y = 64.588999999999999, dy = 32.82;
  const tv::Sweep s = tv::bump::detect({0, y, 10, 13.7}, {0, y + dy}, {0, 100, 16, 16});
  ASSERT_EQ(s.kind, SweepKind::hit);
  EXPECT_EQ(s.ti, 0.6615173674588668);
  // bump's own point, for the negative control: start + ti * move.
  const double bumps = y + dy * s.ti;
  EXPECT_GT(bumps + 13.7, 100.0);
  EXPECT_EQ(s.touch.y + 13.7, 100.0);
  EXPECT_EQ(s.touch.x, 0.0);
}

TEST(BumpDetect, ElsewhereTheContactIsBumpsStartPlusTiTimesMove) {
  //   a (0,0 1x1) falls 5 onto b at y 2: ti = (2 - 1) / 5 = 0.2, touch (0, 1)
  const tv::Sweep s = tv::bump::detect({0, 0, 1, 1}, {0, 5}, {0, 2, 1, 1});
  EXPECT_EQ(s.ti, 0.2);
  EXPECT_EQ(s.touch, (Vec2{0, 1}));
  EXPECT_EQ(s.normal, (Vec2{0, -1}));
}

// -- a move ---------------------------------------------------------------------------------------

//   the item falls on two tiles at once        . . i i . . .
//   (the same ti): the one whose centre is     . . i i . . .
//   nearer comes first; at equal distances,    A A A A B B B B
//   the one added first (bump: hash order)
TEST(BumpMove, HitsAtTheSameTiComeNearestCentreFirstThenInAddOrder) {
  for (const bool aFirst : {true, false}) {
    World w(64);
    ItemId a, b;
    if (aFirst) {
      a = w.add({0, 10, 8, 8});
      b = w.add({8, 10, 8, 8});
    } else {
      b = w.add({8, 10, 8, 8});
      a = w.add({0, 10, 8, 8});
    }
    const ItemId centred = w.add({4, 0, 8, 8});  // centre 8: as near A (4) as B (12)
    const tv::MoveResult r = w.check(centred, {4, 5}, all(response::touch), bumpRules());
    ASSERT_EQ(r.collisions.size(), 1u);
    EXPECT_EQ(r.collisions[0].other, aFirst ? a : b);
    w.remove(centred);
    const ItemId left = w.add({3, 0, 8, 8});  // centre 7: nearer A
    const tv::MoveResult l = w.check(left, {3, 5}, all(response::touch), bumpRules());
    ASSERT_EQ(l.collisions.size(), 1u);
    EXPECT_EQ(l.collisions[0].other, a);
  }
}

//   a ball 2 wide between walls 4 apart, moving 64 right, bouncing:
//   l: 0..16   ball: 17..19   r: 20..36
//   it meets r, then l; its third leg heads into r again, which bump (having visited r) lets it
//   pass through: bump ends the move at x = 77, beyond r. Here the move ends against r.
TEST(BumpMove, AMoveNeverPassesIntoWhatItAlreadyMetAndDidNotCross) {
  World w(64);
  const ItemId l = w.add({0, 0, 16, 64});
  const ItemId r = w.add({20, 0, 16, 64});
  const ItemId ball = w.add({17, 30, 2, 2});
  const tv::MoveResult m = w.move(ball, {17 + 64, 30}, all(response::bounce), bumpRules());
  ASSERT_EQ(m.collisions.size(), 3u);
  EXPECT_EQ(m.collisions[0].other, r);
  EXPECT_EQ(m.collisions[1].other, l);
  EXPECT_EQ(m.collisions[2].other, r);
  EXPECT_EQ(m.position, (Vec2{18, 30}));
  EXPECT_FALSE(tv::overlaps(w.rect(ball), w.rect(l)) || tv::overlaps(w.rect(ball), w.rect(r)));
  // The negative control: bump's third leg, from the contact with l to the bounce's goal,
  // does hit r — the visited rule alone would carry the ball through it.
  const Collision& second = m.collisions[1];
  EXPECT_EQ(second.target.x, 77.0);
  EXPECT_EQ(tv::bump::detect({16, 30, 2, 2}, second.target, w.rect(r)).kind, SweepKind::hit);
}

TEST(BumpMove, AStillItemInsideAnotherStaysAndReportsTheOverlapOnce) {
  World w(64);
  const ItemId block = w.add({0, 0, 64, 64});
  const ItemId item = w.add({20, 20, 6, 6});
  for (int frame = 0; frame < 3; ++frame) {
    const tv::MoveResult m = w.move(item, {20, 20}, {}, bumpRules());
    ASSERT_EQ(m.collisions.size(), 1u);
    EXPECT_TRUE(m.collisions[0].overlaps);
    EXPECT_EQ(m.collisions[0].other, block);
    EXPECT_EQ(m.position, (Vec2{20, 20}));  // bump's slide keeps a still move's goal
  }
}

// Bodies spawned inside solids, moving as debris does (gravity, bouncing): every move meets
// each item at most once, and the body is out within a frame or two. The core's own rules are
// the negative control: a body across two blocks bounces between them 64 times a move, for ever.
struct Spawn {
  const char* what;
  std::vector<Rect> blocks;
  Rect body;
};

std::vector<Spawn> spawns() {
  std::vector<Spawn> out;
  out.push_back({"inside one block", {{0, 0, 64, 64}}, {20, 20, 6, 6}});
  for (int gap = 0; gap <= 4; ++gap) {
    //   [ block ]gap[ block ]     the body (8 wide) straddles the gap
    const double g = gap;
    out.push_back({"across two blocks", {{0, 0, 32, 64}, {32 + g, 0, 32, 64}},
                   {32 + g / 2 - 4, 20, 8, 8}});
  }
  Spawn pile{"inside a pile", {}, {121, 121, 6, 6}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pile.blocks.push_back({100.0 + i * 16, 100.0 + j * 16, 16, 16});
  out.push_back(pile);
  return out;
}

struct Outcome {
  std::size_t mostCollisions = 0;
  int framesInside = 0;
  bool repeated = false;  // one move met the same item twice
};

Outcome play(const Spawn& s, MoveSemantics rules, tv::ResponseId answer) {
  World w(64);
  for (const Rect& b : s.blocks) w.add(b);
  const ItemId body = w.add(s.body);
  MoveOptions o;
  o.semantics = rules;
  Vec2 v{30, -60};
  Outcome out;
  for (int frame = 0; frame < 120; ++frame) {
    v.y += 500.0 / 60;
    const Rect at = w.rect(body);
    const tv::MoveResult m = w.move(body, {at.x + v.x / 60, at.y + v.y / 60}, all(answer), o);
    out.mostCollisions = std::max(out.mostCollisions, m.collisions.size());
    for (std::size_t i = 0; i < m.collisions.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j)
        out.repeated = out.repeated || m.collisions[i].other == m.collisions[j].other;
      const Vec2 n = m.collisions[i].normal;
      if ((n.x < 0 && v.x > 0) || (n.x > 0 && v.x < 0)) v.x = -v.x * 0.1;
      if ((n.y < 0 && v.y > 0) || (n.y > 0 && v.y < 0)) v.y = -v.y * 0.1;
    }
    if (!w.queryRect(w.rect(body), body).empty()) ++out.framesInside;
  }
  return out;
}

TEST(BumpMove, ABodySpawnedInsideSolidsGetsOutAndNeverMeetsAnItemTwiceInAMove) {
  for (const Spawn& s : spawns()) {
    for (const tv::ResponseId answer : {response::bounce, response::slide}) {
      const Outcome o = play(s, MoveSemantics::bump, answer);
      EXPECT_FALSE(o.repeated) << s.what;
      EXPECT_LE(o.mostCollisions, s.blocks.size()) << s.what;
      EXPECT_LE(o.framesInside, 2) << s.what;
    }
  }
}

TEST(BumpMove, NegativeControlTheCoreRulesWedgeABodyAcrossTwoBlocks) {
  const std::vector<Spawn> all = spawns();
  const Outcome o = play(all[3], MoveSemantics::tunnelvision, response::bounce);  // gap 2
  EXPECT_EQ(o.mostCollisions, 64u);
  EXPECT_EQ(o.framesInside, 120);
}

//   cross: bump projects again from where the move began, not from the contact
//   the item (0,0 10x10) heads for (50,30): it slides on the floor f (y 20), then its
//   slide leg meets the cloud c (cross); the leg after that runs from (0,0) again
TEST(BumpMove, ACrossIsProjectedAgainFromTheMovesStart) {
  World w(64);
  w.add({0, 20, 100, 10});                     // f: the floor
  const ItemId c = w.add({30, 0, 4, 40});      // c: a cloud across the path
  const ItemId item = w.add({0, 0, 10, 10});
  const auto filter = [&](ItemId, ItemId other) {
    return other == c ? response::cross : response::slide;
  };
  tv::MoveTrace trace;
  MoveOptions o = bumpRules();
  o.trace = &trace;
  const tv::MoveResult m = w.move(item, {50, 30}, filter, o);
  ASSERT_EQ(m.collisions.size(), 2u);
  EXPECT_EQ(m.collisions[1].other, c);
  EXPECT_EQ(m.collisions[1].itemRect, (Rect{50 * (10.0 / 30), 10, 10, 10}));  // the contact
  EXPECT_EQ(m.position, (Vec2{50, 10}));
  ASSERT_EQ(trace.legs.size(), 3u);
  EXPECT_EQ(trace.legs[2].start, (Rect{0, 0, 10, 10}));
  EXPECT_EQ(trace.legs[2].goal, (Vec2{50, 10}));
}

// A user response under bump's rules: its leg's start is where the next projection runs from,
// its goal the move's new goal, and `stop` ends the move (bump: it returned no collisions).
tv::Leg stopAtTouch(const Collision& c, Vec2) {
  tv::Leg l;
  l.start = c.touch;
  l.goal = {c.touch.x, c.touch.y - 2};
  l.stop = true;
  return l;
}

TEST(BumpMove, AUserResponseThatStopsEndsTheMoveAtItsGoal) {
  World w(64);
  const tv::ResponseId lift = w.addResponse("lift", &stopAtTouch);
  w.add({0, 20, 100, 10});
  const ItemId item = w.add({0, 0, 10, 10});
  const tv::MoveResult m = w.move(item, {0, 30}, all(lift), bumpRules());
  ASSERT_EQ(m.collisions.size(), 1u);
  EXPECT_EQ(m.position, (Vec2{0, 8}));
  EXPECT_TRUE(w.metThisMove().empty());  // only while a response runs
}

}  // namespace
