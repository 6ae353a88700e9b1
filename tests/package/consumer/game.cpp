// A consumer of the installed package: a body falls onto a floor and rests on it exactly; a
// built-in scene runs; a scene file (with tv::level) loads. Exits non-zero on any surprise.
#include <cstdio>

#include <tv/mover.hpp>
#include <tv/sim/simulation.hpp>
#include <tv/world.hpp>
#ifdef GAME_HAS_LEVEL
#include <tv/level/scene_file.hpp>
#endif
#ifdef GAME_HAS_RECORD
#include <tv/record/recorder.hpp>
#endif

int main() {
  tv::World world(32);
  for (int i = 0; i < 10; ++i) world.add({i * 16.0, 100, 16, 16});
  const tv::ItemId body = world.add({40, 20, 10, 10});
  const tv::MoveResult r = world.move(body, {40, 500});
  if (r.position.y != 90.0) {
    std::printf("expected to land at y = 90, got %g\n", r.position.y);
    return 1;
  }
  tv::sim::Simulation sim("bullets-wall", "continuous");
  sim.run(600);
  if (sim.counters().tunnelled != 0) {
    std::puts("bullets-wall tunnelled with the continuous mover");
    return 1;
  }
#ifdef GAME_HAS_LEVEL
  const tv::level::Level level = tv::level::parseSceneFile(
      R"({"format": "tunnelvision-scene", "version": 1, "solids": [[0, 100, 320, 16], [-16, 0, 16, 116], [320, 0, 16, 116]],
          "gravity": [0, 1800], "bodies": [{"rect": [40, 20, 10, 10], "motion": "walker"}]})",
      "inline.json");
  const tv::sim::SceneDef scene = tv::level::makeScene(level);
  tv::sim::Simulation walk(scene, scene.defaults());
  walk.run(120);
  if (walk.bodies()[0].rect.bottom() != 100.0) {
    std::printf("the walker should stand on the floor (bottom 100), but its bottom is %g\n",
                walk.bodies()[0].rect.bottom());
    return 1;
  }
#endif
#ifdef GAME_HAS_RECORD
  {
    tv::World recorded(32);
    tv::Recorder recorder;  // in memory
    recorded.attach(recorder);
    recorded.add({0, 100, 160, 16});
    const tv::ItemId hero = recorded.add({40, 20, 10, 10});
    recorded.move(hero, {40, 500});
    recorder.frame();
    recorded.detach();
    if (!recorder.ok() || recorder.moves() != 1) {
      std::printf("the recorder saw %llu moves (%s)\n",
                  static_cast<unsigned long long>(recorder.moves()), recorder.error().c_str());
      return 1;
    }
  }
#endif
  std::puts("consumer: ok");
  return 0;
}
