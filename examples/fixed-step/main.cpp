// A game loop on a fixed step, with interpolation and recording: the article's first patch
// ("Fix Your Timestep!") done with tv::FixedStep instead of by hand, moves swept so that a fast
// body never tunnels, and a recording for tv-replay and tv-debugger.
//
//   fixed-step-game [--frames N] [--record game.tvrec]
//
// Headless: frames are simulated (144 Hz with a hitch now and then) and "drawing" prints where a
// sprite would go. Replace `frameSeconds` by your clock and `draw` by your renderer.
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include <tv/record/recorder.hpp>
#include <tv/timestep.hpp>
#include <tv/world.hpp>

namespace {

struct Body {
  tv::ItemId item;
  tv::Vec2 velocity;  // px/s
  tv::Vec2 previous;  // position before the last tick: what the draw interpolates from
};

void draw(const char* name, tv::Vec2 p) { std::printf("  %s at (%g, %g)\n", name, p.x, p.y); }

}  // namespace

int main(int argc, char** argv) {
  int frames = 300;
  std::string recordPath;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--frames") frames = std::atoi(argv[i + 1]);
    if (flag == "--record") recordPath = argv[i + 1];
  }

  tv::World world(32);
  for (int x = 0; x < 40; ++x) world.add({x * 16.0, 200, 16, 16});  // a floor of 16 px tiles
  world.add({400, 120, 2, 80});                                      // a wall 2 px thin
  Body player{world.add({32, 186.3, 10, 13.7}), {90, 0}, {}};
  Body bullet{world.add({40, 150, 4, 4}), {1920, 0}, {}};  // 32 px a tick: past the wall at once

  tv::FixedStep clock(1.0 / 60.0, 0.25);  // ticks of 1/60 s; a frame counts at most 0.25 s
  std::optional<tv::Recorder> recorder;
  if (!recordPath.empty()) {
    try {
      recorder.emplace(recordPath);  // throws tv::Error naming the path and the reason
      world.attach(*recorder);
      recorder->attach(clock);  // a frame of the recording per rendered frame
      recorder->label(player.item, "player", "player");
      recorder->label(bullet.item, "bullet", "bullet");
    } catch (const tv::Error& e) {
      std::fprintf(stderr, "not recording: %s\n", e.what());  // the game goes on
      recorder.reset();
    }
  }

  const auto tick = [&](Body& b, double dt) {
    b.previous = world.rect(b.item).position();  // at the start of each tick, not the end
    b.velocity.y += 900 * dt;                     // gravity, px/s²
    const tv::Vec2 goal = b.previous + b.velocity * dt;
    for (const tv::Collision& c : world.move(b.item, goal).collisions) {
      if (c.normal.y != 0) b.velocity.y = 0;  // landed (or hit a ceiling): slide on
      if (c.normal.x != 0) b.velocity.x = 0;  // stopped by a wall
    }
  };
  for (int frame = 0; frame < frames; ++frame) {
    const double frameSeconds = frame % 97 == 50 ? 0.5 : 1.0 / 144.0;  // a 144 Hz screen, a hitch
    for (int n = clock.advance(frameSeconds); n > 0; --n) {
      tick(player, clock.step());
      tick(bullet, clock.step());
    }
    // Draw between the last two ticks, snapped to whole pixels (floor on draw).
    const double alpha = clock.alpha();
    if (frame % 144 == 0) {
      std::printf("frame %d (alpha %.2f)\n", frame, alpha);
      for (Body* b : {&player, &bullet}) {
        const tv::Vec2 now = world.rect(b->item).position();
        draw(b == &player ? "player" : "bullet",
             tv::floorOnDraw(tv::interpolate(b->previous, now, alpha)));
      }
    }
  }
  const tv::Rect b = world.rect(bullet.item);
  std::printf("%llu ticks in %d frames (%llu clamped); bullet stopped at x = %g, before the "
              "wall at 400\n", static_cast<unsigned long long>(clock.ticks()), frames,
              static_cast<unsigned long long>(clock.clampedFrames()), b.right());
  if (recorder) recorder->close();
  return b.right() <= 400 ? 0 : 1;
}
