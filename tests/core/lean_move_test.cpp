// Specification of the lean move: a move whose bounding box meets nothing the filter does not
// ignore skips the legs, responses and exact sweeps, and ends exactly where the reference ends
// (move_reference.hpp: every leg against every item), asking the filter what it asks.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "move_reference.hpp"
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

// Movers that ignore each other and movers that do not, move after move: the same positions,
// collisions and filter questions as the reference, bit for bit, tick after tick.
TEST(LeanMove, EndsExactlyWhereTheReferenceEnds) {
  const std::vector<ResponseFn> fns = {&touchResponse, &crossResponse, &slideResponse,
                                       &bounceResponse, &onewayResponse};
  for (const bool moversMeet : {false, true}) {
    Scene scene(11);
    const std::uint32_t first = scene.firstMover;
    std::vector<ItemId> asked, refAsked;
    const auto answer = [&](ItemId other) {
      return !moversMeet && other.index >= first ? response::ignore : response::slide;
    };
    const auto filter = [&](ItemId, ItemId other) {
      asked.push_back(other);
      return answer(other);
    };
    const auto refFilter = [&](ItemId, ItemId other) {
      refAsked.push_back(other);
      return answer(other);
    };
    std::size_t collisions = 0, free = 0;
    for (int tick = 0; tick < 60; ++tick) {
      for (std::size_t i = 0; i < scene.movers.size(); ++i) {
        const ItemId id = scene.movers[i];
        const Rect from = scene.world.rect(id);
        const Vec2 goal = from.position() + scene.velocity[i];
        asked.clear();
        refAsked.clear();
        const test::ReferenceResult ref =
            test::referenceMove(scene.world, id, from, goal, Filter(refFilter), 64, fns);
        const MoveResult a = scene.world.move(id, goal, filter);
        ASSERT_EQ(a.position, ref.position) << "tick " << tick << " mover " << i;
        ASSERT_EQ(a.collisions.size(), ref.collisions.size());
        for (std::size_t k = 0; k < ref.collisions.size(); ++k) {
          EXPECT_EQ(a.collisions[k].other, ref.collisions[k].other);
          EXPECT_EQ(a.collisions[k].ti, ref.collisions[k].ti);
        }
        ASSERT_EQ(asked, refAsked) << "tick " << tick << " mover " << i;
        collisions += a.collisions.size();
        free += a.collisions.empty() ? 1u : 0u;
        for (const Collision& c : a.collisions) {  // turn back from what was hit
          if (c.normal.x != 0) scene.velocity[i].x = -scene.velocity[i].x;
          if (c.normal.y != 0) scene.velocity[i].y = -scene.velocity[i].y;
        }
      }
    }
    EXPECT_GT(collisions, 100u);  // the scene does collide: both kinds of move were made
    EXPECT_GT(free, 1000u);
  }
}

}  // namespace
}  // namespace tv
