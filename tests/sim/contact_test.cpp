// Contact scenes: resting bodies stay exactly put, walkers cross seams, the player plays.
#include <gtest/gtest.h>

#include <string>

#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

// Movers whose contact is exact from any starting position. The pixel mover moves whole pixels
// from where it starts, so from a fractional start it rests up to a pixel short (it is exact on
// integer scenes only); the discrete ones push out by overlap depth.
bool isExact(std::string_view m) {
  return m != "discrete" && m != "substep-discrete" && m != "pixel";
}

// [SECTION] rest-wall -----------------------------------------------------------------------------
//
//                 |##|  x = 144 (9 tiles)
//        [body]-> |##|
//   ##############|##|  floor top: the body's bottom rests on it
//
// Pushed right and pulled down every tick, the body ends with its right edge on the wall's edge
// and its bottom on the floor's, bit for bit, and never moves again.

TEST(RestWall, APressedBodyRestsExactlyOnTheWallAndNeverJitters) {
  for (const std::string_view m : moverNames()) {
    Simulation sim("rest-wall", m);
    for (int t = 0; t < 240; ++t) sim.tick();
    EXPECT_EQ(sim.counters().jitter, 0u) << m;
    const double tile = sim.params().get(param::tile);
    for (const Body& b : sim.bodies()) {
      EXPECT_NE(b.state & 1, 0) << m << ": pressed against the wall";
      if (isExact(m)) {
        EXPECT_EQ(b.rect.right(), 9 * tile) << m;
        EXPECT_EQ(std::fmod(b.rect.bottom(), tile), 0.0) << m << ": on the floor";
      }
    }
  }
}

// [SECTION] rest-floor ----------------------------------------------------------------------------

TEST(RestFloor, LandedBodiesStayExactlyOnTheFloor) {
  for (const std::string_view m : moverNames()) {
    Simulation sim("rest-floor", m);
    for (int t = 0; t < 240; ++t) sim.tick();
    EXPECT_EQ(sim.counters().landings, sim.bodies().size()) << m;
    EXPECT_EQ(sim.counters().jitter, 0u) << m;
    const double floorTop = sim.solids()[0].rect.y;
    for (const Body& b : sim.bodies()) {
      if (isExact(m)) {
        EXPECT_EQ(b.rect.bottom(), floorTop) << m;
      }
    }
  }
}

TEST(RestFloor, StaysPutAGigapixelFromTheOrigin) {
  const SceneDef& scene = findScene("rest-floor");
  Params p = scene.defaults();
  p.set(param::offset, 1e9);
  Simulation sim(scene, p, parseMover("continuous"));
  for (int t = 0; t < 240; ++t) sim.tick();
  EXPECT_EQ(sim.counters().jitter, 0u);
  for (const Body& b : sim.bodies()) EXPECT_EQ(b.rect.bottom(), sim.solids()[0].rect.y);
}

// [SECTION] seam-walk -----------------------------------------------------------------------------
//
//   [walker] ->
//   ####|####|####|####| ... 1000 tiles, 999 seams
//
// Sliding along the floor never meets a tile's side face: no hit with a horizontal normal.
// A teleport that lands a fraction of a pixel past a seam is pushed back out sideways: a snag.

std::uint64_t snags(std::string_view mover, double speed, int ticks) {
  const SceneDef& scene = findScene("seam-walk");
  Params p = scene.defaults();
  p.set(param::speed, speed);
  Simulation sim(scene, p, parseMover(mover));
  for (int t = 0; t < ticks; ++t) sim.tick();
  return sim.counters().snags;
}

TEST(SeamWalk, NoSweptMoverEverSnagsOnASeam) {
  // 8000 ticks: all the way along, off the far wall and back.
  for (const std::string_view m : moverNames()) {
    if (m == "discrete" || m == "substep-discrete") continue;
    for (const double speed : {240.0, 250.0})
      EXPECT_EQ(snags(m, speed, 8000), 0u) << m << " at " << speed;
  }
}

TEST(SeamWalk, TeleportingSnags) {
  EXPECT_GT(snags("discrete", 250, 8000), 0u);  // the negative control
}

// [SECTION] platformer ----------------------------------------------------------------------------

TEST(Platformer, TheScriptedPlayerRunsJumpsAndLandsInsideNoSolid) {
  for (const std::string_view m : moverNames()) {
    Simulation sim("platformer", m);
    std::uint64_t inSolid = 0;
    for (int t = 0; t < 600; ++t) {
      sim.tick();
      for (const Body& b : sim.bodies()) {
        if (sim.world().anyOverlap(b.rect, b.item)) ++inSolid;
      }
    }
    EXPECT_GT(sim.counters().jumps, 3u) << m;
    EXPECT_GT(sim.counters().landings, 3u) << m;
    if (m != "discrete") {
      EXPECT_EQ(inSolid, 0u) << m;
    }
  }
}

}  // namespace
}  // namespace tv::sim
