// Contact events in the debugger, for every source that has them: a scene's bodies that read
// their contacts and a recording's Contacts::update calls give the frame's events (phase, other
// item, normal, where both stood) and the ground; the world view draws them in their own colours
// on the touching edge, and the legend lists those colours only where there are contacts.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "imgui.h"
#include "imgui_frame.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"

namespace tv::ui {
namespace {

class ContactEvents : public testing::ImGuiFrame {
 protected:

  static std::set<ImU32> coloursIn(const Camera& cam, const WorldPicture& pic) {
    return testing::coloursDrawn(cam, pic);
  }
};

std::unique_ptr<SimSource> sceneAt(std::string_view name, std::uint64_t tick) {
  const sim::SceneDef& s = sim::findScene(name);
  auto source = std::make_unique<SimSource>(s, s.defaults(), MoverSpec{});
  source->advanceTo(tick, 0.0);
  return source;
}

bool listsContacts(const Source& s) {
  const palette::LegendScope scope = legendScopeOf(s);
  int n = 0;
  for (const palette::LegendEntry& e : palette::legend()) {
    const std::string label = e.label;
    if (scope.shows(e) && label.rfind("contact ", 0) == 0) ++n;
  }
  EXPECT_TRUE(n == 0 || n == 3) << n;
  return n == 3;
}

// [SECTION] a scene --------------------------------------------------------------------------------
//
// platformer, tick 21: the player walks right along the floor's tiles; in this tick it leaves
// tile 101's top (an end), stands on 102 (persists) and reaches 103's (a begin).
//
//      [p]-->
//   |101|102|103|      tiles 16 px, the player 12 px
TEST_F(ContactEvents, AScenesFrameGivesEachBodysEventsAndGroundAndDrawsThem) {
  const auto s = sceneAt("platformer", 21);
  const sim::Simulation& sim = s->simulation();
  const ItemId player = sim.bodies()[0].item;
  std::vector<ContactPhase> phases;
  for (const sim::ContactAt& e : s->contactEvents()) {
    EXPECT_EQ(e.event.item, player);
    EXPECT_EQ(e.event.normal, (Vec2{0, -1})) << "standing on each tile";
    phases.push_back(e.event.phase);
  }
  EXPECT_EQ(phases, (std::vector<ContactPhase>{ContactPhase::end, ContactPhase::persist,
                                               ContactPhase::begin}));
  const auto g = s->ground(player);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->kind, GroundKind::ground);
  EXPECT_EQ(s->describe(g->item), "tile 102");
  // Solids read no contacts: no ground for them.
  EXPECT_FALSE(s->ground(ItemId{0, 0}).has_value());

  Camera cam;
  cam.frame(sim.bodies()[0].rect, {0, 0}, {1280, 720});
  const std::set<ImU32> drawn = coloursIn(cam, s->picture());
  for (const ImU32 c : {palette::kContactBegin, palette::kContactPersist, palette::kContactEnd})
    EXPECT_TRUE(drawn.count(c)) << std::hex << c;
  EXPECT_TRUE(listsContacts(*s));
}

TEST_F(ContactEvents, AScenesBodiesThatReadNoContactsDrawNoneAndTheLegendSaysNone) {  // control
  const auto s = sceneAt("bullets-wall", 2);
  EXPECT_TRUE(s->contactEvents().empty());
  Camera cam;
  cam.frame(s->simulation().camera(), {0, 0}, {1280, 720});
  const std::set<ImU32> drawn = coloursIn(cam, s->picture());
  for (const ImU32 c : {palette::kContactBegin, palette::kContactPersist, palette::kContactEnd})
    EXPECT_FALSE(drawn.count(c)) << std::hex << c;
  EXPECT_FALSE(listsContacts(*s));
}

// The contact edge of each phase: a begin on top of a tile marks the body's bottom over the
// shared part; an end whose item has gone marks the body's whole bottom.
//
//   body   x 4..16, y 0..12       +--------+
//   other  x 10..26, y 12..28     | body   |
//                                 +---=====+======+   shared: x 10..16 at y 12
//                                     | other     |
TEST(ContactEdge, IsTheSharedPartOfTheBodysEdgeFacingTheOther) {
  sim::ContactAt c;
  c.bodyRect = {4, 0, 12, 12};
  c.otherRect = {10, 12, 16, 16};
  c.event.normal = {0, -1};
  EXPECT_EQ(contactEdge(c), (std::pair<Vec2, Vec2>{{10, 12}, {16, 12}}));
  c.otherRect = {40, 12, 16, 16};  // gone from under it: the body's whole bottom
  EXPECT_EQ(contactEdge(c), (std::pair<Vec2, Vec2>{{4, 12}, {16, 12}}));
  c.otherRect = {16, 2, 8, 8};  // on its right
  c.event.normal = {-1, 0};
  EXPECT_EQ(contactEdge(c), (std::pair<Vec2, Vec2>{{16, 2}, {16, 10}}));
  c.otherRect = {10, 6, 10, 10};  // overlapping: the overlap's centre
  c.event.normal = {0, 0};
  EXPECT_EQ(contactEdge(c), (std::pair<Vec2, Vec2>{{13, 9}, {13, 9}}));
}

// [SECTION] a recording -----------------------------------------------------------------------------
//
// one-way-rise recorded through tv::Recorder (the scene's riders read their contacts: the
// recording holds each Contacts::update). Replayed, each frame gives the events the scene got in
// that tick, where it got them, and the rider's ground recomputed through core.
TEST_F(ContactEvents, ARecordingsFrameGivesTheEventsItsGameGot) {
  const sim::SceneDef& scene = sim::findScene("one-way-rise");
  sim::Simulation sim(scene, scene.defaults(), parseMover("continuous"));
  Recorder rec(RecorderOptions{16});
  sim.attach(rec);
  std::vector<std::vector<sim::ContactAt>> got;
  std::vector<std::optional<Ground>> grounds;
  for (int t = 0; t < 30; ++t) {
    sim.tick();
    got.emplace_back(sim.contactEvents().begin(), sim.contactEvents().end());
    grounds.push_back(sim.ground(0));
    rec.frame();
  }
  sim.detach();
  rec.close();
  const auto opened = ReplaySource::fromBytes(
      std::make_shared<const std::vector<std::uint8_t>>(rec.bytes()), "one-way-rise");
  ReplaySource& src = *opened;
  EXPECT_TRUE(src.hasContacts());
  EXPECT_TRUE(listsContacts(src));
  const ItemId rider = sim.bodies()[0].item;
  std::size_t compared = 0;
  for (std::uint64_t f = 0; f < 30; ++f) {
    src.goTo(f);
    const auto events = src.contactEvents();
    ASSERT_EQ(events.size(), got[f].size()) << "frame " << f;
    for (std::size_t k = 0; k < events.size(); ++k) {
      const sim::ContactAt &a = events[k], &b = got[f][k];
      EXPECT_EQ(a.event.item, b.event.item) << f;
      EXPECT_EQ(a.event.other, b.event.other) << f;
      EXPECT_EQ(a.event.phase, b.event.phase) << f;
      EXPECT_EQ(a.event.normal, b.event.normal) << f;
      EXPECT_EQ(a.bodyRect, b.bodyRect) << f;
      EXPECT_EQ(a.otherRect, b.otherRect) << f;
      ++compared;
    }
    // The ground, recomputed by the replay: the same item and velocity; its kind is `ground`
    // (the game's one-way list is not recorded).
    const auto g = src.ground(rider);
    ASSERT_TRUE(g.has_value()) << f;
    EXPECT_EQ(g->item, grounds[f]->item) << f;
    EXPECT_EQ(g->velocity, grounds[f]->velocity) << f;
  }
  EXPECT_GT(compared, 30u);
  // Reached by a jump (a seek from a keyframe, then the frames before re-traced), the same.
  for (const std::uint64_t f : {25u, 3u, 17u, 29u}) {
    src.goTo(f);
    ASSERT_EQ(src.contactEvents().size(), got[f].size()) << f;
    for (std::size_t k = 0; k < got[f].size(); ++k)
      EXPECT_EQ(src.contactEvents()[k].event.phase, got[f][k].event.phase) << f;
    EXPECT_EQ(src.ground(rider)->velocity, grounds[f]->velocity) << f;
  }
  // Drawn as a scene's are.
  src.goTo(1);
  Camera cam;
  cam.frame(src.home(), {0, 0}, {1280, 720});
  EXPECT_TRUE(coloursIn(cam, src.picture()).count(palette::kContactPersist));

  // A what-if re-run shows none: its world is not the one the game's events came from.
  const auto whatIf = src.whatIf(parseMover("discrete"), false);
  whatIf->goTo(5);
  EXPECT_TRUE(whatIf->contactEvents().empty());
  EXPECT_FALSE(whatIf->ground(rider).has_value());
}

TEST_F(ContactEvents, ARecordingWithoutContactsListsNone) {  // the control
  World w(16);
  Recorder rec;
  w.attach(rec);
  const ItemId floor = w.add({0, 32, 64, 16});
  const ItemId p = w.add({0, 20, 8, 12});
  (void)floor;
  for (int f = 0; f < 5; ++f) {
    (void)w.move(p, w.rect(p).position() + Vec2{4, 0});
    rec.frame();
  }
  w.detach();
  rec.close();
  ReplaySource src(Replay::fromBytes(rec.bytes()), "plain");
  src.goTo(4);
  EXPECT_TRUE(src.contactEvents().empty());
  EXPECT_FALSE(src.hasContacts());
  EXPECT_FALSE(listsContacts(src));
}

}  // namespace
}  // namespace tv::ui
