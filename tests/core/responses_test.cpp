// Specification of responses and collision reports (tv/response.hpp, World::move): what each
// built-in does, how filters choose, and in which order collisions are reported.

#include "tv/response.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tv/error.hpp"
#include "tv/world.hpp"

namespace {

using tv::Collision;
using tv::ItemId;
using tv::Rect;
using tv::ResponseId;
using tv::Vec2;
using tv::World;
namespace response = tv::response;

// The scene most tests share:
//
//   y=-50      +----+
//              |    |  wall {20,-50,10,100}
//   +----+     |    |
//   | m  | --> |    |  mover {0,0,10,10} -> goal (40,20)
//   +----+     |    |  its right edge reaches 20 after 10 of 40: ti = 0.25,
//              |    |  at which point y = 0 + 0.25 * 20 = 5: touch (10, 5), normal (-1, 0)
//   y=50       +----+
struct WallScene {
  World world{16};
  ItemId wall = world.add({20, -50, 10, 100});
  ItemId mover = world.add({0, 0, 10, 10});
  static constexpr Vec2 kGoal{40, 20};
  static constexpr Vec2 kTouch{10, 5};
};

// [SECTION] built-in responses -----------------------------------------------------------------

TEST(Touch, StopsAtTheContact) {
  WallScene s;
  const tv::MoveResult r =
      s.world.move(s.mover, WallScene::kGoal, tv::Filter::all(response::touch));
  EXPECT_EQ(r.position, WallScene::kTouch);
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].response, response::touch);
  EXPECT_EQ(r.collisions[0].target, WallScene::kTouch);
}

TEST(Slide, KeepsTheMotionAlongTheWall) {
  WallScene s;
  const tv::MoveResult r = s.world.move(s.mover, WallScene::kGoal);  // default filter: slide
  EXPECT_EQ(r.position, (Vec2{10, 20}));
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].response, response::slide);
  EXPECT_EQ(r.collisions[0].target, (Vec2{10, 20}));
  EXPECT_EQ(s.world.rect(s.mover), (Rect{10, 20, 10, 10}));
}

TEST(Bounce, ReflectsTheRestOfTheMoveAboutTheNormal) {
  // Rest of the move after the touch: (40,20) - (10,5) = (30,15); reflected on x: (-30,15).
  // Target: (10 - 30, 5 + 15) = (-20, 20); the second leg leaves the wall and hits nothing.
  WallScene s;
  const tv::MoveResult r =
      s.world.move(s.mover, WallScene::kGoal, tv::Filter::all(response::bounce));
  EXPECT_EQ(r.position, (Vec2{-20, 20}));
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].target, (Vec2{-20, 20}));
}

TEST(Bounce, BetweenTwoWallsReflectsAgain) {
  //   +--+                    +--+
  //   |L |  <-- m -->         |R |   L {-20,-50,10,100} (right edge -10)
  //   +--+                    +--+   R {20,-50,10,100}, mover {0,0,10,10} -> (50, 0)
  // Hit R at x 10 (rest 40 reflected: goal -30), then L at x -10 (rest 20 reflected: goal 10).
  World w(16);
  const ItemId left = w.add({-20, -50, 10, 100});
  const ItemId right = w.add({20, -50, 10, 100});
  const ItemId m = w.add({0, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {50, 0}, tv::Filter::all(response::bounce));
  ASSERT_EQ(r.collisions.size(), 2u);
  EXPECT_EQ(r.collisions[0].other, right);
  EXPECT_EQ(r.collisions[0].touch, (Vec2{10, 0}));
  EXPECT_EQ(r.collisions[1].other, left);
  EXPECT_EQ(r.collisions[1].touch, (Vec2{-10, 0}));
  EXPECT_EQ(r.position, (Vec2{10, 0}));
}

// [SECTION] the table of built-ins ---------------------------------------------------------------

TEST(BuiltinTable, AFreshWorldRegistersEveryEntryUnderItsNameAndPlace) {
  World w;
  for (ResponseId i = 0; i < response::kBuiltinCount; ++i) {
    const tv::ResponseDef& def = tv::kBuiltinResponses[i];
    EXPECT_EQ(w.responseName(i), def.name);
    EXPECT_EQ(w.responseId(def.name), i);
    EXPECT_EQ(tv::builtinResponseId(def.name), i);
    EXPECT_FALSE(def.summary.empty()) << def.name;
  }
  // Not a built-in: "ignore" is the filter's answer, not a response; user names are the world's.
  EXPECT_EQ(tv::builtinResponseId("ignore"), response::ignore);
  EXPECT_EQ(tv::builtinResponseId("stick"), response::ignore);
  EXPECT_THROW((void)w.responseName(response::kBuiltinCount), tv::Error);
}

TEST(BuiltinTable, TheWorldRunsEachEntrysFunctionForItsId) {
  // The WallScene move under each built-in: the leg the world took is the one the table's
  // function gives for the reported collision (its `target` is the next leg's goal).
  for (ResponseId i = 0; i < response::kBuiltinCount; ++i) {
    WallScene s;
    const tv::MoveResult r = s.world.move(s.mover, WallScene::kGoal, tv::Filter::all(i));
    ASSERT_FALSE(r.collisions.empty()) << tv::kBuiltinResponses[i].name;
    const Collision& c = r.collisions[0];
    EXPECT_EQ(c.response, i);
    const tv::Leg leg = tv::kBuiltinResponses[i].fn(c, WallScene::kGoal);
    EXPECT_EQ(c.target, leg.goal) << tv::kBuiltinResponses[i].name;
  }
}

//   floor, normal (0,-1) (from the floor towards the body above it)
//   a body falling right, v = (3, 4), meets it; one rising off it, v = (3, -4), is leaving it.
TEST(BuiltinTable, VelocityRulesByName) {
  Collision floorHit;
  floorHit.normal = {0, -1};
  const Vec2 falling{3, 4}, rising{3, -4};
  const auto after = [&](std::string_view name, Vec2 v) {
    floorHit.response = tv::builtinResponseId(name);
    return tv::velocityAfter(v, floorHit);
  };
  EXPECT_EQ(after("touch", falling), (Vec2{0, 0}));
  EXPECT_EQ(after("cross", falling), falling);
  EXPECT_EQ(after("slide", falling), (Vec2{3, 0}));
  EXPECT_EQ(after("bounce", falling), (Vec2{3, -4}));
  // A component already leaving the obstacle is kept by every rule but touch's.
  EXPECT_EQ(after("slide", rising), rising);
  EXPECT_EQ(after("bounce", rising), rising);
  // A user response keeps the velocity (the game applies its own rule).
  floorHit.response = response::kBuiltinCount;
  EXPECT_EQ(tv::velocityAfter(falling, floorHit), falling);
}

//   +----+   +---+        +---+
//   | m  |-->| A |  ...   | B |     mover {0,0,10,10} -> (100,0)
//   +----+   +---+        +---+     A {20,0,10,10} crossed at ti 0.1, B {50,0,10,10} slid on
//                                   at ti 0.4 of the restarted leg: stops at x = 40.
TEST(Cross, ReportsPassesThroughAndContinuesToTheNextObstacle) {
  World w(16);
  const ItemId a = w.add({20, 0, 10, 10});
  const ItemId b = w.add({50, 0, 10, 10});
  const ItemId m = w.add({0, 0, 10, 10});
  auto filter = [&](ItemId, ItemId other) {
    return other == a ? response::cross : response::slide;
  };
  const tv::MoveResult r = w.move(m, {100, 0}, filter);
  ASSERT_EQ(r.collisions.size(), 2u);
  EXPECT_EQ(r.collisions[0].other, a);
  EXPECT_EQ(r.collisions[0].response, response::cross);
  EXPECT_EQ(r.collisions[0].ti, 0.1);
  EXPECT_EQ(r.collisions[0].target, (Vec2{100, 0}));  // cross keeps the goal
  EXPECT_EQ(r.collisions[1].other, b);
  EXPECT_EQ(r.collisions[1].ti, 0.4);
  EXPECT_EQ(r.collisions[1].touch, (Vec2{40, 0}));
  EXPECT_EQ(r.position, (Vec2{40, 0}));
}

TEST(Cross, AloneReachesTheGoalAndReportsEveryObstacleOnce) {
  World w(16);
  const ItemId a = w.add({20, 0, 10, 10});
  const ItemId b = w.add({50, 0, 10, 10});
  const ItemId m = w.add({0, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {100, 0}, tv::Filter::all(response::cross));
  EXPECT_EQ(r.position, (Vec2{100, 0}));
  ASSERT_EQ(r.collisions.size(), 2u);
  EXPECT_EQ(r.collisions[0].other, a);
  EXPECT_EQ(r.collisions[1].other, b);
}

// [SECTION] filters -----------------------------------------------------------------------------

TEST(Filter, IgnoreLetsTheMoverPassWithoutAReport) {
  WallScene s;
  std::vector<std::pair<ItemId, ItemId>> asked;
  auto filter = [&](ItemId item, ItemId other) {
    asked.emplace_back(item, other);
    return response::ignore;
  };
  const tv::MoveResult r = s.world.move(s.mover, WallScene::kGoal, filter);
  EXPECT_EQ(r.position, WallScene::kGoal);
  EXPECT_TRUE(r.collisions.empty());
  ASSERT_FALSE(asked.empty());
  EXPECT_EQ(asked[0].first, s.mover);
  EXPECT_EQ(asked[0].second, s.wall);
}

TEST(Filter, ChoosesPerPair) {
  // Two walls in a row; the first is ignored, the second touched.
  World w(16);
  const ItemId ghost = w.add({20, -50, 10, 100});
  (void)w.add({60, -50, 10, 100});
  const ItemId m = w.add({0, 0, 10, 10});
  auto filter = [&](ItemId, ItemId other) {
    return other == ghost ? response::ignore : response::touch;
  };
  const tv::MoveResult r = w.move(m, {80, 0}, filter);
  EXPECT_EQ(r.position, (Vec2{50, 0}));
  ASSERT_EQ(r.collisions.size(), 1u);
}

tv::Leg liftResponse(const Collision& c, Vec2) {
  // Stop at the contact, then rise 3 px (away from a side wall, so never inside it).
  return {c.touch, c.touch + Vec2{0, -3}};
}
TEST(CustomResponse, RegisteredByNameAndReturnedByAFilter) {
  WallScene s;
  const ResponseId lift = s.world.addResponse("lift", &liftResponse);
  EXPECT_GE(lift, response::kBuiltinCount);
  EXPECT_EQ(s.world.responseName(lift), "lift");
  EXPECT_EQ(s.world.responseId("lift"), lift);
  EXPECT_EQ(s.world.responseId("bounce"), response::bounce);
  auto filter = [&](ItemId, ItemId) { return lift; };
  const tv::MoveResult r = s.world.move(s.mover, WallScene::kGoal, filter);
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].response, lift);
  EXPECT_EQ(r.collisions[0].target, (Vec2{10, 2}));
  EXPECT_EQ(r.position, (Vec2{10, 2}));
}

// A response registered with a context gets it back at every call: what a binding or a replay
// keeps per world (its current call, its recorded legs) needs no global.
struct Lift {
  double rise = 0;
  int calls = 0;
};
tv::Leg liftBy(void* context, const Collision& c, Vec2 /*goal*/) {
  auto& lift = *static_cast<Lift*>(context);
  ++lift.calls;
  return {c.touch, c.touch + Vec2{0, -lift.rise}};
}

TEST(CustomResponse, ARegisteredContextIsHandedBackAtEveryCall) {
  WallScene s;
  Lift two{2, 0}, five{5, 0};
  const ResponseId a = s.world.addResponse("lift 2", &liftBy, &two);
  const ResponseId b = s.world.addResponse("lift 5", &liftBy, &five);
  tv::MoveResult r = s.world.check(s.mover, WallScene::kGoal, tv::Filter::all(a));
  EXPECT_EQ(r.position, (Vec2{10, 3}));
  r = s.world.check(s.mover, WallScene::kGoal, tv::Filter::all(b));
  EXPECT_EQ(r.position, (Vec2{10, 0}));
  EXPECT_EQ(two.calls, 1);
  EXPECT_EQ(five.calls, 1);
  // A copy of the world shares the context (it is not owned).
  World copy = s.world;
  (void)copy.check(s.mover, WallScene::kGoal, tv::Filter::all(a));
  EXPECT_EQ(two.calls, 2);
  EXPECT_THROW((void)s.world.addResponse("none", tv::ResponseWithContextFn{nullptr}, &two),
               tv::Error);
}

TEST(CustomResponse, FilterReturningAnUnregisteredIdThrowsAndChangesNothing) {
  WallScene s;
  const std::uint64_t before = s.world.stateHash();
  auto filter = [](ItemId, ItemId) { return ResponseId{7}; };
  try {
    (void)s.world.move(s.mover, WallScene::kGoal, filter);
    FAIL() << "expected tv::Error";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find('7'), std::string::npos) << e.what();
  }
  EXPECT_EQ(s.world.stateHash(), before);
  EXPECT_EQ(s.world.rect(s.mover), (Rect{0, 0, 10, 10}));
}

// [SECTION] the collision record -----------------------------------------------------------------

TEST(Collision, CarriesEveryFieldOfTheHit) {
  WallScene s;
  const tv::MoveResult r = s.world.move(s.mover, WallScene::kGoal);
  ASSERT_EQ(r.collisions.size(), 1u);
  const Collision& c = r.collisions[0];
  EXPECT_EQ(c.item, s.mover);
  EXPECT_EQ(c.other, s.wall);
  EXPECT_FALSE(c.overlaps);
  EXPECT_FALSE(c.corner);
  EXPECT_EQ(c.ti, 0.25);
  EXPECT_EQ(c.move, (Vec2{40, 20}));
  EXPECT_EQ(c.normal, (Vec2{-1, 0}));
  EXPECT_EQ(c.touch, (Vec2{10, 5}));
  EXPECT_EQ(c.itemRect, (Rect{0, 0, 10, 10}));
  EXPECT_EQ(c.otherRect, (Rect{20, -50, 10, 100}));
  EXPECT_EQ(c.response, response::slide);
  EXPECT_EQ(c.target, (Vec2{10, 20}));
}

//   mover {18,0,10,10} starts 2 px inside the wall {20,-50,10,100} (intersection 8 x 10):
//   overlaps, ti = -80, pushed left to x = 10 (the shallowest way), then slides to y = 20.
TEST(Collision, StartingInsideIsReportedAsAnOverlap) {
  World w(16);
  const ItemId wall = w.add({20, -50, 10, 100});
  const ItemId m = w.add({18, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {18, 20});
  ASSERT_GE(r.collisions.size(), 1u);
  const Collision& c = r.collisions[0];
  EXPECT_EQ(c.other, wall);
  EXPECT_TRUE(c.overlaps);
  EXPECT_EQ(c.ti, -80.0);
  EXPECT_EQ(c.normal, (Vec2{-1, 0}));
  EXPECT_EQ(c.touch, (Vec2{10, 0}));
  EXPECT_EQ(c.target, (Vec2{10, 20}));
  EXPECT_EQ(r.position, (Vec2{10, 20}));
}

TEST(Collision, ProjectReportsWithAnInvalidItem) {
  WallScene s;
  const tv::MoveResult r = s.world.project({0, 0, 10, 10}, WallScene::kGoal);
  ASSERT_EQ(r.collisions.size(), 2u);  // the wall, and the mover itself (it is in the world)
  EXPECT_FALSE(r.collisions[0].item.valid());
  EXPECT_EQ(r.collisions[0].other, s.mover);  // starts inside it: overlaps sort first
  EXPECT_TRUE(r.collisions[0].overlaps);
}

// [SECTION] order -------------------------------------------------------------------------------

//   Crossing three posts: C (added first) is farthest, B and A are hit at the same ti.
//     m {0,0,10,10} -> (100,0);  B {30,-9,10,10}, A {30,5,10,10}: both at ti 0.2
//                                C {60,0,10,10} at ti 0.5
//   Reported: ti order first, then add order among equal ti: B (added 2nd), A (3rd), C.
TEST(Order, CollisionsAreSortedByTiThenAddOrder) {
  World w(16);
  const ItemId c = w.add({60, 0, 10, 10});
  const ItemId b = w.add({30, -9, 10, 10});
  const ItemId a = w.add({30, 5, 10, 10});
  const ItemId m = w.add({0, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {100, 0}, tv::Filter::all(response::cross));
  ASSERT_EQ(r.collisions.size(), 3u);
  EXPECT_EQ(r.collisions[0].other, b);
  EXPECT_EQ(r.collisions[1].other, a);
  EXPECT_EQ(r.collisions[2].other, c);
  EXPECT_EQ(r.collisions[0].ti, 0.2);
  EXPECT_EQ(r.collisions[1].ti, 0.2);
  EXPECT_EQ(r.collisions[2].ti, 0.5);
}

//   Landing on a floor of two tiles right at the seam:
//            m {-5,0,10,10} -> goal (5,20)
//          +----+
//          | m  |  \                bottom 10 reaches y = 20 at ti 0.5, when m spans x [0,10]
//          +----+   v
//   y=20   +---------+---------+
//          |  T1     |  T2     |    T1 {0,20,10,10}: ordinary hit at 0.5 (y normal)
//          +---------+---------+    T2 {10,20,10,10}: exact corner hit at 0.5 (x normal)
//   T2 is added first, yet T1's face wins: the mover lands and slides to (5, 10). Were the
//   corner taken, the mover would stop on T2's side face at x = 0 (a seam snag).
TEST(Order, AnOrdinaryHitBeatsAnExactCornerHitAtTheSameTi) {
  World w(16);
  const ItemId t2 = w.add({10, 20, 10, 10});
  const ItemId t1 = w.add({0, 20, 10, 10});
  const ItemId m = w.add({-5, 0, 10, 10});
  (void)t2;
  const tv::MoveResult r = w.move(m, {5, 20});
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].other, t1);
  EXPECT_FALSE(r.collisions[0].corner);
  EXPECT_EQ(r.collisions[0].normal, (Vec2{0, -1}));
  EXPECT_EQ(r.position, (Vec2{5, 10}));
}

TEST(Order, AnExactCornerHitAloneIsReportedAsACorner) {
  World w(16);
  const ItemId t = w.add({10, 20, 10, 10});
  const ItemId m = w.add({-5, 0, 10, 10});
  const tv::MoveResult r = w.move(m, {5, 20}, tv::Filter::all(response::touch));
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].other, t);
  EXPECT_TRUE(r.collisions[0].corner);
  EXPECT_EQ(r.collisions[0].normal, (Vec2{-1, 0}));
  EXPECT_EQ(r.position, (Vec2{0, 10}));
}

TEST(Order, MaxResponsesStopsTheItemAtItsLastContact) {
  // Bouncing between walls 2 px apart for a 1000 px move needs hundreds of responses.
  World w(16);
  (void)w.add({-20, -50, 10, 100});
  (void)w.add({2, -50, 10, 100});
  const ItemId m = w.add({-10, 0, 10, 2});  // 10 wide between walls 12 apart: 2 px of play
  tv::MoveOptions o;
  o.maxResponses = 3;
  const tv::MoveResult r = w.move(m, {990, 0}, tv::Filter::all(response::bounce), o);
  EXPECT_EQ(r.collisions.size(), 3u);
  EXPECT_EQ(r.position, r.collisions.back().touch);
}

}  // namespace
