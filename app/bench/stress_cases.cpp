// The stress cases. Index: [SECTION] helpers · [SECTION] bad input · [SECTION] extreme values ·
// [SECTION] exact contact · [SECTION] many items · [SECTION] time steps · [SECTION] geometry
#include "stress_cases.hpp"

#include <malloc.h>

#include <cmath>
#include <limits>
#include <string>

#include "report.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace tv::bench {
namespace {

// [SECTION] helpers -------------------------------------------------------------------------------

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string num(double v) {
  return formatNumber(v);
}
std::string pos(Vec2 p) {
  return "(" + num(p.x) + ", " + num(p.y) + ")";
}

/// Runs `f`, which must throw tv::Error whose message contains `mention`, leaving `world`'s
/// state hash as it was.
template <class F>
CaseResult throwsUnchanged(const World& world, std::string_view mention, F&& f) {
  const std::uint64_t before = world.stateHash();
  try {
    f();
  } catch (const Error& e) {
    const std::string what = e.what();
    const bool named = what.find(mention) != std::string::npos;
    const bool same = world.stateHash() == before;
    return {"tv::Error \"" + what + "\"" + (same ? ", world unchanged" : ", WORLD CHANGED"),
            named && same};
  }
  return {"no exception", false};
}

/// A world with one 16 px tile wall at x = 100 and an 8×8 mover at the origin.
struct Wall {
  World world{16};
  ItemId wall, mover;
  explicit Wall(Rect moverRect = {0, 0, 8, 8}, Rect wallRect = {100, -8, 16, 32}) {
    wall = world.add(wallRect);
    mover = world.add(moverRect);
  }
};

/// Every mover by name, moved once from the same start in a fresh world built by `make`.
template <class Make, class Check>
CaseResult everyMover(Make&& make, Vec2 goal, Check&& check) {
  std::string got;
  bool pass = true;
  for (const std::string_view name : moverNames()) {
    auto setup = make();
    Mover m(parseMover(name));
    const MoveResult r = m.move(setup.world, setup.mover, goal);
    const auto [ok, text] = check(setup, r, name);
    if (!ok) pass = false;
    got += (got.empty() ? "" : "; ") + std::string(name) + " " + text;
  }
  return {got, pass};
}

std::size_t heapInUse() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;  // small chunks + mmapped large ones
}

// [SECTION] bad input -----------------------------------------------------------------------------

void badInput(std::vector<StressCase>& out) {
  out.push_back(
      {"add a rect with x = NaN", "tv::Error naming x and nan; world unchanged", [] {
         Wall w;
         return throwsUnchanged(w.world, "nan", [&] { (void)w.world.add({kNan, 0, 8, 8}); });
       }});
  out.push_back(
      {"add a rect with w = +Inf", "tv::Error naming w and inf; world unchanged", [] {
         Wall w;
         return throwsUnchanged(w.world, "inf", [&] { (void)w.world.add({0, 0, kInf, 8}); });
       }});
  out.push_back(
      {"add a rect with w = 0", "tv::Error naming w; world unchanged", [] {
         Wall w;
         return throwsUnchanged(w.world, "w must be", [&] { (void)w.world.add({0, 0, 0, 8}); });
       }});
  out.push_back({"add a rect with h = -3", "tv::Error naming h and -3; world unchanged", [] {
                   Wall w;
                   return throwsUnchanged(w.world, "-3", [&] { (void)w.world.add({0, 0, 8, -3}); });
                 }});
  out.push_back({"World with cell size 0, -1, NaN, 5e-324, 1e154",
                 "tv::Error for each (cell sizes lie in [2^-485, 2^500])", [] {
                   int threw = 0;
                   for (const double c : {0.0, -1.0, kNan, 5e-324, 1e154}) {
                     try {
                       World w(c);
                     } catch (const Error&) {
                       ++threw;
                     }
                   }
                   return CaseResult{std::to_string(threw) + " of 5 threw", threw == 5};
                 }});
  for (const double bad : {kNan, kInf, -kInf}) {
    out.push_back({"every mover: goal x = " + num(bad),
                   "tv::Error from each of the 7 movers; world unchanged", [bad] {
                     int ok = 0;
                     std::string got;
                     for (const std::string_view name : moverNames()) {
                       Wall w;
                       Mover m(parseMover(name));
                       const CaseResult r = throwsUnchanged(w.world, "goal.x", [&] {
                         (void)m.move(w.world, w.mover, {bad, 0});
                       });
                       if (r.pass) {
                         ++ok;
                       } else {
                         got += " " + std::string(name) + ": " + r.got;
                       }
                     }
                     return CaseResult{
                         std::to_string(ok) + " of 7 threw naming goal.x, world unchanged" + got,
                         ok == 7};
                   }});
  }
}

// [SECTION] extreme values ------------------------------------------------------------------------

void extremes(std::vector<StressCase>& out) {
  out.push_back(
      {"denormal wall width: {100, -8, 5e-324, 32}",
       "tv::Error naming w=5e-324 and x=100: its right edge rounds to 100, a rect with no "
       "interior that only blocked like a line; world unchanged",
       [] {
         Wall w;
         return throwsUnchanged(w.world, "w=5e-324 is below the resolution of x=100",
                                [&] { (void)w.world.add({100, -8, 5e-324, 32}); });
       }});
  out.push_back(
      {"a wall at x = 1e155 in a world of 1e140 cells (beyond the range, 2^500 ≈ 3.27e150)",
       "tv::Error naming x and 1e+155 (past 2^500 the exact time comparison overflows); world "
       "unchanged",
       [] {
         World world(1e140);
         return throwsUnchanged(world, "x must be within ±2^500 (about 3.27e150), but was 1e+155",
                                [&] { (void)world.add({1e155, -1e141, 1e141, 2e141}); });
       }});
  out.push_back({"denormal start x = 5e-324, moving into the wall",
                 "stops with its right edge exactly on the wall: x = 92", [] {
                   Wall w({5e-324, 0, 8, 8});
                   const MoveResult r = w.world.move(w.mover, {150, 0});
                   return CaseResult{"ended at " + pos(r.position), r.position == Vec2{92, 0}};
                 }});
  out.push_back(
      {"1e9 px/s for one 1/60 s tick into a 16 px wall (sweep, continuous, adaptive)",
       "each stops at x = 92, right edge on the wall", [] {
         std::string got;
         bool pass = true;
         for (const std::string_view name : {"sweep", "continuous", "adaptive"}) {
           Wall w;
           Mover m(parseMover(name));
           const MoveResult r = m.move(w.world, w.mover, {1e9 / 60.0, 0});
           pass = pass && r.position == Vec2{92, 0};
           got += (got.empty() ? "" : "; ") + std::string(name) + " " + pos(r.position);
         }
         return CaseResult{got + " (substep movers would need 2·10^6 pieces: see tunnel)", pass};
       }});
  for (const double offset : {0.0, 1e6, 1e9}) {
    out.push_back(
        {"seam floor at offset " + num(offset) + ": walker 13.7 px across 1000 tiles (continuous)",
         "no seam snags; the walker's bottom equals the floor's top bit for bit every tick",
         [offset] {
           const sim::SceneDef& scene = sim::findScene("seam-walk");
           sim::Params p = scene.defaults();
           p.set(sim::param::offset, offset);
           p.set(sim::param::size, 13.7);
           p.set(sim::param::count, 8);
           sim::SimConfig config;
           config.snapshotCapacity = 1;
           sim::Simulation s(scene, p, parseMover("continuous"), config);
           std::uint64_t off = 0;
           const double floorTop = s.solids().front().rect.y;
           for (int t = 0; t < 240; ++t) {
             s.tick();
             for (const sim::Body& b : s.bodies()) off += b.rect.bottom() != floorTop;
           }
           return CaseResult{std::to_string(s.counters().snags) + " snags, " + std::to_string(off) +
                                 " body-ticks off the floor",
                             s.counters().snags == 0 && off == 0};
         }});
  }
  out.push_back({"resting against a wall at offset 1e9 (rest-wall, continuous, 600 ticks)",
                 "0 jitter: a pressed body never moves", [] {
                   const sim::SceneDef& scene = sim::findScene("rest-wall");
                   sim::Params p = scene.defaults();
                   p.set(sim::param::offset, 1e9);
                   sim::SimConfig config;
                   config.snapshotCapacity = 1;
                   sim::Simulation s(scene, p, parseMover("continuous"), config);
                   s.run(600);
                   return CaseResult{std::to_string(s.counters().jitter) + " jitter ticks",
                                     s.counters().jitter == 0};
                 }});
  out.push_back(
      {"near 2^53: an item at x = 2^53 moved by +1 px, then +3 px",
       "the ulp there is 2: +1 rounds back to 2^53 (ties to even), +3 lands on 2^53 + 4 — motion "
       "below the ulp is lost, not an error; documented",
       [] {
         const double big = 9007199254740992.0;  // 2^53
         World w(64);
         const ItemId id = w.add({big, 0, 16, 16});
         const double p1 = w.move(id, {big + 1, 0}).position.x;
         const double p2 = w.move(id, {p1 + 3, 0}).position.x;
         return CaseResult{"x - 2^53 = " + num(p1 - big) + ", then " + num(p2 - big),
                           p1 == big && p2 == big + 4};
       }});
  out.push_back(
      {"an item at x = 1e300 (cell index beyond 2^52)",
       "tv::Error: too far from the origin for the cell size; world unchanged", [] {
         Wall w;
         return throwsUnchanged(w.world, "too far", [&] { (void)w.world.add({1e300, 0, 8, 8}); });
       }});
}

// [SECTION] exact contact -------------------------------------------------------------------------

void contact(std::vector<StressCase>& out) {
  out.push_back({"exact corner hit: 8×8 from (0,0) to (16,16) at a tile whose corner is (12,12)",
                 "hit at ti = 0.25, corner flag set, touch (4, 4)", [] {
                   const Sweep s = sweepRect({0, 0, 8, 8}, {16, 16}, {12, 12, 16, 16});
                   return CaseResult{std::string(s.kind == SweepKind::hit ? "hit" : "no hit") +
                                         " ti " + num(s.ti) + (s.corner ? " corner" : "") +
                                         " touch " + pos(s.touch),
                                     s.kind == SweepKind::hit && s.ti == 0.25 && s.corner &&
                                         s.touch == Vec2{4, 4}};
                 }});
  out.push_back(
      {"exact corner graze: 8×8 from (0,0) to (16,16) past a tile whose corner "
       "(16, 8) its top-right corner runs through",
       "miss: the interiors only share a point", [] {
         const Sweep s = sweepRect({0, 0, 8, 8}, {16, 16}, {16, -8, 16, 16});
         return CaseResult{s.kind == SweepKind::miss ? "miss" : "hit at " + num(s.ti),
                           s.kind == SweepKind::miss};
       }});
  out.push_back(
      {"exactly touching a wall (right edge on its left edge), every mover moving away and along",
       "no collision; moving along keeps x exactly", [] {
         const auto make = [] { return Wall({92, 0, 8, 8}); };
         CaseResult along =
             everyMover(make, {92, -20}, [](const Wall&, const MoveResult& r, std::string_view) {
               return std::pair{r.collisions.empty() && r.position.x == 92, pos(r.position)};
             });
         CaseResult away =
             everyMover(make, {80, 0}, [](const Wall&, const MoveResult& r, std::string_view) {
               return std::pair{r.collisions.empty() && r.position == Vec2{80, 0}, pos(r.position)};
             });
         return CaseResult{"along: " + along.got + " | away: " + away.got, along.pass && away.pass};
       }});
  out.push_back({"exactly touching a wall, pushing into it (every mover but discrete)",
                 "stays at x = 92 (a hit at ti = 0, or a blocked pixel)", [] {
                   std::string got;
                   bool pass = true;
                   for (const std::string_view name : moverNames()) {
                     if (name == "discrete") continue;
                     Wall w({92, 0, 8, 8});
                     Mover m(parseMover(name));
                     const MoveResult r = m.move(w.world, w.mover, {95.5, 0});
                     pass = pass && r.position.x == 92;
                     got +=
                         (got.empty() ? "" : "; ") + std::string(name) + " x " + num(r.position.x);
                   }
                   return CaseResult{got, pass};
                 }});
  out.push_back(
      {"starting overlapped: 8×8 at (101, 4) inside a 16×32 wall at x 100..116, moved 1 px right",
       "every mover but pixel pushes out along the shallowest axis, left, to (92, 4); pixel only "
       "steps into free pixels, so it stays at (101, 4)",
       [] {
         return everyMover(
             [] {
               return Wall({101, 4, 8, 8});
             },
             Vec2{102, 4},
             [](const Wall&, const MoveResult& r, std::string_view name) {
               const bool ok =
                   name == "pixel" ? r.position == Vec2{101, 4} : r.position == Vec2{92, 4};
               return std::pair{ok, pos(r.position)};
             });
       }});
  out.push_back({"a corridor exactly the mover's width (8 px gap between walls), every mover",
                 "passes down the corridor untouched: no collision, ends at (16, 180)", [] {
                   struct Corridor {
                     World world{16};
                     ItemId mover;
                     Corridor() {
                       world.add({0, 0, 16, 100});
                       world.add({24, 0, 16, 100});
                       mover = world.add({16, -20, 8, 8});
                     }
                   };
                   return everyMover([] { return Corridor(); }, Vec2{16, 180},
                                     [](const Corridor&, const MoveResult& r, std::string_view) {
                                       return std::pair{
                                           r.collisions.empty() && r.position == Vec2{16, 180},
                                           pos(r.position)};
                                     });
                 }});
  out.push_back({"a mover spanning 63×63 cells (1000×1000 px, cell 16) moved into a small tile",
                 "continuous and sweep stop it with its right edge on the tile: x = 100", [] {
                   std::string got;
                   bool pass = true;
                   for (const std::string_view name : {"continuous", "sweep"}) {
                     World w(16);
                     w.add({1100, 500, 16, 16});
                     const ItemId id = w.add({0, 0, 1000, 1000});
                     Mover m(parseMover(name));
                     const MoveResult r = m.move(w, id, {300, 0});
                     pass = pass && r.position == Vec2{100, 0};
                     got += (got.empty() ? "" : "; ") + std::string(name) + " " + pos(r.position);
                   }
                   return CaseResult{got, pass};
                 }});
  out.push_back(
      {"acute pocket: bounce between walls 0.001 px wider than the mover, a 1e6 px move",
       "the response loop ends (at most 64 responses) and the mover stays between the walls", [] {
         World w(16);
         w.add({-16, -100, 16, 200});
         w.add({8.001, -100, 16, 200});
         const ItemId id = w.add({0, 0, 8, 8});
         const MoveResult r = w.move(id, {1e6, 0.5}, Filter::all(response::bounce));
         const Rect end = w.rect(id);
         const bool between = end.x >= 0 && end.right() <= 8.001;
         return CaseResult{
             std::to_string(r.collisions.size()) + " responses, ended at " + pos(r.position),
             r.collisions.size() <= 64 && between};
       }});
  out.push_back({"inside corner: slide diagonally into a floor and a wall meeting at (32, 32)",
                 "ends resting in the corner exactly: (24, 24)", [] {
                   World w(16);
                   w.add({0, 32, 64, 16});
                   w.add({32, 0, 16, 32});
                   const ItemId id = w.add({0, 0, 8, 8});
                   const MoveResult r = w.move(id, {100, 90});
                   return CaseResult{pos(r.position) + " after " +
                                         std::to_string(r.collisions.size()) + " collisions",
                                     r.position == Vec2{24, 24}};
                 }});
}

// [SECTION] many items ----------------------------------------------------------------------------

void many(std::vector<StressCase>& out, Mode mode) {
  out.push_back(
      {"10^4 items in one 64 px cell (0.5 px squares, 0.64 px apart); a mover swept "
       "into them",
       "query of the cell finds all 10^4; the move stops on the first column: x = -8", [] {
         World w(64);
         for (int i = 0; i < 100; ++i)
           for (int j = 0; j < 100; ++j) w.add({i * 0.64, j * 0.64, 0.5, 0.5});
         const ItemId id = w.add({-40, 20.1, 8, 8});
         const std::size_t found = w.queryRect({0, 0, 64, 64}, id).size();
         Stopwatch sw;
         const MoveResult r = w.move(id, {60, 20.1});
         const double us = sw.seconds() * 1e6;
         return CaseResult{std::to_string(found) + " found; ended at " + pos(r.position) + " in " +
                               fixed(us, 0) + " µs",
                           found == 10000 && r.position == Vec2{-8, 20.1}};
       }});
  const std::uint64_t cycles = mode == Mode::quick ? 100000 : 1000000;
  out.push_back(
      {std::to_string(cycles) + " add/remove cycles in a world of 1000 tiles",
       "item count and heap back to baseline; the slot is reused", [cycles] {
         World w(32);
         for (int i = 0; i < 1000; ++i) w.add({(i % 40) * 16.0, (i / 40) * 16.0, 16, 16});
         ItemId first = w.add({5, 5, 4, 4});
         w.remove(first);
         for (int i = 0; i < 1000; ++i) w.remove(w.add({5.0 + i % 7, 5, 4, 4}));  // warm-up
         const std::size_t heap0 = heapInUse();
         const std::size_t count0 = w.count();
         ItemId last;
         for (std::uint64_t i = 0; i < cycles; ++i) {
           last = w.add({static_cast<double>(i % 600), static_cast<double>(i % 377), 4, 4});
           w.remove(last);
         }
         const auto growth = static_cast<long long>(heapInUse()) - static_cast<long long>(heap0);
         return CaseResult{"count " + std::to_string(w.count()) + " (was " +
                               std::to_string(count0) + "), heap growth " + std::to_string(growth) +
                               " B, slot " + std::to_string(last.index) + " (first " +
                               std::to_string(first.index) + ")",
                           w.count() == count0 && growth <= 0 && last.index == first.index};
       }});
  const std::int64_t crossed = mode == Mode::quick ? 100000 : 1000000;
  out.push_back(
      {"a body moving across " + std::to_string(crossed) + " empty 16 px cells, 4 px a move",
       "heap back to baseline (cells are recycled); a long move afterwards reads as few cells as "
       "before the trip",
       [crossed] {
         World w(16);
         for (int i = 0; i < 100; ++i) w.add({i * 16.0, 0, 16, 16});
         const ItemId body = w.add({0, 32, 8, 8});
         const ItemId probe = w.add({0, 64, 8, 8});
         (void)w.move(body, {4, 32});  // the move path's scratch, once
         const auto cellsRead = [&] {
           MoveTrace t;
           MoveOptions o;
           o.trace = &t;
           (void)w.check(probe, {2546, 2610}, {}, o);  // a 3600 px diagonal over empty ground
           return t.cells.size();
         };
         const std::size_t cells0 = cellsRead();
         const std::size_t heap0 = heapInUse();
         for (std::int64_t i = 1; i <= crossed * 4; ++i) {
           (void)w.move(body, {4.0 * static_cast<double>(i), 32});
         }
         for (int i = 0; i < 1000; ++i) (void)w.move(body, {4.0 * static_cast<double>(i % 2), 32});
         const auto growth = static_cast<long long>(heapInUse()) - static_cast<long long>(heap0);
         const std::size_t cells1 = cellsRead();
         return CaseResult{"heap growth " + std::to_string(growth) + " B after reaching x = " +
                               formatNumber(16.0 * static_cast<double>(crossed)) +
                               " and coming back; cells read " + std::to_string(cells1) +
                               " (before: " + std::to_string(cells0) + ")",
                           growth <= 0 && (!kTraceCompiledIn || cells1 == cells0)};
       }});
}

// [SECTION] time steps ----------------------------------------------------------------------------

sim::Simulation bullets(double speed) {
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  sim::Params p = scene.defaults();
  p.set(sim::param::count, 20);
  p.set(sim::param::speed, speed);
  sim::SimConfig config;
  config.snapshotCapacity = 2;
  return sim::Simulation(scene, p, parseMover("continuous"), config);
}

void timeSteps(std::vector<StressCase>& out) {
  for (const double dt : {0.0, -1.0 / 60, kNan}) {
    out.push_back(
        {"Simulation::tick(dt = " + num(dt) + ")", "tv::Error naming dt; state unchanged", [dt] {
           sim::Simulation s = bullets(1920);
           const std::uint64_t before = s.stateHash();
           try {
             s.tick(dt);
           } catch (const Error& e) {
             const bool same = s.stateHash() == before;
             return CaseResult{std::string("tv::Error \"") + e.what() + "\"" +
                                   (same ? ", unchanged" : ", CHANGED"),
                               same && std::string(e.what()).find("dt") != std::string::npos};
           }
           return CaseResult{"no exception", false};
         }});
  }
  out.push_back({"Simulation::tick(dt = 1000 s): bullets at 1920 px/s fly 1.9e6 px in one tick",
                 "no tunnelling (continuous): every bullet stops on the near side", [] {
                   sim::Simulation s = bullets(1920);
                   s.tick(1000.0);
                   return CaseResult{std::to_string(s.counters().hits) + " hits, " +
                                         std::to_string(s.counters().tunnelled) + " tunnelled",
                                     s.counters().hits == 20 && s.counters().tunnelled == 0};
                 }});
  out.push_back({"FixedStep::advance(1e9 s): a huge frame",
                 "clamped to maxFrameTime 0.25 s: 15 ticks at 1/60, one clamped frame", [] {
                   FixedStep f(1.0 / 60.0, 0.25);
                   const int n = f.advance(1e9);
                   return CaseResult{std::to_string(n) + " ticks, " +
                                         std::to_string(f.clampedFrames()) + " clamped",
                                     n == 15 && f.clampedFrames() == 1};
                 }});
  out.push_back({"FixedStep::advance(-0.01 s) and advance(NaN)",
                 "tv::Error for each; the accumulator unchanged", [] {
                   FixedStep f(1.0 / 60.0, 0.25);
                   (void)f.advance(0.01);
                   const double acc = f.accumulator();
                   int threw = 0;
                   for (const double bad : {-0.01, kNan}) {
                     try {
                       (void)f.advance(bad);
                     } catch (const Error&) {
                       ++threw;
                     }
                   }
                   return CaseResult{std::to_string(threw) + " of 2 threw, accumulator " +
                                         (f.accumulator() == acc ? "unchanged" : "CHANGED"),
                                     threw == 2 && f.accumulator() == acc};
                 }});
  out.push_back({"Simulation::frame(0): a zero-length frame", "runs no tick, no error", [] {
                   sim::Simulation s = bullets(1920);
                   const int n = s.frame(0.0);
                   return CaseResult{std::to_string(n) + " ticks", n == 0 && s.ticks() == 0};
                 }});
}

// [SECTION] geometry ------------------------------------------------------------------------------

void segments(std::vector<StressCase>& out) {
  out.push_back({"segment along a grid line between two rows of tiles: (-10, 16) to (80, 16)",
                 "no hit: a segment running along edges does not enter an interior", [] {
                   World w(32);
                   for (int i = 0; i < 4; ++i) {
                     w.add({i * 16.0, 0, 16, 16});
                     w.add({i * 16.0, 16, 16, 16});
                   }
                   const auto hits = w.querySegment({-10, 16}, {80, 16});
                   return CaseResult{std::to_string(hits.size()) + " hits", hits.empty()};
                 }});
  out.push_back(
      {"segment along a cell line (x = 32, cell 32) on the tiles' right edges", "no hit", [] {
         World w(32);
         for (int j = 0; j < 4; ++j) w.add({16, j * 16.0, 16, 16});
         const auto hits = w.querySegment({32, -5}, {32, 70});
         return CaseResult{std::to_string(hits.size()) + " hits", hits.empty()};
       }});
  out.push_back(
      {"segment through a corner point only: (0,0) to (32,32) between tiles touching "
       "at (16,16)",
       "no hit: it meets both tiles in one point", [] {
         World w(16);
         w.add({16, 0, 16, 16});
         w.add({0, 16, 16, 16});
         const auto hits = w.querySegment({0, 0}, {32, 32});
         return CaseResult{std::to_string(hits.size()) + " hits", hits.empty()};
       }});
  out.push_back({"segment through an interior: (0, 8) to (40, 8) across a tile at x 16..32",
                 "one hit, entry (16, 8), exit (32, 8), t0 0.4, t1 0.8", [] {
                   World w(16);
                   w.add({16, 0, 16, 16});
                   const auto hits = w.querySegment({0, 8}, {40, 8});
                   if (hits.size() != 1)
                     return CaseResult{std::to_string(hits.size()) + " hits", false};
                   const SegmentHit& h = hits.front();
                   return CaseResult{"entry " + pos(h.entry) + " exit " + pos(h.exit) + " t " +
                                         num(h.t0) + ".." + num(h.t1),
                                     h.entry == Vec2{16, 8} && h.exit == Vec2{32, 8} &&
                                         h.t0 == 0.4 && h.t1 == 0.8};
                 }});
}

}  // namespace

std::vector<StressCase> stressCases(Mode mode) {
  std::vector<StressCase> out;
  badInput(out);
  extremes(out);
  contact(out);
  many(out, mode);
  timeSteps(out);
  segments(out);
  return out;
}

}  // namespace tv::bench
