// Microbenchmarks of the hot paths, so the scale study can say how far one move is from its own
// lower bound: the exact pair test, a cell lookup, and whole moves of several kinds and lengths.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "hot_paths.hpp"
#include "tv/mover.hpp"
#include "tv/sweep.hpp"
#include "tv/world.hpp"

namespace {

using tv::Rect;
using tv::Vec2;

using tv::bench::TileMap;

void sweepHit(benchmark::State& state) {
  const Rect mover{0, 0, 8, 8}, wall{20, -4, 16, 16};
  Vec2 goal{30, 3};
  for (auto _ : state) {
    benchmark::DoNotOptimize(goal);
    benchmark::DoNotOptimize(tv::sweepRect(mover, goal, wall));
  }
}
BENCHMARK(sweepHit);

void sweepMiss(benchmark::State& state) {
  const Rect mover{0, 0, 8, 8}, wall{20, 40, 16, 16};
  Vec2 goal{30, 3};
  for (auto _ : state) {
    benchmark::DoNotOptimize(goal);
    benchmark::DoNotOptimize(tv::sweepRect(mover, goal, wall));
  }
}
BENCHMARK(sweepMiss);

void cellLookup(benchmark::State& state) {
  // One occupied-cell probe: the point query reads exactly one cell.
  TileMap map;
  std::size_t i = 0;
  for (auto _ : state) {
    const Rect& r = map.free[i++ % map.free.size()];
    benchmark::DoNotOptimize(map.world.queryPoint(r.position()));
  }
}
BENCHMARK(cellLookup);

void freeSpotCheck(benchmark::State& state) {
  TileMap map;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(map.world.anyOverlap(map.free[i++ % map.free.size()]));
  }
}
BENCHMARK(freeSpotCheck);

// One move of an 8x8 body among tiles, 2 px in a random direction, by each mover.
void shortMove(benchmark::State& state) {
  TileMap map;
  const auto name = tv::moverNames()[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(std::string(name));
  tv::Mover mover(tv::parseMover(name));
  std::vector<tv::ItemId> ids;
  for (std::size_t k = 0; k < map.free.size(); k += 7) ids.push_back(map.world.add(map.free[k]));
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<> angle(0, 6.283185307179586);
  std::vector<Vec2> step(ids.size());
  for (Vec2& s : step) {
    const double a = angle(rng);
    s = {2 * std::cos(a), 2 * std::sin(a)};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % ids.size();
    const Vec2 p = map.world.rect(ids[k]).position();
    const tv::MoveResult r = mover.move(map.world, ids[k], p + step[k]);
    if (!r.collisions.empty()) step[k] = step[k] * -1.0;
  }
}
BENCHMARK(shortMove)->DenseRange(0, 6);

// A long move across open space: cost against length, along an axis and diagonally.
void longMove(benchmark::State& state) {
  tv::World world(64);
  const double length = static_cast<double>(state.range(0));
  const bool diagonal = state.range(1) != 0;
  const tv::BroadPhase broad = state.range(2) != 0 ? tv::BroadPhase::swept : tv::BroadPhase::bounds;
  state.SetLabel(std::string(diagonal ? "diagonal " : "horizontal ") +
                 (broad == tv::BroadPhase::swept ? "continuous" : "sweep"));
  // Scattered obstacles so cells are occupied but the path stays free.
  for (int k = 0; k < 4000; ++k) world.add({(k % 80) * 64.0 + 28, (k / 80) * 64.0 + 60, 8, 2});
  const tv::ItemId id = world.add({100, 100, 8, 8});
  const Vec2 d =
      diagonal ? Vec2{length / std::sqrt(2.0), length / std::sqrt(2.0)} : Vec2{length, 0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        world.check(id, Vec2{100, 100} + d, tv::Filter::all(tv::response::ignore), {broad})
            .position);
  }
}
BENCHMARK(longMove)->ArgsProduct({{64, 240, 960, 1900}, {0, 1}, {0, 1}});

// The same through a corridor cut in a tile map: the scale study's cost-against-length case.
void corridorMove(benchmark::State& state) {
  const double length = static_cast<double>(state.range(0));
  const bool diagonal = state.range(1) != 0;
  const tv::BroadPhase broad = state.range(2) != 0 ? tv::BroadPhase::swept : tv::BroadPhase::bounds;
  state.SetLabel(std::string(diagonal ? "diagonal " : "horizontal ") +
                 (broad == tv::BroadPhase::swept ? "continuous" : "sweep"));
  const Vec2 d =
      diagonal ? Vec2{length / std::sqrt(2.0), length / std::sqrt(2.0)} : Vec2{length, 0};
  const tv::bench::Corridor c({404, 404}, d);
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.map.world.check(c.mover, c.goal, {}, {broad}).position);
  }
}
BENCHMARK(corridorMove)->ArgsProduct({{64, 240, 960, 1900}, {0, 1}, {0, 1}});

}  // namespace

BENCHMARK_MAIN();
