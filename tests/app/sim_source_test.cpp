// A scene as the debugger's source: a simulation plus the traced body's recent moves, driven tick
// by tick or frame by frame at a render rate; its calls are the tick's body moves; what failed is
// said in words.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "tv/app/scene_source.hpp"
#include "tv/error.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/session.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/view.hpp"
#include "tv/ui/words.hpp"

namespace tv::ui {
namespace {

constexpr MoverSpec kContinuous{.kind = MoverKind::continuous};
constexpr MoverSpec kDiscrete{.kind = MoverKind::discrete};

SimSource restFloor(std::optional<std::size_t> body = 0) {
  const sim::SceneDef& s = sim::findScene("rest-floor");
  SimSource source(s, s.defaults(), kContinuous);
  source.traceBody(body);
  return source;
}

TEST(SimSource, KeepsTheTracedBodysLastMovesOldestFirst) {
  SimSource s = restFloor();
  s.setHistoryLength(3);
  for (int t = 0; t < 10; ++t) s.tick();
  ASSERT_EQ(s.history().size(), 3u);
  EXPECT_EQ(s.history()[0].tick, 8u);
  EXPECT_EQ(s.history()[2].tick, 10u);
  EXPECT_EQ(s.history()[2].trace.item, s.simulation().bodies()[0].item);
}

// A far --tick (lift-crush never ends: tick 999999 ran for minutes without a word) is run with
// its progress told every 4096 ticks, to what the tools print (TickProgress); without a
// listener nothing is told, and the run is the same.
TEST(SimSource, ALongRunToATickTellsHowFarItHasGot) {
  const sim::SceneDef& scene = sim::findScene("lift-crush");
  SimSource told(scene, scene.defaults(), kDiscrete);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> calls;
  told.setProgress([&](std::uint64_t r, std::uint64_t t) { calls.emplace_back(r, t); });
  told.advanceTo(10000, 0.0, true);
  ASSERT_EQ(told.frame(), 10000u) << "lift-crush does not end";
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0], (std::pair<std::uint64_t, std::uint64_t>{4096, 10000}));
  EXPECT_EQ(calls[1], (std::pair<std::uint64_t, std::uint64_t>{8192, 10000}));
  // The control: with the listener taken away, nothing is told.
  told.setProgress({});
  told.advanceTo(12289, 0.0, true);  // past 12288
  EXPECT_EQ(calls.size(), 2u);
}

TEST(SimSource, NoBodyMeansNoTrace) {
  SimSource s = restFloor(std::nullopt);
  s.tick();
  EXPECT_TRUE(s.history().empty());
  EXPECT_FALSE(s.traced());
}

TEST(SimSource, RejectsABodyThatDoesNotExist) {
  SimSource s = restFloor();
  EXPECT_THROW(s.traceBody(999), Error);
}

TEST(SimSource, FramesAtARenderRateReachTheSameTickAndInterpolate) {
  SimSource ticked = restFloor(), framed = restFloor();
  ticked.advanceTo(12, 0.0);
  framed.advanceTo(12, 144.0);
  EXPECT_EQ(framed.frame(), 12u);
  EXPECT_EQ(framed.simulation().stateHash(), ticked.simulation().stateHash());
  EXPECT_FALSE(ticked.interpolating());
  EXPECT_TRUE(framed.interpolating());
  EXPECT_GE(framed.simulation().alpha(), 0.0);
  EXPECT_LT(framed.simulation().alpha(), 1.0);
  // A falling body is drawn behind its physics position.
  const WorldPicture p = framed.picture();
  ASSERT_EQ(p.renderRects.size(), framed.simulation().bodies().size());
}

TEST(SimSource, RefusesToGoBackOrToStepOverTheTick) {
  SimSource s = restFloor();
  s.advanceTo(5, 0.0);
  EXPECT_THROW(s.advanceTo(4, 0.0), Error);
  // 10 Hz with a 60 Hz physics step runs six ticks per frame: tick 8 would be stepped over.
  EXPECT_THROW(s.advanceTo(8, 10.0), Error);
}

TEST(SimSource, GoingBackRetracesTheMovesThatLedThere) {
  SimSource s = restFloor();
  s.advanceTo(20, 0.0);
  s.goTo(6);
  EXPECT_EQ(s.frame(), 6u);
  ASSERT_FALSE(s.history().empty());
  EXPECT_EQ(s.history().back().tick, 6u);
  // The same state as running to 6 directly: determinism makes the re-run the first run.
  SimSource direct = restFloor();
  direct.advanceTo(6, 0.0);
  EXPECT_EQ(s.simulation().stateHash(), direct.simulation().stateHash());
}

TEST(SimSource, FollowViewFramesTheLastMove) {
  SimSource s = restFloor();
  s.advanceTo(3, 0.0);
  const MoveTrace& m = s.history().back().trace;
  const Rect v = s.followView(64.0);
  EXPECT_GE(v.w, 64.0);
  EXPECT_LE(v.x, m.start.x);
  EXPECT_GE(v.right(), m.start.right());
  EXPECT_LE(v.y, m.start.y);
  EXPECT_GE(v.bottom(), m.start.at(m.goal).bottom());
}

TEST(SimSource, NamesBodiesByIndexAndSolidsByWhatTheSceneCallsThem) {
  SimSource s = restFloor();
  const sim::Body& b = s.simulation().bodies()[2];
  EXPECT_EQ(s.describe(b.item), "body 2");
  EXPECT_EQ(s.category(b.item), roleName(b.role));
  // rest-floor's solids are floor tiles (its first solid is item 0).
  EXPECT_EQ(s.describe(ItemId{0, 0}), "floor tile 0");
  EXPECT_EQ(s.category(ItemId{0, 0}), "floor tile");
}

// A tick's calls are its body moves: where each body started and ended, in the order the
// simulation moved them; a body that has stopped makes none.
TEST(SimSource, ATicksCallsAreItsBodyMoves) {
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  SimSource s(scene, scene.defaults(), kContinuous);
  s.tick();
  const auto calls = s.calls();
  ASSERT_FALSE(calls.empty());
  EXPECT_LE(calls.size(), s.simulation().bodies().size());
  const CallInfo& c = calls.front();
  const auto b = s.bodyOf(c.item);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(c.position, s.simulation().bodies()[*b].rect.position());
  EXPECT_EQ(c.frame, 1u);
  // Selecting one traces that body's move in this tick.
  s.selectCall(3);
  ASSERT_NE(s.callTrace(), nullptr);
  EXPECT_EQ(s.callTrace()->item, calls[3].item);
  EXPECT_EQ(s.traced(), calls[3].item);
  EXPECT_EQ(s.frame(), 1u);
}

// bullets-wall at 1920 px/s: the naive bullet passes the wall in its second tick.
//
//    [b]--32px-->  |####|  [b]
TEST(SimSource, SaysInWordsThatTheTracedMoveTunnelledAndThroughWhat) {
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  SimSource naive(scene, scene.defaults(), kDiscrete);
  naive.traceBody(2);
  naive.advanceTo(2, 0.0);
  ASSERT_FALSE(naive.history().empty());
  const TracedMove& m = naive.history().back();
  const auto failed = naive.failureOf(m);
  ASSERT_TRUE(failed.has_value());
  EXPECT_EQ(failed->kind, FailureKind::tunnelled);
  const Said said = whatHappened(m.trace, naive, &*failed);
  EXPECT_TRUE(said.bad);
  EXPECT_EQ(said.text.rfind("tunnelled through ", 0), 0u) << said.text;
  // The negative control: the exact sweep stops at the face, and says so.
  SimSource exact(scene, scene.defaults(), kContinuous);
  exact.traceBody(2);
  exact.advanceTo(2, 0.0);
  const TracedMove& e = exact.history().back();
  EXPECT_FALSE(exact.failureOf(e).has_value());
  const Said stopped = whatHappened(e.trace, exact, nullptr);
  EXPECT_FALSE(stopped.bad);
  EXPECT_NE(stopped.text.find("stopped against"), std::string::npos) << stopped.text;
}

// The discrete walker at 250 px/s lands a fraction of a pixel into the floor tiles at a seam
// and is pushed out of them along its walk, then back: a snag, said as such, with the push-outs
// that made it.
TEST(SimSource, SaysASnagIsAPushOutSideways) {
  const sim::SceneDef& scene = sim::findScene("seam-walk");
  sim::Params p = scene.defaults();
  p.set(sim::param::speed, 250.0);
  SimSource naive(scene, p, kDiscrete);
  naive.traceBody(0);
  naive.advanceTo(18, 0.0);
  const TracedMove& m = naive.history().back();
  const auto failed = naive.failureOf(m);
  ASSERT_TRUE(failed.has_value());
  EXPECT_EQ(failed->kind, FailureKind::snagged);
  const Said said = whatHappened(m.trace, naive, &*failed);
  EXPECT_EQ(said.text.rfind("snagged on a seam", 0), 0u) << said.text;
  EXPECT_NE(said.text.find("pushed back out of"), std::string::npos) << said.text;
}

// The comparison's verdict names the tick a mover first failed: the seam snag at 250 px/s
// happens at tick 18 for the teleporting walker; the sweep never snags (the negative control).
TEST(SimSource, RemembersTheTickItFirstFailedAndForgetsItOnRestart) {
  const sim::SceneDef& scene = sim::findScene("seam-walk");
  sim::Params p = scene.defaults();
  p.set(sim::param::speed, 250.0);
  SimSource naive(scene, p, kDiscrete), exact(scene, p, kContinuous);
  naive.advanceTo(30, 0.0);
  exact.advanceTo(30, 0.0);
  ASSERT_TRUE(naive.firstFailureTick().has_value());
  EXPECT_EQ(*naive.firstFailureTick(), 18u);
  EXPECT_GT(naive.simulation().counters().snags, 0u);
  EXPECT_FALSE(exact.firstFailureTick().has_value());
  naive.restart(p, kDiscrete);
  EXPECT_FALSE(naive.firstFailureTick().has_value());
}

// -- verdicts in the scene's words ----------------------------------------------------------------

Verdict verdictAt(std::string_view scene, MoverSpec mover, std::uint64_t tick,
                  std::vector<std::pair<std::string, double>> params = {}) {
  const sim::SceneDef& def = sim::findScene(scene);
  sim::Params p = def.defaults();
  for (const auto& [name, value] : params) p.set(name, value);
  SimSource s(def, p, mover);
  s.advanceTo(tick, 0.0, true);
  Source* all[] = {&s};
  return verdictOf(s, all, false);
}

// A tunnelling scene counts its projectiles.
TEST(Verdict, ATunnellingSceneCountsItsProjectiles) {
  const Verdict v = verdictAt("bullets-wall", kDiscrete, 2);
  EXPECT_NE(v.text.find("of 1000 projectiles tunnelled"), std::string::npos) << v.text;
  EXPECT_TRUE(v.bad);
  EXPECT_FALSE(verdictAt("bullets-wall", kContinuous, 2).bad);  // the control
}

// A walking scene counts snags, not "0 of 1 tunnelled".
TEST(Verdict, AWalkingSceneCountsSnagsNotTunnels) {
  const Verdict exact = verdictAt("seam-walk", kContinuous, 30);
  EXPECT_EQ(exact.text.find("tunnelled"), std::string::npos) << exact.text;
  EXPECT_NE(exact.text.find("snags 0"), std::string::npos) << exact.text;
  EXPECT_FALSE(exact.bad);
  const Verdict naive = verdictAt("seam-walk", kDiscrete, 30, {{"speed", 250.0}});
  EXPECT_NE(naive.text.find("snags "), std::string::npos) << naive.text;
  EXPECT_TRUE(naive.bad);
}

// corner-graze's exact grazes are what must happen: "grazes", never a red "misses".
TEST(Verdict, AnExactMoversGrazesAreNotMisses) {
  const Verdict v = verdictAt("corner-graze", kContinuous, 10);
  EXPECT_NE(v.text.find("grazes 8"), std::string::npos) << v.text;
  EXPECT_EQ(v.text.find("misses"), std::string::npos) << v.text;
  EXPECT_FALSE(v.bad);
}

// bullets-enemies' misses are crossings that never met: not a green verdict.
TEST(Verdict, MissesOfMovingTargetsAreFailures) {
  const Verdict v = verdictAt("bullets-enemies", kContinuous, 100);
  EXPECT_NE(v.text.find("misses"), std::string::npos) << v.text;
  EXPECT_TRUE(v.bad) << v.text;
  // The control: the batch meets every crossing.
  const Verdict batch = verdictAt("bullets-enemies", kContinuous, 100, {{"batch", 1.0}});
  EXPECT_FALSE(batch.bad) << batch.text;
}

// A map's "of N" counts its bullets, not its player and walkers.
TEST(Verdict, AMapCountsItsBulletsNotItsWalkers) {
  const app::SceneSource file =
      app::SceneSource::forFile(std::string(TV_SCREENSHOTS_DIR) + "/../levels/meadow.tmj");
  const sim::SceneDef& scene = file.scene();
  SimSource s(scene, scene.defaults(), kContinuous, SourceKind::level);
  std::size_t bullets = 0;
  for (const sim::Body& b : s.simulation().bodies()) bullets += b.role == sim::BodyRole::projectile;
  ASSERT_GT(bullets, 0u);
  ASSERT_GT(s.simulation().bodies().size(), bullets);
  s.advanceTo(3, 0.0);
  Source* all[] = {&s};
  const Verdict v = verdictOf(s, all, false);
  EXPECT_NE(v.text.find("of " + std::to_string(bullets) + " projectiles"), std::string::npos)
      << v.text;
  EXPECT_NE(v.text.find("snags"), std::string::npos) << v.text;  // it has walkers too
}

// -- the session: panels in lockstep ---------------------------------------------------------------

TEST(Session, ComparedMoversGoToTheSameTickAndTraceTheSameBody) {
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  auto first = std::make_unique<SimSource>(scene, scene.defaults(), kDiscrete);
  first->traceBody(2);
  Session s(std::move(first));
  s.compareWith({kContinuous, MoverSpec{.kind = MoverKind::substep}});
  ASSERT_EQ(s.size(), 3u);
  s.goTo(2);
  for (std::size_t k = 0; k < s.size(); ++k) {
    EXPECT_EQ(s.panel(k).frame(), 2u) << k;
    EXPECT_EQ(s.panel(k).traced(), s.primary().traced()) << k;
  }
  EXPECT_EQ(s.panel(1).moverName(), "continuous");
  // A call selected in the primary traces the same body in the others.
  s.selectCall(0);
  const ItemId item = s.primary().calls()[0].item;
  for (std::size_t k = 0; k < s.size(); ++k) EXPECT_EQ(s.panel(k).traced(), item) << k;
}

TEST(Session, GoingPastASceneThatEndsStopsAtItsEnd) {
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  Session s(std::make_unique<SimSource>(scene, scene.defaults(), kContinuous));
  const std::uint64_t reached = s.goTo(500, true);
  EXPECT_LT(reached, 500u);
  EXPECT_TRUE(s.ended());
}

}  // namespace
}  // namespace tv::ui
