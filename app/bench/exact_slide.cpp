#include "exact_slide.hpp"

#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <limits>
#include <optional>

namespace tv::bench {
namespace {

using Q = mpq_class;

struct QVec {
  Q x, y;
};

// Round to nearest, ties to even (mpq_class::get_d truncates, so compare its neighbours).
double roundNearest(const Q& q) {
  const double d = q.get_d();
  double best = d;
  Q bestErr = abs(q - Q(d));
  for (const double c : {std::nextafter(d, std::numeric_limits<double>::infinity()),
                         std::nextafter(d, -std::numeric_limits<double>::infinity())}) {
    const Q err = abs(q - Q(c));
    const bool even = (std::bit_cast<std::uint64_t>(c) & 1u) == 0;
    if (err < bestErr || (err == bestErr && even)) {
      best = c;
      bestErr = err;
    }
  }
  return best;
}

// The open time interval during which the mover's [a0, a0 + size] overlaps (o0, o1) on one
// axis, moving by d; nullopt bounds are infinite.
struct Interval {
  bool empty = false;
  std::optional<Q> lo, hi;
};

Interval axis(const Q& a0, const Q& size, const Q& d, double o0, double o1) {
  Interval in;
  const Q a1 = a0 + size;
  if (sgn(d) > 0) {
    in.lo = (Q(o0) - a1) / d;
    in.hi = (Q(o1) - a0) / d;
  } else if (sgn(d) < 0) {
    in.lo = (Q(o1) - a0) / d;
    in.hi = (Q(o0) - a1) / d;
  } else if (!(a0 < Q(o1) && a1 > Q(o0))) {
    in.empty = true;
  }
  return in;
}

struct Hit {
  Q t;
  bool corner = false;
  bool onX = false;
  std::size_t index = 0;
};

std::optional<Hit> sweep(const QVec& p, const QVec& size, const QVec& d, const Rect& o,
                         std::size_t index) {
  const Interval ix = axis(p.x, size.x, d.x, o.x, o.right());
  const Interval iy = axis(p.y, size.y, d.y, o.y, o.bottom());
  if (ix.empty || iy.empty) return std::nullopt;
  // Entry: the later of the two entries (a missing bound is minus infinity).
  int order = 0;  // > 0: x entered last, < 0: y, 0: tie
  if (ix.lo && iy.lo) {
    order = cmp(*ix.lo, *iy.lo);
  } else {
    order = ix.lo ? 1 : (iy.lo ? -1 : 0);
  }
  const std::optional<Q>& enter = order >= 0 ? ix.lo : iy.lo;
  if (!enter || sgn(*enter) < 0 || cmp(*enter, 1) >= 0) return std::nullopt;
  for (const std::optional<Q>* hi : {&ix.hi, &iy.hi}) {
    if (*hi && cmp(*enter, **hi) >= 0) return std::nullopt;
  }
  return Hit{*enter, order == 0, order >= 0, index};
}

}  // namespace

ExactMove exactSlide(const std::vector<Rect>& obstacles, Vec2 size, Vec2 start, Vec2 goal) {
  ExactMove out;
  const QVec s{Q(size.x), Q(size.y)};
  QVec p{Q(start.x), Q(start.y)};
  QVec g{Q(goal.x), Q(goal.y)};
  for (int response = 0; response < 64; ++response) {
    const QVec d{g.x - p.x, g.y - p.y};
    if (sgn(d.x) == 0 && sgn(d.y) == 0) break;
    std::optional<Hit> best;
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      const std::optional<Hit> h = sweep(p, s, d, obstacles[k], k);
      if (!h) continue;
      if (!best) {
        best = h;
        continue;
      }
      const int c = cmp(h->t, best->t);
      if (c < 0 || (c == 0 && !h->corner && best->corner)) best = h;
    }
    if (!best) {
      p = g;
      break;
    }
    const Rect& o = obstacles[best->index];
    QVec touch{p.x + best->t * d.x, p.y + best->t * d.y};
    if (best->onX) {
      touch.x = sgn(d.x) > 0 ? Q(o.x) - s.x : Q(o.right());
      out.hits.push_back({o, {sgn(d.x) > 0 ? -1.0 : 1.0, 0.0}});
      g.x = touch.x;
    } else {
      touch.y = sgn(d.y) > 0 ? Q(o.y) - s.y : Q(o.bottom());
      out.hits.push_back({o, {0.0, sgn(d.y) > 0 ? -1.0 : 1.0}});
      g.y = touch.y;
    }
    p = touch;
    if (response == 63) g = p;
  }
  out.position = {roundNearest(p.x), roundNearest(p.y)};
  return out;
}

}  // namespace tv::bench
