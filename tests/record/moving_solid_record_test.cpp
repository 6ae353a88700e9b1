// A game that moves solids (tv/solid.hpp) records and replays bit for bit: a solid's move is
// made of World calls (updates of the solid and of bodies put back, moves of the bodies it
// pushes and carries), each recorded as the game made it.

#include <gtest/gtest.h>

#include <optional>
#include <string_view>
#include <vector>

#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/solid.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Vec2;

//   ceiling {0, 0, 96, 8}
//   a lift {0, 100, 48, 8} with two riders rises 7.3 px a frame into the ceiling (squishing
//   them), then sinks; a door {60, 40, 8, 40} pushes a box right into a wall and back.
TEST(MovingSolidRecording, ReplaysBitForBitAndEndsInTheSameState) {
  tv::World world(32);
  world.add({0, 0, 96, 8});
  world.add({140, 0, 8, 160});
  const ItemId lift = world.add({0, 100, 48, 8});
  const ItemId door = world.add({60, 40, 8, 40});
  tv::Recorder rec(tv::RecorderOptions{8});
  world.attach(rec);
  const std::vector<ItemId> bodies{world.add({4, 88, 8, 12}), world.add({30, 90, 10, 10}),
                                   world.add({80, 60, 6, 6})};
  tv::SolidOptions o;
  o.bodies = bodies;
  std::size_t squishes = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const double dy = frame < 30 ? -7.3 : 5.1;
    const tv::Rect l = world.rect(lift);
    squishes += tv::moveSolid(world, lift, {l.x, l.y + dy}, o).squished.size();
    const tv::Rect d = world.rect(door);
    squishes += tv::moveSolid(world, door, {d.x + (frame < 40 ? 3.7 : -6.1), d.y}, o).squished.size();
    rec.frame();
  }
  EXPECT_GT(squishes, 0u) << "the scene must squish, or it tests less than it says";
  const std::uint64_t hash = world.stateHash();
  rec.close();
  tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
  const std::optional<tv::Divergence> div = replay.validate();
  ASSERT_FALSE(div) << div->report();
  EXPECT_EQ(replay.world().stateHash(), hash);
}

// The built-in one-way-rise scene, recorded with every mover: its platforms' moves (tv::moveSolid)
// and the riders' (Mover::move) replay with zero divergences and the same world.
TEST(MovingSolidRecording, TheOneWayRiseSceneReplaysWithEveryMover) {
  const tv::sim::SceneDef& scene = tv::sim::findScene("one-way-rise");
  for (const std::string_view m : tv::moverNames()) {
    tv::sim::Simulation sim(scene, scene.defaults(), tv::parseMover(m));
    tv::Recorder rec(tv::RecorderOptions{16});
    sim.attach(rec);
    for (int t = 0; t < 120; ++t) {
      sim.tick();
      rec.frame();
    }
    EXPECT_EQ(sim.counters().drops + sim.counters().pops, 0u) << m;
    rec.close();
    tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
    const std::optional<tv::Divergence> div = replay.validate();
    ASSERT_FALSE(div) << m << ": " << div->report();
    EXPECT_EQ(replay.world().stateHash(), sim.world().stateHash()) << m;
  }
}

}  // namespace
