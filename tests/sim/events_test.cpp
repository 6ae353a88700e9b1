// What the rules counted, move by move: the tools go straight to the body that failed and name
// what it passed through, instead of a tick and a count.
#include <gtest/gtest.h>

#include <algorithm>

#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

// bullets-wall at its defaults: 2 px bullets at 1920 px/s (32 px a tick) into a 16 px wall.
//
//    [b]--32px-->  |####|  [b]        discrete: the goal is past the wall, nothing overlaps
//                  |####|             there, the bullet is put at the goal: tunnelled.
Simulation bulletsWall(MoverKind kind) {
  const SceneDef& scene = findScene("bullets-wall");
  return Simulation(scene, scene.defaults(), MoverSpec{.kind = kind});
}

TEST(Events, NameTheBodyThatTunnelledAndTheWallItPassedThrough) {
  Simulation s = bulletsWall(MoverKind::discrete);
  std::vector<TickEvent> seen;
  for (int t = 0; t < 4 && seen.empty(); ++t) {
    s.tick();
    for (const TickEvent& e : s.events()) {
      if (e.what == Counted::tunnelled) seen.push_back(e);
    }
  }
  ASSERT_FALSE(seen.empty());
  const TickEvent& e = seen.front();
  EXPECT_EQ(e.tick, s.ticks());
  ASSERT_GE(e.body, 0);
  ASSERT_TRUE(e.other.valid());
  // The other is a solid: no body has that item.
  const auto bodies = s.bodies();
  EXPECT_TRUE(std::none_of(bodies.begin(), bodies.end(),
                           [&](const Body& b) { return b.item == e.other; }));
  // It lies between where the bullet started the tick and where it ended.
  const Rect wall = s.world().rect(e.other);
  const Body& b = bodies[static_cast<std::size_t>(e.body)];
  EXPECT_GE(b.rect.x, wall.right());
  // As many events as the counter rose.
  std::uint64_t counted = 0;
  for (const TickEvent& x : s.events()) {
    if (x.what == Counted::tunnelled) counted += x.count;
  }
  EXPECT_GT(counted, 0u);
}

TEST(Events, AnExactMoverCountsNoTunnel) {  // the negative control
  Simulation s = bulletsWall(MoverKind::continuous);
  for (int t = 0; t < 4; ++t) {
    s.tick();
    for (const TickEvent& e : s.events()) EXPECT_NE(e.what, Counted::tunnelled) << e.body;
  }
}

TEST(Events, ASeekForgetsTheLastTicksEvents) {
  Simulation s = bulletsWall(MoverKind::discrete);
  s.tick();
  s.tick();
  ASSERT_FALSE(s.events().empty());
  s.seek(1);
  EXPECT_TRUE(s.events().empty());
}

TEST(Events, MovesWithManyCollisionsAreListedOnlyWhenAsked) {
  // bounce-gap: a ball bounces between the slot's walls several times within one tick.
  const SceneDef& scene = findScene("bounce-gap");
  Simulation s(scene, scene.defaults(), MoverSpec{.kind = MoverKind::continuous});
  s.tick();
  EXPECT_TRUE(std::none_of(s.events().begin(), s.events().end(),
                           [](const TickEvent& e) { return e.what == Counted::manyCollisions; }));
  Simulation asked(scene, scene.defaults(), MoverSpec{.kind = MoverKind::continuous});
  asked.setManyCollisions(2);
  asked.tick();
  const auto many = std::find_if(asked.events().begin(), asked.events().end(),
                                 [](const TickEvent& e) { return e.what == Counted::manyCollisions; });
  ASSERT_NE(many, asked.events().end());
  EXPECT_GT(many->collisions, 2u);
  // Counting changes nothing: the same state either way.
  EXPECT_EQ(asked.stateHash(), s.stateHash());
}

}  // namespace
}  // namespace tv::sim
