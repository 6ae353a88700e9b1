// World::move with the slide response, checked against an exact rational reference.
//
// The reference is the model of tv/geometry.hpp and tv/sweep.hpp computed in exact rationals
// (GMP's mpq_class), by brute force over every obstacle (no grid):
// - a rect's edges are the doubles x and x + w (each rounded once, as computed in double);
// - on a leg the mover's edges travel linearly from the start rect's edges to the goal rect's;
// - a hit is when the open interiors intersect at some time before the goal; ti is the exact
//   entry time; the normal is on the axis entered last (an exact tie is a corner: x normal);
// - hits are ordered by exact ti, ordinary hits before corners, then by add order;
// - the touch coordinate on the normal's axis is tv::placeBefore(edge, size) (or the start's,
//   when the mover's far edge already rests on that edge) or the obstacle's far edge; the other
//   is start + ti * (goal - start) computed exactly, rounded to nearest;
// - a leg that starts inside an obstacle is resolved as core/src/sweep.cpp does (smallest push
//   out in the order up, left, right, down; ti = minus the intersection area, in double);
// - slide: the next leg runs from the touch to the goal with the normal's coordinate replaced;
//   after maxResponses responses the item stays at its last contact (with maxResponses 1 the
//   result is the first touch itself, interpolated coordinate included) — or, if the last
//   response pushed it out of an overlap, at the last contact before that push (or its start).
// Random scenes mix integer-aligned and dyadic rects (exact corners, touches and grazes occur
// often) with general-position doubles.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tv/world.hpp"

namespace {

using Q = mpq_class;
using tv::Rect;
using tv::Vec2;

constexpr double kInf = std::numeric_limits<double>::infinity();

// [SECTION] exact helpers -----------------------------------------------------------------------

bool evenMantissa(double d) {
  return (std::bit_cast<std::uint64_t>(d) & 1u) == 0;
}

// Round to nearest, ties to even. (mpq_class::get_d truncates towards zero, so its result and
// its two neighbours are the candidates.)
double roundNearest(const Q& q) {
  const double d = q.get_d();
  double best = d;
  Q bestErr = abs(q - Q(d));
  for (const double c : {std::nextafter(d, kInf), std::nextafter(d, -kInf)}) {
    const Q err = abs(q - Q(c));
    if (err < bestErr || (err == bestErr && evenMantissa(c) && !evenMantissa(best))) {
      best = c;
      bestErr = err;
    }
  }
  return best;
}

TEST(ExactReference, RoundsToNearestEvenNotTowardsZero) {
  // 1/10 lies just below its nearest double: truncation would give the double below 0.1.
  EXPECT_NE(Q(1, 10).get_d(), 0.1);
  EXPECT_EQ(roundNearest(Q(1, 10)), 0.1);
  EXPECT_EQ(roundNearest(Q(2, 3)), 2.0 / 3.0);
  EXPECT_EQ(roundNearest(Q(-7, 10)), -0.7);
  // Exactly halfway between 1 and 1 + 2^-52: to the even one, 1.
  Q half = Q(1) + Q(1) / Q(mpz_class(1) << 53);
  EXPECT_EQ(roundNearest(half), 1.0);
  // Halfway between 1 + 2^-52 (odd) and 1 + 2^-51 (even): up.
  Q half2 = Q(1) + Q(3) / Q(mpz_class(1) << 53);
  EXPECT_EQ(roundNearest(half2), 1.0 + std::ldexp(1.0, -51));
  EXPECT_EQ(roundNearest(Q(12345)), 12345.0);
}

// [SECTION] the reference sweep -----------------------------------------------------------------

// The open interval of times during which the mover's interior overlaps the obstacle's on one
// axis; nullopt bounds are infinite.
struct Interval {
  bool empty = false;
  std::optional<Q> lo, hi;
  void above(const Q& v) {
    if (!lo || v > *lo) lo = v;
  }
  void below(const Q& v) {
    if (!hi || v < *hi) hi = v;
  }
};

// Near edge travels s0 -> e0, far edge s1 -> e1 (rounded separately); obstacle (o0, o1).
Interval axisInterval(double s0, double s1, double e0, double e1, double o0, double o1) {
  Interval in;
  const Q d0 = Q(e0) - Q(s0), d1 = Q(e1) - Q(s1);
  // Near edge below the obstacle's far edge: s0 + t d0 < o1.
  if (sgn(d0) > 0) {
    in.below((Q(o1) - Q(s0)) / d0);
  } else if (sgn(d0) < 0) {
    in.above((Q(o1) - Q(s0)) / d0);
  } else if (!(s0 < o1)) {
    in.empty = true;
  }
  // Far edge above the obstacle's near edge: o0 < s1 + t d1.
  if (sgn(d1) > 0) {
    in.above((Q(o0) - Q(s1)) / d1);
  } else if (sgn(d1) < 0) {
    in.below((Q(o0) - Q(s1)) / d1);
  } else if (!(s1 > o0)) {
    in.empty = true;
  }
  return in;
}

// nullopt is minus infinity here (an entry time).
int compareEntry(const std::optional<Q>& a, const std::optional<Q>& b) {
  if (!a || !b) return (a ? 1 : 0) - (b ? 1 : 0);
  return cmp(*a, *b) < 0 ? -1 : (cmp(*a, *b) > 0 ? 1 : 0);
}

struct RefHit {
  bool overlap = false;
  double overlapTi = 0.0;  // minus the area, for overlaps
  Q ti;                    // exact, for hits
  bool corner = false;
  Vec2 normal, touch;
};

// As core/src/sweep.cpp resolves a leg that starts inside (doubles, same expressions).
RefHit overlapHit(const Rect& a, const Rect& b) {
  const double up = a.bottom() - b.y, down = b.bottom() - a.y;
  const double left = a.right() - b.x, right = b.right() - a.x;
  RefHit h;
  h.overlap = true;
  const double ix = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double iy = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
  h.overlapTi = -(ix * iy);
  double best = up;
  h.normal = {0, -1};
  h.touch = {a.x, tv::placeBefore(b.y, a.h)};
  if (left < best) {
    best = left;
    h.normal = {-1, 0};
    h.touch = {tv::placeBefore(b.x, a.w), a.y};
  }
  if (right < best) {
    best = right;
    h.normal = {1, 0};
    h.touch = {b.right(), a.y};
  }
  if (down < best) {
    h.normal = {0, 1};
    h.touch = {a.x, b.bottom()};
  }
  return h;
}

std::optional<RefHit> refSweep(const Rect& a, Vec2 goal, const Rect& b) {
  if (tv::overlaps(a, b)) return overlapHit(a, b);
  const Rect g = a.at(goal);
  // Exact early out: the mover stays inside the hull of its start and goal rects.
  const double hx0 = std::min(a.x, g.x), hx1 = std::max(a.right(), g.right());
  const double hy0 = std::min(a.y, g.y), hy1 = std::max(a.bottom(), g.bottom());
  if (!(hx0 < b.right() && b.x < hx1 && hy0 < b.bottom() && b.y < hy1)) return std::nullopt;

  const Interval ix = axisInterval(a.x, a.right(), g.x, g.right(), b.x, b.right());
  const Interval iy = axisInterval(a.y, a.bottom(), g.y, g.bottom(), b.y, b.bottom());
  if (ix.empty || iy.empty) return std::nullopt;
  const int order = compareEntry(ix.lo, iy.lo);
  const std::optional<Q>& enter = order >= 0 ? ix.lo : iy.lo;
  if (!enter || sgn(*enter) < 0 || cmp(*enter, 1) >= 0) return std::nullopt;
  for (const auto* hi : {&ix.hi, &iy.hi}) {
    if (*hi && cmp(*enter, **hi) >= 0) return std::nullopt;
  }
  RefHit h;
  h.ti = *enter;
  h.corner = order == 0;
  const bool onX = order >= 0, onY = order <= 0;
  const auto along = [&](double from, double to) {
    return roundNearest(Q(from) + h.ti * (Q(to) - Q(from)));
  };
  // Already resting on the face (far edge equal to it): the coordinate stays.
  const auto nearSide = [](double s, double size, double s1, double edge) {
    return s1 == edge ? s : tv::placeBefore(edge, size);
  };
  h.touch.x = onX ? (goal.x > a.x ? nearSide(a.x, a.w, a.right(), b.x) : b.right())
                  : along(a.x, goal.x);
  h.touch.y = onY ? (goal.y > a.y ? nearSide(a.y, a.h, a.bottom(), b.y) : b.bottom())
                  : along(a.y, goal.y);
  h.normal = onX ? Vec2{goal.x > a.x ? -1.0 : 1.0, 0.0} : Vec2{0.0, goal.y > a.y ? -1.0 : 1.0};
  return h;
}

// Overlaps (deepest first) before hits; hits by exact ti; ordinary before corner; add order.
bool before(const RefHit& a, std::size_t orderA, const RefHit& b, std::size_t orderB) {
  if (a.overlap != b.overlap) return a.overlap;
  if (a.overlap) {
    if (a.overlapTi != b.overlapTi) return a.overlapTi < b.overlapTi;
  } else if (const int c = cmp(a.ti, b.ti); c != 0) {
    return c < 0;
  }
  if (a.corner != b.corner) return !a.corner;
  return orderA < orderB;
}

struct RefMove {
  Vec2 position;
  int responses = 0;
  int corners = 0, touches = 0, overlaps = 0;
};

RefMove referenceMove(const std::vector<Rect>& obstacles, Vec2 size, Vec2 start, Vec2 goal,
                      int maxResponses) {
  RefMove m;
  Vec2 safe = start;
  for (int i = 0;; ++i) {
    if (i == maxResponses) {
      goal = safe;
      break;
    }
    const Rect a{start.x, start.y, size.x, size.y};
    std::optional<RefHit> best;
    std::size_t bestOrder = 0;
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      std::optional<RefHit> h = refSweep(a, goal, obstacles[k]);
      if (h && (!best || before(*h, k, *best, bestOrder))) {
        best = std::move(h);
        bestOrder = k;
      }
    }
    if (!best) break;
    ++m.responses;
    m.corners += best->corner;
    m.overlaps += best->overlap;
    m.touches += !best->overlap && sgn(best->ti) == 0;
    const Vec2 t = best->touch;
    goal = best->normal.x != 0.0 ? Vec2{t.x, goal.y} : Vec2{goal.x, t.y};
    start = t;
    if (!best->overlap) safe = start;
  }
  m.position = goal;
  return m;
}

// [SECTION] random scenes -----------------------------------------------------------------------

enum class Kind { integer, dyadic, general, mixed };

struct Gen {
  std::mt19937_64 rng;
  double offset = 0.0;  // added to every coordinate
  // A step of 0 draws general-position doubles; otherwise multiples of the step.

  double coord(double lo, double hi, double step) {
    if (step == 0.0) return offset + std::uniform_real_distribution<double>(lo, hi)(rng);
    const auto n = static_cast<std::int64_t>((hi - lo) / step);
    return offset + lo +
           step * static_cast<double>(std::uniform_int_distribution<std::int64_t>(0, n)(rng));
  }
  double extent(double lo, double hi, double step) {
    if (step == 0.0) return std::uniform_real_distribution<double>(lo, hi)(rng);
    const auto n = static_cast<std::int64_t>((hi - lo) / step);
    return lo + step * static_cast<double>(std::uniform_int_distribution<std::int64_t>(0, n)(rng));
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
};

std::string describe(const std::vector<Rect>& obstacles, Vec2 size, Vec2 start, Vec2 goal) {
  std::ostringstream s;
  s.precision(17);
  s << "mover size (" << size.x << ", " << size.y << ") from (" << start.x << ", " << start.y
    << ") to (" << goal.x << ", " << goal.y << ") among";
  for (const Rect& r : obstacles)
    s << " {" << r.x << ", " << r.y << ", " << r.w << ", " << r.h << "}";
  return s.str();
}

// 100 000 seeded random slide moves against the rational model. Goals ending an ulp inside an
// obstacle are among them (the hull case of World.AGoalEndingAnUlpInsideAnObstacleIsStopped...);
// all agree within 9.1e-13 px (one ulp at 4096).
TEST(ExactReference, SlideMovesMatchTheExactModel) {
  const std::uint64_t seed = 0x7456C0DEull;
  Gen gen{std::mt19937_64(seed)};
  constexpr int kScenes = 5000, kMovesPerScene = 20;
  double maxError = 0.0;
  long moves = 0, inexact = 0, countMismatch = 0, endsInside = 0, bad = 0, responses = 0,
       corners = 0, touches = 0, overlaps = 0;
  std::vector<std::string> report;
  for (int scene = 0; scene < kScenes; ++scene) {
    // integer, dyadic and general-position scenes, and mixed ones (integer obstacles with a
    // general mover, or the other way round).
    const auto kind = static_cast<Kind>(scene % 4);
    const double obstacleStep = kind == Kind::integer   ? 1.0
                                : kind == Kind::dyadic  ? 0.25
                                : kind == Kind::general ? 0.0
                                                        : (scene % 8 == 3 ? 1.0 : 0.0);
    const double moverStep = kind == Kind::mixed ? (obstacleStep == 0.0 ? 1.0 : 0.0) : obstacleStep;
    gen.offset = gen.chance(0.25) ? (gen.chance(0.5) ? 1024.0 : -4096.0) : 0.0;
    const double cell = std::array<double, 4>{4.0, 8.0, 16.0, 32.0}[gen.rng() % 4];

    tv::World world(cell);
    std::vector<Rect> obstacles;
    const int n = 4 + static_cast<int>(gen.rng() % 9);
    for (int k = 0; k < n; ++k) {
      const Rect r{gen.coord(-8, 48, obstacleStep), gen.coord(-8, 48, obstacleStep),
                   gen.extent(1, 16, obstacleStep), gen.extent(1, 16, obstacleStep)};
      obstacles.push_back(r);
      (void)world.add(r);
    }
    const Vec2 size{gen.extent(1, 12, moverStep), gen.extent(1, 12, moverStep)};
    const tv::ItemId mover = world.add({gen.offset, gen.offset, size.x, size.y});

    for (int i = 0; i < kMovesPerScene; ++i) {
      Vec2 start{gen.coord(-16, 56, moverStep), gen.coord(-16, 56, moverStep)};
      // Mostly start in free space (a start inside an obstacle is pushed out first; keep some).
      for (int tries = 0; tries < 8 && gen.chance(0.9); ++tries) {
        const Rect r{start.x, start.y, size.x, size.y};
        if (std::none_of(obstacles.begin(), obstacles.end(),
                         [&](const Rect& o) { return tv::overlaps(r, o); })) {
          break;
        }
        start = {gen.coord(-16, 56, moverStep), gen.coord(-16, 56, moverStep)};
      }
      if (gen.chance(0.3)) {
        // Start resting on an obstacle's top or against its left side: touches and slides.
        const Rect& o = obstacles[gen.rng() % obstacles.size()];
        if (gen.chance(0.5)) {
          start.y = tv::placeBefore(o.y, size.y);
        } else {
          start.x = tv::placeBefore(o.x, size.x);
        }
      }
      Vec2 d{gen.extent(-40, 40, moverStep), gen.extent(-40, 40, moverStep)};
      if (gen.chance(0.2)) (gen.chance(0.5) ? d.x : d.y) = 0.0;
      if (gen.chance(0.25)) d.y = gen.chance(0.5) ? d.x : -d.x;  // 45 degrees: corners
      Vec2 goal = start + d;
      if (gen.chance(0.1)) {
        // A goal whose far edge ends a hair (an ulp or two) inside an obstacle's near edge: the
        // move must still stop at the edge.
        const Rect& o = obstacles[gen.rng() % obstacles.size()];
        if (gen.chance(0.5)) {
          goal.x = std::nextafter(tv::placeBefore(o.x, size.x), kInf);
        } else {
          goal.y = std::nextafter(tv::placeBefore(o.y, size.y), kInf);
        }
      }

      world.update(mover, start);
      tv::MoveOptions options;
      options.broad = i % 2 == 0 ? tv::BroadPhase::swept : tv::BroadPhase::bounds;
      options.maxResponses = i % 3 == 0 ? 1 : (i % 3 == 1 ? 2 : 64);
      const tv::MoveResult got = world.move(mover, goal, {}, options);
      const RefMove want = referenceMove(obstacles, size, start, goal, options.maxResponses);
      ++moves;
      inexact += got.position != want.position;
      countMismatch += static_cast<long>(got.collisions.size()) != want.responses;
      // Wherever it ends, the mover is inside nothing it did not end inside in the model.
      const Rect end{got.position.x, got.position.y, size.x, size.y};
      const Rect wantEnd{want.position.x, want.position.y, size.x, size.y};
      for (const Rect& o : obstacles) {
        if (tv::overlaps(end, o) && !tv::overlaps(wantEnd, o)) {
          ++endsInside;
          if (report.size() < 5) {
            std::ostringstream s;
            s.precision(17);
            s << "scene " << scene << " move " << i << ": ends inside {" << o.x << ", " << o.y
              << ", " << o.w << ", " << o.h << "}: " << describe(obstacles, size, start, goal)
              << "\n  got (" << got.position.x << ", " << got.position.y << ") after "
              << got.collisions.size() << " responses, reference (" << want.position.x << ", "
              << want.position.y << ") after " << want.responses;
            report.push_back(s.str());
          }
          break;
        }
      }
      responses += want.responses;
      corners += want.corners;
      touches += want.touches;
      overlaps += want.overlaps;
      const double err = std::max(std::fabs(got.position.x - want.position.x),
                                  std::fabs(got.position.y - want.position.y));
      maxError = std::max(maxError, err);
      if (!(err <= 1e-9)) {
        ++bad;
        if (report.size() < 5) {
          std::ostringstream s;
          s.precision(17);
          s << "scene " << scene << " move " << i << ": " << describe(obstacles, size, start, goal)
            << "\n  got (" << got.position.x << ", " << got.position.y << ") after "
            << got.collisions.size() << " responses, reference (" << want.position.x << ", "
            << want.position.y << ") after " << want.responses;
          report.push_back(s.str());
        }
      }
    }
  }
  for (const std::string& r : report) ADD_FAILURE() << r;
  EXPECT_EQ(bad, 0) << "moves off by more than 1e-9 px (seed " << seed << ")";
  EXPECT_EQ(endsInside, 0) << "moves that end inside an obstacle the model stops at (seed " << seed
                           << ")";
  EXPECT_EQ(countMismatch, 0) << "moves with another number of responses than the model";
  EXPECT_LE(maxError, 1e-9);
  // The scenes must exercise what the model decides exactly.
  EXPECT_GT(corners, 100);
  EXPECT_GT(touches, 1000);
  EXPECT_GT(overlaps, 1000);
  RecordProperty("max_error_px", std::to_string(maxError));
  std::printf(
      "[ reference ] seed %llu: %ld moves, %ld responses (%ld exact corners, %ld at ti 0, "
      "%ld overlaps), %ld not bit-identical, %ld ending inside, %ld other response counts, "
      "max position error %.3g px\n",
      static_cast<unsigned long long>(seed), moves, responses, corners, touches, overlaps, inexact,
      endsInside, countMismatch, maxError);
}

}  // namespace
