#pragma once
// Fixtures of the hot paths, shared by tv-microbench (Google Benchmark) and the scale study,
// so both time the same inputs: a tile map like the crowd's, and a corridor cut through it for
// long moves.

#include <vector>

#include "tv/world.hpp"

namespace tv::bench {

/// A square of 16 px tiles, ~30% solid (seeded), in a world of 32 px cells, with the free
/// tiles' centred 8×8 spots listed.
struct TileMap {
  explicit TileMap(int side = 200, std::uint64_t seed = 1);
  World world{32};
  std::vector<Rect> free;  ///< an 8×8 rect centred in each free tile
  int side;
};

/// An 8×8 mover at `start` in a tile map, and the tiles its sweep to `start + move` would meet
/// removed: a corridor exactly as wide as its path, so the move runs its whole length past
/// solid tiles on both sides (they are broad-phase candidates, never hit).
struct Corridor {
  Corridor(Vec2 start, Vec2 move, int side = 256, std::uint64_t seed = 1);
  TileMap map;
  ItemId mover;
  Vec2 goal;
};

}  // namespace tv::bench
