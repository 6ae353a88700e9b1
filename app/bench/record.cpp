// record: what recording costs and what a recording holds. The 10^4 crowd and bump-crowd moved
// with and without a Recorder attached (alternating runs, best of each; wall time and the game
// thread's CPU time), bytes per recorded move on the crowd and
// on the sample platformer, the replay + validate rate (tracing compiled in, off), seek time on
// a 10^5-frame recording, and the time to open one.
//
// Index: [SECTION] the crowd · [SECTION] the study

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "bump_crowd.hpp"
#include "report.hpp"
#include "studies.hpp"
#include "tv/app/platformer_game.hpp"
#include "tv/mover.hpp"
#include "tv/record/live.hpp"
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

// CPU time of the calling thread: what the game's own thread spent.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
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

  // -- overhead on the crowds ----------------------------------------------------------------
  // Three copies of a workload in lockstep from the same seed: one detached, one recording to
  // memory, one to a file in --out. Runs alternate so machine noise falls on all three. Wall
  // time is what a game on an idle machine feels; the game thread's CPU time is what recording
  // takes from the game's own thread, whatever else the machine runs (the writer's thread works
  // beside it).
  Crowd plain(count, o.seed), memory(count, o.seed), file(count, o.seed), idle(count, o.seed),
      watched(count, o.seed);
  Recorder memRec;
  const std::filesystem::path crowdPath = o.out / "crowd.tvrec";
  Recorder fileRec(crowdPath.string());
  memory.world().attach(memRec);
  file.world().attach(fileRec);
  // Live: a stream nobody listens to (a port just freed), and one to a receiver in this process.
  LiveOptions nobody;
  nobody.onMessage = [](std::string_view) {};
  {
    LiveReceiverOptions any;
    any.address = "127.0.0.1:0";
    nobody.address = "127.0.0.1:" + std::to_string(LiveReceiver(any).port());
  }
  Recorder idleRec(nobody);
  idle.world().attach(idleRec);
  LiveReceiverOptions rxOptions;
  rxOptions.address = "127.0.0.1:0";
  rxOptions.keepBytes = std::uint64_t{64} << 20;
  LiveReceiver receiver(rxOptions);
  LiveOptions toReceiver = nobody;
  toReceiver.address = receiver.address();
  Recorder watchedRec(toReceiver);
  for (int i = 0; i < 400 && !watchedRec.liveStatus().connected; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  watched.world().attach(watchedRec);
  BumpCrowdSpec bumpSpec;
  bumpSpec.movers = count;
  bumpSpec.seed = o.seed;
  BumpCrowd bumpPlain(bumpSpec), bumpMemory(bumpSpec), bumpFile(bumpSpec), bumpIdle(bumpSpec);
  Recorder bumpMemRec, bumpFileRec((o.out / "bump-crowd.tvrec").string()), bumpIdleRec(nobody);
  bumpMemory.world().attach(bumpMemRec);
  bumpFile.world().attach(bumpFileRec);
  bumpIdle.world().attach(bumpIdleRec);
  struct Timed {
    bool bump;  // the bump-crowd (cheaper ticks: timed 4 times as many)
    std::string name;
    std::function<void()> tick;
    double wall = 1e300, cpu = 1e300;
  };
  std::vector<Timed> runs = {
      {false, "detached", [&] { plain.tick(); }},
      {false, "recording to memory",
       [&] {
         memory.tick();
         memRec.frame();
       }},
      {false, "recording to a file (flushed per frame)",
       [&] {
         file.tick();
         fileRec.frame();
       }},
      {false, "live stream, nobody listening",
       [&] {
         idle.tick();
         idleRec.frame();
       }},
      {false, "live stream to a receiver in this process",
       [&] {
         watched.tick();
         watchedRec.frame();
         (void)receiver.poll();
       }},
      {true, "detached", [&] { bumpPlain.tick(CrowdFilter::tiles); }},
      {true, "recording to memory",
       [&] {
         bumpMemory.tick(CrowdFilter::tiles);
         bumpMemRec.frame();
       }},
      {true, "recording to a file (flushed per frame)",
       [&] {
         bumpFile.tick(CrowdFilter::tiles);
         bumpFileRec.frame();
       }},
      {true, "live stream, nobody listening",
       [&] {
         bumpIdle.tick(CrowdFilter::tiles);
         bumpIdleRec.frame();
       }},
  };
  for (int t = 0; t < 3; ++t) {  // warm: cells and buffers reach their steady sizes
    for (Timed& r : runs) r.tick();
  }
  const std::uint64_t bumpTicks = ticks * 4;
  for (int rep = 0; rep < repeats; ++rep) {
    for (Timed& r : runs) {
      const std::uint64_t n = r.bump ? bumpTicks : ticks;
      const double cpu0 = threadCpuSeconds();
      Stopwatch sw;
      for (std::uint64_t t = 0; t < n; ++t) r.tick();
      const double wall = ms(sw) / static_cast<double>(n);
      const double cpu = (threadCpuSeconds() - cpu0) * 1e3 / static_cast<double>(n);
      r.wall = std::min(r.wall, wall);
      r.cpu = std::min(r.cpu, cpu);
    }
  }
  memory.world().detach();
  file.world().detach();
  idle.world().detach();
  watched.world().detach();
  bumpMemory.world().detach();
  bumpFile.world().detach();
  bumpIdle.world().detach();
  Table overhead(
      {"workload", "recording", "ms/tick:", "overhead:", "game thread CPU ms/tick:", "overhead:"});
  for (const Timed& r : runs) {
    const Timed& base = r.bump ? runs[5] : runs[0];
    const std::string workload = r.bump ? "bump-crowd of " + std::to_string(count) + ", tiles"
                                        : "crowd of " + std::to_string(count) + ", continuous";
    const bool first = &r == &base;
    overhead.add({workload, r.name, fixed(r.wall, 3),
                  first ? "-" : percent(r.wall - base.wall, base.wall), fixed(r.cpu, 3),
                  first ? "-" : percent(r.cpu - base.cpu, base.cpu)});
  }
  os << "### Recording on the crowds\n\n";
  overhead.printMarkdown(os);
  overhead.writeCsv(o.out, "record_overhead.csv");
  os << "\nThe game waited for the writer "
     << memRec.stalls() + fileRec.stalls() + bumpMemRec.stalls() + bumpFileRec.stalls()
     << " times (its queue is bounded). The receiver kept " << receiver.window().nextFrame
     << " frames of the watched crowd"
     << (idleRec.calls() == 0 ? "; the stream nobody listened to copied no call" : "") << ".\n";

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
