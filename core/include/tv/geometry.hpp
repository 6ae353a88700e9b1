#pragma once
/// Geometry in world units (pixels in our scenes), all in `double`.
///
/// Tolerance model — written down once, used everywhere in tv:
/// - A rect's edges are the doubles `x`, `y`, `right() = x + w` and `bottom() = y + h`, each
///   rounded once. Every test of contact or overlap compares these doubles exactly; there is no
///   epsilon, absolute or relative, so the rules mean the same at 0 and at 1e9.
/// - Two rects *overlap* when their open interiors intersect:
///   `a.x < b.right() && b.x < a.right()` and the same on y. Sharing an edge is not overlapping.
/// - Two rects *touch* when their closed rects intersect but they do not overlap.
/// - A move *hits* an obstacle when the mover's interior would intersect the obstacle's interior
///   at some time in (ti, 1]; see sweep.hpp. Touching and sliding along an edge never hits.
/// - After a hit, the mover is placed against the obstacle from the obstacle's edge (see
///   `placeBefore`), so a resting body's edge equals the obstacle's edge bit for bit whenever a
///   double allows it, and is never inside it.

#include <cmath>
#include <cstdint>

namespace tv {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

[[nodiscard]] inline double length(Vec2 v) { return std::hypot(v.x, v.y); }

/// Axis-aligned rectangle: top-left corner (x, y), size (w, h); y grows downwards as on screen.
struct Rect {
  double x = 0.0;
  double y = 0.0;
  double w = 0.0;
  double h = 0.0;

  [[nodiscard]] constexpr double left() const { return x; }
  [[nodiscard]] constexpr double top() const { return y; }
  [[nodiscard]] constexpr double right() const { return x + w; }
  [[nodiscard]] constexpr double bottom() const { return y + h; }
  [[nodiscard]] constexpr Vec2 position() const { return {x, y}; }
  [[nodiscard]] constexpr Vec2 size() const { return {w, h}; }
  [[nodiscard]] constexpr Rect at(Vec2 p) const { return {p.x, p.y, w, h}; }
  [[nodiscard]] constexpr Vec2 center() const { return {x + w * 0.5, y + h * 0.5}; }
  friend constexpr bool operator==(const Rect& a, const Rect& b) = default;
};

/// True when the open interiors intersect (sharing an edge is not overlapping).
[[nodiscard]] constexpr bool overlaps(const Rect& a, const Rect& b) {
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

/// True when the closed rects intersect but the interiors do not.
[[nodiscard]] constexpr bool touches(const Rect& a, const Rect& b) {
  return !overlaps(a, b) && a.x <= b.right() && b.x <= a.right() && a.y <= b.bottom() &&
         b.y <= a.bottom();
}

/// Half-open containment [x, right) × [y, bottom): a point on a shared edge belongs to exactly
/// one of two neighbouring tiles.
[[nodiscard]] constexpr bool contains(const Rect& r, Vec2 p) {
  return r.x <= p.x && p.x < r.right() && r.y <= p.y && p.y < r.bottom();
}

/// Smallest rect holding both: its right() and bottom() are never below either rect's, even
/// when the size rounds.
[[nodiscard]] Rect unite(const Rect& a, const Rect& b);

/// Where a mover of extent `size` must stand so that its far edge rests on `edge`: the
/// coordinate `c` nearest to edge − size with `c + size == edge` in double arithmetic — bit for
/// bit — whenever some double achieves that; otherwise the nearest with `c + size < edge`,
/// short of the edge by one rounding step, never past it. Landing always exists on grids of
/// dyadic sizes (integers, halves, 1/16ths...). It can fail when the coordinate's ulp is coarser
/// than the edge's (a position near -1e6 against an edge of 1e-3), or when every sum c + size is
/// a rounding tie and the edge's mantissa is odd (edge 0.9, size 0.2).
[[nodiscard]] double placeBefore(double edge, double size);

/// True when every field is finite.
[[nodiscard]] inline bool isFinite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
[[nodiscard]] inline bool isFinite(const Rect& r) {
  return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.w) && std::isfinite(r.h);
}

}  // namespace tv
