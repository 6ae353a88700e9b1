// Specification of the narrow move: when something the filter keeps is in reach of a short move,
// World::move gathers the items meeting the move's box once and sweeps every leg that stays in
// the box against that list; a leg that leaves the box (a bounce, a user response) walks the
// cells. Either way the result is the full path's, bit for bit. A traced move always takes the
// full path, so a traced twin of the world is the reference here.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tv/sim/rng.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

using Rng = sim::Rng;

// Doubles compared by their bits: -0 and 0 differ, as they would in a state hash.
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const Rect& a, const Rect& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.w, b.w) && same(a.h, b.h);
}

// Every field of two collision lists, bit for bit; the first difference as a message.
std::string differences(std::span<const Collision> a, std::span<const Collision> b) {
  if (a.size() != b.size())
    return std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " collisions";
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Collision& x = a[k];
    const Collision& y = b[k];
    const bool equal = x.item == y.item && x.other == y.other && x.overlaps == y.overlaps &&
                       x.corner == y.corner && same(x.ti, y.ti) && same(x.move, y.move) &&
                       same(x.normal, y.normal) && same(x.touch, y.touch) &&
                       same(x.itemRect, y.itemRect) && same(x.otherRect, y.otherRect) &&
                       x.response == y.response && same(x.target, y.target);
    if (!equal) return "collision " + std::to_string(k) + " differs";
  }
  return {};
}

// The spatial hash seen through the world: every item is listed in exactly the cells
// Grid::cellsHolding names for its rect, once each, and no cell lists anything else.
void expectCellsExact(const World& w) {
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>> expected;
  w.forEachItem([&](ItemId id, const Rect& r) {
    Grid::forEachCell(w.grid().cellsHolding(r),
                      [&](Cell c) { expected[{c.x, c.y}].push_back(id.index); });
  });
  std::size_t occupied = 0;
  w.forEachOccupiedCell([&](Cell c, std::size_t n) {
    ++occupied;
    std::vector<std::uint32_t> got = w.cellItems(c);
    std::vector<std::uint32_t> want = expected[{c.x, c.y}];
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(got, want) << "cell " << c.x << "," << c.y;
    EXPECT_EQ(n, got.size());
  });
  EXPECT_EQ(occupied, expected.size());
  EXPECT_EQ(w.countCells(), expected.size());
  // A query over everything finds each item once: an item in several cells is marked shared, so
  // the cells' walk lists it once.
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::vector<ItemId> all;
  w.forEachItem([&](ItemId id, const Rect& r) {
    x0 = std::min(x0, r.x), y0 = std::min(y0, r.y);
    x1 = std::max(x1, r.right()), y1 = std::max(y1, r.bottom());
    all.push_back(id);
  });
  std::vector<ItemId> found = w.queryRect({x0, y0, x1 - x0, y1 - y0});
  const auto byIndex = [](ItemId a, ItemId b) { return a.index < b.index; };
  std::sort(found.begin(), found.end(), byIndex);
  EXPECT_EQ(found, all);
}

// A user response whose next leg stays in the move's box: half way from the contact to the goal.
Leg halfwayResponse(const Collision& c, Vec2 goal) {
  return {c.touch, c.touch + (goal - c.touch) * 0.5};
}
// A user response whose next leg leaves the box: back the way it came, twice as far.
Leg recoilResponse(const Collision& c, Vec2 /*goal*/) {
  return {c.touch, c.touch - c.move * 2.0};
}
// The same without growing from leg to leg: back from the contact as far as the leg went.
Leg backResponse(const Collision& c, Vec2 /*goal*/) {
  return {c.touch, c.touch - c.move};
}

// The seeded scene of the differential test: tiles, large items spanning 5+ cells, and movers of
// mixed sizes, each answering with one response (the filter is a pure function of the pair).
class Scene {
 public:
  static constexpr double kCell = 16;

  explicit Scene(std::uint64_t seed) : rng_(seed) {
    halfway_ = world.addResponse("halfway", &halfwayResponse);
    recoil_ = world.addResponse("back", &backResponse);
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x)
        if (x == 0 || y == 0 || x == 23 || y == 23 || rng_.uniform() < 0.12)
          world.add({x * 16.0, y * 16.0, 16, 16});
    for (int i = 0; i < 6; ++i) world.add(largeRect());  // 3×3 cells and more
    while (movers.size() < 60) movers.push_back(world.add(moverRect()));
    for (std::size_t i = 0; i < movers.size(); ++i) velocity.push_back(randomVelocity());
  }

  // Which response an item answers with, and which pairs it ignores: fixed by the slots alone.
  [[nodiscard]] ResponseId responseOf(ItemId item, ItemId other) const {
    if ((item.index * 3 + other.index) % 7 == 0) return response::ignore;
    switch (item.index % 6) {
      case 0: return response::slide;
      case 1: return response::touch;
      case 2: return response::cross;
      case 3: return response::bounce;
      case 4: return halfway_;
      default: return (other.index % 2 == 0) ? recoil_ : response::slide;
    }
  }

  Rect moverRect() {
    // Mostly within one to four cells; one in five spans 5+ cells (3×2 and more).
    const bool big = rng_.uniform() < 0.2;
    const double w = big ? rng_.uniform(33, 60) : rng_.uniform(3, 20);
    const double h = big ? rng_.uniform(17, 40) : rng_.uniform(3, 20);
    return {rng_.uniform(16, 340), rng_.uniform(16, 340), w, h};
  }
  Rect largeRect() {
    return {rng_.uniform(0, 300), rng_.uniform(0, 300), rng_.uniform(40, 90),
            rng_.uniform(33, 70)};
  }
  Vec2 randomVelocity() {
    // Whole and fractional steps, some along an axis, a few long enough to leave four cells.
    const double reach = rng_.uniform() < 0.1 ? 40 : 7;
    Vec2 v{rng_.uniform(-reach, reach), rng_.uniform(-reach, reach)};
    if (rng_.uniform() < 0.3) v = {std::floor(v.x), std::floor(v.y)};
    if (rng_.uniform() < 0.15) v.x = 0;
    if (rng_.uniform() < 0.15) v.y = 0;
    return v;
  }
  Rng& rng() { return rng_; }

  World world{kCell};
  std::vector<ItemId> movers;
  std::vector<Vec2> velocity;

 private:
  Rng rng_;
  ResponseId halfway_ = 0, recoil_ = 0;
};

// Two identical scenes, one moved untraced (the lean and narrow paths wherever they apply), one
// traced (the full path every move): every move's position and collisions are the same bit for
// bit, and so are the state hashes; the traced move asks the filter about no pair the untraced
// one did not ask about (while the two share their history); while movers resize across the four-cell boundary, teleport
// into overlaps, are removed and re-added, and the untraced world is swapped for a copy and for a
// restored state on the way.
TEST(NarrowMove, EveryMoveEqualsTheTracedFullPathBitForBit) {
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out: no reference";
  std::size_t collisions = 0, moves = 0, overlapsAtStart = 0, largeMovers = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Scene lean(seed), full(seed);
    // What the untraced move asked; the traced one must ask nothing else (a recording made
    // untraced holds those answers by pair, and the debugger steps it traced).
    std::set<std::pair<std::uint32_t, std::uint32_t>> asked;
    std::string unasked;
    const auto filter = [&](ItemId item, ItemId other) {
      asked.insert({item.index, other.index});
      return lean.responseOf(item, other);
    };
    const auto tracedFilter = [&](ItemId item, ItemId other) {
      if (asked.count({item.index, other.index}) == 0 && unasked.empty())
        unasked = std::to_string(item.index) + " about " + std::to_string(other.index);
      return lean.responseOf(item, other);
    };
    for (int tick = 0; tick < 40; ++tick) {
      if (tick == 13) {  // a copy carries on as the original would
        World copy = lean.world;
        lean.world = World(Scene::kCell);
        lean.world = copy;
      }
      if (tick == 27) {  // so does a world restored from the state
        World restored(Scene::kCell);
        (void)restored.addResponse("halfway", &halfwayResponse);
        (void)restored.addResponse("back", &backResponse);
        restored.restore(lean.world.state());
        lean.world = std::move(restored);
      }
      for (std::size_t i = 0; i < lean.movers.size(); ++i) {
        Rng& rng = lean.rng();
        const double u = rng.uniform();
        if (u < 0.04) {
          // Resized in place, often across the four-cell boundary (2×2 ↔ 3×2 at cell 16).
          const Rect r = lean.world.rect(lean.movers[i]);
          const Rect resized{r.x, r.y, rng.uniform() < 0.5 ? 20.0 : 36.0, rng.uniform(3, 20)};
          lean.world.update(lean.movers[i], resized);
          full.world.update(full.movers[i], resized);
          continue;
        }
        if (u < 0.06) {  // somewhere else, maybe inside something
          const Rect r = lean.moverRect();
          lean.world.update(lean.movers[i], r);
          full.world.update(full.movers[i], r);
          continue;
        }
        if (u < 0.07) {  // removed and added again: slots, generations and large places reused
          const Rect r = lean.moverRect();
          lean.world.remove(lean.movers[i]);
          full.world.remove(full.movers[i]);
          lean.movers[i] = lean.world.add(r);
          full.movers[i] = full.world.add(r);
          ASSERT_EQ(lean.movers[i], full.movers[i]);
          continue;
        }
        if (u < 0.12) lean.velocity[i] = lean.randomVelocity();
        MoveOptions options;
        const double m = rng.uniform();
        options.maxResponses = m < 0.1 ? 1 : m < 0.2 ? 2 : m < 0.3 ? 3 : 64;
        MoveTrace trace;
        MoveOptions traced = options;
        traced.trace = &trace;
        const ItemId id = lean.movers[i];
        const Rect from = lean.world.rect(id);
        const Vec2 goal = from.position() + lean.velocity[i];
        overlapsAtStart += lean.world.anyOverlap(from, id) ? 1u : 0u;
        largeMovers += lean.world.grid().cellsHolding(from).count() > 4 ? 1u : 0u;
        asked.clear();
        const MoveResult a = lean.world.move(id, goal, filter, options);
        const std::vector<Collision> ca(a.collisions.begin(), a.collisions.end());
        const MoveResult b = full.world.move(full.movers[i], goal, tracedFilter, traced);
        // Until the restore: which pairs a move asks about follows the order of the cells'
        // entries, which a restored world rebuilds in slot order (a copy keeps it).
        if (tick < 27) {
          ASSERT_EQ(unasked, "") << "the traced move asked " << unasked << ", seed " << seed
                                 << " tick " << tick << " mover " << i;
        }
        unasked.clear();
        ASSERT_TRUE(same(a.position, b.position))
            << "seed " << seed << " tick " << tick << " mover " << i;
        ASSERT_EQ(differences(ca, b.collisions), "")
            << "seed " << seed << " tick " << tick << " mover " << i;
        ++moves;
        collisions += ca.size();
        for (const Collision& c : ca) {  // turn back from what was hit
          if (c.normal.x != 0) lean.velocity[i].x = -lean.velocity[i].x;
          if (c.normal.y != 0) lean.velocity[i].y = -lean.velocity[i].y;
        }
      }
      ASSERT_EQ(lean.world.stateHash(), full.world.stateHash()) << "seed " << seed;
      if (tick % 10 == 9) {
        expectCellsExact(lean.world);
        if (HasFailure()) return;
      }
    }
    expectCellsExact(lean.world);
    expectCellsExact(full.world);
  }
  // The scenes did exercise what is compared: hits, starts inside something, large movers.
  EXPECT_GT(collisions, moves / 4);
  EXPECT_GT(overlapsAtStart, 50u);
  EXPECT_GT(largeMovers, 500u);
}

// An untraced move asks the filter about every pair its traced twin asks about: a recording made
// untraced keeps the answers by pair, and the debugger steps it traced (the full path), so a pair
// the traced move asks and the recording lacks is reported as a divergence. Cell 64:
//
//   x:  0         36   46     64 66         110 114
//   y 20 +-----------------------+-----------[M]-+   M (4×4) drops steeply onto F (leg 1) and
//        |                       |A          /   |   slides left along it (leg 2), meeting A
//   y 40 |                       |A        /     |   first and B, beyond A, later.
//   y 64 +-----------------------+A------/-------+   A (2×30) is in cells (1,0) and (1,1),
//   y 66 |           [ B ]       |A    /         |   B in (0,1) only: the untraced move lists
//   y 72 |[==========F===========|=============] |   A before B (row by row over the move's
//   y 80 +-----------------------+---------------+   box); leg 2's own walk meets B first.
TEST(NarrowMove, ATracedMoveAsksTheFilterNothingItsUntracedTwinDidNotAsk) {
  const auto scene = [](World& w) {
    const ItemId a = w.add({64, 40, 2, 30});
    w.add({0, 72, 128, 8});  // F
    w.add({36, 66, 10, 6});  // B
    return std::pair{a, w.add({110, 20, 4, 4})};
  };
  World lean(64), full(64);
  const auto [a, m] = scene(lean);
  (void)scene(full);
  std::set<std::uint32_t> asked;
  const auto record = [&](ItemId, ItemId other) {
    asked.insert(other.index);
    return response::slide;
  };
  const MoveResult r = lean.move(m, {40, 100}, record);
  ASSERT_EQ(r.collisions.size(), 2u);
  EXPECT_EQ(r.collisions[0].normal, (Vec2{0, -1}));  // onto F
  EXPECT_EQ(r.collisions[1].other, a);               // then against A
  EXPECT_EQ(r.position, (Vec2{66, 68}));
  if constexpr (!kTraceCompiledIn) GTEST_SKIP() << "tracing compiled out: no reference";
  MoveTrace trace;
  MoveOptions traced;
  traced.trace = &trace;
  const MoveResult t = full.move(m, {40, 100}, [](ItemId, ItemId) { return response::slide; },
                                 traced);
  EXPECT_EQ(t.position, (Vec2{66, 68}));
  ASSERT_FALSE(trace.answers.empty());
  for (const TraceAnswer& answer : trace.answers)
    EXPECT_EQ(asked.count(answer.other.index), 1u) << "item " << answer.other.index;
}

// A leg that leaves the move's box is swept against everything, not against the items gathered
// for the box:
//
//        L              M→    W       M (8×8) moves 16 right into W and recoils: back twice the
//   [=========]       [m]   [====]    way it came (32), past the box's left edge, where L stands.
//   -40      -16      0  8  20  36
//                     |<-box->|        the box: x in [0, 24]
//
// The untraced move stops against L as its traced twin does; without L the recoil runs its
// course to x = -20 (the control: the second leg does leave the box).
TEST(NarrowMove, ALegThatLeavesTheBoxStillMeetsWhatLiesBeyondIt) {
  struct Setup {
    World world{16};
    ItemId mover, wall;
    ResponseId recoil = 0;
  };
  const auto scene = [](Setup& s, bool withL) {
    s.recoil = s.world.addResponse("recoil", &recoilResponse);
    s.wall = s.world.add({20, 0, 16, 16});
    if (withL) s.world.add({-40, 0, 24, 16});
    s.mover = s.world.add({0, 4, 8, 8});
  };
  for (const bool withL : {false, true}) {
    Setup lean, full;
    scene(lean, withL);
    scene(full, withL);
    // Recoil from W, touch anything else.
    const auto filter = [&](ItemId, ItemId other) {
      return other == lean.wall ? lean.recoil : response::touch;
    };
    const MoveResult a = lean.world.move(lean.mover, {16, 4}, filter);
    const std::vector<Collision> ca(a.collisions.begin(), a.collisions.end());
    ASSERT_FALSE(ca.empty());
    EXPECT_EQ(ca[0].other, lean.wall);
    EXPECT_EQ(ca[0].touch, (Vec2{12, 4}));  // against W's face at x = 20
    if (withL) {
      ASSERT_EQ(ca.size(), 2u);
      EXPECT_EQ(ca[1].otherRect, (Rect{-40, 0, 24, 16}));
      EXPECT_EQ(a.position, (Vec2{-16, 4}));  // against L's face
    } else {
      EXPECT_EQ(ca.size(), 1u);
      EXPECT_EQ(a.position, (Vec2{-20, 4}));  // 12 - 2 * 16
    }
    if constexpr (kTraceCompiledIn) {
      MoveTrace trace;
      MoveOptions traced;
      traced.trace = &trace;
      const MoveResult b = full.world.move(full.mover, {16, 4}, filter, traced);
      EXPECT_TRUE(same(a.position, b.position));
      EXPECT_EQ(differences(ca, b.collisions), "");
    }
  }
}

}  // namespace
}  // namespace tv
