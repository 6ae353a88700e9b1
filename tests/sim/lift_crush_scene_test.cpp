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
