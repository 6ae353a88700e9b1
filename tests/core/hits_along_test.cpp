// Specification of World::hitsAlong, the straight-leg query (bump.lua's `World:project`): every
// hit of one leg, in the order a move takes them. Its promise is agreement with the move: the
// first hit it lists is the move's first collision, and a move that crosses everything meets
// them all in its order. The naive query (the items in the leg's box, swept, sorted on the
// rounded ti) is the negative control: where two faces lie a rounding apart it disagrees.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "expect_rejected.hpp"
#include "tv/bump.hpp"
#include "tv/world.hpp"

namespace {

using tv::Collision;
using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;
namespace response = tv::response;

using Ids = std::vector<ItemId>;

Ids othersOf(const std::vector<Collision>& cols) {
  Ids ids;
  for (const Collision& c : cols) ids.push_back(c.other);
  return ids;
}

// The straight-leg query as it was written outside the core (the Lua module's `project` before
// it called hitsAlong): the items overlapping the leg's bounding box in add order, swept, then
// stable-sorted on the rounded ti, ordinary hits before corner hits.
std::vector<Collision> roundedTiOrder(const World& w, ItemId self, const Rect& r, Vec2 goal) {
  std::vector<Collision> cols;
  for (const ItemId other : w.queryRect(tv::unite(r, r.at(goal)), self)) {
    const tv::Sweep s = tv::sweepRect(r, goal, w.rect(other));
    if (s.kind == tv::SweepKind::miss) continue;
    Collision c;
    c.other = other;
    c.ti = s.ti;
    c.corner = s.corner;
    cols.push_back(c);
  }
  std::stable_sort(cols.begin(), cols.end(), [](const Collision& a, const Collision& b) {
    if (a.ti != b.ti) return a.ti < b.ti;
    return !a.corner && b.corner;
  });
  return cols;
}

// [SECTION] order -------------------------------------------------------------------------------

//        far  (added first)  |G####|        G = F + 1 ulp
//   [m]------------------>  |F####|         near (added second)
//   0                       F ≈ 5e6
//
// Both faces give the same rounded ti. Sorted on it, add order decides and `far` comes first —
// but a move hits `near` first (its touch against `far` would lie inside `near`).
TEST(HitsAlong, OfTwoFacesARoundingApartTheNearerComesFirstAsInAMove) {
  const double F = 5024691.3560000006, G = std::nextafter(F, INFINITY);
  World w(64);
  const ItemId far = w.add({G, -50, 10, 100});
  const ItemId near = w.add({F, -50, 10, 100});
  const ItemId m = w.add({0, 0, 1, 1});
  const Vec2 goal{1e7, 0};

  std::vector<Collision> hits;
  w.hitsAlong(m, w.rect(m), goal, tv::Filter::all(response::touch), hits);
  EXPECT_EQ(othersOf(hits), (Ids{near, far}));
  EXPECT_EQ(hits[0].touch.x + 1, F) << "flush with the nearer face";
  EXPECT_EQ(hits[0].response, response::touch);
  EXPECT_EQ(hits[0].item, m);

  World moved = w;
  const tv::MoveResult r = moved.move(m, goal, tv::Filter::all(response::touch));
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].other, hits[0].other) << "the query's first hit is the move's";

  // Negative control: the rounded ti are equal, and a sort on them puts the farther face first.
  const std::vector<Collision> naive = roundedTiOrder(w, m, w.rect(m), goal);
  ASSERT_EQ(naive.size(), 2u);
  EXPECT_EQ(naive[0].ti, naive[1].ti) << "the premise: one rounded ti for both faces";
  EXPECT_EQ(othersOf(naive), (Ids{far, near})) << "the rounded order gets it wrong";
}

//   m {0, 0, 4, 4} moving by (16, 16); at t 0.25 its right edge reaches x 8 and its corner (8, 8):
//
//        |b|      b {8, -20, 4, 28} and `later` {8, -10, 4, 16}: the same face x 8, entered at
//        |b|        t 0.25 while m's rows already overlap theirs — ordinary hits, an exact tie
//   [m]  |b|          broken by add order
//     \      |c|  c {8, 8, 4, 4}: met corner to corner at t 0.25 (both axes at once) — an exact
//                   corner hit, after the ordinary ones although c was added first
TEST(HitsAlong, AtTheSameInstantOrdinaryHitsComeBeforeACornerHitThenAddOrder) {
  World w(16);
  const ItemId c = w.add({8, 8, 4, 4});
  const ItemId b = w.add({8, -20, 4, 28});
  const ItemId later = w.add({8, -10, 4, 16});
  const ItemId m = w.add({0, 0, 4, 4});
  std::vector<Collision> hits;
  w.hitsAlong(m, w.rect(m), {16, 16}, tv::Filter::all(response::cross), hits);
  ASSERT_EQ(hits.size(), 3u);
  EXPECT_EQ(othersOf(hits), (Ids{b, later, c}));
  EXPECT_FALSE(hits[0].corner);
  EXPECT_TRUE(hits[2].corner);
  EXPECT_EQ(hits[0].ti, hits[2].ti);
  World moved = w;
  const tv::MoveResult r = moved.move(m, {16, 16}, tv::Filter::all(response::cross));
  EXPECT_EQ(othersOf({r.collisions.begin(), r.collisions.end()}), othersOf(hits));
}

// [SECTION] filter ------------------------------------------------------------------------------

//   [m]----> |a| |b| |c|    the filter ignores b: a and c are listed, each with its answer,
//                            and the filter was asked about a, b, c in that order, once each
TEST(HitsAlong, AsksTheFilterOnceAboutEachHitInOrderAndLeavesTheIgnoredOut) {
  World w(16);
  const ItemId c = w.add({40, 0, 4, 4});
  const ItemId a = w.add({10, 0, 4, 4});
  const ItemId b = w.add({20, 0, 4, 4});
  const ItemId m = w.add({0, 0, 4, 4});
  (void)w.add({0, 30, 4, 4});  // off the path: never asked about
  Ids asked;
  const auto filter = [&](ItemId self, ItemId other) {
    EXPECT_EQ(self, m);
    asked.push_back(other);
    return other == b ? response::ignore : other == a ? response::touch : response::bounce;
  };
  std::vector<Collision> hits{Collision{}};  // cleared first
  w.hitsAlong(m, w.rect(m), {60, 0}, filter, hits);
  EXPECT_EQ(asked, (Ids{a, b, c}));
  ASSERT_EQ(othersOf(hits), (Ids{a, c}));
  EXPECT_EQ(hits[0].response, response::touch);
  EXPECT_EQ(hits[1].response, response::bounce);
  EXPECT_EQ(hits[1].touch, (Vec2{36, 0}));
  EXPECT_EQ(hits[1].target, hits[1].touch) << "no response ran";
}

// A rect that is no item (an invalid self) meets every item, m included; m asking leaves itself
// out, and so does the rect it stands for even when elsewhere.
TEST(HitsAlong, LeavesOutTheItemTheRectStandsForAndNothingElse) {
  World w(16);
  const ItemId m = w.add({0, 0, 4, 4});
  const ItemId a = w.add({10, 0, 4, 4});
  std::vector<Collision> hits;
  w.hitsAlong({}, {-10, 0, 4, 4}, {20, 0}, {}, hits);
  EXPECT_EQ(othersOf(hits), (Ids{m, a}));
  EXPECT_FALSE(hits[0].item.valid());
  w.hitsAlong(m, {-10, 0, 4, 4}, {20, 0}, {}, hits);
  EXPECT_EQ(othersOf(hits), (Ids{a}));
}

// Under bump's rules the query is bump's project (its order: ti, then distance between centres).
TEST(HitsAlong, WithBumpSemanticsIsBumpsProject) {
  World w(64);
  (void)w.add({10, -4, 4, 16});
  (void)w.add({10, 4, 4, 16});
  (void)w.add({30, 0, 4, 4});
  const ItemId m = w.add({0, 2, 4, 4});
  tv::MoveOptions o;
  o.semantics = tv::MoveSemantics::bump;
  std::vector<Collision> hits, bumps;
  w.hitsAlong(m, w.rect(m), {50, 2}, tv::Filter::all(response::cross), hits, o);
  tv::bump::project(w, m, w.rect(m), {50, 2}, tv::Filter::all(response::cross), {}, bumps);
  ASSERT_EQ(hits.size(), 3u);
  EXPECT_EQ(othersOf(hits), othersOf(bumps));
  for (std::size_t i = 0; i < hits.size(); ++i) EXPECT_EQ(hits[i].touch, bumps[i].touch);
}

// [SECTION] bad input ---------------------------------------------------------------------------

TEST(HitsAlong, RefusesBadInputNamingTheValueAndLeavesNothingBehind) {
  World w(16);
  const ItemId m = w.add({0, 0, 4, 4});
  (void)w.add({10, 0, 4, 4});
  const ItemId gone = w.add({50, 50, 4, 4});
  w.remove(gone);
  std::vector<Collision> hits{Collision{}};
  const double nan = std::nan(""), inf = INFINITY;
  expectRejected(w, {"tv::World::hitsAlong", "x", "nan"},
                 [&] { w.hitsAlong(m, {nan, 0, 4, 4}, {20, 0}, {}, hits); });
  EXPECT_TRUE(hits.empty());
  expectRejected(w, {"tv::World::hitsAlong", "goal.y", "inf"},
                 [&] { w.hitsAlong(m, {0, 0, 4, 4}, {20, inf}, {}, hits); });
  expectRejected(w, {"tv::World::hitsAlong", "w must", "-4"},
                 [&] { w.hitsAlong(m, {0, 0, -4, 4}, {20, 0}, {}, hits); });
  expectRejected(w, {"tv::World::hitsAlong", "item {index=2", "not in the world"},
                 [&] { w.hitsAlong(gone, {0, 0, 4, 4}, {20, 0}, {}, hits); });
  tv::MoveOptions bad;
  bad.maxResponses = 0;
  expectRejected(w, {"tv::World::hitsAlong", "maxResponses", "was 0"},
                 [&] { w.hitsAlong(m, {0, 0, 4, 4}, {20, 0}, {}, hits, bad); });
  hits.assign(3, Collision{});
  expectRejected(w, {"tv::World::hitsAlong", "response 99", "not registered"},
                 [&] { w.hitsAlong(m, {0, 0, 4, 4}, {20, 0}, tv::Filter::all(99), hits); });
  EXPECT_TRUE(hits.empty()) << "a refused answer leaves no partial list";
}

// [SECTION] randomized --------------------------------------------------------------------------

// Uniform double in [lo, hi) from the engine's raw bits (the same on every standard library).
double uniform(std::mt19937_64& g, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(g() >> 11) * 0x1p-53);
}

// A seeded field of 16 px tiles at decimal offsets, a third of them with a twin whose face is
// 1 to 3 ulps away on one side (added before or after it): the near-coincident faces a tile map
// with decimal coordinates makes.
struct Field {
  explicit Field(std::uint64_t seed) : g(seed) {
    for (int row = 0; row < 16; ++row) {
      for (int col = 0; col < 16; ++col) {
        if (g() % 10 >= 3) continue;
        const Rect t{col * 16 + 0.1 * static_cast<double>(g() % 4), row * 16 + 0.1 * 3, 16, 16};
        if (g() % 3 != 0) {
          (void)world.add(t);
          continue;
        }
        Rect twin = t;
        const int ulps = 1 + static_cast<int>(g() % 3);
        const bool up = (g() & 1) != 0;
        double& edge = (g() & 1) != 0 ? twin.x : twin.y;
        for (int i = 0; i < ulps; ++i) edge = std::nextafter(edge, up ? INFINITY : -INFINITY);
        const bool twinFirst = (g() & 1) != 0;
        (void)world.add(twinFirst ? twin : t);
        (void)world.add(twinFirst ? t : twin);
      }
    }
  }
  std::mt19937_64 g;
  World world{16};
};

// Which response the filter gives a pair: a fixed function of the other item, so that a move
// (which asks lazily) and the query (which asks about every hit) get the same answers.
tv::ResponseId answerFor(ItemId other) {
  static constexpr tv::ResponseId kAnswers[] = {response::cross, response::slide, response::touch,
                                                response::cross, response::bounce,
                                                response::ignore};
  return kAnswers[(other.index * 2654435761u >> 7) % 6];
}

bool sameHit(const Collision& a, const Collision& b) {
  return a.other == b.other && a.ti == b.ti && a.touch == b.touch && a.normal == b.normal &&
         a.overlaps == b.overlaps && a.corner == b.corner && a.response == b.response &&
         a.itemRect == b.itemRect && a.otherRect == b.otherRect && a.move == b.move;
}

// For many random legs over the field, both broad phases:
// - a move meets the query's hits in the query's order up to and including the first it does
//   not cross (the answers mixed: cross, slide, touch, bounce, ignore);
// - a move that crosses everything meets exactly the query's hits, in its order.
// Negative control: the rounded-ti sort disagrees with the move on some of these legs.
TEST(HitsAlong, OnRandomLegsOverATileFieldTheMoveTakesTheHitsInTheQuerysOrder) {
  int legs = 0, withHits = 0, naiveWrong = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Field f(seed);
    std::mt19937_64& g = f.g;
    for (int i = 0; i < 250; ++i) {
      const Rect start{uniform(g, -20, 270), uniform(g, -20, 270), uniform(g, 0.5, 20),
                       uniform(g, 0.5, 20)};
      const Vec2 goal{start.x + uniform(g, -200, 200),
                      (g() % 4 == 0) ? start.y : start.y + uniform(g, -200, 200)};
      const ItemId m = f.world.add(start);
      for (const tv::BroadPhase broad : {tv::BroadPhase::swept, tv::BroadPhase::bounds}) {
        const std::string what = "seed " + std::to_string(seed) + " leg " + std::to_string(i) +
                                 (broad == tv::BroadPhase::swept ? " swept" : " bounds");
        tv::MoveOptions o;
        o.broad = broad;
        o.maxResponses = 4096;
        ++legs;
        // Mixed answers: the move's collisions up to its first non-cross one.
        const auto mixed = [](ItemId, ItemId other) { return answerFor(other); };
        std::vector<Collision> hits;
        f.world.hitsAlong(m, start, goal, mixed, hits, o);
        World moved = f.world;
        const tv::MoveResult r = moved.move(m, goal, mixed, o);
        std::size_t k = 0;
        for (; k < hits.size(); ++k) {
          ASSERT_LT(k, r.collisions.size()) << what << ": the move met fewer";
          ASSERT_TRUE(sameHit(hits[k], r.collisions[k])) << what << " hit " << k;
          if (hits[k].response != response::cross) break;
        }
        if (k == hits.size()) {
          EXPECT_EQ(r.collisions.size(), hits.size()) << what << ": all crossed, no more met";
        }
        // Everything crossed: the whole list.
        const tv::Filter all = tv::Filter::all(response::cross);
        f.world.hitsAlong(m, start, goal, all, hits, o);
        const tv::MoveResult c = f.world.check(m, goal, all, o);
        ASSERT_EQ(c.collisions.size(), hits.size()) << what;
        for (std::size_t j = 0; j < hits.size(); ++j) {
          ASSERT_TRUE(sameHit(hits[j], c.collisions[j])) << what << " hit " << j;
        }
        if (!hits.empty()) ++withHits;
        if (broad == tv::BroadPhase::swept &&
            othersOf(roundedTiOrder(f.world, m, start, goal)) != othersOf(hits)) {
          ++naiveWrong;
        }
      }
      f.world.remove(m);
    }
  }
  EXPECT_EQ(legs, 8 * 250 * 2);
  EXPECT_GT(withHits, legs / 2) << "most legs meet something";
  EXPECT_GT(naiveWrong, 0) << "negative control: the rounded-ti order disagrees somewhere";
  std::printf("hitsAlong: %d legs agreed with the move (%d meeting something); the rounded-ti "
              "sort disagreed on %d\n",
              legs, withHits, naiveWrong);
}

}  // namespace
