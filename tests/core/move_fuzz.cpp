// The differential move fuzzer: one move, whatever watches it. Random worlds shaped like real
// games — blocks and long platforms, movers of three classes whose filters ignore whole
// categories (clouds of smoke puffs around them, debris, pickups they cross), built-in and user
// responses, starts inside things, items added, resized and removed as it runs, cells of 16 to
// 128 px — and every move made through two worlds kept in the same state:
//
//   game   untraced, a Recorder attached (what a game does);
//   twin   traced, now and then rebuilt from the game's state (a replay's keyframe: its cells
//          list their items in another order) or copied from it;
//
// and, for the moves the specification defines directly, a third time by the reference
// (move_reference.hpp: every leg against every item, no broad phase). Each entry point takes
// its turn: World::move, check and project, every Mover, tv::Batch, anyOverlap. Compared: the
// position, every field of every collision bit for bit, and the filter's questions — the same
// pairs in the same order. At the end of each world its recording must validate, untraced and
// traced, and frames seeked from their keyframes and stepped traced (as the debugger shows them)
// must replay bit for bit.
//
// TV_MOVE_FUZZ_MOVES sets how many moves to make (default 10^6: the CI run; the sanitizer run
// makes fewer; a long run more), TV_MOVE_FUZZ_SEED the first world's seed.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "move_reference.hpp"
#include "tv/batch.hpp"
#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/rng.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

using sim::Rng;

// [SECTION] comparing -------------------------------------------------------------------------

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const Rect& a, const Rect& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.w, b.w) && same(a.h, b.h);
}
bool same(const Collision& x, const Collision& y) {
  return x.item == y.item && x.other == y.other && x.overlaps == y.overlaps &&
         x.corner == y.corner && same(x.ti, y.ti) && same(x.move, y.move) &&
         same(x.normal, y.normal) && same(x.touch, y.touch) && same(x.itemRect, y.itemRect) &&
         same(x.otherRect, y.otherRect) && x.response == y.response && same(x.target, y.target);
}
bool same(std::span<const Collision> a, std::span<const Collision> b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}
std::string text(Vec2 v) {
  return "(" + formatNumber(v.x) + ", " + formatNumber(v.y) + ")";
}

struct Asked {
  ItemId item, other;
  bool operator==(const Asked&) const = default;
};

// One making of a call: what came back and what the filter was asked, in order.
struct Made {
  Vec2 position;
  std::vector<Collision> collisions;
  std::vector<Asked> asked;
  bool any = false;  // anyOverlap
};

// [SECTION] the worlds ------------------------------------------------------------------------

enum Kind : std::uint8_t { kBlock, kPlatform, kMover, kPuff, kDebris, kPickup, kKinds };
constexpr int kClasses = 3;  // of movers, each with its own filter row

// User responses: one whose next leg stays in the move's box, one that leaves it, one that
// stops, one that passes through.
Leg halfwayResponse(const Collision& c, Vec2 goal) {
  const Leg s = slideResponse(c, goal);  // half the slide
  return {s.start, s.start + (s.goal - s.start) * 0.5};
}
Leg recoilResponse(const Collision& c, Vec2) {
  return {c.touch, c.touch - c.move * 0.5};
}
Leg stickResponse(const Collision& c, Vec2) {
  return {c.touch, c.touch};
}
Leg skimResponse(const Collision& c, Vec2 goal) {
  return {c.touch, goal, true};
}
constexpr std::array<std::pair<const char*, ResponseFn>, 4> kUserResponses = {{
    {"halfway", &halfwayResponse},
    {"recoil", &recoilResponse},
    {"stick", &stickResponse},
    {"skim", &skimResponse},
}};

constexpr std::array<std::string_view, 7> kMovers = {
    "discrete", "sweep", "substep-discrete", "substep-sweep", "continuous", "pixel", "adaptive"};

struct Totals {
  std::uint64_t moves = 0, referenced = 0, candidates = 0, tracedMoves = 0, inRange = 0;
  std::uint64_t collisions = 0, overlapsAtStart = 0, userResponses = 0, largeMovers = 0;
  std::uint64_t batches = 0, recordedCalls = 0, worlds = 0;
  std::uint64_t differences = 0;
  std::string first;  // the first difference, described
};

class FuzzWorld {
 public:
  FuzzWorld(std::uint64_t seed, Totals& totals)
      : rng_(seed), seed_(seed), t_(totals), game_(pickCell()), twin_(game_.cellSize()) {
    for (World* w : {&game_, &twin_})
      for (const auto& [name, fn] : kUserResponses) (void)w->addResponse(name, fn);
    responses_ = {&touchResponse, &crossResponse, &slideResponse, &bounceResponse, &onewayResponse};
    for (const auto& r : kUserResponses) responses_.push_back(r.second);
    pickFilters();
    build();
    for (const std::string_view m : kMovers) {
      // Substep pieces of a quarter cell: half the smallest item (a puff) would cut a bullet's
      // move into hundreds of pieces.
      MoverSpec spec = parseMover(m);
      if (spec.kind == MoverKind::substep) spec.maxStep = game_.cellSize() / 4;
      gameMovers_.emplace_back(spec);
      twinMovers_.emplace_back(spec);
    }
  }

  // Plays `steps` calls with the recorder attached, then checks the recording.
  void play(int steps) {
    Recorder rec(RecorderOptions{32});
    game_.attach(rec);
    for (int s = 0; s < steps && t_.differences < 20; ++s) {
      step();
      if (s % 16 == 15) rec.frame();
      if (s % 97 == 0) resyncTwin();
    }
    game_.detach();
    if (!rec.ok()) note("the recorder failed: " + rec.error());
    checkRecording(rec.bytes());
    ++t_.worlds;
  }

 private:
  // [SECTION] building -----------------------------------------------------------------------

  double pickCell() {
    constexpr std::array<double, 7> cells = {16, 24, 32, 48, 64, 96, 128};
    return cells[rng_.below(cells.size())];
  }

  // Coordinates as games make them: whole tiles, halves, and some arbitrary doubles.
  double coord(double lo, double hi) {
    const double u = rng_.uniform(lo, hi);
    switch (rng_.below(4)) {
      case 0: return std::floor(u);
      case 1: return std::floor(u * 4.0) / 4.0;
      default: return u;
    }
  }

  void pickFilters() {
    // Each mover class answers each kind of item with one response: whole categories ignored
    // (puffs nearly always), pickups crossed, blocks slid on, touched, bounced off or met with
    // a user's response; debris and other movers anything.
    const auto pick = [&](std::initializer_list<ResponseId> from) {
      return *(from.begin() + rng_.below(from.size()));
    };
    const ResponseId halfway = 4, recoil = 5, stick = 6, skim = 7;
    for (auto& row : table_) {
      row[kBlock] = pick({response::slide, response::slide, response::slide, response::touch,
                          response::bounce, stick});
      row[kPlatform] = pick({response::slide, response::slide, response::touch, recoil});
      row[kMover] = pick({response::ignore, response::slide, response::cross, response::bounce,
                          skim});
      row[kPuff] = rng_.below(8) == 0 ? response::cross : response::ignore;
      row[kDebris] = pick({response::ignore, response::touch, response::cross, halfway});
      row[kPickup] = pick({response::cross, skim, response::ignore});
    }
  }

  [[nodiscard]] ResponseId answer(ItemId item, ItemId other) const {
    const Kind ko = kindOf(other);
    if (ko == kKinds) return response::ignore;  // not one of ours: never asked
    // Not only by category: a pair here and there is ignored, as real filters do.
    if ((item.index * 7u + other.index * 3u) % 23u == 0) return response::ignore;
    const int cls = kindOf(item) == kMover ? static_cast<int>(item.index % kClasses) : 0;
    return table_[static_cast<std::size_t>(cls)][ko];
  }
  [[nodiscard]] Kind kindOf(ItemId id) const {
    return id.index < kinds_.size() ? kinds_[id.index] : kKinds;
  }

  ItemId add(const Rect& r, Kind k) {
    const ItemId id = game_.add(r);
    const ItemId twin = twin_.add(r);
    if (twin != id) note("add returned another handle in the twin");
    if (kinds_.size() <= id.index) kinds_.resize(id.index + 1, kKinds);
    kinds_[id.index] = k;
    (k == kMover ? movers_ : others_).push_back(id);
    return id;
  }
  void remove(ItemId id) {
    game_.remove(id);
    twin_.remove(id);
    kinds_[id.index] = kKinds;
    for (auto* list : {&movers_, &others_}) {
      const auto it = std::find(list->begin(), list->end(), id);
      if (it != list->end()) {
        *it = list->back();
        list->pop_back();
      }
    }
  }
  void update(ItemId id, const Rect& r) {
    game_.update(id, r);
    twin_.update(id, r);
  }

  void build() {
    const double c = game_.cellSize();
    cols_ = 8 + static_cast<int>(rng_.below(8));
    rows_ = 6 + static_cast<int>(rng_.below(6));
    const double tile = std::array<double, 4>{c / 4, c / 2, c, 16}[rng_.below(4)];
    const double width = cols_ * c, height = rows_ * c;
    // A floor of tiles, some a little higher (a hand-made map), walls, platforms, blocks.
    for (double x = 0; x < width; x += tile) {
      const double lift = rng_.below(9) == 0 ? 1.0 : 0.0;
      add({x, height - tile - lift, tile, tile + lift}, kBlock);
    }
    add({-tile, 0, tile, height}, kBlock);
    add({width, 0, tile, height}, kBlock);
    const int platforms = 3 + static_cast<int>(rng_.below(5));
    for (int i = 0; i < platforms; ++i) {
      // Several cells long: an item registered in more cells than a small one.
      const double w = c * rng_.uniform(1.0, 6.0);
      add({coord(0, width - w), coord(c, height - 2 * c), w, coord(4, tile + 4)}, kPlatform);
    }
    const int blocks = 10 + static_cast<int>(rng_.below(30));
    for (int i = 0; i < blocks; ++i)
      add({coord(0, width), coord(0, height - tile), tile, tile}, kBlock);
    const int movers = 3 + static_cast<int>(rng_.below(6));
    for (int i = 0; i < movers; ++i) {
      const double w = rng_.uniform(3, c * (rng_.below(5) == 0 ? 2.5 : 1.0));
      const double h = rng_.uniform(3, c * (rng_.below(5) == 0 ? 2.5 : 1.0));
      const ItemId m = add({coord(0, width - w), coord(0, height - h - tile), w, h}, kMover);
      velocity_.resize(std::max<std::size_t>(velocity_.size(), m.index + 1));
      velocity_[m.index] = randomVelocity(m);
    }
    // Clouds of smoke around the movers (what most of a move's candidates are), debris and
    // pickups scattered.
    for (const ItemId m : std::vector<ItemId>(movers_)) {
      const int puffs = 80 + static_cast<int>(rng_.below(100));
      for (int i = 0; i < puffs; ++i) addPuffNear(game_.rect(m));
    }
    const int debris = 10 + static_cast<int>(rng_.below(40));
    for (int i = 0; i < debris; ++i) {
      const double s = rng_.uniform(2, 10);
      add({coord(0, width), coord(0, height), s, s}, kDebris);
    }
    for (int i = 0; i < 8; ++i) add({coord(0, width), coord(0, height), 6, 6}, kPickup);
  }

  Rect puffNear(const Rect& r) {
    const double c = game_.cellSize();
    const double s = rng_.uniform(1.5, c / 4 + 2);
    return {r.x + rng_.uniform(-c / 2, c / 2 + r.w), r.y + rng_.uniform(-c / 2, c / 2 + r.h), s, s};
  }
  void addPuffNear(const Rect& r) { add(puffNear(r), kPuff); }

  Vec2 randomVelocity(ItemId m) {
    const double c = game_.cellSize();
    switch (rng_.below(12)) {
      case 0: case 1: return {0, rng_.uniform(0.01, 2)};          // pressed onto a floor
      case 2: case 3: return {rng_.uniform(-4, 4), rng_.uniform(0, 1)};  // walking on it
      case 4: case 5: return {rng_.uniform(-c, c), rng_.uniform(-c, c)};  // a cell a move
      case 6: return {rng_.uniform(-4 * c, 4 * c), rng_.uniform(-3 * c, 3 * c)};  // a bullet
      case 7: case 8: return {static_cast<double>(m.index % 3) - 1.0, 0};  // along an axis
      default: return {rng_.uniform(-3, 3), rng_.uniform(-3, 3)};
    }
  }

  // [SECTION] one step -----------------------------------------------------------------------

  void step() {
    const std::uint64_t u = rng_.below(100);
    if (movers_.empty() || u < 8) return churn();
    if (u < 16) return drift();
    if (u < 20) return anyOverlap();
    if (u < 24) return project();
    if (u < 25) return batch();
    if (u < 28) return teleport();
    moveOne();
  }

  ItemId someMover() { return movers_[rng_.below(movers_.size())]; }

  // Items come and go, puffs grow.
  void churn() {
    const std::uint64_t u = rng_.below(10);
    if (u < 4 && !others_.empty()) {
      const ItemId id = others_[rng_.below(others_.size())];
      if (kindOf(id) == kPuff || kindOf(id) == kDebris || kindOf(id) == kPickup) remove(id);
    } else if (u < 8 && !movers_.empty()) {
      addPuffNear(game_.rect(someMover()));
    } else if (u == 8 && movers_.size() > 2) {
      remove(someMover());
    } else if (movers_.size() < 8) {
      const double c = game_.cellSize();
      const double w = rng_.uniform(3, c), h = rng_.uniform(3, c);
      const ItemId m = add({coord(0, cols_ * c - w), coord(0, rows_ * c - h), w, h}, kMover);
      velocity_.resize(std::max<std::size_t>(velocity_.size(), m.index + 1));
      velocity_[m.index] = randomVelocity(m);
    }
  }

  // A few puffs rise and grow (update with a new size), or are puffed again by a mover.
  void drift() {
    for (int i = 0; i < 16 && !others_.empty(); ++i) {
      const ItemId id = others_[rng_.below(others_.size())];
      if (kindOf(id) != kPuff) continue;
      if (rng_.below(2) == 0) {
        update(id, puffNear(game_.rect(someMover())));
        continue;
      }
      const Rect r = game_.rect(id);
      update(id, {r.x + rng_.uniform(-1, 1), r.y - rng_.uniform(0, 2), r.w + 0.25, r.h + 0.25});
    }
  }

  // A mover put somewhere else, maybe inside something, maybe resized.
  void teleport() {
    const ItemId m = someMover();
    const Rect r = game_.rect(m);
    const double c = game_.cellSize();
    const Rect to{r.x + rng_.uniform(-c, c), r.y + rng_.uniform(-c, c),
                  rng_.below(3) == 0 ? rng_.uniform(3, 2 * c) : r.w, r.h};
    if (!game_.grid().fits(to)) return;
    update(m, to);
  }

  // A mover stuck inside things (every move a pocket of 64 responses) is put back somewhere it
  // overlaps no block or platform, as a game respawns it.
  void respawn(ItemId m) {
    const Rect r = game_.rect(m);
    const double c = game_.cellSize();
    const auto solid = [this](ItemId, ItemId o) {
      return kindOf(o) == kBlock || kindOf(o) == kPlatform ? response::slide : response::ignore;
    };
    for (int i = 0; i < 10; ++i) {
      const Rect to{coord(0, cols_ * c - r.w), coord(0, rows_ * c - r.h), r.w, r.h};
      if (!game_.anyOverlap(to, m, solid)) {
        update(m, to);
        return;
      }
    }
  }

  void resyncTwin() {
    if (rng_.below(2) == 0) {
      World restored(game_.cellSize());
      for (const auto& [name, fn] : kUserResponses) (void)restored.addResponse(name, fn);
      restored.restore(game_.state());
      twin_ = std::move(restored);
    } else {
      twin_ = game_;  // a copy keeps the cells' order (and reports to no one)
    }
  }

  // The filter of one making, logging its questions.
  struct Logged {
    const FuzzWorld* w;
    std::vector<Asked>* asked;
    ResponseId operator()(ItemId a, ItemId b) const {
      asked->push_back({a, b});
      return w->answer(a, b);
    }
  };

  void moveOne() {
    const ItemId m = someMover();
    Vec2& v = velocity_[m.index];
    if (rng_.below(8) == 0) v = randomVelocity(m);
    const Rect from = game_.rect(m);
    const Vec2 goal = from.position() + v;
    if (!game_.grid().fits(from.at(goal)) || std::fabs(goal.x) > 1e6 || std::fabs(goal.y) > 1e6) {
      v = {-v.x, -v.y};
      return;
    }
    MoveOptions o;
    const std::uint64_t mr = rng_.below(10);
    o.maxResponses = mr == 0 ? 1 : mr == 1 ? 2 : mr == 2 ? 3 : 64;
    o.broad = rng_.below(4) == 0 ? BroadPhase::bounds : BroadPhase::swept;
    const std::uint64_t entry = rng_.below(10);
    t_.overlapsAtStart += game_.anyOverlap(from, m) ? 1u : 0u;
    t_.largeMovers += game_.grid().cellsHolding(from).count() > 4 ? 1u : 0u;
    Made ref, a, b;
    MoveTrace trace;
    std::string what;
    if (entry < 6 || entry == 9) {
      // World::move (or check): the reference first, on the world as it is.
      const Logged fr{this, &ref.asked};
      const test::ReferenceResult r =
          test::referenceMove(game_, m, from, goal, Filter(fr), o.maxResponses, responses_);
      ref.position = r.position;
      ref.collisions = r.collisions;
      ++t_.referenced;
      const bool check = entry == 9;
      what = check ? "World::check" : "World::move";
      const Logged fa{this, &a.asked}, fb{this, &b.asked};
      MoveOptions traced = o;
      traced.trace = &trace;
      const MoveResult ra = check ? game_.check(m, goal, Filter(fa), o)
                                  : game_.move(m, goal, Filter(fa), o);
      a.position = ra.position;
      a.collisions.assign(ra.collisions.begin(), ra.collisions.end());
      const MoveResult rb = check ? twin_.check(m, goal, Filter(fb), traced)
                                  : twin_.move(m, goal, Filter(fb), traced);
      b.position = rb.position;
      b.collisions.assign(rb.collisions.begin(), rb.collisions.end());
      compare(what + " against the reference", ref, a);
    } else {
      // A mover: each kind through the same two worlds; the swept ones against the reference.
      std::size_t k = rng_.below(kMovers.size());
      // The pixel mover makes a query per pixel: only the slow moves it is made for.
      if (kMovers[k] == "pixel" && std::fabs(goal.x - from.x) + std::fabs(goal.y - from.y) > 24) {
        k = 4;  // continuous
      }
      what = "Mover " + std::string(kMovers[k]);
      const bool swept = kMovers[k] == "sweep" || kMovers[k] == "continuous" ||
                         kMovers[k] == "adaptive";
      if (swept) {
        const Logged fr{this, &ref.asked};
        const test::ReferenceResult r = test::referenceMove(game_, m, from, goal, Filter(fr),
                                                            MoveOptions{}.maxResponses,
                                                            responses_);
        ref.position = r.position;
        ref.collisions = r.collisions;
        ++t_.referenced;
      }
      const Logged fa{this, &a.asked}, fb{this, &b.asked};
      try {
        const MoveResult ra = gameMovers_[k].move(game_, m, goal, Filter(fa));
        a.position = ra.position;
        a.collisions.assign(ra.collisions.begin(), ra.collisions.end());
      } catch (const Error&) {
        // A pixel move too long, a substep move in too many pieces: refused, nothing changed.
        a.position = {-1, -1};
      }
      try {
        const MoveResult rb = twinMovers_[k].move(twin_, m, goal, Filter(fb), &trace);
        b.position = rb.position;
        b.collisions.assign(rb.collisions.begin(), rb.collisions.end());
      } catch (const Error&) {
        b.position = {-1, -1};
      }
      if (swept) compare(what + " against the reference", ref, a);
    }
    compare(what + " traced (twin) against untraced (game)", a, b);
    ++t_.moves;
    t_.collisions += a.collisions.size();
    for (const Collision& c : a.collisions) {
      if (c.response >= response::kBuiltinCount) ++t_.userResponses;
      if (c.normal.x != 0) v.x = -v.x;
      if (c.normal.y != 0) v.y = -v.y;
    }
    if (kTraceCompiledIn && entry < 6 && t_.moves % 8 == 0) {
      // How crowded a move is, as bump.lua counts it: the items in the cells its first read
      // (or its legs' walks) visited.
      ++t_.tracedMoves;
      std::vector<std::uint32_t> seen;
      for (const Cell& cell : trace.cells)
        for (const std::uint32_t slot : twin_.cellItems(cell)) seen.push_back(slot);
      std::sort(seen.begin(), seen.end());
      const auto n =
          static_cast<std::uint64_t>(std::unique(seen.begin(), seen.end()) - seen.begin());
      t_.candidates += n;
      if (n >= 50 && n <= 200) ++t_.inRange;
    }
    if (a.collisions.size() >= 16) respawn(m);  // stuck in a pocket: put it somewhere free
    // Smoke follows the movers, as a jetpack's or a rocket's does: a few puffs are puffed
    // again around the one that just moved.
    for (int i = 0; i < 3 && !others_.empty(); ++i) {
      const ItemId p = others_[rng_.below(others_.size())];
      if (kindOf(p) == kPuff) update(p, puffNear(game_.rect(m)));
    }
    if (t_.moves % 64 == 0 && game_.stateHash() != twin_.stateHash()) {
      note("after " + what + " of item " + std::to_string(m.index) +
           ": the twin's state differs from the game's");
      resyncTwin();
    }
  }

  void project() {
    const double c = game_.cellSize();
    const ItemId near = someMover();
    const Rect n = game_.rect(near);
    const Rect r{n.x + rng_.uniform(-c, c), n.y + rng_.uniform(-c, c), rng_.uniform(2, c),
                 rng_.uniform(2, c)};
    const Vec2 goal = r.position() + randomVelocity(near);
    if (!game_.grid().fits(r.at(goal))) return;
    Made ref, a, b;
    const Logged fr{this, &ref.asked}, fa{this, &a.asked}, fb{this, &b.asked};
    const test::ReferenceResult rr = test::referenceMove(game_, ItemId{}, r, goal, Filter(fr),
                                                         MoveOptions{}.maxResponses, responses_);
    ref.position = rr.position;
    ref.collisions = rr.collisions;
    MoveTrace trace;
    MoveOptions traced;
    traced.trace = &trace;
    const MoveResult ra = game_.project(r, goal, Filter(fa));
    a.position = ra.position;
    a.collisions.assign(ra.collisions.begin(), ra.collisions.end());
    const MoveResult rb = twin_.project(r, goal, Filter(fb), traced);
    b.position = rb.position;
    b.collisions.assign(rb.collisions.begin(), rb.collisions.end());
    compare("World::project against the reference", ref, a);
    compare("World::project traced (twin) against untraced (game)", a, b);
    ++t_.moves;
    ++t_.referenced;
  }

  void anyOverlap() {
    const double c = game_.cellSize();
    const ItemId skip = rng_.below(3) == 0 ? ItemId{} : someMover();
    const Rect n = skip.valid() ? game_.rect(skip) : game_.rect(someMover());
    const Rect r = rng_.below(2) == 0
                       ? n
                       : Rect{n.x + rng_.uniform(-c, c), n.y + rng_.uniform(-c, c),
                              rng_.uniform(1, 3 * c), rng_.uniform(1, 3 * c)};
    Made ref, a, b;
    const Logged fr{this, &ref.asked}, fa{this, &a.asked}, fb{this, &b.asked};
    ref.any = test::referenceAnyOverlap(game_, r, skip, Filter(fr));
    a.any = game_.anyOverlap(r, skip, Filter(fa));
    b.any = twin_.anyOverlap(r, skip, Filter(fb));
    compare("World::anyOverlap against the reference", ref, a);
    compare("World::anyOverlap on the twin against the game", a, b);
  }

  void batch() {
    std::vector<BatchMove> moves;
    for (const ItemId m : movers_) {
      if (rng_.below(3) == 0) continue;
      const Rect r = game_.rect(m);
      const Vec2 goal = r.position() + velocity_[m.index];
      if (game_.grid().fits(r.at(goal))) moves.push_back({m, goal});
    }
    if (moves.empty()) return;
    Made a, b;
    const Logged fa{this, &a.asked}, fb{this, &b.asked};
    constexpr int kMaxEvents = 64;  // bodies bouncing in a pocket need not run to 4096
    gameBatch_.step(game_, moves, Filter(fa), kMaxEvents);
    twinBatch_.step(twin_, moves, Filter(fb), kMaxEvents);
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const BatchOutcome oa = gameBatch_.outcome(i), ob = twinBatch_.outcome(i);
      a.position = oa.position;
      b.position = ob.position;
      a.collisions.assign(oa.collisions.begin(), oa.collisions.end());
      b.collisions.assign(ob.collisions.begin(), ob.collisions.end());
      if (i + 1 < moves.size()) {
        Made pa = a, pb = b;
        pa.asked.clear();
        pb.asked.clear();
        compare("Batch body " + std::to_string(i) + " on the twin against the game", pa, pb);
      }
      for (const Collision& c : a.collisions) {
        Vec2& v = velocity_[moves[i].item.index];
        if (c.normal.x != 0) v.x = -v.x;
        if (c.normal.y != 0) v.y = -v.y;
      }
    }
    compare("Batch on the twin against the game", a, b);  // the last body, and every question
    t_.moves += moves.size();
    ++t_.batches;
  }

  // [SECTION] checks -------------------------------------------------------------------------

  void note(const std::string& what) {
    ++t_.differences;
    if (t_.first.empty()) t_.first = "seed " + std::to_string(seed_) + ": " + what;
  }

  void compare(const std::string& what, const Made& x, const Made& y) {
    std::string d;
    if (!same(x.position, y.position)) {
      d = "position " + text(x.position) + " against " + text(y.position);
    } else if (!same(x.collisions, y.collisions)) {
      d = std::to_string(x.collisions.size()) + " collisions against " +
          std::to_string(y.collisions.size()) + " (or a field differs)";
    } else if (x.asked != y.asked) {
      d = "the filter was asked " + std::to_string(x.asked.size()) + " questions against " +
          std::to_string(y.asked.size());
      for (std::size_t i = 0; i < std::min(x.asked.size(), y.asked.size()); ++i) {
        if (!(x.asked[i] == y.asked[i])) {
          d += "; question " + std::to_string(i) + " about item " +
               std::to_string(x.asked[i].other.index) + " against item " +
               std::to_string(y.asked[i].other.index);
          break;
        }
      }
    } else if (x.any != y.any) {
      d = "anyOverlap " + std::to_string(x.any) + " against " + std::to_string(y.any);
    }
    if (!d.empty()) note(what + ": " + d);
  }

  void checkRecording(const std::vector<std::uint8_t>& bytes) {
    Replay replay = Replay::fromBytes(bytes);
    t_.recordedCalls += replay.summary().calls;
    // Untraced, as tv-replay --validate (every fourth world: the traced run below compares
    // every call too, and the world at each keyframe).
    if (seed_ % 4 == 0) {
      if (const std::optional<Divergence> d = replay.validate()) {
        note("the recording does not validate: " + d->report());
        return;
      }
    }
    if (const std::optional<Divergence> d = replay.validate({}, Replay::Tracing::on)) {
      note("the recording does not validate traced: " + d->report());
      return;
    }
    // As the debugger shows a frame: seeked from its keyframe, its calls stepped traced.
    MoveTrace trace;
    for (int i = 0; i < 1 && replay.frames() > 1; ++i) {
      const std::uint64_t f = 1 + rng_.below(replay.frames() - 1);
      replay.seek(f, 0);
      while (replay.frame() == f && replay.call() < replay.callCount(f)) {
        trace.clear();
        if (const std::optional<Divergence> d = replay.step(&trace)) {
          note("frame " + std::to_string(f) + " seeked and stepped traced: " + d->report());
          return;
        }
      }
    }
  }

  Rng rng_;
  std::uint64_t seed_;
  Totals& t_;
  World game_, twin_;
  std::vector<ResponseFn> responses_;
  std::array<std::array<ResponseId, kKinds>, kClasses> table_{};
  std::vector<Kind> kinds_;
  std::vector<ItemId> movers_, others_;
  std::vector<Vec2> velocity_;
  std::vector<Mover> gameMovers_, twinMovers_;
  Batch gameBatch_, twinBatch_;
  int cols_ = 0, rows_ = 0;
};

std::uint64_t fromEnv(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  if (v == nullptr || *v == '\0') return fallback;
  return std::strtoull(v, nullptr, 10);
}

TEST(MoveFuzz, EveryMoveIsTheSameWhateverWatchesItAndEqualsTheReference) {
  const std::uint64_t target = fromEnv("TV_MOVE_FUZZ_MOVES", 1000000);
  std::uint64_t seed = fromEnv("TV_MOVE_FUZZ_SEED", 1);
  Totals t;
  while (t.moves < target && t.differences == 0) {
    FuzzWorld w(seed++, t);
    w.play(3000);
  }
  std::printf("%" PRIu64 " moves in %" PRIu64 " worlds (%" PRIu64
              " against the reference, %" PRIu64 " in batches), %" PRIu64
              " collisions (%" PRIu64 " by user responses), %" PRIu64
              " starting inside something, %" PRIu64 " by movers in more than 4 cells; %" PRIu64
              " recorded calls replayed; candidates a World::move (items in the cells it read): %.1f "
              "on average, %.0f%% in [50, 200]; differences: %" PRIu64 "\n",
              t.moves, t.worlds, t.referenced, t.batches, t.collisions, t.userResponses,
              t.overlapsAtStart, t.largeMovers, t.recordedCalls,
              t.tracedMoves ? static_cast<double>(t.candidates) / static_cast<double>(t.tracedMoves)
                            : 0.0,
              t.tracedMoves ? 100.0 * static_cast<double>(t.inRange) /
                                  static_cast<double>(t.tracedMoves)
                            : 0.0,
              t.differences);
  EXPECT_EQ(t.differences, 0u) << t.first;
  // The worlds did exercise what is compared.
  EXPECT_GT(t.collisions, t.moves / 4);
  EXPECT_GT(t.userResponses, t.moves / 100);
  EXPECT_GT(t.overlapsAtStart, t.moves / 100);
  EXPECT_GT(t.largeMovers, t.moves / 100);
  if (kTraceCompiledIn) {
    EXPECT_GT(static_cast<double>(t.candidates) / static_cast<double>(t.tracedMoves), 50.0);
  }
}

}  // namespace
}  // namespace tv
