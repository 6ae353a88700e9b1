// levels/meadow.tmj, the sample map, as tv::level reads it — and the LÖVE example
// (examples/love-tiled) reads the same map in Tiled's Lua format the way STI's bump plugin does:
// both must find the same collidable items (its ctest passes --expect-solids with this count).
#include <gtest/gtest.h>

#include <cstddef>

#include "tv/level/level.hpp"
#include "tv/level/tiled.hpp"

namespace tv::level {
namespace {

// The count the LÖVE example is held to (tests/lua/CMakeLists.txt, lua.love.tiled).
constexpr std::size_t kMeadowSolids = 461;

TEST(Meadow, EveryCollidableTileAndPlatformIsOneSolid) {
  const Level lv = loadTiledMap(TV_SOURCE_DIR "/levels/meadow.tmj");
  // Tiles of tileset tiles 0..2 (collidable in the tileset) on the ground layer, one item each,
  // plus the four rectangles of the collidable "platforms" object layer.
  std::size_t platforms = 0;
  for (const sim::Solid& s : lv.solids) platforms += s.rect.w != 16.0 || s.rect.h != 16.0;
  EXPECT_EQ(platforms, 4u);
  EXPECT_EQ(lv.solids.size(), kMeadowSolids);
}

}  // namespace
}  // namespace tv::level
