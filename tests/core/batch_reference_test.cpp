// tv::Batch against the all-pairs reference it replaced (batch_reference.cpp): on random scenes
// of movers and tiles — head-on, crossing, crowded, on a dyadic grid so that exact ties in time
// happen — the same positions and the same collisions, bit for bit, in the same order.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "batch_reference.hpp"
#include "tv/batch.hpp"

namespace tv {
namespace {

struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Multiples of 1/4 in [lo, hi): coordinates and moves on a grid, so ties are common.
  double grid(double lo, double hi) { return lo + std::floor((hi - lo) * 4 * uniform()) / 4; }
};

void expectSame(const Collision& a, const Collision& b, const std::string& where) {
  EXPECT_EQ(a.item, b.item) << where;
  EXPECT_EQ(a.other, b.other) << where;
  EXPECT_EQ(a.ti, b.ti) << where;
  EXPECT_EQ(a.normal, b.normal) << where;
  EXPECT_EQ(a.touch, b.touch) << where;
  EXPECT_EQ(a.target, b.target) << where;
  EXPECT_EQ(a.itemRect, b.itemRect) << where;
  EXPECT_EQ(a.otherRect, b.otherRect) << where;
  EXPECT_EQ(a.response, b.response) << where;
  EXPECT_EQ(a.corner, b.corner) << where;
  EXPECT_EQ(a.overlaps, b.overlaps) << where;
}

TEST(BatchReference, MatchesTheAllPairsSearchBitForBitOnRandomScenes) {
  std::size_t events = 0, ties = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    Rng rng{seed};
    World w(16);
    const int tiles = static_cast<int>(rng.next() % 12);
    for (int k = 0; k < tiles; ++k) w.add({rng.grid(-64, 64), rng.grid(-64, 64), 8, 8});
    std::vector<BatchMove> moves;
    const int movers = 2 + static_cast<int>(rng.next() % 40);
    for (int k = 0; k < movers; ++k) {
      const Rect r{rng.grid(-64, 64), rng.grid(-64, 64), rng.grid(1, 8) + 0.25, 4};
      if (w.anyOverlap(r)) continue;
      const ItemId id = w.add(r);
      const double speed = seed % 3 == 0 ? 64 : 24;  // some steps cross the whole scene
      moves.push_back({id, {r.x + rng.grid(-speed, speed), r.y + rng.grid(-speed, speed)}});
    }
    // Each scene under every built-in response, and a filter that makes some pairs ignore
    // each other (one side only, or both).
    for (const ResponseId resp :
         {response::touch, response::slide, response::bounce, response::cross}) {
      const auto filter = [resp](ItemId a, ItemId b) {
        return (a.index + b.index) % 5 == 0 ? response::ignore : resp;
      };
      World mine = w, theirs = w;
      Batch batch;
      batch.step(mine, moves, filter);
      const std::vector<reference::Outcome> ref = reference::batchStep(theirs, moves, filter);
      ASSERT_EQ(batch.size(), ref.size());
      const std::string where =
          "seed " + std::to_string(seed) + " response " + std::to_string(resp);
      for (std::size_t i = 0; i < ref.size(); ++i) {
        const BatchOutcome out = batch.outcome(i);
        EXPECT_EQ(out.position, ref[i].position) << where << " body " << i;
        ASSERT_EQ(out.collisions.size(), ref[i].collisions.size()) << where << " body " << i;
        for (std::size_t k = 0; k < ref[i].collisions.size(); ++k) {
          expectSame(out.collisions[k], ref[i].collisions[k], where);
          ++events;
          // An event at the very instant of the one before it: a tie the order had to break.
          if (out.collisions[k].ti == 0.0) ++ties;
        }
      }
      EXPECT_EQ(mine.stateHash(), theirs.stateHash()) << where;
    }
  }
  EXPECT_GT(events, 1000u) << "the scenes do collide";
  EXPECT_GT(ties, 10u) << "and some events tie in time";
}

}  // namespace
}  // namespace tv
