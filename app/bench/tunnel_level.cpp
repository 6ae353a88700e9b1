// tunnel --map / --scene-file: the tunnel table on the user's own level. Shots of two sizes at
// random angles are aimed at random points inside the level's solids, each starting a random
// fraction of one tick's travel short of where its path enters solid ground, and every mover
// fires them at the table's speeds. A shot tunnelled when one of its moves went through a solid
// (or round its corner) and out again (tv::level's bullet rule), whatever the mover said.
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "report.hpp"
#include "studies.hpp"
#include "tv/app/scene_source.hpp"
#include "tv/error.hpp"
#include "tv/level/level.hpp"
#include "tv/mover.hpp"
#include "tv/sim/rng.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/world.hpp"

namespace tv::bench {
namespace {

struct Shot {
  Vec2 centre;     // where it starts
  Vec2 direction;  // unit
};

/// `count` shots of side `size` at `speed`: each aims at a random point inside a random solid,
/// from a free start at most one tick's travel (plus the shot's half-diagonal and 1 px) away.
std::vector<Shot> aim(const std::vector<sim::Solid>& solids, const World& world, double size,
                      double travel, std::int64_t count, std::uint64_t seed) {
  sim::Rng rng(seed);
  std::vector<Shot> shots;
  for (std::int64_t k = 0, tries = 0; k < count && tries < 100 * count; ++tries) {
    const Rect& target = solids[rng.below(solids.size())].rect;
    const Vec2 point{target.x + rng.uniform() * target.w, target.y + rng.uniform() * target.h};
    const double a = 2.0 * std::numbers::pi * rng.uniform();
    const Vec2 d{std::cos(a), std::sin(a)};
    const double back = size * std::numbers::sqrt2 / 2.0 + 1.0 + rng.uniform() * travel;
    const Vec2 c = point - d * back;
    if (world.anyOverlap({c.x - size / 2, c.y - size / 2, size, size})) continue;  // not free
    shots.push_back({c, d});
    ++k;
  }
  return shots;
}

struct Outcome {
  std::uint64_t shots = 0, tunnelled = 0, farPushOuts = 0;
};

Outcome fire(const std::vector<sim::Solid>& solids, const std::vector<Shot>& shots, double size,
             double speed, double dt, double cell, const std::string& mover) {
  level::Level lv;
  lv.name = "tunnel";
  lv.source = "tunnel";
  lv.dt = dt;
  lv.cell = cell;
  lv.solids = solids;
  for (const Shot& s : shots) {
    level::LevelBody b;
    b.motion = level::Motion::bullet;
    b.body.rect = {s.centre.x - size / 2, s.centre.y - size / 2, size, size};
    b.body.velocity = s.direction * speed;
    b.body.response = response::touch;
    b.body.role = sim::BodyRole::projectile;
    b.body.layer = sim::kLayerProjectile;
    lv.bodies.push_back(b);
  }
  const sim::SceneDef scene = level::makeScene(std::move(lv));
  sim::SimConfig config;
  config.snapshotCapacity = 1;
  sim::Simulation sim(scene, scene.defaults(), parseMover(mover), config);
  sim.run(600);  // every shot meets solid ground within two ticks; 600 is a generous bound
  Outcome o;
  o.shots = shots.size();
  o.tunnelled = sim.counters().tunnelled;
  o.farPushOuts = sim.counters().farPushOuts;
  for (const sim::Body& b : sim.bodies()) o.tunnelled += b.active ? 1 : 0;  // never stopped
  return o;
}

}  // namespace

int runLevelTunnel(const Options& o) {
  app::SceneSource source;
  for (const char* flag : {"map", "scene-file", "solid-layer"}) {
    if (!o.has(flag)) continue;
    std::string error;
    (void)source.take(flag, o.extra.at(flag), error);
    if (!error.empty()) throw UsageError{error};
  }
  if (source.strayLayers()) throw UsageError{"--solid-layer goes with --map"};
  const sim::SceneDef& scene = source.scene();
  const sim::Params params = scene.defaults();
  const sim::SceneSetup setup = scene.build(params);
  if (setup.solids.empty()) {
    throw UsageError{source.describe() +
                     ": nothing in it is solid, so there is nothing to shoot at"};
  }
  World world(setup.cellSize);
  for (const sim::Solid& s : setup.solids) (void)world.add(s.rect);
  const double dt = params.get(sim::param::dt);

  const std::vector<double> speeds =
      o.numbers("speeds", {240, 480, 720, 960, 1920, 3840, 7680, 1e5});
  const auto count =
      static_cast<std::int64_t>(o.has("count") ? parseCount("count", o.extra.at("count"))
                                               : o.pick<std::uint64_t>(100, 1000, 5000));
  if (count < 1 || count > 100000) {
    throw UsageError{"--count " + std::to_string(count) + ": expected 1 to 100000"};
  }
  for (const double v : speeds) {
    if (!(v > 0 && v <= 1e9)) throw UsageError{"--speeds: " + sig3(v) + " is not in (0, 1e9]"};
  }
  const std::vector<std::string> movers = {
      "discrete", "substep-discrete", "substep-sweep", "sweep", "continuous", "pixel", "adaptive"};
  std::ostream& os = std::cout;
  printHeading(os, "tunnel: tunnelling rates on " + scene.name, modeName(o.mode), o.seed, o.out);
  os << "Shots at the " << setup.solids.size() << " solids of " << source.describe() << ": "
     << count << " per cell, each aimed at a random point inside a random solid at a random "
     << "angle, from a free start less than one tick's travel (plus half its diagonal and 1 px) "
     << "short of it. **Tunnelled**: one of the shot's moves went through a solid (its rect "
     << "overlapped it on the way and ended clear of it on the far side or round a corner), "
     << "or the shot never stopped. Fixed step " << formatNumber(dt)
     << " s; substep pieces are tile/2 = " << formatNumber(params.get(sim::param::tile) / 2)
     << " px.\n\n";
  Progress progress("tunnel", 2 * speeds.size() * movers.size());
  std::uint64_t safeTunnelled = 0, safeShots = 0, naiveTunnelled = 0, naiveShots = 0;
  for (const double size : {2.0, 8.0}) {
    std::vector<std::string> head = {"px/s:"};
    for (const std::string& m : movers) head.push_back(m + ":");
    Table table(head);
    for (const double v : speeds) {
      const std::vector<Shot> shots =
          aim(setup.solids, world, size, v * dt, count, o.seed + static_cast<std::uint64_t>(v));
      std::vector<std::string> row = {fixed(v, 0)};
      for (const std::string& m : movers) {
        const Outcome out = fire(setup.solids, shots, size, v, dt, setup.cellSize, m);
        row.push_back(percent(static_cast<double>(out.tunnelled), static_cast<double>(out.shots)));
        if (m == "discrete") {
          naiveTunnelled += out.tunnelled, naiveShots += out.shots;
        } else if (m == "sweep" || m == "substep-sweep" || m == "continuous" || m == "adaptive") {
          safeTunnelled += out.tunnelled, safeShots += out.shots;
        }
        progress.step(std::to_string(static_cast<int>(size)) + " px " + fixed(v, 0) + " px/s " + m);
      }
      table.add(row);
    }
    const std::string title = fixed(size, 0) + "×" + fixed(size, 0) + " shots";
    os << "### " << title << "\n\n";
    table.printMarkdown(os);
    table.writeCsv(o.out, "tunnel_level_" + fixed(size, 0) + "px.csv");
  }
  os << "sweep, substep-sweep, continuous and adaptive never tunnelled: "
     << (safeTunnelled == 0 ? "yes" : "NO") << " (" << safeTunnelled << " of " << safeShots
     << " shots). The negative control, discrete, tunnelled " << naiveTunnelled << " of "
     << naiveShots << ".\n\n";
  os << "CSV: " << (o.out / "tunnel_level_*.csv").string() << "\n";
  return 0;
}

}  // namespace tv::bench
