// What the platform scenes report beside their counters: the contact events and ground of the
// bodies that read their contacts (as a game reads its player's), and each drop and pop named by
// the rider it happened to, so the tools can list it as that rider's failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

Params withCarry(std::string_view scene, double carry) {
  Params p = findScene(scene).defaults();
  p.set("carry", carry);
  return p;
}

std::vector<ContactAt> eventsOf(const Simulation& s, std::size_t body) {
  std::vector<ContactAt> out;
  for (const ContactAt& e : s.contactEvents())
    if (e.body == body) out.push_back(e);
  return out;
}

// [SECTION] contact events -----------------------------------------------------------------------
//
//     [r]        rider 0 stands on platform 1 (one-way, a moving solid) at tick 0
//    =====       tick 1: the rider's first update begins the contact; tick 2: it persists, and
//                the ground is the platform, moving up at its speed
//
// Column 0's platform rises 16 px a tick at the defaults.

TEST(SceneContacts, ARiderBeginsThenKeepsItsContactWithThePlatformItStandsOn) {
  Simulation sim(findScene("one-way-rise"), withCarry("one-way-rise", 1), parseMover("continuous"));
  const ItemId platform = sim.bodies()[1].item;
  sim.tick();
  auto first = eventsOf(sim, 0);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].event.phase, ContactPhase::begin);
  EXPECT_EQ(first[0].event.other, platform);
  EXPECT_EQ(first[0].event.normal, (Vec2{0, -1}));
  EXPECT_EQ(first[0].bodyRect, sim.bodies()[0].rect);
  EXPECT_EQ(first[0].otherRect, sim.bodies()[1].rect);
  sim.tick();
  auto second = eventsOf(sim, 0);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].event.phase, ContactPhase::persist);
  const auto g = sim.ground(0);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->kind, GroundKind::oneWay);  // a one-way moving platform is listed as one-way
  EXPECT_EQ(g->item, platform);
  EXPECT_EQ(g->velocity, (Vec2{0, -16}));  // its displacement since the rider's last update
  EXPECT_FALSE(sim.ground(1).has_value()) << "the platform does not read its contacts";
  EXPECT_THROW((void)sim.ground(99), Error);
}

// A body that leaves what it stood on ends the contact: the corner-nudge jumpers leave the floor
// on their first tick, and land on it again later.
TEST(SceneContacts, AJumperEndsItsContactWithTheFloorAndIsInTheAir) {
  Simulation sim("corner-nudge", "continuous");
  sim.tick();  // jumps: its first update finds nothing under it
  EXPECT_TRUE(eventsOf(sim, 0).empty());
  EXPECT_EQ(sim.ground(0)->kind, GroundKind::air);
  // Play until a jumper is back on the floor: a begin with normal (0, -1).
  bool landed = false;
  for (int t = 0; t < 120 && !landed; ++t) {
    sim.tick();
    for (const ContactAt& e : sim.contactEvents())
      landed = landed || (e.event.phase == ContactPhase::begin && e.event.normal == Vec2{0, -1});
  }
  EXPECT_TRUE(landed);
}

// Stepping back restores a tick's events and ground, and the contacts go on from there as they
// did: the game's tracker is kept with each snapshot.
TEST(SceneContacts, EventsAfterASeekAreTheEventsOfAnUninterruptedRun) {
  for (const std::string_view scene : {"lift-crush", "one-way-rise", "platformer"}) {
    Simulation straight(scene, "continuous");
    Simulation again(scene, "continuous");
    std::vector<std::vector<ContactAt>> seen;
    for (int t = 0; t < 40; ++t) {
      straight.tick();
      seen.emplace_back(straight.contactEvents().begin(), straight.contactEvents().end());
    }
    for (int t = 0; t < 40; ++t) again.tick();
    again.seek(20);
    const auto compare = [&](const Simulation& s, std::uint64_t t) {
      const auto& want = seen[t - 1];
      ASSERT_EQ(s.contactEvents().size(), want.size()) << scene << " tick " << t;
      for (std::size_t k = 0; k < want.size(); ++k) {
        const ContactAt& a = s.contactEvents()[k];
        EXPECT_EQ(a.body, want[k].body) << scene << " tick " << t;
        EXPECT_EQ(a.event.other, want[k].event.other) << scene << " tick " << t;
        EXPECT_EQ(a.event.phase, want[k].event.phase) << scene << " tick " << t;
      }
    };
    compare(again, 20);
    for (std::uint64_t t = 21; t <= 40; ++t) {
      again.tick();
      compare(again, t);
    }
    EXPECT_FALSE(seen.back().empty()) << scene << ": its bodies read their contacts";
  }
}

TEST(SceneContacts, ScenesWhoseBodiesDoNotReadContactsHaveNone) {
  Simulation sim("bullets-wall", "continuous");
  for (int t = 0; t < 30; ++t) sim.tick();
  EXPECT_TRUE(sim.contactEvents().empty());
  EXPECT_FALSE(sim.ground(0).has_value());
}

// [SECTION] drops and pops, named ----------------------------------------------------------------
//
// Each drop and pop is an event of the rider it happened to, against its platform or lift, so
// the tools can list it; together they are the counters.

struct Named {
  std::uint64_t drops = 0, pops = 0;
  bool allNamed = true;  // every one names a rider and the solid it left
};

Named namedOver(Simulation& s, int ticks) {
  Named n;
  for (int t = 0; t < ticks; ++t) {
    s.tick();
    for (const TickEvent& e : s.events()) {
      if (e.what != Counted::dropped && e.what != Counted::popped) continue;
      (e.what == Counted::dropped ? n.drops : n.pops) += e.count;
      const bool rider = e.body >= 0 && !s.bodies()[static_cast<std::size_t>(e.body)].solid &&
                         s.bodies()[static_cast<std::size_t>(e.body)].layer != kLayerSolid;
      n.allNamed = n.allNamed && rider && e.other.valid() && e.tick == s.ticks();
    }
  }
  return n;
}

TEST(SceneContacts, EveryDropAndPopOfTheNegativeControlsIsNamedByItsRider) {
  for (const std::string_view scene : {"one-way-rise", "lift-crush"}) {
    std::uint64_t total = 0;
    for (const std::string_view m : moverNames()) {
      Simulation sim(findScene(scene), withCarry(scene, 0), parseMover(m));
      const Named n = namedOver(sim, 240);
      EXPECT_EQ(n.drops, sim.counters().drops) << scene << " " << m;
      EXPECT_EQ(n.pops, sim.counters().pops) << scene << " " << m;
      EXPECT_TRUE(n.allNamed) << scene << " " << m;
      total += n.drops + n.pops;
    }
    EXPECT_GT(total, 0u) << scene << ": the naive platforms drop or pop their riders";
  }
}

TEST(SceneContacts, TheExactMovingSolidsDropAndPopNoOne) {
  for (const std::string_view scene : {"one-way-rise", "lift-crush"}) {
    for (const std::string_view m : moverNames()) {
      Simulation sim(findScene(scene), withCarry(scene, 1), parseMover(m));
      const Named n = namedOver(sim, 240);
      EXPECT_EQ(n.drops + n.pops, 0u) << scene << " " << m;
    }
  }
}

}  // namespace
}  // namespace tv::sim
