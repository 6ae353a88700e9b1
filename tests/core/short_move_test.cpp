// Specification of the short move: World::move reads the few cells of a short move's box once,
// asks the filter about what meets the box, and sweeps every leg that stays in the box against
// what it kept; a leg that leaves the box (a bounce, a user response) walks the cells. Either
// way the move is the reference's (move_reference.hpp: every leg against every item), bit for
// bit, down to the filter's questions.

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

#include "move_reference.hpp"
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
  // The functions of the responses the filter may return, by id.
  [[nodiscard]] std::vector<ResponseFn> responses() const {
    return {&touchResponse, &crossResponse, &slideResponse, &bounceResponse, &onewayResponse, &halfwayResponse,
            &backResponse};
  }

  World world{kCell};
  std::vector<ItemId> movers;
  std::vector<Vec2> velocity;

 private:
  Rng rng_;
  ResponseId halfway_ = 0, recoil_ = 0;
};

// Every move, made untraced and traced in turn, equals the reference's (computed on the world
// just before it) bit for bit, position, collisions and the filter's questions in order; while
// movers resize across the four-cell boundary, teleport into overlaps, are removed and re-added,
// and the world is swapped for a copy and for a restored state on the way (a restored world's
// cells list their items in another order).
TEST(ShortMove, EveryMoveEqualsTheReferenceBitForBit) {
  std::size_t collisions = 0, moves = 0, overlapsAtStart = 0, largeMovers = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Scene scene(seed);
    const std::vector<ResponseFn> fns = scene.responses();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> asked, refAsked;
    const auto filter = [&](ItemId item, ItemId other) {
      asked.push_back({item.index, other.index});
      return scene.responseOf(item, other);
    };
    const auto refFilter = [&](ItemId item, ItemId other) {
      refAsked.push_back({item.index, other.index});
      return scene.responseOf(item, other);
    };
    for (int tick = 0; tick < 40; ++tick) {
      if (tick == 13) {  // a copy carries on as the original would
        World copy = scene.world;
        scene.world = World(Scene::kCell);
        scene.world = copy;
      }
      if (tick == 27) {  // so does a world restored from the state
        World restored(Scene::kCell);
        (void)restored.addResponse("halfway", &halfwayResponse);
        (void)restored.addResponse("back", &backResponse);
        restored.restore(scene.world.state());
        scene.world = std::move(restored);
      }
      for (std::size_t i = 0; i < scene.movers.size(); ++i) {
        Rng& rng = scene.rng();
        const double u = rng.uniform();
        if (u < 0.04) {
          // Resized in place, often across the four-cell boundary (2×2 ↔ 3×2 at cell 16).
          const Rect r = scene.world.rect(scene.movers[i]);
          scene.world.update(scene.movers[i],
                             {r.x, r.y, rng.uniform() < 0.5 ? 20.0 : 36.0, rng.uniform(3, 20)});
          continue;
        }
        if (u < 0.06) {  // somewhere else, maybe inside something
          scene.world.update(scene.movers[i], scene.moverRect());
          continue;
        }
        if (u < 0.07) {  // removed and added again: slots, generations and large places reused
          const Rect r = scene.moverRect();
          scene.world.remove(scene.movers[i]);
          scene.movers[i] = scene.world.add(r);
          continue;
        }
        if (u < 0.12) scene.velocity[i] = scene.randomVelocity();
        MoveOptions options;
        const double m = rng.uniform();
        options.maxResponses = m < 0.1 ? 1 : m < 0.2 ? 2 : m < 0.3 ? 3 : 64;
        MoveTrace trace;
        if (i % 2 == 1) options.trace = &trace;
        const ItemId id = scene.movers[i];
        const Rect from = scene.world.rect(id);
        const Vec2 goal = from.position() + scene.velocity[i];
        overlapsAtStart += scene.world.anyOverlap(from, id) ? 1u : 0u;
        largeMovers += scene.world.grid().cellsHolding(from).count() > 4 ? 1u : 0u;
        asked.clear();
        refAsked.clear();
        const test::ReferenceResult ref = test::referenceMove(
            scene.world, id, from, goal, Filter(refFilter), options.maxResponses, fns);
        const MoveResult a = scene.world.move(id, goal, filter, options);
        const std::vector<Collision> ca(a.collisions.begin(), a.collisions.end());
        ASSERT_TRUE(same(a.position, ref.position))
            << "seed " << seed << " tick " << tick << " mover " << i;
        ASSERT_EQ(differences(ca, ref.collisions), "")
            << "seed " << seed << " tick " << tick << " mover " << i;
        ASSERT_EQ(asked, refAsked) << "seed " << seed << " tick " << tick << " mover " << i;
        ++moves;
        collisions += ca.size();
        for (const Collision& c : ca) {  // turn back from what was hit
          if (c.normal.x != 0) scene.velocity[i].x = -scene.velocity[i].x;
          if (c.normal.y != 0) scene.velocity[i].y = -scene.velocity[i].y;
        }
      }
      if (tick % 10 == 9) {
        expectCellsExact(scene.world);
        if (HasFailure()) return;
      }
    }
    expectCellsExact(scene.world);
  }
  // The scenes did exercise what is compared: hits, starts inside something, large movers.
  EXPECT_GT(collisions, moves / 4);
  EXPECT_GT(overlapsAtStart, 50u);
  EXPECT_GT(largeMovers, 500u);
}

// The filter is asked about what the move meets, not in the order the cells list it. M drops
// steeply onto F (leg 1) and slides left along it (leg 2), meeting A first and B, beyond A,
// later. Cell 64:
//
//   x:  0         36   46     64 66         110 114
//   y 20 +-----------------------+-----------[M]-+   The move's box spans 2×2 cells: it is
//        |                       |A          /   |   read once, and A (cells (1,0) and (1,1)),
//   y 40 |                       |A        /     |   F and B are asked about in slot order,
//   y 64 +-----------------------+A------/-------+   before anything is swept, traced or not,
//   y 66 |           [ B ]       |A    /         |   in a world built in another order too.
//   y 72 |[==========F===========|=============] |
//   y 80 +-----------------------+---------------+
TEST(ShortMove, AsksTheFilterAboutWhatItsBoxMeetsInSlotOrderTracedOrNot) {
  for (const bool traced : {false, true}) {
    for (const bool reversed : {false, true}) {
      World w(64);
      std::vector<Rect> rects = {{64, 40, 2, 30}, {0, 72, 128, 8}, {36, 66, 10, 6}};
      if (reversed) {  // B, F, A added last first: other slots, other cells' order
        std::reverse(rects.begin(), rects.end());
      }
      std::vector<ItemId> ids;
      for (const Rect& r : rects) ids.push_back(w.add(r));
      const ItemId m = w.add({110, 20, 4, 4});
      std::vector<std::uint32_t> asked;
      const auto record = [&](ItemId, ItemId other) {
        asked.push_back(other.index);
        return response::slide;
      };
      MoveTrace trace;
      MoveOptions o;
      if (traced) o.trace = &trace;
      const MoveResult r = w.move(m, {40, 100}, record, o);
      ASSERT_EQ(r.collisions.size(), 2u);
      EXPECT_EQ(r.collisions[0].normal, (Vec2{0, -1}));                // onto F
      EXPECT_EQ(r.collisions[1].otherRect, (Rect{64, 40, 2, 30}));     // then against A
      EXPECT_EQ(r.position, (Vec2{66, 68}));
      EXPECT_EQ(asked, (std::vector<std::uint32_t>{0, 1, 2})) << traced << reversed;
      if (traced && kTraceCompiledIn) {
        ASSERT_EQ(trace.answers.size(), 3u);
        for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(trace.answers[k].other.index, k);
      }
    }
  }
}

// A leg that leaves the move's box is swept against everything, not against the items gathered
// for the box:
//
//        L              M→    W       M (8×8) moves 16 right into W and recoils: back twice the
//   [=========]       [m]   [====]    way it came (32), past the box's left edge, where L stands.
//   -40      -16      0  8  20  36
//                     |<-box->|        the box: x in [0, 24]
//
// The move stops against L as the reference does; without L the recoil runs its course to
// x = -20 (the control: the second leg does leave the box).
TEST(ShortMove, ALegThatLeavesTheBoxStillMeetsWhatLiesBeyondIt) {
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
    const test::ReferenceResult ref = test::referenceMove(
        full.world, full.mover, full.world.rect(full.mover), {16, 4}, Filter(filter), 64,
        std::vector<ResponseFn>{&touchResponse, &crossResponse, &slideResponse, &bounceResponse, &onewayResponse,
                                &recoilResponse});
    EXPECT_TRUE(same(a.position, ref.position));
    EXPECT_EQ(differences(ca, ref.collisions), "");
  }
}

}  // namespace
}  // namespace tv
