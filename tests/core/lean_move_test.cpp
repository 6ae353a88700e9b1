// Specification of the lean move: a move whose bounding box meets nothing the filter does not
// ignore skips the legs, responses and exact sweeps, and ends exactly where the full path ends.
// A traced move always takes the full path, so tracing is the reference here.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

// SplitMix64, so the scene is the same on every standard library.
struct Rng {
  std::uint64_t s;
  double uniform() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
};

struct Scene {
  World world{32};
  std::vector<ItemId> movers;
  std::vector<Vec2> velocity;
  std::uint32_t firstMover = 0;
  explicit Scene(std::uint64_t seed) {
    Rng rng{seed};
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x)
        if (x == 0 || y == 0 || x == 39 || y == 39 || rng.uniform() < 0.25)
          world.add({x * 16.0, y * 16.0, 16, 16});
    firstMover = static_cast<std::uint32_t>(world.count());
    while (movers.size() < 300) {
      const Rect r{rng.uniform(16, 616), rng.uniform(16, 616), 8, 8};
      if (world.anyOverlap(r)) continue;
      movers.push_back(world.add(r));
      velocity.push_back({rng.uniform(-4, 4), rng.uniform(-4, 4)});
    }
  }
};

// Two identical scenes, one moved traced (the full path every time), one untraced (the lean
// path wherever it applies), with movers that ignore each other and movers that do not: the
// same positions and collisions bit for bit, tick after tick.
TEST(LeanMove, EndsExactlyWhereTheFullPathEnds) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out: no reference";
  for (const bool moversMeet : {false, true}) {
    Scene lean(11), full(11);
    const std::uint32_t first = lean.firstMover;
    const auto filter = [&](ItemId, ItemId other) {
      return !moversMeet && other.index >= first ? response::ignore : response::slide;
    };
    std::size_t collisions = 0;
    for (int tick = 0; tick < 60; ++tick) {
      for (std::size_t i = 0; i < lean.movers.size(); ++i) {
        MoveTrace trace;
        MoveOptions traced;
        traced.trace = &trace;
        const Vec2 goal = lean.world.rect(lean.movers[i]).position() + lean.velocity[i];
        const MoveResult a = lean.world.move(lean.movers[i], goal, filter);
        const std::vector<Collision> ca(a.collisions.begin(), a.collisions.end());
        const MoveResult b = full.world.move(full.movers[i], goal, filter, traced);
        ASSERT_EQ(a.position, b.position) << "tick " << tick << " mover " << i;
        ASSERT_EQ(ca.size(), b.collisions.size());
        for (std::size_t k = 0; k < ca.size(); ++k) {
          EXPECT_EQ(ca[k].other, b.collisions[k].other);
          EXPECT_EQ(ca[k].ti, b.collisions[k].ti);
        }
        collisions += ca.size();
        for (const Collision& c : ca) {  // turn back from what was hit
          if (c.normal.x != 0) lean.velocity[i].x = -lean.velocity[i].x;
          if (c.normal.y != 0) lean.velocity[i].y = -lean.velocity[i].y;
        }
      }
    }
    EXPECT_EQ(lean.world.stateHash(), full.world.stateHash());
    EXPECT_GT(collisions, 100u);  // the scene does collide: both paths were exercised
  }
}

}  // namespace
}  // namespace tv
