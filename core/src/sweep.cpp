#include "tv/sweep.hpp"

#include <algorithm>

#include "exact_time.hpp"
#include "hit_order.hpp"

namespace tv {

using detail::Time;

namespace {

// The open time interval during which a mover's interior overlaps an obstacle's on one axis.
// The mover's near and far edges travel from (s0, s1) to (e0, e1); the obstacle spans (o0, o1).
struct Span {
  Time enter, exit;
};

Span axisSpan(double s0, double s1, double e0, double e1, double o0, double o1) {
  if (e0 > s0) {
    return {s1 > o0 ? Time::neg() : (e1 > o0 ? Time{o0 - s1, e1 - s1} : Time::pos()),
            s0 >= o1 ? Time::neg() : (e0 >= o1 ? Time{o1 - s0, e0 - s0} : Time::pos())};
  }
  if (e0 < s0) {
    return {s0 < o1 ? Time::neg() : (e0 < o1 ? Time{s0 - o1, s0 - e0} : Time::pos()),
            s1 <= o0 ? Time::neg() : (e1 <= o0 ? Time{s1 - o0, s1 - e1} : Time::pos())};
  }
  const bool inside = s0 < o1 && o0 < s1;
  return {inside ? Time::neg() : Time::pos(), inside ? Time::pos() : Time::neg()};
}

Sweep overlapSweep(const Rect& a, const Rect& b) {
  // Smallest push out; on equal depths the first of up, left, right, down.
  const double up = a.bottom() - b.y, down = b.bottom() - a.y;
  const double left = a.right() - b.x, right = b.right() - a.x;
  Sweep s;
  s.kind = SweepKind::overlap;
  const double ix = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double iy = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
  s.ti = -(ix * iy);
  double best = up;
  s.normal = {0, -1};
  s.touch = {a.x, placeBefore(b.y, a.h)};
  if (left < best) {
    best = left;
    s.normal = {-1, 0};
    s.touch = {placeBefore(b.x, a.w), a.y};
  }
  if (right < best) {
    best = right;
    s.normal = {1, 0};
    s.touch = {b.right(), a.y};
  }
  if (down < best) {
    s.normal = {0, 1};
    s.touch = {a.x, b.bottom()};
  }
  return s;
}

}  // namespace

Sweep sweepRect(const Rect& a, Vec2 goal, const Rect& b) {
  if (overlaps(a, b)) return overlapSweep(a, b);
  const Rect g = a.at(goal);
  const Span sx = axisSpan(a.x, a.right(), g.x, g.right(), b.x, b.right());
  const Span sy = axisSpan(a.y, a.bottom(), g.y, g.bottom(), b.y, b.bottom());
  const Time& enter = detail::later(sx.enter, sy.enter);
  const Time& exit = detail::earlier(sx.exit, sy.exit);
  if (enter.inf != 0 || detail::compare(enter, exit) >= 0) return {};

  Sweep s;
  s.kind = SweepKind::hit;
  s.ti = enter.value();
  const int order = detail::compare(sx.enter, sy.enter);
  s.corner = order == 0;
  const bool onX = order >= 0;  // exact corner: x, as bump.lua does
  const bool onY = order <= 0;
  const auto along = [&](double from, double to) {
    // Off the normal's axis the position is interpolated, kept between start and goal.
    const double v = from + s.ti * (to - from);
    return std::clamp(v, std::min(from, to), std::max(from, to));
  };
  // A mover already resting on the face (its far edge equal to it) stays where it is: when
  // its extent is finer than the face's ulp, several positions rest on the face, and placing it
  // anew at the one nearest edge − size could step it back — a body under a gravity step below
  // an ulp of the floor's top would then toggle between two of them for ever.
  if (onX) {
    s.touch.x = goal.x > a.x ? (a.right() == b.x ? a.x : placeBefore(b.x, a.w)) : b.right();
  } else {
    s.touch.x = along(a.x, goal.x);
  }
  if (onY) {
    s.touch.y = goal.y > a.y ? (a.bottom() == b.y ? a.y : placeBefore(b.y, a.h)) : b.bottom();
  } else {
    s.touch.y = along(a.y, goal.y);
  }
  if (onX) {
    s.normal = {goal.x > a.x ? -1.0 : 1.0, 0.0};
  } else {
    s.normal = {0.0, goal.y > a.y ? -1.0 : 1.0};
  }
  return s;
}

SegmentClip clipSegment(Vec2 a, Vec2 b, const Rect& r) {
  if (a == b) {
    const bool inside = r.x < a.x && a.x < r.right() && r.y < a.y && a.y < r.bottom();
    return {inside, 0.0, 0.0};
  }
  // Same spans as a zero-size mover: on each axis the open interval of t inside the rect.
  const auto span = [](double p0, double p1, double o0, double o1) -> Span {
    if (p1 > p0) {
      return {p0 > o0 ? Time::neg() : Time{o0 - p0, p1 - p0},
              p0 >= o1 ? Time::neg() : Time{o1 - p0, p1 - p0}};
    }
    if (p1 < p0) {
      return {p0 < o1 ? Time::neg() : Time{p0 - o1, p0 - p1},
              p0 <= o0 ? Time::neg() : Time{p0 - o0, p0 - p1}};
    }
    const bool inside = o0 < p0 && p0 < o1;
    return {inside ? Time::neg() : Time::pos(), inside ? Time::pos() : Time::neg()};
  };
  const Span sx = span(a.x, b.x, r.x, r.right());
  const Span sy = span(a.y, b.y, r.y, r.bottom());
  const Time zero{0.0, 1.0, 0}, one{1.0, 1.0, 0};
  const Time& t0 = detail::later(detail::later(sx.enter, sy.enter), zero);
  const Time& t1 = detail::earlier(detail::earlier(sx.exit, sy.exit), one);
  if (detail::compare(t0, t1) >= 0) return {};
  return {true, t0.value(), t1.value()};
}

namespace detail {

namespace {

// A hit's time of impact as the fraction (n0 − n1) / (d0 − d1) that sweepRect compared: the
// gap to the face its normal names over the distance the near edge travels.
struct Impact {
  double n0, n1, d0, d1;
};

Impact impact(const Rect& a, Vec2 goal, const Sweep& s, const Rect& o) {
  const Rect g = a.at(goal);
  if (s.normal.x < 0) return {o.x, a.right(), g.right(), a.right()};
  if (s.normal.x > 0) return {a.x, o.right(), a.x, g.x};
  if (s.normal.y < 0) return {o.y, a.bottom(), g.bottom(), a.bottom()};
  return {a.y, o.bottom(), a.y, g.y};
}

}  // namespace

int compareHitTimes(const Rect& mover, Vec2 goal, const Sweep& a, const Rect& oa, const Sweep& b,
                    const Rect& ob) {
  const Impact p = impact(mover, goal, a, oa), q = impact(mover, goal, b, ob);
  // na/da < nb/db with positive denominators: na·db < nb·da.
  return compareDifferenceProducts(p.n0, p.n1, q.d0, q.d1, q.n0, q.n1, p.d0, p.d1);
}

}  // namespace detail

}  // namespace tv
