// Specification of the recording hook (tv/observer.hpp) and of a world's state (World::state,
// World::restore): what an observer is told, and that a restored world behaves as the original.

#include "tv/observer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "expect_rejected.hpp"
#include "tv/batch.hpp"
#include "tv/mover.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::ResponseId;
using tv::Vec2;
using tv::World;

// Writes each report as one line, so a test states the exact sequence it expects.
class Log final : public tv::WorldObserver {
 public:
  std::vector<std::string> lines;
  std::size_t itemsAtAttach = 0;

  void attached(const World& w) override {
    itemsAtAttach = w.count();
    lines.push_back("attached");
  }
  void detached(const World&) override { lines.push_back("detached"); }
  void added(ItemId id, const Rect&) override { lines.push_back("add " + name(id)); }
  void removed(ItemId id) override { lines.push_back("remove " + name(id)); }
  void updated(ItemId id, const Rect& r) override {
    lines.push_back("update " + name(id) + " x=" + tv::formatNumber(r.x));
  }
  void moved(ItemId id, Vec2, const tv::MoveOptions&, const tv::MoveResult& r) override {
    lines.push_back("move " + name(id) + " hits=" + std::to_string(r.collisions.size()));
  }
  void checked(ItemId id, Vec2, const tv::MoveOptions&, const tv::MoveResult&) override {
    lines.push_back("check " + name(id));
  }
  void projected(const Rect&, Vec2, const tv::MoveOptions&, const tv::MoveResult&) override {
    lines.push_back("project");
  }
  void queriedRect(const Rect&, ItemId, std::span<const ItemId> found) override {
    lines.push_back("queryRect found=" + std::to_string(found.size()));
  }
  void queriedPoint(Vec2, std::span<const ItemId> found) override {
    lines.push_back("queryPoint found=" + std::to_string(found.size()));
  }
  void queriedSegment(Vec2, Vec2, std::span<const tv::SegmentHit> hits) override {
    lines.push_back("querySegment hits=" + std::to_string(hits.size()));
  }
  void askedOverlap(const Rect&, ItemId, bool any) override {
    lines.push_back(std::string("anyOverlap ") + (any ? "yes" : "no"));
  }
  void responseAdded(std::string_view n, ResponseId id) override {
    lines.push_back("response " + std::string(n) + "=" + std::to_string(id));
  }
  void moverMoved(const tv::Mover& m, ItemId id, const Rect&, Vec2, const tv::MoveResult&) override {
    lines.push_back("mover " + m.spec().name() + " " + name(id));
  }
  void batchStepped(std::span<const tv::BatchMove> moves, int, const tv::Batch&) override {
    lines.push_back("batch " + std::to_string(moves.size()));
  }
  void advanced(double, int ticks) override { lines.push_back("advance " + std::to_string(ticks)); }
  void filtered(ItemId a, ItemId b, ResponseId r) override {
    lines.push_back("  filter " + name(a) + "," + name(b) + "=" + std::to_string(r));
  }
  void responded(const tv::Collision&, Vec2, const tv::Leg& leg) override {
    lines.push_back("  leg to x=" + tv::formatNumber(leg.goal.x));
  }
  void failed() override { lines.push_back("  failed"); }
  void sourceGone(const void* source) override { gone.push_back(source); }
  std::vector<const void*> gone;

 private:
  static std::string name(ItemId id) { return id.valid() ? std::to_string(id.index) : "-"; }
};

tv::Leg stopShort(const tv::Collision& c, Vec2) { return {c.touch, c.touch - Vec2{1, 0}}; }

// A wall of one tile and a mover left of it:
//    mover (0,0) 8×8      wall (16,0) 16×16
//    [m]     |  [####]
TEST(Observer, SeesEachOutermostCallWithItsResultAndTheFiltersAnswers) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  const ItemId wall = w.add({16, 0, 16, 16});
  w.attach(log);
  EXPECT_EQ(log.itemsAtAttach, 1u);
  const ItemId m = w.add({0, 0, 8, 8});
  (void)w.move(m, {20, 0});
  (void)w.check(m, {20, 0}, [](ItemId, ItemId) { return tv::response::ignore; });
  (void)w.queryRect({0, 0, 40, 40});
  (void)w.anyOverlap({20, 0, 2, 2});
  (void)w.queryPoint({9, 1});  // the mover, now flush with the wall at x 8..16
  (void)w.querySegment({-5, 4}, {40, 4});
  w.update(m, Vec2{0, 0});
  w.remove(m);
  w.detach();
  (void)w.add({100, 100, 1, 1});  // after detach: not reported
  const std::vector<std::string> expected = {
      "attached",
      "add 1",
      "  filter 1,0=2",  // once: about the hit, whatever path the move takes
      "move 1 hits=1",
      "  filter 1,0=65535",
      "check 1",
      "queryRect found=2",
      "  filter -,0=2",  // anyOverlap's default skip: the filter is asked (skip, other)
      "anyOverlap yes",
      "queryPoint found=1",
      "querySegment hits=2",
      "update 1 x=0",
      "remove 1",
      "detached",
  };
  EXPECT_EQ(log.lines, expected);
  (void)wall;
}

TEST(Observer, AMoversWorldCallsArePartOfOneCall) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  (void)w.add({16, 0, 16, 16});
  const ItemId m = w.add({0, 0, 8, 8});
  w.attach(log);
  tv::Mover substep(tv::parseMover("substep-discrete"));
  (void)substep.move(w, m, {20, 0});
  // Only the outer call, with the filter's answers from inside it.
  ASSERT_FALSE(log.lines.empty());
  EXPECT_EQ(log.lines.back(), "mover substep-discrete 1");
  for (std::size_t i = 1; i + 1 < log.lines.size(); ++i) {
    EXPECT_EQ(log.lines[i].rfind("  filter", 0), 0u) << log.lines[i];
  }
}

TEST(Observer, ABatchStepIsOneCall) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  const ItemId a = w.add({0, 0, 4, 4});
  const ItemId b = w.add({40, 0, 4, 4});
  w.attach(log);
  tv::Batch batch;
  const tv::BatchMove moves[] = {{a, {60, 0}}, {b, {-20, 0}}};
  batch.step(w, moves);
  EXPECT_EQ(log.lines.back(), "batch 2");
}

TEST(Observer, AUserResponsesLegIsReported) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  (void)w.add({16, 0, 16, 16});
  const ItemId m = w.add({0, 0, 8, 8});
  w.attach(log);
  const ResponseId stop = w.addResponse("stop-short", &stopShort);
  (void)w.move(m, {20, 0}, tv::Filter::all(stop));
  // The first id after the built-ins (response::kBuiltinCount: 5).
  const std::vector<std::string> expected = {"attached", "response stop-short=5",
                                             "  filter 1,0=5", "  leg to x=7",
                                             "move 1 hits=1"};
  EXPECT_EQ(log.lines, expected);
}

TEST(Observer, ACallThatThrowsIsNotReportedAndVoidsItsAnswers) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  const ItemId m = w.add({0, 0, 8, 8});
  w.attach(log);
  EXPECT_THROW((void)w.move(m, {std::nan(""), 0}), tv::Error);
  EXPECT_THROW(w.remove(ItemId{7, 0}), tv::Error);
  const std::vector<std::string> expected = {"attached", "  failed", "  failed"};
  EXPECT_EQ(log.lines, expected);
}

TEST(Observer, AFixedStepReportsEachFrame) {
  Log log;  // declared first: an observer outlives what it observes
  tv::FixedStep step(0.25, 1.0);
  step.attach(&log);
  (void)step.advance(0.6);
  EXPECT_EQ(log.lines, std::vector<std::string>{"advance 2"});
}

TEST(Observer, ACopyOfAnAttachedWorldReportsToNoOne) {
  Log log;  // declared first: an observer outlives what it observes
  World w(16);
  w.attach(log);
  World copy = w;
  EXPECT_EQ(copy.observer(), nullptr);
  EXPECT_EQ(w.observer(), &log);
}

// A game may destroy its world and its FixedStep before the recorder: the observer is told, so
// it never calls a dangling pointer; a copy of either was never attached and tells nothing.
TEST(Observer, HearsWhenItsWorldOrFixedStepIsDestroyed) {
  Log log;
  const void* worldAt = nullptr;
  const void* stepAt = nullptr;
  {
    World w(16);
    tv::FixedStep step;
    w.attach(log);
    step.attach(&log);
    worldAt = &w;
    stepAt = &step;
    { const World copy = w; }
    { const tv::FixedStep copy = step; }
    EXPECT_TRUE(log.gone.empty());
  }
  ASSERT_EQ(log.gone.size(), 2u);
  EXPECT_EQ(log.gone[0], stepAt);  // members die in reverse order of declaration
  EXPECT_EQ(log.gone[1], worldAt);
}

// [SECTION] state and restore ------------------------------------------------------------------

World scrambled() {
  World w(16);
  std::vector<ItemId> ids;
  for (int i = 0; i < 10; ++i) ids.push_back(w.add({i * 16.0, 100, 16, 16}));
  w.remove(ids[3]);
  w.remove(ids[7]);
  w.remove(ids[5]);
  (void)w.add({0, 0, 8, 13.7});  // reuses slot 5, generation 1
  return w;
}

TEST(WorldState, ARestoredWorldBehavesAsTheOriginal) {
  World original = scrambled();
  World copy(16);
  copy.restore(original.state());
  EXPECT_EQ(copy.stateHash(), original.stateHash());
  // The same next handle, the same moves.
  EXPECT_EQ(copy.add({50, 50, 2, 2}), original.add({50, 50, 2, 2}));
  const ItemId m = original.idAt(5);
  EXPECT_EQ(copy.move(m, {300, 90}).position, original.move(m, {300, 90}).position);
  EXPECT_EQ(copy.stateHash(), original.stateHash());
}

TEST(WorldState, ABadStateIsRefusedNamingWhatIsWrongAndChangesNothing) {
  World w(16);
  (void)w.add({0, 0, 4, 4});
  const tv::WorldState good = scrambled().state();

  tv::WorldState s = good;
  s.cellSize = 32;
  expectRejected(w, {"cellSize", "32"}, [&] { w.restore(s); });

  s = good;
  s.slots[2].rect.w = -1;
  expectRejected(w, {"slot 2", "w", "-1"}, [&] { w.restore(s); });

  s = good;
  s.slots[1].rect.x = std::nan("");
  expectRejected(w, {"slot 1", "nan"}, [&] { w.restore(s); });

  s = good;
  s.slots[4].order = s.slots[2].order;
  expectRejected(w, {"add order"}, [&] { w.restore(s); });

  s = good;
  s.slots[4].order = s.nextOrder;
  expectRejected(w, {"nextOrder"}, [&] { w.restore(s); });

  s = good;
  s.freeSlots.push_back(0);  // alive
  expectRejected(w, {"free slot 0"}, [&] { w.restore(s); });

  s = good;
  s.freeSlots.push_back(999);
  expectRejected(w, {"free slot 999"}, [&] { w.restore(s); });

  s = good;
  s.freeSlots.push_back(s.freeSlots.front());
  expectRejected(w, {"listed twice"}, [&] { w.restore(s); });

  s = good;
  s.responses.push_back("mine");
  expectRejected(w, {"responses"}, [&] { w.restore(s); });
}

}  // namespace
