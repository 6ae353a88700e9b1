// scale: what a tick costs as the crowd grows, what one move costs against its length, how far
// a move is from its own lower bound, and adaptive against discrete where nothing moves fast.
//
// Index: [SECTION] the crowd driver · [SECTION] crowd table · [SECTION] move length ·
//        [SECTION] lower bound · [SECTION] slow scenes · [SECTION] bump-crowd ·
//        [SECTION] slow scenes, the table · [SECTION] the study
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "bump_crowd.hpp"
#include "hot_paths.hpp"
#include "report.hpp"
#include "studies.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/sweep.hpp"
#include "tv/trace.hpp"

namespace tv::bench {
namespace {

// [SECTION] the crowd driver ----------------------------------------------------------------------
//
// The crowd scene's own data (tv::sim builds it), moved the way tv::sim::Simulation moves it —
// the same filter (mask against layer, the body's response) and the same velocity response —
// but without the scene's checking rules (an extra overlap query per move, to count overlaps)
// and without the snapshot ring, so the figure is what the moves cost. The Simulation's own
// tick is timed beside it.

std::size_t heapInUse() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;  // small chunks + mmapped large ones
}

class CrowdRun {
 public:
  CrowdRun(std::int64_t count, std::uint64_t seed, MoverSpec mover, double speed = 120.0)
      : mover_(mover) {
    const sim::SceneDef& scene = sim::findScene("crowd");
    sim::Params p = scene.defaults();
    p.set(sim::param::count, static_cast<double>(count));
    p.set(sim::param::seed, static_cast<double>(seed % 1000000));
    p.set(sim::param::speed, speed);
    dt_ = p.get(sim::param::dt);
    sim::SceneSetup s = scene.build(p);
    const std::size_t heap0 = heapInUse();
    world_ = World(s.cellSize);
    for (const sim::Solid& solid : s.solids) {
      const ItemId id = world_.add(solid.rect);
      grow(id);
    }
    bodies_ = std::move(s.bodies);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      bodies_[i].item = world_.add(bodies_[i].rect);
      grow(bodies_[i].item);
      bodyBySlot_[bodies_[i].item.index] = static_cast<std::int32_t>(i);
    }
    items_ = s.solids.size() + bodies_.size();
    worldBytes_ = heapInUse() - heap0;
  }

  void tick(MoveTrace* trace = nullptr) {
    const auto filter = [this](ItemId item, ItemId other) {
      const sim::Body& b = bodies_[static_cast<std::size_t>(bodyBySlot_[item.index])];
      const std::int32_t o = bodyBySlot_[other.index];
      const std::uint32_t layer =
          o < 0 ? sim::kLayerSolid : bodies_[static_cast<std::size_t>(o)].layer;
      return (b.mask & layer) != 0 ? b.response : response::ignore;
    };
    for (sim::Body& b : bodies_) {
      const Vec2 goal = b.rect.position() + b.velocity * dt_;
      const MoveResult r = mover_.move(world_, b.item, goal, filter, trace);
      b.rect = b.rect.at(r.position);
      b.velocity = sim::respondVelocity(b.velocity, r.collisions);
      if (trace) {
        cells_ += trace->cells.size();
        candidates_ += trace->candidates.size();
        ++traced_;
      }
    }
  }

  [[nodiscard]] std::size_t bodies() const { return bodies_.size(); }
  [[nodiscard]] std::size_t items() const { return items_; }
  [[nodiscard]] double bytesPerItem() const {
    return static_cast<double>(worldBytes_) / static_cast<double>(items_);
  }
  [[nodiscard]] double cellsPerMove() const { return ratio(cells_); }
  [[nodiscard]] double candidatesPerMove() const { return ratio(candidates_); }

 private:
  void grow(ItemId id) {
    if (id.index >= bodyBySlot_.size()) bodyBySlot_.resize(id.index + 1, -1);
  }
  [[nodiscard]] double ratio(std::uint64_t n) const {
    return traced_ ? static_cast<double>(n) / static_cast<double>(traced_) : 0.0;
  }

  Mover mover_;
  double dt_ = 1.0 / 60.0;
  World world_;
  std::vector<sim::Body> bodies_;
  std::vector<std::int32_t> bodyBySlot_;
  std::size_t items_ = 0, worldBytes_ = 0;
  std::uint64_t cells_ = 0, candidates_ = 0, traced_ = 0;
};

/// Best of `repeats` timings of `ticks` ticks, in ms per tick.
template <class Tick>
double msPerTick(Tick&& tick, std::uint64_t ticks, int repeats) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    Stopwatch sw;
    for (std::uint64_t t = 0; t < ticks; ++t) tick();
    best = std::min(best, sw.seconds() * 1e3 / static_cast<double>(ticks));
  }
  return best;
}

// [SECTION] crowd table ---------------------------------------------------------------------------

struct CrowdRow {
  std::int64_t n;
  std::string mover;
  double ms, simMs, cells, candidates, bytes;
};

CrowdRow crowdRow(std::int64_t n, const std::string& mover, std::uint64_t seed, std::uint64_t ticks,
                  int repeats) {
  CrowdRun run(n, seed, parseMover(mover));
  for (int t = 0; t < 3; ++t) run.tick();  // warm: cells and buffers reach their steady sizes
  CrowdRow row{n, mover, 0, 0, 0, 0, run.bytesPerItem()};
  row.ms = msPerTick([&] { run.tick(); }, ticks, repeats);
  if constexpr (kTraceCompiledIn) {
    MoveTrace trace;
    run.tick(&trace);
    row.cells = run.cellsPerMove();
    row.candidates = run.candidatesPerMove();
  }
  const sim::SceneDef& scene = sim::findScene("crowd");
  sim::Params p = scene.defaults();
  p.set(sim::param::count, static_cast<double>(n));
  p.set(sim::param::seed, static_cast<double>(seed % 1000000));
  sim::SimConfig config;
  config.snapshotCapacity = 1;
  sim::Simulation s(scene, p, parseMover(mover), config);
  for (int t = 0; t < 3; ++t) s.tick();
  row.simMs = msPerTick([&] { s.tick(); }, std::max<std::uint64_t>(ticks / 2, 3), 1);
  return row;
}

// [SECTION] move length ---------------------------------------------------------------------------

struct LengthRow {
  double length;
  bool diagonal;
  double sweepNs, continuousNs, sweepCandidates, continuousCandidates;
};

double nsPerCheck(const Corridor& c, BroadPhase broad, std::uint64_t reps) {
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    Stopwatch sw;
    for (std::uint64_t i = 0; i < reps; ++i)
      keep(c.map.world.check(c.mover, c.goal, {}, {broad}).position);
    best = std::min(best, sw.seconds() * 1e9 / static_cast<double>(reps));
  }
  return best;
}

double candidatesOf(const Corridor& c, BroadPhase broad) {
  if constexpr (!kTraceCompiledIn) return 0.0;
  MoveTrace t;
  (void)c.map.world.check(c.mover, c.goal, {}, {broad, &t});
  return static_cast<double>(t.candidates.size());
}

LengthRow lengthRow(double length, bool diagonal, std::uint64_t reps) {
  const double a = length / std::sqrt(2.0);
  const Corridor c({404, 404}, diagonal ? Vec2{a, a} : Vec2{length, 0});
  return {length,
          diagonal,
          nsPerCheck(c, BroadPhase::bounds, reps),
          nsPerCheck(c, BroadPhase::swept, reps),
          candidatesOf(c, BroadPhase::bounds),
          candidatesOf(c, BroadPhase::swept)};
}

// [SECTION] lower bound ---------------------------------------------------------------------------
//
// One move's floor: the cells its broad phase must read, each at the cost of one cell probe,
// plus the candidates it must test, each at the cost of one exact pair test. Both kernels are
// timed here the way tv-microbench times them (sweepMiss, freeSpotCheck).

struct Kernels {
  double pairNs = 0, probeNs = 0;
};

Kernels kernels(std::uint64_t reps) {
  Kernels k;
  const Rect mover{0, 0, 8, 8}, wall{20, 40, 16, 16};
  Vec2 goal{30, 3};
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    Stopwatch sw;
    for (std::uint64_t i = 0; i < reps; ++i) {
      keep(goal);
      keep(sweepRect(mover, goal, wall).ti);
    }
    best = std::min(best, sw.seconds() * 1e9 / static_cast<double>(reps));
  }
  k.pairNs = best;
  // A free 8×8 spot inside one tile of a 32 px cell grid: one or more cell probes (an 8×8 rect
  // centred in a 16 px tile meets one cell, or two or four where tiles straddle cell lines).
  TileMap map(200);
  std::vector<Rect> spots;
  for (const Rect& r : map.free) {
    if (map.world.grid().cellsOf(r).count() == 1) spots.push_back(r);
  }
  best = 1e300;
  for (int r = 0; r < 3; ++r) {
    Stopwatch sw;
    for (std::uint64_t i = 0; i < reps; ++i) keep(map.world.anyOverlap(spots[i % spots.size()]));
    best = std::min(best, sw.seconds() * 1e9 / static_cast<double>(reps));
  }
  k.probeNs = best;
  return k;
}

// [SECTION] slow scenes ---------------------------------------------------------------------------

struct SlowScene {
  std::string label;
  std::string name;  // for --slow-scenes
  std::string scene;
  std::int64_t count;
  double speed;  // 0: the scene's default
};

struct SlowTiming {
  double ms = -1.0;            // best of the repeats, per tick; < 0 when not run
  double instructions = -1.0;  // per tick, over `ticks` more ticks; < 0 without the counter
};

SlowTiming simPerTick(const SlowScene& s, const std::string& mover, std::uint64_t seed,
                      std::uint64_t ticks, int repeats) {
  const sim::SceneDef& scene = sim::findScene(s.scene);
  sim::Params p = scene.defaults();
  p.set(sim::param::count, static_cast<double>(s.count));
  p.set(sim::param::seed, static_cast<double>(seed % 1000000));
  if (s.speed > 0) p.set(sim::param::speed, s.speed);
  sim::SimConfig config;
  config.snapshotCapacity = 1;
  sim::Simulation sim(scene, p, parseMover(mover), config);
  for (int t = 0; t < 30; ++t) sim.tick();  // past the landing: bodies at rest
  SlowTiming out;
  out.ms = msPerTick([&] { sim.tick(); }, ticks, repeats);
  const InstructionCounter counter;
  if (counter.available()) {
    const std::uint64_t before = counter.read();
    for (std::uint64_t t = 0; t < ticks; ++t) sim.tick();
    out.instructions = static_cast<double>(counter.read() - before) / static_cast<double>(ticks);
  }
  return out;
}

// [SECTION] bump-crowd ----------------------------------------------------------------------------

struct BumpRow {
  std::int64_t n;
  double cell;
  CrowdFilter filter;
  double ms, instructions, bytes;  // instructions per move: < 0 when the counter is unavailable
  std::uint64_t hash = 0;           // the crowd's state at the end of the run
};

BumpRow bumpRow(std::int64_t n, double cell, CrowdFilter filter, std::uint64_t seed,
                std::uint64_t ticks, int repeats, bool batched) {
  BumpCrowd crowd({n, cell, seed});
  const auto tick = [&] { batched ? crowd.tickBatched(filter) : crowd.tick(filter); };
  for (int t = 0; t < 3; ++t) tick();  // warm: cells and buffers reach their steady sizes
  BumpRow row{n, cell, filter, 0, -1, crowd.bytesPerItem()};
  row.ms = msPerTick(tick, ticks, repeats);
  const InstructionCounter counter;
  if (counter.available()) {
    const std::uint64_t before = counter.read();
    for (std::uint64_t t = 0; t < ticks; ++t) tick();
    row.instructions = static_cast<double>(counter.read() - before) /
                       static_cast<double>(ticks * static_cast<std::uint64_t>(n));
  }
  row.hash = crowd.stateHash();
  return row;
}

std::vector<std::int64_t> wholeNumbers(const Options& o, std::string_view flag,
                                       std::vector<double> fallback, double max) {
  std::vector<std::int64_t> out;
  for (const double c : o.numbers(flag, std::move(fallback))) {
    if (!(c >= 1 && c <= max && c == std::floor(c))) {
      throw UsageError{"--" + std::string(flag) + ": " + sig3(c) +
                       " is not a whole number in [1, " + sig3(max) + "]"};
    }
    out.push_back(static_cast<std::int64_t>(c));
  }
  return out;
}

std::string verdict(double measured, double target) {
  return measured <= target ? "met" : "MISSED by " + fixed(measured / target, 2) + "×";
}

void runBumpCrowd(const Options& o, int repeats, std::ostream& os) {
  const std::vector<std::int64_t> counts = wholeNumbers(
      o, "bump-counts", o.pick<std::vector<double>>({1000}, {1000, 10000}, {1000, 10000, 100000}),
      100000);
  const std::vector<double> cells =
      o.numbers("cells", o.pick<std::vector<double>>({32}, {16, 32, 64}, {16, 32, 64}));
  for (const double c : cells) {
    if (!(c >= 1 && c <= 4096)) throw UsageError{"--cells: " + sig3(c) + " is not in [1, 4096]"};
  }
  std::vector<CrowdFilter> filters;
  for (const std::string& f : o.names("filters", {"tiles", "all"})) {
    if (f != "tiles" && f != "all") throw UsageError{"--filters " + f + ": tiles or all"};
    filters.push_back(f == "tiles" ? CrowdFilter::tiles : CrowdFilter::all);
  }
  const auto ticksFor = [&](std::int64_t n) -> std::uint64_t {
    if (o.has("ticks")) return std::max<std::uint64_t>(1, parseCount("ticks", o.extra.at("ticks")));
    const double budget = o.pick(2e4, 2e5, 2e6);  // moves per repeat
    return static_cast<std::uint64_t>(std::clamp(budget / static_cast<double>(n), 3.0, 2000.0));
  };

  os << "### bump-crowd: bump.lua's benchmark scene\n\n"
     << "A 2000×2000 px world of 16×16 tiles (125×125; 6320×6320 for 10^5 movers, the same "
        "density): a solid border plus random horizontal platforms 3–12 tiles long until 30% of "
        "the grid is solid, one item per tile. N 8×8 movers at random free spots, random "
        "directions, speeds uniform in [30, 240] px/s; each tick (1/60 s) every mover makes one "
        "`World::move` with `slide` and flips the velocity component of each normal it reports. "
        "Filter `tiles`: movers ignore each other; `all`: they slide against each other too. "
        "**instr/move** is the CPU's instruction counter (perf_event_open; n/a where the kernel "
        "does not expose it — `valgrind --tool=callgrind` gives the same figure); bytes per item "
        "is the world's heap over its items (tiles + movers), right after it was filled.\n\n";
  Table table({"N:", "cell:", "filter", "ms/tick:", "ns/move:", "instr/move:", "bytes/item:"});
  // The crowd's state at the end of each row's run (the same flags run the same ticks): a change
  // that must keep every result bit for bit leaves this file as it was.
  Table hashes({"N:", "cell:", "filter", "state hash"});
  std::vector<BumpRow> rows;
  Progress progress("scale bump-crowd", counts.size() * cells.size() * filters.size());
  for (const std::int64_t n : counts) {
    for (const double cell : cells) {
      for (const CrowdFilter f : filters) {
        const BumpRow r = bumpRow(n, cell, f, o.seed, ticksFor(n), repeats, false);
        rows.push_back(r);
        table.add({std::to_string(n), fixed(cell, 0), filterName(f), fixed(r.ms, 3),
                   fixed(r.ms * 1e6 / static_cast<double>(n), 0),
                   r.instructions < 0 ? "n/a" : fixed(r.instructions, 0), fixed(r.bytes, 0)});
        hashes.add({std::to_string(n), fixed(cell, 0), filterName(f), hex(r.hash)});
        progress.step(std::to_string(n) + " cell " + fixed(cell, 0) + " " + filterName(f));
      }
    }
  }
  table.printMarkdown(os);
  table.writeCsv(o.out, "scale_bump_crowd.csv");
  hashes.writeCsv(o.out, "scale_bump_crowd_hashes.csv");
  // Targets, at the best cell size for each N.
  const auto best = [&](std::int64_t n, CrowdFilter f) -> const BumpRow* {
    const BumpRow* b = nullptr;
    for (const BumpRow& r : rows)
      if (r.n == n && r.filter == f && (!b || r.ms < b->ms)) b = &r;
    return b;
  };
  const std::pair<std::int64_t, double> targets[] = {{1000, 0.08}, {10000, 1.0}, {100000, 15.0}};
  for (const auto& [n, target] : targets) {
    const BumpRow* t = best(n, CrowdFilter::tiles);
    if (!t) continue;
    os << "Target: bump-crowd " << n << " `tiles` ≤ " << sig3(target)
       << " ms/tick: " << fixed(t->ms, 3) << " ms at cell " << fixed(t->cell, 0) << " ("
       << verdict(t->ms, target) << ")";
    if (const BumpRow* a = best(n, CrowdFilter::all)) {
      os << "; `all` " << fixed(a->ms, 3) << " ms, " << fixed(a->ms / t->ms, 2)
         << "× `tiles` (target ≤ 1.3×: " << (a->ms / t->ms <= 1.3 ? "met" : "MISSED") << ")";
    }
    os << ".\n\n";
  }
  double bytes = 0;
  for (const BumpRow& r : rows) bytes = std::max(bytes, r.bytes);
  os << "Target: ≤ 128 bytes per item: at most " << fixed(bytes, 0) << " (" << verdict(bytes, 128)
     << ").\n\n";

  // Moving versus moving: the same crowd, `all`, through one tv::Batch per tick.
  const std::vector<std::int64_t> batchCounts = wholeNumbers(
      o, "batch-counts", o.pick<std::vector<double>>({100, 1000}, {100, 1000, 10000}, {100, 1000, 10000}),
      100000);
  os << "### bump-crowd through tv::Batch (moving versus moving)\n\n"
     << "The same scene with filter `all`, every mover in one `Batch::step` per tick: movers meet "
        "by relative motion during the tick (earliest time of impact first), which one move at a "
        "time cannot do. Cell 32. The step searches each body against the world once and again "
        "only when an event changes its path, and pairs only among bodies whose swept hulls share "
        "a cell of its hull grid.\n\n";
  Table batch({"N:", "ms/tick:", "ns/move:", "instr/move:"});
  std::vector<BumpRow> batchRows;
  for (const std::int64_t n : batchCounts) {
    const BumpRow r = bumpRow(n, 32, CrowdFilter::all, o.seed, ticksFor(n), repeats, true);
    batchRows.push_back(r);
    batch.add({std::to_string(n), fixed(r.ms, 3), fixed(r.ms * 1e6 / static_cast<double>(n), 0),
               r.instructions < 0 ? "n/a" : fixed(r.instructions, 0)});
  }
  batch.printMarkdown(os);
  batch.writeCsv(o.out, "scale_batch.csv");
  for (const BumpRow& r : batchRows) {
    const double target = r.n <= 1000 ? 1.0 : 10.0;
    if (r.n != 1000 && r.n != 10000) continue;
    os << "Target: tv::Batch of " << r.n << " colliding movers ≤ " << sig3(target)
       << " ms/tick: " << fixed(r.ms, 3) << " ms (" << verdict(r.ms, target) << ").\n\n";
  }
}

// [SECTION] slow scenes, the table ---------------------------------------------------------------

// The scenes by the names --slow-scenes takes, in the table's order.
std::vector<SlowScene> slowScenes(std::int64_t n) {
  return {
      {"crowd, 60 px/s (1 px a tick)", "crowd-1px", "crowd", n, 60},
      {"crowd, 120 px/s (2 px a tick)", "crowd-2px", "crowd", n, 120},
      {"rest-floor (bodies resting on a floor under gravity)", "rest-floor", "rest-floor", n, 0},
      {"seam-walk (walking on a floor of tiles, 240 px/s)", "seam-walk", "seam-walk", n, 0},
  };
}

// Each case can run alone (--slow-only --slow-scenes S --slow-movers M) so that an instruction
// count (valgrind --tool=callgrind --toggle-collect='tv::sim::Simulation::tick(*') covers one
// scene and one mover: 30 warm-up ticks, then --ticks timed ones.
int runSlowScenes(const Options& o, int repeats, std::ostream& os) {
  const std::vector<SlowScene> all =
      slowScenes(o.has("slow-count") ? wholeNumbers(o, "slow-count", {}, 10000).front()
                                     : o.pick<std::int64_t>(500, 5000, 10000));
  std::vector<std::string> names;
  for (const SlowScene& s : all) names.push_back(s.name);
  std::vector<SlowScene> slow;
  for (const std::string& n : o.names("slow-scenes", names)) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const SlowScene& s) { return s.name == n; });
    if (it == all.end()) {
      std::string list;
      for (const std::string& k : names) list += (list.empty() ? "" : ", ") + k;
      throw UsageError{"--slow-scenes " + n + ": unknown scene (known: " + list + ")"};
    }
    slow.push_back(*it);
  }
  const std::vector<std::string> movers =
      o.names("slow-movers", {"discrete", "adaptive", "continuous"});
  for (const std::string& m : movers) {
    if (m != "discrete" && m != "adaptive" && m != "continuous") {
      throw UsageError{"--slow-movers " + m + ": discrete, adaptive or continuous"};
    }
  }
  const std::uint64_t slowTicks =
      o.has("ticks") ? std::max<std::uint64_t>(1, parseCount("ticks", o.extra.at("ticks")))
                     : o.pick<std::uint64_t>(10, 60, 300);
  os << "### adaptive against discrete where nothing moves fast\n\n"
     << "Whole tv::sim::Simulation ticks (rules and snapshot included, the same for every "
        "mover). Target: adaptive within 10% of discrete. **in instructions** is the same ratio "
        "from the CPU's instruction counter (n/a where the kernel does not expose it; "
        "`valgrind --tool=callgrind` gives it, one scene and mover at a time).\n\n";
  Table slowTable({"scene", "N:", "discrete ms:", "adaptive ms:", "continuous ms:",
                   "adaptive / discrete:", "in instructions:"});
  Progress progress("scale slow scenes", slow.size());
  for (const SlowScene& s : slow) {
    const auto timed = [&](const char* mover) {
      const bool wanted = std::find(movers.begin(), movers.end(), mover) != movers.end();
      return wanted ? simPerTick(s, mover, o.seed, slowTicks, repeats) : SlowTiming{};
    };
    const SlowTiming dis = timed("discrete");
    const SlowTiming ada = timed("adaptive");
    const SlowTiming con = timed("continuous");
    const auto ms = [](const SlowTiming& t) { return t.ms < 0 ? std::string() : fixed(t.ms, 3); };
    const auto ratio = [](double a, double d) {
      return a < 0 || d <= 0 ? std::string("n/a")
                             : fixed(a / d, 2) + "×" + (a / d <= 1.10 ? "" : " (missed)");
    };
    slowTable.add({s.label, std::to_string(s.count), ms(dis), ms(ada), ms(con),
                   ratio(ada.ms, dis.ms), ratio(ada.instructions, dis.instructions)});
    progress.step("slow " + s.name);
  }
  slowTable.printMarkdown(os);
  slowTable.writeCsv(o.out, "scale_slow_scenes.csv");
  return 0;
}

}  // namespace

// [SECTION] the study -----------------------------------------------------------------------------

int runScale(const Options& o) {
  const std::vector<double> countsD =
      o.numbers("counts", o.pick<std::vector<double>>({100, 1000}, {100, 1000, 10000, 100000},
                                                      {100, 1000, 10000, 100000}));
  std::vector<std::int64_t> counts;
  for (const double c : countsD) {
    if (!(c >= 1 && c <= 100000 && c == std::floor(c))) {
      throw UsageError{"--counts: " + sig3(c) + " is not a whole number in [1, 100000]"};
    }
    counts.push_back(static_cast<std::int64_t>(c));
  }
  const std::vector<std::string> movers = o.names("movers", {"sweep", "continuous", "adaptive"});
  for (const std::string& m : movers) {
    try {
      (void)parseMover(m);
    } catch (const Error& e) {
      throw UsageError{"--movers " + m + ": " + e.what()};
    }
  }
  const bool crowdOnly = o.has("crowd-only");
  const bool bumpOnly = o.has("bump-only");
  const bool slowOnly = o.has("slow-only");
  const int repeats = o.pick(1, 3, 5);
  const auto ticksFor = [&](std::int64_t n) -> std::uint64_t {
    if (o.has("ticks")) return std::max<std::uint64_t>(1, parseCount("ticks", o.extra.at("ticks")));
    const double budget = o.pick(2e4, 2e5, 2e6);  // moves per repeat
    return static_cast<std::uint64_t>(std::clamp(budget / static_cast<double>(n), 3.0, 2000.0));
  };

  std::ostream& os = std::cout;
  printHeading(os, "scale: cost against crowd size and move length", modeName(o.mode), o.seed,
               o.out);
  os << "Single thread. Tracing compiled " << (kTraceCompiledIn ? "in (and off)" : "out")
     << ". Times are the best of " << repeats << " repeat(s).\n\n";

  if (slowOnly) return runSlowScenes(o, repeats, os);
  if (!crowdOnly) runBumpCrowd(o, repeats, os);
  if (bumpOnly) return 0;

  // -- crowd
  os << "### crowd: 8×8 movers among 16×16 tiles (~30% solid, world grown with N), 120 px/s\n\n"
     << "**ms/tick** moves every body once the way tv::sim::Simulation does (same filter and "
        "velocity response) without the scene's checking rules or the snapshot ring; **sim "
        "ms/tick** is tv::sim::Simulation::tick itself, whose crowd rules add one overlap query "
        "per move (to count overlaps) and which records a snapshot. Cells and candidates per "
        "move come from a traced tick; bytes per item is the world's heap over its items "
        "(tiles + movers).\n\n";
  Table crowd({"N:", "mover", "ms/tick:", "moves/s:", "ns/move:", "sim ms/tick:", "cells/move:",
               "candidates/move:", "bytes/item:"});
  Progress progress("scale", counts.size() * movers.size() + (crowdOnly ? 0 : 9));
  std::vector<CrowdRow> rows;
  for (const std::int64_t n : counts) {
    for (const std::string& m : movers) {
      const CrowdRow r = crowdRow(n, m, o.seed, ticksFor(n), repeats);
      rows.push_back(r);
      const double moves = static_cast<double>(n);
      crowd.add({std::to_string(n), m, fixed(r.ms, 3), sig3(moves / (r.ms * 1e-3)),
                 fixed(r.ms * 1e6 / moves, 0), fixed(r.simMs, 3),
                 kTraceCompiledIn ? fixed(r.cells, 2) : "n/a",
                 kTraceCompiledIn ? fixed(r.candidates, 2) : "n/a", fixed(r.bytes, 0)});
      progress.step("crowd " + std::to_string(n) + " " + m);
    }
  }
  crowd.printMarkdown(os);
  crowd.writeCsv(o.out, "scale_crowd.csv");
  for (const CrowdRow& r : rows) {
    if (r.n == 10000 && r.mover == "continuous") {
      os << "Target: crowd of 10^4 with continuous ≤ 1 ms/tick (stretch 0.3 ms): measured "
         << fixed(r.ms, 3) << " ms/tick ("
         << (r.ms <= 0.3   ? "meets the stretch goal"
             : r.ms <= 1.0 ? "met; stretch missed by " + fixed(r.ms / 0.3, 2) + "×"
                           : "MISSED by " + fixed(r.ms / 1.0, 2) + "×")
         << "); the full Simulation tick " << fixed(r.simMs, 3) << " ms.\n\n";
    }
  }
  if (crowdOnly) return 0;

  // -- move length
  os << "### one move against its length\n\n"
     << "An 8×8 mover in a 256×256 tile map (16 px tiles, ~30% solid, 32 px cells) through a "
        "corridor cut exactly along its path, so the move runs its whole length with solid tiles "
        "beside it (candidates, never hit). `sweep` reads every cell of the move's bounding box; "
        "`continuous` only the cells the rect crosses. `adaptive` makes such a move as "
        "`continuous` does (it reads a move's bounding box only for a body pressing into what it "
        "touches, and only when the box spans at most 4 cells), so it is not listed.\n\n";
  Table length({"px:", "direction",
                "sweep ns:", "continuous ns:", "sweep candidates:", "continuous candidates:"});
  const std::uint64_t reps = o.pick<std::uint64_t>(2000, 20000, 100000);
  std::vector<LengthRow> lengths;
  for (const double len : {64.0, 240.0, 960.0, 1900.0}) {
    for (const bool diag : {false, true}) {
      const LengthRow r = lengthRow(
          len, diag, std::max<std::uint64_t>(reps / static_cast<std::uint64_t>(len / 32 + 1), 50));
      lengths.push_back(r);
      length.add({fixed(len, 0), diag ? "diagonal" : "horizontal", fixed(r.sweepNs, 0),
                  fixed(r.continuousNs, 0), kTraceCompiledIn ? fixed(r.sweepCandidates, 0) : "n/a",
                  kTraceCompiledIn ? fixed(r.continuousCandidates, 0) : "n/a"});
      progress.step("length " + fixed(len, 0));
    }
  }
  length.printMarkdown(os);
  length.writeCsv(o.out, "scale_length.csv");
  const LengthRow& h = lengths[6];
  const LengthRow& d = lengths[7];
  os << "Target: a 1900 px diagonal move ≤ 2× a 1900 px horizontal one (bump.lua: 12×): "
     << "continuous " << fixed(d.continuousNs / h.continuousNs, 2) << "× ("
     << verdict(d.continuousNs / h.continuousNs, 2.0) << "), sweep "
     << fixed(d.sweepNs / h.sweepNs, 2) << "× (the bounding-box broad phase, for comparison).\n\n";

  // -- lower bound
  const Kernels k = kernels(o.pick<std::uint64_t>(200000, 2000000, 10000000));
  progress.step("kernels");
  os << "### how far one move is from its lower bound\n\n"
     << "Kernels (as in tv-microbench): one exact pair test (sweepRect, a miss) "
     << fixed(k.pairNs, 1) << " ns; one free-spot probe of a single cell (anyOverlap) "
     << fixed(k.probeNs, 1)
     << " ns. A move's floor = cells/move × probe + candidates/move × pair test.\n\n";
  Table bound(
      {"case", "measured ns/move:", "cells:", "candidates:", "floor ns:", "measured / floor:"});
  for (const CrowdRow& r : rows) {
    if (r.mover != "continuous" || !kTraceCompiledIn) continue;
    const double ns = r.ms * 1e6 / static_cast<double>(r.n);
    const double floor = r.cells * k.probeNs + r.candidates * k.pairNs;
    bound.add({"crowd N=" + std::to_string(r.n) + " continuous", fixed(ns, 0), fixed(r.cells, 2),
               fixed(r.candidates, 2), fixed(floor, 0), fixed(ns / floor, 2) + "×"});
  }
  for (const LengthRow* r : {&h, &d}) {
    if (!kTraceCompiledIn) break;
    // The corridor's cells are not counted by the check itself; the candidates dominate.
    const double floor = r->continuousCandidates * k.pairNs;
    bound.add({"1900 px " + std::string(r->diagonal ? "diagonal" : "horizontal") +
                   " continuous (candidates only)",
               fixed(r->continuousNs, 0), "", fixed(r->continuousCandidates, 0), fixed(floor, 0),
               fixed(r->continuousNs / floor, 2) + "×"});
  }
  bound.printMarkdown(os);
  bound.writeCsv(o.out, "scale_lower_bound.csv");

  return runSlowScenes(o, repeats, os);
}

}  // namespace tv::bench
