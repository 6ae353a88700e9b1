// pareto: run time against position error. Every mover configuration makes the same seeded
// random slide moves; each end position is compared with an exact rational reference
// (exact_slide.hpp), and the same moves are timed.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "exact_slide.hpp"
#include "frame_clock.hpp"
#include "plot.hpp"
#include "report.hpp"
#include "studies.hpp"
#include "tv/mover.hpp"
#include "tv/world.hpp"

namespace tv::bench {
namespace {

constexpr double kTile = 16.0;
constexpr int kSide = 64;  // tiles per side of the map
constexpr double kMaxMove = 64.0;

struct Config {
  std::string label;
  MoverSpec spec;
};

std::vector<Config> configs() {
  std::vector<Config> out;
  for (const MoverKind inner : {MoverKind::discrete, MoverKind::sweep}) {
    for (const int div : {1, 2, 4, 8, 16, 32}) {
      MoverSpec s;
      s.kind = MoverKind::substep;
      s.inner = inner;
      s.maxStep = kTile / div;
      out.push_back({std::string(inner == MoverKind::sweep ? "substep-sweep" : "substep-discrete") +
                         " tile/" + std::to_string(div),
                     s});
    }
  }
  for (const char* name : {"discrete", "sweep", "continuous", "pixel", "adaptive"}) {
    out.push_back({name, parseMover(name)});
  }
  return out;
}

struct Workload {
  World world{32};
  std::vector<Rect> solids;
  struct Move {
    Rect start;
    Vec2 goal;
    ExactMove exact;
  };
  std::vector<Move> moves;
  ItemId mover;
};

void build(Workload& w, std::size_t count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Rect> freeTiles;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const Rect r{x * kTile, y * kTile, kTile, kTile};
      const bool border = x == 0 || y == 0 || x == kSide - 1 || y == kSide - 1;
      if (border || rng.uniform() < 0.3) {
        w.solids.push_back(r);
        w.world.add(r);
      } else {
        freeTiles.push_back(r);
      }
    }
  }
  w.mover = w.world.add({-1000, -1000, 8, 8});
  std::vector<Rect> near;
  std::vector<ItemId> found;
  while (w.moves.size() < count) {
    // Half 2×2, half 8×8, anywhere inside a free tile: general-position doubles.
    const double size = rng.uniform() < 0.5 ? 2.0 : 8.0;
    const Rect& t =
        freeTiles[static_cast<std::size_t>(rng.uniform() * static_cast<double>(freeTiles.size()))];
    const Rect start{t.x + rng.uniform() * (kTile - size), t.y + rng.uniform() * (kTile - size),
                     size, size};
    const double a = 2 * std::numbers::pi * rng.uniform();
    const double len = kMaxMove * rng.uniform();
    const Vec2 goal = start.position() + Vec2{std::cos(a), std::sin(a)} * len;
    const Rect hull = unite(start, start.at(goal));
    w.world.queryRect(hull, found, w.mover);
    near.clear();
    for (const ItemId id : found) near.push_back(w.world.rect(id));
    w.moves.push_back({start, goal, exactSlide(near, start.size(), start.position(), goal)});
  }
}

struct Stats {
  double ns = 0, maxErr = 0, p99 = 0, mean = 0;
  std::size_t tunnelled = 0, exact = 0;
};

// Directly behind an obstacle the exact move stopped against: past its far edge along the
// normal, and still within its span on the other axis. (Going around the obstacle's end — as
// substep pieces do, keeping the move's direction — is not tunnelling.)
bool tunnelledPast(const Rect& end, const ExactMove& ref) {
  for (const ExactHit& h : ref.hits) {
    const Rect& o = h.obstacle;
    const bool spanY = end.y < o.bottom() && o.y < end.bottom();
    const bool spanX = end.x < o.right() && o.x < end.right();
    if ((h.normal.x < 0 && end.x >= o.right() && spanY) ||
        (h.normal.x > 0 && end.right() <= o.x && spanY) ||
        (h.normal.y < 0 && end.y >= o.bottom() && spanX) ||
        (h.normal.y > 0 && end.bottom() <= o.y && spanX)) {
      return true;
    }
  }
  return false;
}

Stats measure(Workload& w, const Config& c, int repeats) {
  Stats s;
  Mover mover(c.spec);
  std::vector<double> errors;
  errors.reserve(w.moves.size());
  for (const Workload::Move& m : w.moves) {
    w.world.update(w.mover, m.start);
    mover.reset();  // the pixel mover's remainder belongs to one body's history, not this move
    const Vec2 end = mover.move(w.world, w.mover, m.goal).position;
    const double err = std::hypot(end.x - m.exact.position.x, end.y - m.exact.position.y);
    errors.push_back(err);
    const Rect endRect = m.start.at(end);
    if (tunnelledPast(endRect, m.exact) || w.world.anyOverlap(endRect, w.mover)) ++s.tunnelled;
    if (err == 0.0) ++s.exact;
  }
  std::sort(errors.begin(), errors.end());
  s.maxErr = errors.back();
  s.p99 = errors[static_cast<std::size_t>(0.99 * static_cast<double>(errors.size() - 1))];
  double sum = 0;
  for (const double e : errors) sum += e;
  s.mean = sum / static_cast<double>(errors.size());
  // Time: the moves minus the cost of putting the mover back at each start.
  double best = 1e300, base = 1e300;
  for (int r = 0; r < repeats; ++r) {
    Stopwatch b;
    for (const Workload::Move& m : w.moves) {
      w.world.update(w.mover, m.start);
      keep(m.goal);
    }
    base = std::min(base, b.seconds());
    Stopwatch sw;
    for (const Workload::Move& m : w.moves) {
      w.world.update(w.mover, m.start);
      keep(mover.move(w.world, w.mover, m.goal).position);
    }
    best = std::min(best, sw.seconds());
  }
  s.ns = std::max(best - base, 0.0) * 1e9 / static_cast<double>(w.moves.size());
  return s;
}

// One row of a pareto.csv written by this study: configuration, ns/move, max, p99 and mean
// error, exact and tunnelled shares ("18.7%"), front. The file is untrusted: every field is
// checked and a bad one is refused naming the line and the column.
std::vector<std::pair<std::string, Stats>> readPublished(const std::string& path,
                                                         std::size_t moves) {
  // A published pareto.csv is about 1 KB: anything over 1 MB is not one (and is not read).
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) throw UsageError{"--from-csv " + path + ": cannot read it (" + ec.message() + ")"};
  if (bytes > (1u << 20))
    throw UsageError{"--from-csv " + path + ": " + std::to_string(bytes) +
                     " bytes; a pareto.csv is far smaller (at most 1 MB is read)"};
  std::ifstream in(path);
  if (!in) throw UsageError{"--from-csv " + path + ": cannot open it"};
  std::vector<std::pair<std::string, Stats>> rows;
  std::string line;
  std::size_t number = 0;
  const auto bad = [&](const std::string& what) {
    return UsageError{"--from-csv " + path + ":" + std::to_string(number) + ": " + what};
  };
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (line.rfind("configuration,ns/move,max error px,", 0) != 0)
        throw bad("expected the header of a pareto.csv, got '" + line.substr(0, 60) + "'");
      continue;
    }
    if (line.empty()) continue;
    if (rows.size() >= 1000) throw bad("more than 1000 rows");
    std::vector<std::string> f;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      f.push_back(line.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (f.size() != 8) throw bad("expected 8 fields, got " + std::to_string(f.size()));
    const auto num = [&](std::size_t k, const char* column) {
      double v = -1;
      try {
        v = parseNumber(column, f[k]);
      } catch (const UsageError&) {
        v = -1;
      }
      if (!(v >= 0)) throw bad(std::string(column) + ": expected a number >= 0, got '" + f[k] + "'");
      return v;
    };
    const auto share = [&](std::size_t k, const char* column) {
      if (f[k].empty() || f[k].back() != '%') throw bad(std::string(column) + ": expected N%");
      f[k].pop_back();
      const double pct = num(k, column);
      if (pct > 100) throw bad(std::string(column) + ": over 100%");
      return static_cast<std::size_t>(std::llround(pct * static_cast<double>(moves) / 100.0));
    };
    Stats st;
    st.ns = num(1, "ns/move");
    st.maxErr = num(2, "max error px");
    st.p99 = num(3, "p99 error px");
    st.mean = num(4, "mean error px");
    st.exact = share(5, "exact");
    st.tunnelled = share(6, "tunnelled");
    rows.emplace_back(f[0], st);
  }
  if (rows.empty()) throw bad("no rows");
  return rows;
}

}  // namespace

int runPareto(const Options& o) {
  const std::size_t moves = o.has("moves") ? parseCount("moves", o.extra.at("moves"))
                                           : o.pick<std::size_t>(500, 20000, 100000);
  if (moves < 100 || moves > 10000000) {
    throw UsageError{"--moves " + std::to_string(moves) + ": expected 100 to 10000000"};
  }
  const int repeats = o.pick(1, 3, 5);
  // A published file is read (and refused) before anything is printed.
  const auto published = o.has("from-csv") ? readPublished(o.extra.at("from-csv"), moves)
                                           : std::vector<std::pair<std::string, Stats>>{};
  std::vector<std::string> labels;
  std::vector<Stats> stats;
  std::ostream& os = std::cout;
  printHeading(os, "pareto: run time against position error", modeName(o.mode), o.seed, o.out);
  os << "Workload: " << moves
     << " slide moves in a 64×64 map of 16 px tiles (~30% solid, walled, 32 px cells); movers "
        "half 2×2, half 8×8, starting anywhere in a free tile (general-position doubles); each "
        "move in a uniform random direction, 0 to 64 px long (up to 3840 px/s at 60 Hz). "
        "**Error** is the distance (px) from the exact end — the same move slid in exact "
        "rational arithmetic (GMP) and rounded once — to where the mover ended. **Tunnelled**: "
        "ended past the far side of an obstacle the exact move was stopped by, or inside a "
        "solid. **ns/move** is the best of "
     << repeats
     << " timed passes, minus the cost of placing the mover at each start. The substep movers "
        "differ from one slide by design, not only by rounding: each piece keeps the move's "
        "direction, so after sliding off the end of a wall they resume it where a slide goes on "
        "along the wall; their errors of tens of px are mostly that. Likewise pixel moves along x "
        "then y, a staircase that can go round a corner the straight move hits: its "
        "'tunnelled' shots are that, never a pass through a solid (it tests every pixel).\n\n";
  if (!published.empty()) {
    for (auto& [label, st] : published) {
      labels.push_back(label);
      stats.push_back(st);
    }
    os << "(Numbers read from " << o.extra.at("from-csv") << ", not measured again.)\n\n";
  } else {
    Workload w;
    build(w, moves, o.seed);
    const std::vector<Config> cs = configs();
    Progress progress("pareto", cs.size());
    for (const Config& c : cs) {
      labels.push_back(c.label);
      stats.push_back(measure(w, c, repeats));
      progress.step(c.label);
    }
  }
  Table t({"configuration", "ns/move:", "max error px:", "p99 error px:", "mean error px:",
           "exact:", "tunnelled:", "front"});
  // The front: among the configurations that never tunnel, those no other is both at least as
  // fast as and at most as wrong as (by max error). A mover that tunnels is never on it, however
  // fast: the front reads "the fastest among the correct ones" (the plot marks the others).
  std::vector<bool> front(labels.size(), false);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (stats[i].tunnelled > 0) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < labels.size(); ++j) {
      if (j == i || stats[j].tunnelled > 0) continue;
      const bool noWorse = stats[j].ns <= stats[i].ns && stats[j].maxErr <= stats[i].maxErr;
      const bool better = stats[j].ns < stats[i].ns || stats[j].maxErr < stats[i].maxErr;
      if (noWorse && better) dominated = true;
    }
    front[i] = !dominated;
  }
  ScatterPlot plot;
  plot.title = "Run time against position error, " + std::to_string(moves) + " slide moves";
  plot.subtitle = "error against an exact rational reference; seed " + std::to_string(o.seed);
  plot.xLabel = "ns per move (log)";
  plot.yLabel = "max position error, px (log)";
  plot.legendGood = "never tunnels";
  plot.legendBad = "tunnels";
  plot.legendFront = "Pareto front of the movers that never tunnel (time, max error)";
  plot.keyColumns = {"ns/move", "max err px", "tunnelled"};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const Stats& s = stats[i];
    t.add({labels[i], fixed(s.ns, 0), sig3(s.maxErr), sig3(s.p99), sig3(s.mean),
           percent(static_cast<double>(s.exact), static_cast<double>(moves)),
           percent(static_cast<double>(s.tunnelled), static_cast<double>(moves)),
           front[i] ? "yes" : ""});
    plot.points.push_back({labels[i], std::max(s.ns, 1.0), s.maxErr, s.tunnelled > 0, front[i],
                           {fixed(s.ns, 0), sig3(s.maxErr),
                            percent(static_cast<double>(s.tunnelled), static_cast<double>(moves))}});
  }
  t.printMarkdown(os);
  t.writeCsv(o.out, "pareto.csv");
  if (canPlot()) {
    const auto png = o.out / "pareto.png";
    writeScatterPng(plot, png);
    os << "Plot: " << png.string() << "\n";
  } else {
    os << "Plot: not written (tv-bench was built without Dear ImGui and stb)\n";
  }
  return 0;
}

}  // namespace tv::bench
