// record: what recording costs and what a recording holds. The 10^4 crowd moved with and without
// a Recorder attached (alternating runs, best of each), bytes per recorded move on the crowd and
// on the sample platformer, the replay + validate rate (tracing compiled in, off), seek time on
// a 10^5-frame recording, and the time to open one.
//
// Index: [SECTION] the crowd · [SECTION] the study

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "tv/app/platformer_game.hpp"
#include "report.hpp"
#include "studies.hpp"
#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/rng.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::bench {
namespace {

// [SECTION] the crowd -----------------------------------------------------------------------------
//
// The crowd scene (tv::sim builds it) moved as Simulation moves it — its filter, the continuous
// mover, the velocity response — in a World the benchmark owns, so a Recorder can be attached.

class Crowd {
 public:
  Crowd(std::int64_t count, std::uint64_t seed) : mover_(parseMover("continuous")) {
    const sim::SceneDef& scene = sim::findScene("crowd");
    sim::Params p = scene.defaults();
    p.set(sim::param::count, static_cast<double>(count));
    p.set(sim::param::seed, static_cast<double>(seed % 1000000));
    dt_ = p.get(sim::param::dt);
    sim::SceneSetup s = scene.build(p);
    world_ = World(s.cellSize);
    for (const sim::Solid& solid : s.solids) grow(world_.add(solid.rect));
    bodies_ = std::move(s.bodies);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      bodies_[i].item = world_.add(bodies_[i].rect);
      grow(bodies_[i].item);
      bodyBySlot_[bodies_[i].item.index] = static_cast<std::int32_t>(i);
    }
  }

  World& world() { return world_; }
  [[nodiscard]] std::size_t bodies() const { return bodies_.size(); }

  void tick() {
    const auto filter = [this](ItemId item, ItemId other) {
      const sim::Body& b = bodies_[static_cast<std::size_t>(bodyBySlot_[item.index])];
      const std::int32_t o = bodyBySlot_[other.index];
      const std::uint32_t layer =
          o < 0 ? sim::kLayerSolid : bodies_[static_cast<std::size_t>(o)].layer;
      return (b.mask & layer) != 0 ? b.response : response::ignore;
    };
    for (sim::Body& b : bodies_) {
      const Vec2 goal = b.rect.position() + b.velocity * dt_;
      const MoveResult r = mover_.move(world_, b.item, goal, filter);
      b.rect = b.rect.at(r.position);
      b.velocity = sim::respondVelocity(b.velocity, r.collisions);
    }
  }

 private:
  void grow(ItemId id) {
    if (id.index >= bodyBySlot_.size()) bodyBySlot_.resize(id.index + 1, -1);
  }
  Mover mover_;
  double dt_ = 1.0 / 60.0;
  World world_;
  std::vector<sim::Body> bodies_;
  std::vector<std::int32_t> bodyBySlot_;
};

double ms(const Stopwatch& sw) {
  return sw.seconds() * 1e3;
}

// [SECTION] the study -----------------------------------------------------------------------------

}  // namespace

int runRecord(const Options& o) {
  const auto count =
      static_cast<std::int64_t>(o.has("count") ? parseCount("count", o.extra.at("count")) : 10000);
  if (count < 1 || count > 100000) throw UsageError{"--count: expected 1 to 100000"};
  std::uint64_t ticks = o.pick<std::uint64_t>(10, 60, 300);
  if (o.has("ticks")) ticks = parseCount("ticks", o.extra.at("ticks"));
  // One variant alone, for an instruction count (valgrind --tool=callgrind): the crowd moved
  // `ticks` ticks detached, recording to memory, or recording and then validated.
  if (o.has("variant")) {
    const std::string v = o.extra.at("variant");
    if (v != "detached" && v != "memory" && v != "validate") {
      throw UsageError{"--variant: expected detached, memory or validate, but got '" + v + "'"};
    }
    Crowd crowd(count, o.seed);
    Recorder rec;
    if (v != "detached") crowd.world().attach(rec);
    for (std::uint64_t t = 0; t < ticks; ++t) {
      crowd.tick();
      rec.frame();
    }
    crowd.world().detach();
    if (v == "validate") {
      Replay r = Replay::fromBytes(rec.bytes());
      std::cout << (r.validate() ? "DIVERGED" : "ok") << "\n";
    }
    std::cout << v << ": " << ticks * crowd.bodies() << " moves, " << rec.size() << " bytes\n";
    return 0;
  }
  const int repeats = o.pick(2, 4, 7);
  const std::uint64_t seekFrames = o.pick<std::uint64_t>(10000, 100000, 100000);
  std::ostream& os = std::cout;
  printHeading(os, "record: the cost of recording, the size of a recording, replay and seek",
               modeName(o.mode), o.seed, o.out);
  os << "Single thread, Release; tracing compiled " << (kTraceCompiledIn ? "in (and off)" : "out")
     << ". Timings are the best of " << repeats << " alternating runs.\n\n";

  // -- overhead on the crowd ------------------------------------------------------------------
  // Two crowds in lockstep from the same seed: one detached, one recording (to memory, and to a
  // file in --out). Runs alternate so machine noise falls on both.
  Crowd plain(count, o.seed), memory(count, o.seed), file(count, o.seed);
  Recorder memRec;
  const std::filesystem::path crowdPath = o.out / "crowd.tvrec";
  Recorder fileRec(crowdPath.string());
  memory.world().attach(memRec);
  file.world().attach(fileRec);
  for (int t = 0; t < 3; ++t) {  // warm: cells and buffers reach their steady sizes
    plain.tick();
    memory.tick();
    memRec.frame();
    file.tick();
    fileRec.frame();
  }
  double bestPlain = 1e300, bestMemory = 1e300, bestFile = 1e300;
  for (int r = 0; r < repeats; ++r) {
    Stopwatch a;
    for (std::uint64_t t = 0; t < ticks; ++t) plain.tick();
    bestPlain = std::min(bestPlain, ms(a) / static_cast<double>(ticks));
    Stopwatch b;
    for (std::uint64_t t = 0; t < ticks; ++t) {
      memory.tick();
      memRec.frame();
    }
    bestMemory = std::min(bestMemory, ms(b) / static_cast<double>(ticks));
    Stopwatch c;
    for (std::uint64_t t = 0; t < ticks; ++t) {
      file.tick();
      fileRec.frame();
    }
    bestFile = std::min(bestFile, ms(c) / static_cast<double>(ticks));
  }
  memory.world().detach();
  file.world().detach();
  Table overhead({"crowd of " + std::to_string(count) + ", continuous", "ms/tick:", "overhead:"});
  overhead.add({"detached", fixed(bestPlain, 3), "-"});
  overhead.add(
      {"recording to memory", fixed(bestMemory, 3), percent(bestMemory - bestPlain, bestPlain)});
  overhead.add({"recording to a file (flushed per frame)", fixed(bestFile, 3),
                percent(bestFile - bestPlain, bestPlain)});
  os << "### Recording on the crowd\n\n";
  overhead.printMarkdown(os);
  overhead.writeCsv(o.out, "record_overhead.csv");

  // -- sizes ----------------------------------------------------------------------------------
  Recorder game;
  (void)example::play(o.pick<std::uint64_t>(600, 3600, 3600), false, &game);
  Recorder naive;
  (void)example::play(o.pick<std::uint64_t>(600, 3600, 3600), true, &naive);
  Table sizes({"recording", "frames:", "calls:", "moves:", "bytes:", "bytes/move:", "bytes/call:"});
  const auto sizeRow = [&](const std::string& name, const Recorder& r) {
    const double moves = static_cast<double>(std::max<std::uint64_t>(1, r.moves()));
    sizes.add({name, std::to_string(r.frames()), std::to_string(r.calls()),
               std::to_string(r.moves()), std::to_string(r.size()),
               r.moves() ? fixed(static_cast<double>(r.size()) / moves, 1) : "-",
               fixed(static_cast<double>(r.size()) / static_cast<double>(r.calls()), 1)});
  };
  sizeRow("crowd of " + std::to_string(count) + " (Mover::move per body per tick)", memRec);
  sizeRow("sample platformer (continuous)", game);
  sizeRow("sample platformer, --naive (updates and queries, no moves)", naive);
  os << "\n### What a recording holds\n\n";
  sizes.printMarkdown(os);
  sizes.writeCsv(o.out, "record_sizes.csv");

  // -- replay + validate ----------------------------------------------------------------------
  Table replay({"recording", "open ms:", "validate ms:", "moves/s:", "calls/s:", "result"});
  const auto replayRow = [&](const std::string& name, const std::vector<std::uint8_t>& bytes) {
    double bestOpen = 1e300, bestValidate = 1e300;
    std::string result;
    std::uint64_t moves = 0, calls = 0;
    for (int r = 0; r < repeats; ++r) {
      Stopwatch a;
      Replay rp = Replay::fromBytes(bytes);
      bestOpen = std::min(bestOpen, ms(a));
      Stopwatch b;
      const std::optional<Divergence> d = rp.validate();
      bestValidate = std::min(bestValidate, ms(b));
      result = d ? "DIVERGED" : "ok";
      moves = rp.summary().moves;
      calls = rp.summary().calls;
    }
    replay.add({name, fixed(bestOpen, 2), fixed(bestValidate, 2),
                sig3(static_cast<double>(moves) / (bestValidate / 1e3)),
                sig3(static_cast<double>(calls) / (bestValidate / 1e3)), result});
  };
  replayRow("crowd of " + std::to_string(count), memRec.bytes());
  replayRow("sample platformer", game.bytes());
  os << "\n### Replay and validation (every call re-executed and compared bit for bit)\n\n";
  replay.printMarkdown(os);
  replay.writeCsv(o.out, "record_replay.csv");

  // -- seek -------------------------------------------------------------------------------------
  Recorder longRec;
  (void)example::play(seekFrames, false, &longRec);
  Stopwatch openWatch;
  Replay longReplay = Replay::fromBytes(longRec.bytes());
  const double openMs = ms(openWatch);
  sim::Rng rng(o.seed);
  double worst = 0, total = 0;
  const int seeks = 50;
  for (int i = 0; i < seeks; ++i) {
    const std::uint64_t k = rng.below(longReplay.frames());
    Stopwatch sw;
    longReplay.seek(k);
    const double t = ms(sw);
    worst = std::max(worst, t);
    total += t;
  }
  Table seek({"recording", "frames:", "bytes:", "keyframe every:", "open ms:", "seek ms (mean):",
              "seek ms (worst):"});
  seek.add({"sample platformer", std::to_string(longReplay.frames()),
            std::to_string(longRec.size()), "64", fixed(openMs, 1), fixed(total / seeks, 2),
            fixed(worst, 2)});
  os << "\n### Seeking (" << seeks << " random frames, each from its nearest keyframe)\n\n";
  seek.printMarkdown(os);
  seek.writeCsv(o.out, "record_seek.csv");
  os << "\nThe crowd recording is in " << crowdPath.string() << " (tv-replay it).\n";
  return 0;
}

}  // namespace tv::bench
