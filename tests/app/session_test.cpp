// The session: a simulation plus the traced body's recent moves, driven tick by tick or frame by
// frame at a render rate.
#include <gtest/gtest.h>

#include "tv/error.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {
namespace {

Session restFloor(std::optional<std::size_t> body = 0) {
  const sim::SceneDef& s = sim::findScene("rest-floor");
  return Session(s, s.defaults(), parseMover("continuous"), body);
}

TEST(Session, KeepsTheTracedBodysLastMovesOldestFirst) {
  Session s = restFloor();
  s.setHistoryLength(3);
  for (int t = 0; t < 10; ++t) s.tick();
  ASSERT_EQ(s.moves().size(), 3u);
  EXPECT_EQ(s.moves()[0].tick, 8u);
  EXPECT_EQ(s.moves()[2].tick, 10u);
  EXPECT_EQ(s.moves()[2].trace.item, s.sim().bodies()[0].item);
}

TEST(Session, NoBodyMeansNoTrace) {
  Session s = restFloor(std::nullopt);
  s.tick();
  EXPECT_TRUE(s.moves().empty());
}

TEST(Session, RejectsABodyThatDoesNotExist) {
  const sim::SceneDef& scene = sim::findScene("rest-floor");
  EXPECT_THROW(Session(scene, scene.defaults(), parseMover("continuous"), 999), Error);
}

TEST(Session, FramesAtARenderRateReachTheSameTickAndInterpolate) {
  Session ticked = restFloor(), framed = restFloor();
  ticked.advanceTo(12, 0.0);
  framed.advanceTo(12, 144.0);
  EXPECT_EQ(framed.sim().ticks(), 12u);
  EXPECT_EQ(framed.sim().stateHash(), ticked.sim().stateHash());
  EXPECT_FALSE(ticked.interpolating());
  EXPECT_TRUE(framed.interpolating());
  EXPECT_GE(framed.sim().alpha(), 0.0);
  EXPECT_LT(framed.sim().alpha(), 1.0);
  // A falling body is drawn behind its physics position.
  const WorldPicture p = framed.picture();
  ASSERT_EQ(p.renderRects.size(), framed.sim().bodies().size());
}

TEST(Session, RefusesToGoBackOrToStepOverTheTick) {
  Session s = restFloor();
  s.advanceTo(5, 0.0);
  EXPECT_THROW(s.advanceTo(4, 0.0), Error);
  // 10 Hz with a 60 Hz physics step runs six ticks per frame: tick 8 would be stepped over.
  EXPECT_THROW(s.advanceTo(8, 10.0), Error);
}

TEST(Session, FollowViewFramesTheLastMove) {
  Session s = restFloor();
  s.advanceTo(3, 0.0);
  const MoveTrace& m = s.moves().back().trace;
  const Rect v = s.followView(64.0);
  EXPECT_GE(v.w, 64.0);
  EXPECT_LE(v.x, m.start.x);
  EXPECT_GE(v.right(), m.start.right());
  EXPECT_LE(v.y, m.start.y);
  EXPECT_GE(v.bottom(), m.start.at(m.goal).bottom());
}

TEST(Session, DescribesBodiesAndSolids) {
  Session s = restFloor();
  EXPECT_EQ(s.describe(s.sim().bodies()[2].item), "body 2");
  EXPECT_EQ(s.describe(ItemId{0, 0}), "solid 0");
}

}  // namespace
}  // namespace tv::ui

namespace tv::ui {
namespace {

// The comparison's verdict names the tick a mover first failed: the seam snag at 250 px/s
// happens at tick 18 for the teleporting walker; the sweep never snags (the negative control).
TEST(Session, RemembersTheTickItFirstFailedAndForgetsItOnRestart) {
  const sim::SceneDef& scene = sim::findScene("seam-walk");
  sim::Params p = scene.defaults();
  p.set(sim::param::speed, 250.0);
  Session naive(scene, p, parseMover("discrete"), 0);
  Session exact(scene, p, parseMover("continuous"), 0);
  naive.advanceTo(30, 0.0);
  exact.advanceTo(30, 0.0);
  ASSERT_TRUE(naive.firstFailureTick().has_value());
  EXPECT_EQ(*naive.firstFailureTick(), 18u);
  EXPECT_GT(naive.sim().counters().snags, 0u);
  EXPECT_FALSE(exact.firstFailureTick().has_value());
  naive.restart(p, parseMover("discrete"));
  EXPECT_FALSE(naive.firstFailureTick().has_value());
}

}  // namespace
}  // namespace tv::ui
