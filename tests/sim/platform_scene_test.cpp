// The one-way-rise scene as a table: riders on one-way platforms moving up and down at 1 to 10
// tiles a tick, for every mover, with the platforms as moving solids (carry 1) and, as the
// negative control, teleported by the rules with the rider given the platform's velocity and the
// bump-game one-way filter (carry 0). Counted: drops (a rider below its platform's top), pops
// (above it, not on it), overlaps (inside it), squishes.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

constexpr std::uint64_t kTicks = 240;  // 20 turns of each platform at the default period

Counters run(std::string_view mover, bool carry, std::uint64_t ticks = kTicks) {
  const SceneDef& scene = findScene("one-way-rise");
  Params p = scene.defaults();
  p.set("carry", carry ? 1 : 0);
  Simulation s(scene, p, parseMover(mover));
  for (std::uint64_t t = 0; t < ticks; ++t) s.tick();
  return s.counters();
}

TEST(OneWayRise, EveryMoverKeepsEveryRiderOnItsPlatformAtOneToTenTilesATick) {
  for (const std::string_view m : moverNames()) {
    const Counters c = run(m, true);
    EXPECT_EQ(c.drops, 0u) << m;
    EXPECT_EQ(c.pops, 0u) << m;
    EXPECT_EQ(c.overlaps, 0u) << m;
    EXPECT_EQ(c.squishes, 0u) << m;
    EXPECT_GT(c.moves, 0u) << m;
  }
}

TEST(OneWayRiseNegativeControl, TeleportingThePlatformsDropsEveryRiderWithEveryMover) {
  // The rider follows its platform's velocity plus a tick of gravity, so it ends a little below
  // a rising platform's top; next tick it is not above it and the one-way filter lets it fall
  // (Godot's CharacterBody2D on a rising one-way platform, its issue #9399). Every one of the
  // 10 riders, at every speed from 1 to 10 tiles a tick, with every mover.
  for (const std::string_view m : moverNames()) {
    const Counters c = run(m, false);
    EXPECT_GE(c.drops, 10u) << m;
    EXPECT_GT(c.overlaps, 0u) << m;
  }
}

TEST(OneWayRise, TheSameTicksGiveTheSameHash) {
  const SceneDef& scene = findScene("one-way-rise");
  Simulation a(scene, scene.defaults(), parseMover("continuous"));
  Simulation b(scene, scene.defaults(), parseMover("continuous"));
  for (int t = 0; t < 100; ++t) {
    a.tick();
    b.tick();
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_EQ(a.world().stateHash(), b.world().stateHash());
}

}  // namespace
}  // namespace tv::sim
