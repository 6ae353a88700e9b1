// Malformed and hostile files: each gets a tv::Error naming the file, the JSON path and the
// bad value (or the unsupported feature), and nothing comes back half-loaded. A mutation loop
// over real files checks that no corruption crashes the loaders (run under ASan in the suite).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "map_builder.hpp"
#include "tv/error.hpp"
#include "tv/level/scene_file.hpp"
#include "tv/level/tiled.hpp"
#include "tv/sim/rng.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::level {
namespace {

using namespace tv::level::test;

template <class F>
void expectError(F&& load, std::initializer_list<std::string_view> mentions) {
  try {
    (void)load();
    ADD_FAILURE() << "loaded; expected an error mentioning " << *mentions.begin();
  } catch (const Error& e) {
    const std::string msg = e.what();
    for (const std::string_view m : mentions) {
      EXPECT_NE(msg.find(m), std::string::npos) << "message \"" << msg << "\" lacks \"" << m << '"';
    }
  }
}

void expectMapError(const std::string& text, std::initializer_list<std::string_view> mentions) {
  expectError([&] { return parseTiledMap(text, "level.tmj"); }, mentions);
}

const std::vector<std::uint32_t> kRow = {1, 1, 1, 1};

TEST(MalformedMap, ABadGidNamesTheLayerTheIndexAndTheValue) {
  std::string data = tileData(kRow, "csv");
  data.replace(data.find("1,1,1"), 5, "1,-5,1");
  expectMapError(
      map(4, 1,
          tileLayer("a", 4, 1, tileData(kRow, "csv")) + "," +
              tileLayer("b", 4, 1, tileData(kRow, "csv")) + "," + tileLayer("c", 4, 1, data)),
      {"level.tmj", "layers[2].data[1]", "-5"});
}

TEST(MalformedMap, AGidOutsideEveryTilesetIsNamed) {
  expectMapError(map(4, 1, tileLayer("a", 4, 1, tileData({1, 99, 1, 1}, "csv"))),
                 {"layers[0].data[1]", "gid 99 is in no tileset", "1 to 16"});
}

TEST(MalformedMap, UnsupportedFeaturesAreNamedAsUnsupported) {
  std::string iso = map(4, 1, tileLayer("a", 4, 1, tileData(kRow, "csv")));
  iso.replace(iso.find("orthogonal"), 10, "isometric");
  expectMapError(iso, {"orientation", "unsupported", "isometric"});
  std::string hex = iso;
  hex.replace(hex.find("isometric"), 9, "hexagonal");
  expectMapError(hex, {"unsupported", "hexagonal"});
  std::string zstd = map(4, 1, tileLayer("a", 4, 1, tileData(kRow, "base64")));
  zstd.replace(zstd.find("\"compression\": \"\""), 17, "\"compression\": \"zstd\"");
  expectMapError(zstd, {"layers[0].compression", "unsupported compression", "zstd"});
  std::string lzma = zstd;
  lzma.replace(lzma.find("zstd"), 4, "lzma");
  expectMapError(lzma, {"unsupported compression", "lzma"});
  expectMapError(map(4, 1,
                     R"({"type": "objectgroup", "name": "o", "objects": [
                   {"id": 1, "x": 0, "y": 0, "width": 8, "height": 8, "ellipse": true, )" +
                         collidable() + "}]}"),
                 {"layers[0].objects[0]", "unsupported", "ellipse"});
  expectMapError(map(4, 1,
                     R"({"type": "objectgroup", "name": "o", "objects": [
                   {"id": 1, "x": 0, "y": 0, "width": 8, "height": 8, "rotation": 30, )" +
                         collidable() + "}]}"),
                 {"layers[0].objects[0].rotation", "rotated", "30"});
  expectMapError(map(4, 1, "", R"({"firstgid": 1, "source": "tiles.tsx"})"),
                 {"tilesets[0].source", "unsupported", "tiles.tsx"});
}

TEST(MalformedMap, DataThatDoesNotMatchTheLayerSizeIsRefused) {
  expectMapError(map(4, 2, tileLayer("a", 4, 2, tileData(kRow, "csv"))),
                 {"layers[0].data", "holds 4 gids", "width × height is 8"});
  expectMapError(map(4, 2, tileLayer("a", 4, 2, tileData(kRow, "base64"))),
                 {"layers[0].data", "holds 16 bytes", "32"});
  expectMapError(map(4, 2, tileLayer("a", 4, 2, tileData(kRow, "zlib"))),
                 {"layers[0].data", "16 bytes", "32"});
  std::string junk = map(4, 1, tileLayer("a", 4, 1, tileData(kRow, "base64")));
  junk.replace(junk.find("AQAAAAEAAAABAAAAAQAAAA=="), 4, "A!AA");
  expectMapError(junk, {"layers[0].data", "not base64", "'!'"});
  std::string corrupt = map(4, 1, tileLayer("a", 4, 1, tileData(kRow, "gzip")));
  corrupt.replace(corrupt.find("H4sI"), 4, "H4sJ");
  expectMapError(corrupt, {"layers[0].data", "gzip"});
}

TEST(MalformedMap, HugeDeclaredSizesAreRefusedBeforeAnythingIsAllocated) {
  // 2^24 × 2^24 tiles declared with a few bytes of zlib data: refused by arithmetic, not by
  // running out of memory (under ASan an attempt to allocate 2^50 bytes would abort).
  const std::string big =
      map(16777216, 16777216, tileLayer("a", 16777216, 16777216, tileData(kRow, "zlib")));
  expectMapError(big, {"layers[0].data", "declares 281474976710656 tiles", "more than"});
  expectMapError(map(4, 1, tileLayer("a", 16777216, 16777216, tileData(kRow, "csv"))),
                 {"layers[0].data", "holds 4 gids"});
  expectMapError(map(4, 1, tileLayer("a", 99999999, 1, tileData(kRow, "csv"))),
                 {"layers[0].width", "99999999"});
}

TEST(MalformedMap, SyntaxErrorsNameTheByte) {
  expectMapError(R"({"type": "map", "orientation": )", {"level.tmj", "byte 32", "not JSON"});
  expectMapError("[1, 2]", {"level.tmj", "expected a Tiled map"});
  expectMapError(R"({"type": "map", "orientation": "orthogonal", "tilewidth": -16})",
                 {"tilewidth", "-16"});
}

void expectSceneError(const std::string& text, std::initializer_list<std::string_view> mentions) {
  expectError([&] { return parseSceneFile(text, "s.json"); }, mentions);
}

std::string scene(const std::string& members) {
  return R"({"format": "tunnelvision-scene", "version": 1)" +
         (members.empty() ? "" : ", " + members) + "}";
}

TEST(MalformedScene, EachBadValueIsNamedByItsPath) {
  expectSceneError(scene(R"("solids": [[0, 0, 16, 16], [0, 0, -16, 16]])"),
                   {"s.json", "solids[1][2]", "-16"});
  expectSceneError(scene(R"("bodies": [{"rect": [0, 0, 8, 8], "motion": "teleport"}])"),
                   {"bodies[0].motion", "teleport", "fly, bullet, walker, player"});
  // The valid responses are listed from the core's one table of built-ins.
  expectSceneError(scene(R"("bodies": [{"rect": [0, 0, 8, 8], "response": "stick"}])"),
                   {"bodies[0].response", "stick", "touch, cross, slide, bounce"});
  expectSceneError(scene(R"("bodies": [{"rect": [0, 0, 8, 8], "velocity": [1e300, 0]}])"),
                   {"bodies[0].velocity", "1e+300"});
  expectSceneError(scene(R"("bodies": [{"rect": [0, 0, 8, 8], "sped": 3}])"),
                   {"bodies[0].sped", "unknown key"});
  expectSceneError(scene(R"("bodies": [{"rect": [0, 0, 8, 8], "motion": "bullet", "speed": 3}])"),
                   {"bodies[0].speed", "walkers and players"});
  expectSceneError(scene(R"("dt": 0)"), {"dt", "(0, 1]", "0"});
  expectSceneError(scene(R"("mover": "warp")"), {"mover", "warp"});
  expectSceneError(scene(R"("rules": "bullets-wall", "params": {"speed": "fast"})"),
                   {"params.speed", "\"fast\""});
  expectSceneError(R"({"format": "tunnelvision-scene", "version": 7})", {"version 7", "newer"});
  expectSceneError(R"({"format": "tiled", "version": 1})", {"format", "tiled"});
  expectSceneError(R"({"version": 1})", {"missing \"format\""});
}

TEST(MalformedScene, RulesAndParametersMustMatchABuiltinScene) {
  expectError(
      [] { return makeScene(parseSceneFile(scene(R"("rules": "warp", "params": {})"), "s.json")); },
      {"s.json", "rules", "warp", "bullets-wall"});
  expectError(
      [] {
        return makeScene(
            parseSceneFile(scene(R"("rules": "crowd", "params": {"speed": 1})"), "s.json"));
      },
      {"s.json", "params", "missing"});
}

TEST(MalformedScene, ABuiltinScenesRulesGetTheBodiesTheyWereBuiltFor) {
  // bullets-enemies pairs body k with body k + 1 and corner-graze aims shot k at tiles[group]:
  // a body more or less, or another group, would send those rules out of bounds.
  const sim::SceneDef& pairs = sim::findScene("bullets-enemies");
  Level lv = exportScene(pairs, pairs.defaults());
  lv.bodies.pop_back();
  const std::string fewer = writeSceneFile(lv);
  expectError([&] { return makeScene(parseSceneFile(fewer, "s.json")); },
              {"s.json", "bodies", "expect 200 bodies", "has 199"});
  const sim::SceneDef& graze = sim::findScene("corner-graze");
  Level regrouped = exportScene(graze, graze.defaults());
  regrouped.bodies[3].body.group = 99999;
  const std::string text = writeSceneFile(regrouped);
  expectError([&] { return makeScene(parseSceneFile(text, "s.json")); },
              {"s.json", "bodies[3].group", "99999"});
}

// [SECTION] mutation loop -------------------------------------------------------------------------

/// Random corruptions of `text`: flipped bytes, deleted and duplicated spans, digits changed to
/// huge or negative numbers. Each must load or throw tv::Error; nothing else (ASan watches).
template <class Load>
int mutate(const std::string& text, std::uint64_t seed, int rounds, Load&& load) {
  sim::Rng rng(seed);
  int errors = 0;
  for (int round = 0; round < rounds; ++round) {
    std::string t = text;
    const int edits = 1 + static_cast<int>(rng.below(4));
    for (int e = 0; e < edits && !t.empty(); ++e) {
      const std::size_t at = rng.below(t.size());
      switch (rng.below(5)) {
        case 0:
          t[at] = static_cast<char>(rng.below(256));
          break;
        case 1:
          t.erase(at, 1 + rng.below(16));
          break;
        case 2:
          t.insert(at, t.substr(at, 1 + rng.below(32)));
          break;
        case 3:
          t.insert(at, rng.below(2) ? "99999999999" : "-1");
          break;
        default:
          t[at] = "[]{},:\"0e-"[rng.below(10)];
          break;
      }
    }
    try {
      (void)load(t);
    } catch (const Error&) {
      ++errors;
    }
  }
  return errors;
}

TEST(Mutation, CorruptedMapsAndSceneFilesLoadOrFailCleanly) {
  std::vector<std::uint32_t> gids(8 * 4, 0);
  for (int x = 0; x < 8; ++x) gids[24 + static_cast<std::size_t>(x)] = 2;
  gids[5] = 1 | 0x80000000u;
  const std::string objects = R"({"type": "objectgroup", "name": "o", "objects": [
      {"id": 1, "type": "walker", "x": 20, "y": 40, "point": true},
      {"id": 2, "type": "spawner", "x": 100, "y": 0, "width": 4, "height": 40,
       "properties": [{"name": "count", "type": "int", "value": 4}]},
      {"id": 3, "x": 0, "y": 0, "width": 8, "height": 8, )" +
                              collidable() + "}]}";
  int rounds = 0, errors = 0;
  for (const char* format : {"csv", "zlib", "gzip"}) {
    const std::string text =
        map(8, 4, tileLayer("g", 8, 4, tileData(gids, format), collidable()) + "," + objects,
            tileset("1"));
    errors += mutate(text, 7, 600, [](const std::string& t) {
      const sim::SceneDef def = makeScene(parseTiledMap(t, "m.tmj"));
      sim::Simulation sim(def, def.defaults());  // whatever loaded must also run
      sim.run(3);
      return sim.stateHash();
    });
    rounds += 600;
  }
  for (const char* name : {"platformer", "bullets-enemies", "corner-graze", "bounce-gap"}) {
    const sim::SceneDef& s = sim::findScene(name);
    const std::string text = writeSceneFile(exportScene(s, s.defaults(), "continuous"));
    errors += mutate(text, 11, 300, [](const std::string& t) {
      const sim::SceneDef def = makeScene(parseSceneFile(t, "s.json"));
      sim::Simulation sim(def, def.defaults());
      sim.run(3);
      return sim.stateHash();
    });
    rounds += 300;
  }
  // The loop is a real test of the error paths only if most mutations were caught as errors.
  EXPECT_GT(errors, rounds / 2) << errors << " of " << rounds << " corruptions were rejected";
}

}  // namespace
}  // namespace tv::level
