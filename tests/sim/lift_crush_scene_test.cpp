// The lift-crush scene as a table: a lift carrying two walking riders into a ceiling, a crusher
// coming down onto two bodies on a floor, a door pushing a crowd of three against a wall — at 1
// to 10 tiles a tick, for every mover, the solids moved as moving solids (tv::moveSolid, carry 1)
// and, as the negative control, as a naive game moves them: "move the lift, then move the
// riders" (teleport the solid, give its riders its velocity, let the mover move them: carry 0).
//
//     ##########   ceiling        +--------+   crusher       |  [e][f][g]  #   door, crowd,
//      [a]  [b]    riders          [c]  [d]                  ##############    wall
//     ==========   lift           ##########   floor
//
// Counted: drops (a rider left its lift's top downwards), pops (upwards, not on it), overlaps
// (a body that ended a tick inside a solid: a body left inside), tunnelled (a crusher or door
// passed a body, or pressed it through the floor or wall), snags (a rider's walk met its lift's
// side), squishes (a body pressed against the ceiling, floor or wall: what should happen).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

constexpr std::uint64_t kTicks = 240;  // 20 strokes of each solid at the default period
constexpr double kTile = 16.0, kHz = 60.0;

enum Rows : int { kLifts = 1, kCrushers = 2, kDoors = 4, kAll = 7 };

const char* rowName(int rows) {
  return rows == kLifts ? "lift" : rows == kCrushers ? "crusher" : rows == kDoors ? "door" : "all";
}

// One column of `rows` at `tiles` a tick (count 1), or the default ten columns (tiles 0).
Counters run(std::string_view mover, bool carry, int rows, int tiles) {
  const SceneDef& scene = findScene("lift-crush");
  Params p = scene.defaults();
  p.set("carry", carry ? 1 : 0);
  p.set("solids", rows);
  if (tiles > 0) {
    p.set("count", 1);
    p.set("speed", tiles * kTile * kHz);
  }
  Simulation s(scene, p, parseMover(mover));
  for (std::uint64_t t = 0; t < kTicks; ++t) s.tick();
  return s.counters();
}

std::string where(std::string_view mover, int rows, int tiles) {
  return std::string(mover) + ", " + rowName(rows) + ", " + std::to_string(tiles) +
         " tiles a tick";
}

TEST(LiftCrush, NoBodyIsDroppedPoppedPassedOrLeftInsideByAnySolidAtAnySpeedWithAnyMover) {
  for (const std::string_view m : moverNames()) {
    for (const int rows : {kLifts, kCrushers, kDoors}) {
      for (int tiles = 1; tiles <= 10; ++tiles) {
        const Counters c = run(m, true, rows, tiles);
        const std::string at = where(m, rows, tiles);
        EXPECT_EQ(c.drops, 0u) << at;
        EXPECT_EQ(c.pops, 0u) << at;
        EXPECT_EQ(c.overlaps, 0u) << at;
        EXPECT_EQ(c.tunnelled, 0u) << at;
        EXPECT_EQ(c.snags, 0u) << at;
        // Every stroke presses its bodies against the ceiling, floor or wall, and says so.
        EXPECT_GT(c.squishes, 0u) << at;
        EXPECT_GT(c.moves, 0u) << at;
      }
    }
  }
}

TEST(LiftCrush, TheWholeSceneAtItsDefaultsCountsOnlySquishes) {
  for (const std::string_view m : moverNames()) {
    const Counters c = run(m, true, kAll, 0);
    EXPECT_EQ(c.drops + c.pops + c.overlaps + c.tunnelled + c.snags, 0u) << m;
    EXPECT_GT(c.squishes, 0u) << m;
  }
}

TEST(LiftCrushNegativeControl, MovingTheSolidThenTheRidersFailsWithEveryMoverAtEverySpeed) {
  // The lift teleported up puts its riders inside it; the mover then resolves that overlap
  // (discrete pushes them up, the swept movers see them start inside and let them fall through:
  // drops or pops). The crusher teleported down onto a body leaves it inside, or the body's own
  // move carries it out below the floor; the door teleported right lands in the crowd or past
  // it (tunnelled). Something fails for every solid, every speed, every mover.
  for (const std::string_view m : moverNames()) {
    for (const int rows : {kLifts, kCrushers, kDoors}) {
      for (int tiles = 1; tiles <= 10; ++tiles) {
        const Counters c = run(m, false, rows, tiles);
        const std::string at = where(m, rows, tiles);
        if (rows == kLifts) {
          EXPECT_GT(c.drops + c.pops, 0u) << at;
        } else {
          EXPECT_GT(c.tunnelled + c.overlaps, 0u) << at;
        }
        EXPECT_EQ(c.squishes, 0u) << at;  // the naive game has no idea
      }
    }
  }
}

// What each moving solid did, body by body, for the tools to draw. One column at 1 tile a tick:
//
//     ##########   ceiling, 4 tiles above the riders' heads: reached after 4 ticks
//      [0]  [1]
//     ====2=====   the lift (body 2) carries 0 and 1 up 16 px a tick
//
//     |9|  [6][7][8]  #    the door (body 9) meets the crowd after a tick and pushes it on
TEST(LiftCrush, TheSimulationSaysWhatEachMovingSolidDidAndASeekKeepsIt) {
  const SceneDef& scene = findScene("lift-crush");
  Params p = scene.defaults();
  p.set("count", 1);
  p.set("speed", kTile * kHz);
  Simulation s(scene, p, parseMover("continuous"));
  const auto find = [&](std::size_t body, SolidAct act) -> const SolidContact* {
    for (const SolidContact& c : s.solidContacts())
      if (c.body == body && c.act == act) return &c;
    return nullptr;
  };
  EXPECT_TRUE(s.solidContacts().empty());  // nothing has moved yet
  s.tick();
  for (const std::size_t rider : {0u, 1u}) {
    const SolidContact* c = find(rider, SolidAct::carried);
    ASSERT_NE(c, nullptr) << rider;
    EXPECT_EQ(c->solid, 2u);
    EXPECT_EQ(c->to.y, c->from.y - kTile);  // lifted with the lift, 16 px
  }
  const std::vector<SolidContact> first(s.solidContacts().begin(), s.solidContacts().end());
  bool squished = false, pushed = false;
  for (int t = 1; t < 6; ++t) {
    s.tick();
    squished = squished || find(0, SolidAct::squished) || find(1, SolidAct::squished);
    pushed = pushed || find(6, SolidAct::pushed);
  }
  EXPECT_TRUE(squished);  // the riders pressed against the ceiling
  EXPECT_TRUE(pushed);    // the crowd's first in the door's way
  s.seek(1);
  ASSERT_EQ(s.solidContacts().size(), first.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(s.solidContacts()[i].body, first[i].body);
    EXPECT_EQ(s.solidContacts()[i].act, first[i].act);
    EXPECT_EQ(s.solidContacts()[i].to, first[i].to);
  }
  // The naive control moves no solid: nothing to say.
  p.set("carry", 0);
  Simulation naive(scene, p, parseMover("continuous"));
  for (int t = 0; t < 6; ++t) {
    naive.tick();
    EXPECT_TRUE(naive.solidContacts().empty());
  }
}

TEST(LiftCrush, TheSameTicksGiveTheSameHash) {
  const SceneDef& scene = findScene("lift-crush");
  Simulation a(scene, scene.defaults(), parseMover("continuous"));
  Simulation b(scene, scene.defaults(), parseMover("continuous"));
  for (int t = 0; t < 100; ++t) {
    a.tick();
    b.tick();
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_EQ(a.world().stateHash(), b.world().stateHash());
}

TEST(LiftCrush, BodiesLargerThanATileAreRefusedNamingTheSize) {
  const SceneDef& scene = findScene("lift-crush");
  Params p = scene.defaults();
  p.set("size", 20);
  try {
    Simulation s(scene, p, parseMover("continuous"));
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("size 20"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tv::sim
