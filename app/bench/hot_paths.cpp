#include "hot_paths.hpp"

#include "tv/sweep.hpp"

namespace tv::bench {

namespace {

// SplitMix64, so the map is the same on every standard library.
double uniform(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

}  // namespace

TileMap::TileMap(int sideTiles, std::uint64_t seed) : side(sideTiles) {
  std::uint64_t s = seed;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const Rect r{x * 16.0, y * 16.0, 16, 16};
      if (uniform(s) < 0.3) {
        world.add(r);
      } else {
        free.push_back({r.x + 4, r.y + 4, 8, 8});
      }
    }
  }
}

Corridor::Corridor(Vec2 start, Vec2 move, int side, std::uint64_t seed) : map(side, seed) {
  const Rect r{start.x, start.y, 8, 8};
  goal = start + move;
  std::vector<ItemId> blocking;
  map.world.forEachItem([&](ItemId id, const Rect& tile) {
    if (overlaps(tile, r) || sweepRect(r, goal, tile).kind != SweepKind::miss) {
      blocking.push_back(id);
    }
  });
  for (const ItemId id : blocking) map.world.remove(id);
  mover = map.world.add(r);
}

}  // namespace tv::bench
