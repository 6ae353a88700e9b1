// Tiled maps as levels: every way Tiled writes tile data gives the same solids; solidity comes
// from the layer, the tileset's tiles, the object or the command line; objects of class player,
// walker, bullet and spawner become bodies that walk on and are fired at the level.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "map_builder.hpp"
#include "tv/error.hpp"
#include "tv/level/level.hpp"
#include "tv/level/tiled.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::level {
namespace {

using namespace tv::level::test;

std::vector<Rect> solidsOf(const Level& lv) {
  std::vector<Rect> out;
  for (const sim::Solid& s : lv.solids) out.push_back(s.rect);
  return out;
}

// 4×3 tiles of 16 px; gid 1 (tile 0) floats, gid 2 (tile 1) is the floor:
//   . 1 . .        y = 0
//   . . . .        y = 16
//   2 2 2 2        y = 32
const std::vector<std::uint32_t> kGids = {0, 1, 0, 0, 0, 0, 0, 0, 2, 2, 2, 2};
const std::vector<Rect> kAllTiles = {
    {16, 0, 16, 16}, {0, 32, 16, 16}, {16, 32, 16, 16}, {32, 32, 16, 16}, {48, 32, 16, 16}};
const std::vector<Rect> kFloorOnly = {
    {0, 32, 16, 16}, {16, 32, 16, 16}, {32, 32, 16, 16}, {48, 32, 16, 16}};

class TileEncodings : public ::testing::TestWithParam<const char*> {};

TEST_P(TileEncodings, ACollidableLayerMakesEveryTileSolidHoweverItsDataIsWritten) {
  const std::string text =
      map(4, 3, tileLayer("ground", 4, 3, tileData(kGids, GetParam()), collidable()));
  EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj")), kAllTiles);
}

TEST_P(TileEncodings, FlipFlagsAreMaskedOff) {
  // The top four bits flip a tile; the tile (and its collidable property) stays the same.
  std::vector<std::uint32_t> gids = kGids;
  gids[8] |= 0x80000000u;   // horizontal
  gids[9] |= 0x40000000u;   // vertical
  gids[10] |= 0x20000000u;  // diagonal
  gids[11] |= 0xF0000000u;
  const std::string text =
      map(4, 3, tileLayer("ground", 4, 3, tileData(gids, GetParam())), tileset("1"));
  EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj")), kFloorOnly);
}

INSTANTIATE_TEST_SUITE_P(Tiled, TileEncodings, ::testing::Values("csv", "base64", "zlib", "gzip"));

TEST(Tiled, TilesetTilePropertiesMakeOnlyThoseTilesSolid) {
  // STI's convention: tile 1 (gid 2) has collidable = true; the layer has no property.
  const std::string text =
      map(4, 3, tileLayer("ground", 4, 3, tileData(kGids, "csv")), tileset("1"));
  EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj")), kFloorOnly);
}

TEST(Tiled, ALayerNamedOnTheCommandLineIsSolidAndWithoutItNothingIs) {
  const std::string text = map(4, 3, tileLayer("ground", 4, 3, tileData(kGids, "csv")));
  TiledOptions named;
  named.solidLayers = {"ground"};
  EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj", named)), kAllTiles);
  TiledOptions typo;
  typo.solidLayers = {"grond"};
  EXPECT_THROW((void)parseTiledMap(text, "m.tmj", typo), Error) << "a layer name that is not there";
  const Level plain = parseTiledMap(text, "m.tmj");
  EXPECT_TRUE(plain.solids.empty());
  ASSERT_FALSE(plain.notes.empty());
  EXPECT_NE(plain.notes[0].find("nothing is solid"), std::string::npos) << plain.notes[0];
}

TEST(Tiled, ACollidableFalseLayerStillHonoursItsTilesProperties) {
  const std::string text =
      map(4, 3, tileLayer("ground", 4, 3, tileData(kGids, "csv"), collidable(false)), tileset("1"));
  EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj")), kFloorOnly);
}

TEST(Tiled, InfiniteMapsReadEveryChunkAtItsOwnPlace) {
  // Two 4×1 chunks, one left of the origin: tiles at x = -16 and x = 0 and 48, row 2.
  for (const char* format : {"csv", "zlib"}) {
    const std::vector<std::uint32_t> left = {0, 0, 0, 3}, right = {3, 0, 0, 3};
    std::string chunk = [&](const std::vector<std::uint32_t>& g, int x) {
      std::string data = tileData(g, format);
      if (std::string(format) != "csv")
        data = "\"data\"" + data.substr(data.find(", \"data\"") + 8);
      return R"({"x": )" + std::to_string(x) + R"(, "y": 2, "width": 4, "height": 1, )" + data +
             "}";
    }(left, -4) + "," + [&](const std::vector<std::uint32_t>& g, int x) {
      std::string data = tileData(g, format);
      if (std::string(format) != "csv")
        data = "\"data\"" + data.substr(data.find(", \"data\"") + 8);
      return R"({"x": )" + std::to_string(x) + R"(, "y": 2, "width": 4, "height": 1, )" + data +
             "}";
    }(right, 0);
    const std::string encoding =
        std::string(format) == "csv" ? "" : R"("encoding": "base64", "compression": "zlib", )";
    const std::string layer = R"({"type": "tilelayer", "name": "g", )" + encoding +
                              R"("chunks": [)" + chunk + "], " + collidable() + "}";
    std::string text = map(0, 0, layer);
    text.replace(text.find("\"infinite\": false"), 17, "\"infinite\": true");
    const std::vector<Rect> expected = {{-16, 32, 16, 16}, {0, 32, 16, 16}, {48, 32, 16, 16}};
    EXPECT_EQ(solidsOf(parseTiledMap(text, "m.tmj")), expected) << format;
  }
}

TEST(Tiled, LayerAndGroupOffsetsMoveTheirTiles) {
  const std::string inner =
      tileLayer("ground", 4, 3, tileData(kGids, "csv"), collidable() + R"(, "offsetx": 3)");
  const std::string group =
      R"({"type": "group", "name": "g", "offsety": -8, "layers": [)" + inner + "]}";
  const std::vector<Rect> got = solidsOf(parseTiledMap(map(4, 3, group), "m.tmj"));
  ASSERT_EQ(got.size(), kAllTiles.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i], (Rect{kAllTiles[i].x + 3, kAllTiles[i].y - 8, 16, 16}));
  }
}

// An object layer (Tiled's pixel coordinates):
//   +-------+ wall: collidable layer                  [tile object]: its y is its bottom
//   |       |            a collidable object in a plain layer; a plain object is ignored
const std::string kObjects = R"(
  {"type": "objectgroup", "name": "walls", )" +
                             collidable() + R"(, "objects": [
    {"id": 1, "x": 0, "y": 0, "width": 64, "height": 8},
    {"id": 2, "gid": 2, "x": 100, "y": 50, "width": 16, "height": 16}]},
  {"type": "objectgroup", "name": "decor", "objects": [
    {"id": 3, "x": 10, "y": 20, "width": 5, "height": 6, )" +
                             collidable() + R"(},
    {"id": 4, "x": 30, "y": 20, "width": 5, "height": 6},
    {"id": 5, "x": 30, "y": 20, "ellipse": true, "width": 5, "height": 6}]})";

TEST(Tiled, ObjectRectanglesAreSolidByLayerOrByTheirOwnProperty) {
  const std::vector<Rect> expected = {{0, 0, 64, 8}, {100, 34, 16, 16}, {10, 20, 5, 6}};
  EXPECT_EQ(solidsOf(parseTiledMap(map(10, 10, kObjects), "m.tmj")), expected);
}

std::string object(const std::string& cls, const std::string& geometry, const std::string& props) {
  return R"({"id": 9, "type": ")" + cls + "\", " + geometry + R"(, "properties": [)" + props + "]}";
}

std::string prop(const std::string& name, const std::string& type, const std::string& value) {
  return R"({"name": ")" + name + R"(", "type": ")" + type + R"(", "value": )" + value + "}";
}

TEST(Tiled, ClassedObjectsBecomeBodiesWithTheirProperties) {
  const std::string layer =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      object("player", R"("x": 40, "y": 100, "point": true)",
             prop("speed", "float", "90") + "," + prop("jump", "float", "48") + "," +
                 prop("every", "int", "30")) +
      "," +
      object("walker", R"("x": 80, "y": 88, "width": 12, "height": 12)",
             prop("direction", "string", "\"left\"")) +
      "," +
      object("bullet", R"("x": 8, "y": 60, "width": 4, "height": 4)",
             prop("speed", "float", "1920") + "," + prop("angle", "float", "90")) +
      "," +
      object("spawner", R"("x": 200, "y": 0, "width": 4, "height": 30)",
             prop("count", "int", "3") + "," + prop("speed", "float", "600") + "," +
                 prop("angle", "float", "180")) +
      "]}";
  // Class in Tiled 1.9's "class" member works the same as "type".
  std::string text = map(20, 10, layer);
  const Level lv = parseTiledMap(text, "m.tmj");
  ASSERT_EQ(lv.bodies.size(), 6u);
  const LevelBody& player = lv.bodies[0];
  EXPECT_EQ(player.motion, Motion::player);
  EXPECT_EQ(player.body.rect, (Rect{34, 88, 12, 12})) << "a point player stands on its point";
  EXPECT_EQ(player.speed, 90.0);
  EXPECT_EQ(player.jump.every, 30);
  EXPECT_DOUBLE_EQ(player.jump.speed, std::sqrt(2.0 * 1800.0 * 48.0)) << "jump height 48 px";
  const LevelBody& walker = lv.bodies[1];
  EXPECT_EQ(walker.motion, Motion::walker);
  EXPECT_TRUE(walker.facingLeft);
  EXPECT_TRUE(walker.body.falls);
  const LevelBody& bullet = lv.bodies[2];
  EXPECT_EQ(bullet.motion, Motion::bullet);
  EXPECT_NEAR(bullet.body.velocity.x, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(bullet.body.velocity.y, 1920.0) << "angle 90: down (Tiled's y points down)";
  for (int k = 0; k < 3; ++k) {
    const sim::Body& b = lv.bodies[3 + static_cast<std::size_t>(k)].body;
    // Three lanes at 1/6, 3/6, 5/6 of the spawner's 30 px height, centred on its 4 px width.
    EXPECT_EQ(b.rect, (Rect{200, 5.0 + 10.0 * k - 2.0, 4, 4})) << k;
    EXPECT_DOUBLE_EQ(b.velocity.x, -600.0);
  }
}

std::string named(const std::string& name, const std::string& cls, const std::string& geometry,
                  const std::string& props) {
  return R"({"id": 9, "name": ")" + name + R"(", "type": ")" + cls + "\", " + geometry +
         R"(, "properties": [)" + props + "]}";
}

// The tools call things what the map calls them: an object's name is its body's or solid's
// name ("Block 12"); a spawner's bullets are its name and their number.
TEST(Tiled, ObjectNamesAreWhatTheToolsCallTheirBodiesAndSolids) {
  const std::string layer =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      named("Hero", "player", R"("x": 40, "y": 100, "point": true)", "") + "," +
      named("Block 12", "", R"("x": 100, "y": 34, "width": 16, "height": 16)",
            prop("collidable", "bool", "true")) +
      "," +
      named("turret", "spawner", R"("x": 200, "y": 0, "width": 4, "height": 30)",
            prop("count", "int", "2")) +
      "]}";
  const Level lv = parseTiledMap(map(20, 10, layer), "m.tmj");
  ASSERT_EQ(lv.bodies.size(), 3u);
  EXPECT_EQ(lv.bodies[0].name, "Hero");
  EXPECT_EQ(lv.bodies[1].name, "turret 0");
  EXPECT_EQ(lv.bodies[2].name, "turret 1");
  ASSERT_EQ(lv.solids.size(), 1u);
  ASSERT_EQ(lv.solidNames.size(), 1u);
  EXPECT_EQ(lv.solidNames[0], "Block 12");
  // And they reach the simulation the tools run.
  const sim::SceneDef scene = makeScene(lv);
  const sim::Simulation sim(scene, scene.defaults(), MoverSpec{});
  EXPECT_EQ(sim.bodyName(0), "Hero");
  EXPECT_EQ(sim.solidName(0), "Block 12");
  EXPECT_EQ(sim.solidOf(sim.world().queryRect({100, 34, 16, 16}).front()), std::size_t{0});
}

// An object of a class the loader makes nothing of is not dropped in silence: a note names the
// class, how many, and the first one.
TEST(Tiled, AnObjectOfAnUnknownClassIsNamedInANote) {
  const std::string layer =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      named("gold", "coin", R"("x": 10, "y": 20, "width": 4, "height": 4)", "") + "," +
      named("silver", "coin", R"("x": 30, "y": 20, "width": 4, "height": 4)", "") + "]}";
  const Level lv = parseTiledMap(map(20, 10, layer), "m.tmj");
  EXPECT_TRUE(lv.bodies.empty());
  bool said = false;
  for (const std::string& n : lv.notes) {
    if (n.find("2 objects of class 'coin' ignored") != std::string::npos &&
        n.find("'gold' at (10, 20)") != std::string::npos)
      said = true;
  }
  EXPECT_TRUE(said) << (lv.notes.empty() ? std::string("no notes") : lv.notes.front());
}

TEST(Tiled, KnownClassesLeaveNoSuchNote) {  // the negative control
  const std::string layer =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      named("Hero", "player", R"("x": 40, "y": 100, "point": true)", "") + "]}";
  const Level lv = parseTiledMap(map(20, 10, layer), "m.tmj");
  for (const std::string& n : lv.notes) EXPECT_EQ(n.find("ignored"), std::string::npos) << n;
}

// A level to walk on and shoot at: a floor of 20 tiles with a wall at each end, a walker, and a
// spawner firing 2×2 bullets at the right wall at 7680 px/s (two tiles a tick).
//   |#                    #|
//   |#  w          >>>>   #|
//   |######################|
std::string arena() {
  std::vector<std::uint32_t> gids(22 * 6, 0);
  for (int x = 0; x < 22; ++x) gids[5 * 22 + static_cast<std::size_t>(x)] = 1;
  for (int y = 0; y < 6; ++y)
    gids[static_cast<std::size_t>(y) * 22] = gids[static_cast<std::size_t>(y) * 22 + 21] = 1;
  const std::string actors =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      object("walker", R"("x": 40, "y": 80, "point": true)", prop("speed", "float", "120")) + "," +
      object("spawner", R"("x": 200, "y": 20, "width": 4, "height": 56)",
             prop("count", "int", "10") + "," + prop("speed", "float", "7680") + "," +
                 prop("size", "float", "2")) +
      "]}";
  return map(22, 6,
             tileLayer("ground", 22, 6, tileData(gids, "zlib"), collidable()) + "," + actors);
}

TEST(Tiled, AWalkerWalksTheFloorAndBulletsStopAtTheWall) {
  const sim::SceneDef scene = makeScene(parseTiledMap(arena(), "arena.tmj"));
  sim::Simulation s(scene, scene.defaults(), parseMover("continuous"));
  double minX = 1e9, maxX = -1e9;
  for (int t = 0; t < 600; ++t) {
    s.tick();
    const Rect w = s.bodies()[0].rect;
    if (t > 30) {
      EXPECT_EQ(w.bottom(), 80.0) << "tick " << t << ": the walker stands on the floor";
    }
    minX = std::min(minX, w.x), maxX = std::max(maxX, w.right());
  }
  EXPECT_EQ(minX, 16.0) << "it walked to the left wall";
  EXPECT_EQ(maxX, 336.0) << "and to the right wall";
  EXPECT_EQ(s.counters().hits, 10u);
  EXPECT_EQ(s.counters().tunnelled, 0u);
  EXPECT_EQ(s.counters().overlaps, 0u);
}

TEST(Tiled, NegativeControlTheDiscreteMoverTunnelsThroughTheSameWall) {
  const sim::SceneDef scene = makeScene(parseTiledMap(arena(), "arena.tmj"));
  sim::Simulation s(scene, scene.defaults(), parseMover("discrete"));
  s.run(60);
  EXPECT_GT(s.counters().tunnelled, 0u) << "128 px a tick through a 16 px wall";
}

// One-way tiles: a layer (or a tileset tile, or an object) with the bool property `oneway` is
// solid from above only. A player on the floor jumps every 40 ticks, 5 tiles high, under a ledge
// 3 tiles above the floor:
//   y  48 . . . . . .
//   y  64 . = = = = .      ledge: layer "ledges", oneway = true (row 4)
//   y  80 . . . . . .
//   y  96 . . . . . .
//   y 112 # # # # # #      floor: layer "ground", collidable (row 7)
//           P              player at x 36, standing on the floor
std::string ledgeMap(const std::string& ledgeProperty) {
  std::vector<std::uint32_t> floor(6 * 8, 0), ledge(6 * 8, 0);
  for (int x = 0; x < 6; ++x) floor[7 * 6 + static_cast<std::size_t>(x)] = 1;
  for (int x = 1; x < 5; ++x) ledge[4 * 6 + static_cast<std::size_t>(x)] = 1;
  const std::string actors =
      R"({"type": "objectgroup", "name": "actors", "objects": [)" +
      object("player", R"("x": 42, "y": 112, "point": true)",
             prop("speed", "float", "0") + "," + prop("jump", "float", "80") + "," +
                 prop("every", "int", "40")) +
      "]}";
  return map(6, 8,
             tileLayer("ground", 6, 8, tileData(floor, "csv"), collidable()) + "," +
                 tileLayer("ledges", 6, 8, tileData(ledge, "csv"),
                           R"("properties": [{"name": ")" + ledgeProperty +
                               R"(", "type": "bool", "value": true}])") +
                 "," + actors);
}

TEST(Tiled, AOneWayLayerIsJumpedUpThroughAndStoodOn) {
  const Level lv = parseTiledMap(ledgeMap("oneway"), "ledge.tmj");
  int oneWay = 0;
  for (const sim::Solid& s : lv.solids) oneWay += s.oneWay ? 1 : 0;
  EXPECT_EQ(oneWay, 4) << "the four ledge tiles, and not the floor";
  const sim::SceneDef scene = makeScene(lv);
  for (const std::string_view mover : moverNames()) {
    if (mover == "discrete") continue;  // the negative control of every other test here
    sim::Simulation s(scene, scene.defaults(), parseMover(mover));
    bool onLedge = false;
    for (int t = 0; t < 240; ++t) {
      s.tick();
      const Rect p = s.bodies()[0].rect;
      if (onLedge) {
        // It jumps again from the ledge and comes back to it: never below its top again.
        EXPECT_LE(p.bottom(), 64.0) << mover << " tick " << t << ": fell through the ledge";
      }
      if (p.bottom() == 64.0 && s.bodies()[0].velocity.y == 0.0) onLedge = true;
    }
    EXPECT_TRUE(onLedge) << mover << ": jumped up through the ledge and landed on it";
    EXPECT_EQ(s.counters().overlaps, 0u) << mover << ": inside the ledge is not inside a solid";
  }
}

TEST(Tiled, NegativeControlACollidableLedgeStopsTheSameJump) {
  const sim::SceneDef scene = makeScene(parseTiledMap(ledgeMap("collidable"), "ledge.tmj"));
  sim::Simulation s(scene, scene.defaults(), parseMover("continuous"));
  double highest = 1e9;
  for (int t = 0; t < 240; ++t) {
    s.tick();
    highest = std::min(highest, s.bodies()[0].rect.y);
  }
  EXPECT_EQ(highest, 80.0) << "its head stops under the ledge (bottom of row 4)";
}

}  // namespace
}  // namespace tv::level
