// Specification of the bump-crowd scene (bump.lua's benchmark): its layout, and movers that
// slide, flip the velocity component of each normal (keeping its magnitude) and never end
// inside a tile — nor, with `meet` 1, inside each other.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/world.hpp"

namespace tv::sim {
namespace {

Params withCount(std::int64_t count, int meet) {
  Params p = findScene("bump-crowd").defaults();
  p.set(param::count, static_cast<double>(count));
  p.set("meet", meet);
  return p;
}

TEST(BumpCrowd, LayoutIsABorderedGridThirtyPercentSolidWithMoversInFreeSpots) {
  const SceneSetup s = findScene("bump-crowd").build(withCount(500, 0));
  const double grid = 125.0 * 125.0;  // 2000 px of 16 px tiles
  EXPECT_GE(static_cast<double>(s.solids.size()), 0.3 * grid);
  EXPECT_LT(static_cast<double>(s.solids.size()), 0.3 * grid + 12);  // the last platform's tail
  ASSERT_EQ(s.bodies.size(), 500u);
  World w(s.cellSize);
  for (const Solid& t : s.solids) w.add(t.rect);
  // The border is closed: every tile of row 0 and column 0 is solid.
  for (int k = 0; k < 125; ++k) {
    EXPECT_FALSE(w.queryPoint({k * 16.0 + 8, 8}).empty()) << k;
    EXPECT_FALSE(w.queryPoint({8, k * 16.0 + 8}).empty()) << k;
  }
  for (const Body& b : s.bodies) {
    EXPECT_FALSE(w.anyOverlap(b.rect));
    const double speed = std::hypot(b.velocity.x, b.velocity.y);
    EXPECT_GE(speed, 30.0 * (1 - 1e-6));
    EXPECT_LE(speed, 240.0 * (1 + 1e-6));
    w.add(b.rect);  // movers do not overlap each other either
  }
}

TEST(BumpCrowd, MoversFlipOnNormalsKeepTheirSpeedsAndNeverEndInsideATile) {
  for (const int meet : {0, 1}) {
    Simulation sim(findScene("bump-crowd"), withCount(300, meet), parseMover("continuous"));
    std::vector<Vec2> start;
    for (const Body& b : sim.bodies()) start.push_back(b.velocity);
    for (int t = 0; t < 240; ++t) sim.tick();
    EXPECT_GT(sim.counters().hits, 300u) << "they do hit the platforms";
    std::size_t flipped = 0;
    for (std::size_t i = 0; i < start.size(); ++i) {
      const Body& b = sim.bodies()[i];
      EXPECT_EQ(std::fabs(b.velocity.x), std::fabs(start[i].x)) << i;
      EXPECT_EQ(std::fabs(b.velocity.y), std::fabs(start[i].y)) << i;
      flipped += b.velocity.x != start[i].x || b.velocity.y != start[i].y;
      const bool inTile = sim.world().anyOverlap(b.rect, b.item, [&](ItemId, ItemId other) {
        return other.index < sim.bodies().front().item.index ? response::touch : response::ignore;
      });
      EXPECT_FALSE(inTile) << i;
      if (meet == 1) {
        const bool inMover = sim.world().anyOverlap(b.rect, b.item, [&](ItemId, ItemId other) {
          return other.index >= sim.bodies().front().item.index ? response::touch
                                                                : response::ignore;
        });
        EXPECT_FALSE(inMover) << i;
      }
    }
    EXPECT_GT(flipped, 100u);
  }
}

}  // namespace
}  // namespace tv::sim
