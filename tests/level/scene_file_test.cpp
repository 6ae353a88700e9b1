// Scene files: every built-in scene exported and loaded again runs tick for tick like the
// original (same state hash after 600 ticks); a hand-written file runs with its motions.
#include <gtest/gtest.h>

#include "tv/error.hpp"
#include "tv/level/level.hpp"
#include "tv/level/scene_file.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::level {
namespace {

TEST(SceneFile, EveryBuiltinSceneRoundTripsToTheSameStateHash) {
  for (const sim::SceneDef& scene : sim::builtinScenes().all()) {
    // pixel keeps per-item state (sub-pixel remainders) that a file must not lose.
    for (const char* mover : {"continuous", "pixel"}) {
      const sim::Params params = scene.defaults();
      const std::string text = writeSceneFile(exportScene(scene, params, mover));
      const Level loaded = parseSceneFile(text, scene.name + ".json");
      ASSERT_EQ(loaded.mover, mover);
      const sim::SceneDef fromFile = makeScene(loaded);
      sim::Simulation original(scene, params, parseMover(mover));
      sim::Simulation again(fromFile, fromFile.defaults(), parseMover(*loaded.mover));
      for (int t = 0; t < 600; ++t) {
        original.tick();
        again.tick();
      }
      EXPECT_EQ(again.stateHash(), original.stateHash()) << scene.name << " with " << mover;
      EXPECT_EQ(again.counters(), original.counters()) << scene.name << " with " << mover;
      EXPECT_EQ(fromFile.camera(fromFile.defaults()), scene.camera(params)) << scene.name;
      // Written again, the file is the same text: nothing was lost or rounded on the way.
      EXPECT_EQ(writeSceneFile(loaded), text) << scene.name;
    }
  }
}

TEST(SceneFile, NonDefaultParametersRoundTripToo) {
  const sim::SceneDef& scene = sim::findScene("platformer");
  sim::Params params = scene.defaults();
  params.set("speed", 210);
  params.set("count", 3);
  params.set("gravity", 2400);
  const sim::SceneDef fromFile =
      makeScene(parseSceneFile(writeSceneFile(exportScene(scene, params)), "p.json"));
  sim::Simulation original(scene, params, parseMover("adaptive"));
  sim::Simulation again(fromFile, fromFile.defaults(), parseMover("adaptive"));
  original.run(600);
  again.run(600);
  EXPECT_EQ(again.stateHash(), original.stateHash());
  EXPECT_GT(again.counters().jumps, 0u);
}

TEST(SceneFile, AFileOfABuiltinSceneKeepsItsGeometryButMovesWithOffset) {
  const sim::SceneDef& scene = sim::findScene("rest-floor");
  const sim::SceneDef fromFile =
      makeScene(parseSceneFile(writeSceneFile(exportScene(scene, scene.defaults())), "r.json"));
  sim::Params p = fromFile.defaults();
  EXPECT_THROW(p.set("tile", 32), Error) << "tile shapes the file's geometry: fixed";
  p.set("offset", 1e6);
  sim::Params original = scene.defaults();
  original.set("offset", 1e6);
  sim::Simulation a(scene, original, parseMover("continuous"));
  sim::Simulation b(fromFile, p, parseMover("continuous"));
  a.run(300);
  b.run(300);
  EXPECT_EQ(b.stateHash(), a.stateHash());
}

// A hand-written level: a floor with walls, a walker, a jumping player and one bullet.
//   |#                              #|
//   |#   p        w           <-b   #|      b at 960 px/s into the left wall
//   |################################|
constexpr const char* kHandWritten = R"({
  "format": "tunnelvision-scene", "version": 1,
  "name": "hand", "gravity": [0, 1800], "tile": 16,
  "solids": [[0, 96, 512, 16], [0, 0, 16, 96], {"rect": [496, 0, 16, 96], "tag": 3}],
  "bodies": [
    {"rect": [40, 80, 12, 16], "motion": "player", "speed": 100, "jump": {"every": 40}},
    {"rect": [200, 84, 12, 12], "motion": "walker", "direction": "left"},
    {"rect": [440, 40, 4, 4], "motion": "bullet", "velocity": [-960, 0]}
  ]
})";

TEST(SceneFile, AHandWrittenFileRunsItsMotions) {
  const Level lv = parseSceneFile(kHandWritten, "hand.json");
  ASSERT_EQ(lv.bodies.size(), 3u);
  EXPECT_EQ(lv.solids[2].tag, 3);
  const sim::SceneDef scene = makeScene(lv);
  EXPECT_EQ(scene.name, "hand");
  sim::Simulation s(scene, scene.defaults(), parseMover("continuous"));
  bool walkerTurned = false;
  for (int t = 0; t < 600; ++t) {
    s.tick();
    walkerTurned = walkerTurned || s.bodies()[1].velocity.x > 0;
  }
  EXPECT_GT(s.counters().jumps, 3u) << "the player jumps every 40 ticks it is grounded";
  // Both walking bodies land once on the first tick (they start on the floor), then the player
  // lands after each jump but possibly the last one, still in the air.
  EXPECT_GE(s.counters().landings, s.counters().jumps + 1);
  EXPECT_LE(s.counters().landings, s.counters().jumps + 2);
  EXPECT_TRUE(walkerTurned) << "the walker started left and turned at the wall";
  EXPECT_EQ(s.counters().hits, 1u);
  EXPECT_EQ(s.bodies()[2].rect.x, 16.0) << "the bullet stopped exactly on the wall";
  EXPECT_EQ(s.counters().overlaps, 0u);
}

TEST(SceneFile, SpeedSetsWalkersWithoutTheirOwn) {
  const sim::SceneDef scene = makeScene(parseSceneFile(kHandWritten, "hand.json"));
  sim::Params p = scene.defaults();
  p.set("speed", 60);
  sim::Simulation s(scene, p, parseMover("continuous"));
  s.tick();
  EXPECT_EQ(s.bodies()[1].velocity.x, -60.0) << "the walker has no speed of its own";
  EXPECT_EQ(s.bodies()[0].velocity.x, 100.0) << "the player has";
}

TEST(SceneFile, EveryBuiltinResponseIsNamedAsTheCoreNamesIt) {
  // A body per entry of the core's table of built-in responses, written and read back.
  for (ResponseId id = 0; id < response::kBuiltinCount; ++id) {
    const std::string name(kBuiltinResponses[id].name);
    const Level lv = parseSceneFile(
        R"({"format": "tunnelvision-scene", "version": 1, "bodies": [{"rect": [0, 0, 8, 8],)"
        R"( "response": ")" + name + R"("}]})",
        "r.json");
    ASSERT_EQ(lv.bodies.size(), 1u);
    EXPECT_EQ(lv.bodies[0].body.response, id) << name;
    const std::string written = writeSceneFile(lv);
    EXPECT_NE(written.find('"' + name + '"'), std::string::npos) << written;
    EXPECT_EQ(parseSceneFile(written, "again.json").bodies[0].body.response, id) << name;
  }
}

}  // namespace
}  // namespace tv::level
