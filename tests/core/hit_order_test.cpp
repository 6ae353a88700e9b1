// Specification of the order of hits (tv/world.hpp): collisions are ordered by their exact time
// of impact, not by the rounded ti. Two faces less than a rounding apart share the same rounded
// ti; the nearer one must still be hit first, and the move must end flush with it, never an
// ulp inside it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

//        far  (added first)  |G####|        G = F + 1 ulp
//   [m]------------------>  |F####|         near (added second)
//   0                       F ≈ 5e6
//
// Both faces give the same rounded ti (the negative control below shows it): ordered by the
// rounded ti, add order would pick `far`, whose touch (right() == G) lies inside `near`.
TEST(HitOrder, OfTwoFacesAnUlpApartTheNearerIsHitFirstAndTheMoveEndsFlushWithIt) {
  const double F = 5024691.3560000006, G = std::nextafter(F, INFINITY);
  for (const int budget : {1, 2, 64}) {
    World w(64);
    const ItemId far = w.add({G, -50, 10, 100});
    const ItemId near = w.add({F, -50, 10, 100});
    const ItemId m = w.add({0, 0, 1, 1});
    tv::MoveOptions o;
    o.maxResponses = budget;
    const tv::MoveResult r = w.move(m, {1e7, 0}, {}, o);
    ASSERT_FALSE(r.collisions.empty());
    EXPECT_EQ(r.collisions[0].other, near) << "maxResponses " << budget;
    EXPECT_EQ(w.rect(m).right(), F) << "maxResponses " << budget;
    EXPECT_FALSE(tv::overlaps(w.rect(m), w.rect(near))) << "maxResponses " << budget;
    EXPECT_EQ(r.collisions.size(), 1u) << "the far face is behind the near one: never met";
    (void)far;
  }
  // Negative control: the rounded times of impact cannot tell the faces apart.
  const Rect mover{0, 0, 1, 1};
  EXPECT_EQ(tv::sweepRect(mover, {1e7, 0}, {F, -50, 10, 100}).ti,
            tv::sweepRect(mover, {1e7, 0}, {G, -50, 10, 100}).ti);
}

// Bouncing off the nearer of two faces 1 to 4 ulps apart sends the mover back, not into the face.
TEST(HitOrder, ABounceOffTheNearerOfTwoCloseFacesComesBack) {
  const double F = 5024691.3560000006;
  double G = F;
  for (int apart = 1; apart <= 4; ++apart) {
    G = std::nextafter(G, INFINITY);
    World w(64);
    (void)w.add({G, -50, 10, 100});
    const ItemId near = w.add({F, -50, 10, 100});
    const ItemId m = w.add({0, 0, 1, 1});
    const tv::MoveResult r = w.move(m, {1e7, 0}, tv::Filter::all(tv::response::bounce));
    ASSERT_FALSE(r.collisions.empty());
    EXPECT_EQ(r.collisions[0].other, near) << apart << " ulps apart";
    EXPECT_LT(w.rect(m).right(), F) << apart << " ulps apart: bounced back";
  }
}

// The opposite case: two faces at exactly the same place are an exact tie, and the tie is still
// broken by add order (the first added is reported first).
TEST(HitOrder, FacesAtExactlyTheSamePlaceAreStillOrderedByAddOrder) {
  const double F = 5024691.3560000006;
  World w(64);
  const ItemId first = w.add({F, -50, 10, 100});
  const ItemId second = w.add({F, -40, 10, 100});
  const ItemId m = w.add({0, 0, 1, 1});
  const tv::MoveResult r = w.move(m, {1e7, 0}, tv::Filter::all(tv::response::cross));
  ASSERT_EQ(r.collisions.size(), 2u);
  EXPECT_EQ(r.collisions[0].other, first);
  EXPECT_EQ(r.collisions[1].other, second);
}

// Decimal tile maps make such faces: 0.1 * 3 is an ulp above 0.3.
//
//   [m]---->  |a|       a's face at 0.1 * 3, b's at 0.3, both 16 wide; a added first
//             |b|
TEST(HitOrder, DecimalCoordinatesThatDifferByAnUlpAreOrderedExactly) {
  const double fa = 0.1 * 3, fb = 0.3;
  ASSERT_GT(fa, fb) << "the premise: the decimal product is an ulp above";
  World w(16);
  (void)w.add({fa, 0, 16, 16});
  const ItemId b = w.add({fb, 0, 16, 16});
  const ItemId m = w.add({-20, 4, 0.25, 8});
  const tv::MoveResult r = w.move(m, {400, 6});
  ASSERT_FALSE(r.collisions.empty());
  EXPECT_EQ(r.collisions[0].other, b);
  EXPECT_EQ(w.rect(m).right(), fb);
}

// [SECTION] randomized ----------------------------------------------------------------------------

// Uniform double in [lo, hi) from the engine's raw bits (std::uniform_real_distribution is not
// the same on every standard library, and these cases must be).
double uniform(std::mt19937_64& g, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(g() >> 11) * 0x1p-53);
}

double ulpsAway(double v, int k, double towards) {
  for (int i = 0; i < k; ++i) v = std::nextafter(v, towards);
  return v;
}

// Two walls whose faces are 0 to 4 ulps apart, added in either order, approached along x or y
// from either side with a small sideways drift; every built-in response; maxResponses from 1
// to 64. The first hit is always the nearer face (or, on an exact tie, the first added), and
// the move never ends inside a wall (cross aside, which passes through by definition).
TEST(HitOrder, RandomFacesAFewUlpsApartAreHitNearestFirstAndNeverEndedIn) {
  std::mt19937_64 g(20240601);
  const tv::ResponseId responses[] = {tv::response::touch, tv::response::slide,
                                      tv::response::bounce, tv::response::cross};
  int cases = 0;
  for (int i = 0; i < 2000; ++i) {
    // Along u (the motion's axis) the faces; across it, v. Decimal-looking coordinates.
    const double face = std::round(uniform(g, 1, 1e7) * 1000) / 1000 + 0.1 * 3;
    const int apart = static_cast<int>(g() % 5);
    const bool positive = (g() & 1) != 0;
    const bool alongX = (g() & 1) != 0;
    const bool nearFirst = (g() & 1) != 0;
    const double thick = uniform(g, 0.5, 20);
    const double size = uniform(g, 0.1, 8);
    const double across = uniform(g, 0.1, 8);
    // Gaps as long as the faces' coordinates: the time's numerator then rounds as coarsely as
    // the faces, and a few ulps between faces vanish in the rounded ti.
    const double gap = uniform(g, 1, face);
    const double drift = uniform(g, -10, 10);
    const double v0 = uniform(g, -30, 30);
    // Faces: for a positive move the walls' near (low) edges, else their far (high) edges.
    const double nearFace = face;
    const double farFace = ulpsAway(face, apart, positive ? INFINITY : -INFINITY);
    const auto wall = [&](double f) {
      const double lo = positive ? f : f - thick;  // far edge f - thick + thick may round
      return alongX ? Rect{lo, -50, thick, 100} : Rect{-50, lo, 100, thick};
    };
    const double u = positive ? nearFace - gap - size : nearFace + thick + gap;
    const double du = (positive ? 1 : -1) * (gap + 2 * thick + uniform(g, 0, face));
    const Rect start = alongX ? Rect{u, v0, size, across} : Rect{v0, u, across, size};
    const Vec2 goal = alongX ? Vec2{u + du, v0 + drift} : Vec2{v0 + drift, u + du};
    for (const tv::ResponseId resp : responses) {
      for (const int budget : {1, 2, 3, static_cast<int>(1 + g() % 64), 64}) {
        World w(131072);  // cells as long as the moves: the broad phase stays cheap
        const Rect nearRect = wall(nearFace), farRect = wall(farFace);
        const ItemId first = w.add(nearFirst ? nearRect : farRect);
        const ItemId second = w.add(nearFirst ? farRect : nearRect);
        const ItemId nearId = nearFirst ? first : second, farId = nearFirst ? second : first;
        // The faces actually compared: after rounding the far edges, "near" may tie.
        const auto faceOf = [&](const Rect& r) {
          return alongX ? (positive ? r.x : r.right()) : (positive ? r.y : r.bottom());
        };
        const double fn = faceOf(w.rect(nearId)), ff = faceOf(w.rect(farId));
        const ItemId m = w.add(start);
        tv::MoveOptions o;
        o.maxResponses = budget;
        const tv::MoveResult r = w.move(m, goal, tv::Filter::all(resp), o);
        ++cases;
        const std::string what = "case " + std::to_string(i) + " response " + std::to_string(resp) +
                                 " maxResponses " + std::to_string(budget);
        ASSERT_FALSE(r.collisions.empty()) << what;
        const ItemId expected =
            fn == ff ? first : ((positive ? fn < ff : fn > ff) ? nearId : farId);
        ASSERT_EQ(r.collisions[0].other, expected) << what;
        if (resp != tv::response::cross) {
          ASSERT_FALSE(tv::overlaps(w.rect(m), w.rect(nearId))) << what;
          ASSERT_FALSE(tv::overlaps(w.rect(m), w.rect(farId))) << what;
        }
      }
    }
  }
  EXPECT_EQ(cases, 2000 * 4 * 5);
}

}  // namespace
