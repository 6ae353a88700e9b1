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
///
/// Range — where the exact arithmetic behind these rules holds:
/// - Every coordinate, size and goal the World accepts has a magnitude of at most
///   kMaxMagnitude = 2^500 ≈ 3.27e150, and every cell size lies in [2^-485, 2^500]; anything
///   beyond is refused with tv::Error naming the value. Within it, edges stay within 2^501 and
///   their differences within 2^502, so the exact time comparison (products of two differences,
///   summed sixteen at a time) stays within 2^1008, far from overflow (2^1024), and no
///   displacement overflows to infinity.
/// - Exactness also needs the products of two edge differences not to underflow. That holds
///   whenever every coordinate and size is a multiple of 2^-537 — every double of magnitude at
///   least 2^-485 ≈ 1.0e-146 is, and so is 0: then every edge and difference is a multiple of
///   2^-537, each product a multiple of 2^-1074, and its rounding error (fma) exact. Nonzero
///   values closer to 0 are accepted (a step of one ulp at 0 is 5e-324), but a decision that
///   compares two such tiny differences may round.
/// A rect must also have an interior: x + w > x and y + h > y once rounded (a width below half
/// an ulp of x would give right() == x).

#include <cmath>
#include <cstdint>

namespace tv {

/// A point or a displacement, in world units; y grows downwards as on screen.
struct Vec2 {
  double x = 0.0;  ///< horizontal, world units
  double y = 0.0;  ///< vertical (down is positive), world units

  /// Componentwise sum.
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  /// Componentwise difference.
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  /// Scaled by `s`.
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  /// Scaled by `s`.
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  /// Exact comparison of both components (no tolerance: see the tolerance model above).
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

/// Euclidean length (std::hypot: no overflow for large components).
[[nodiscard]] inline double length(Vec2 v) { return std::hypot(v.x, v.y); }

/// Axis-aligned rectangle: top-left corner (x, y), size (w, h); y grows downwards as on screen.
///
///     tv::Rect tile{16, 200, 16, 16};   // x, y, w, h: covers [16, 32) × [200, 216)
struct Rect {
  double x = 0.0;  ///< left edge, world units
  double y = 0.0;  ///< top edge, world units
  double w = 0.0;  ///< width, world units; > 0 for anything the World accepts
  double h = 0.0;  ///< height, world units; > 0 for anything the World accepts

  [[nodiscard]] constexpr double left() const { return x; }       ///< x
  [[nodiscard]] constexpr double top() const { return y; }        ///< y
  [[nodiscard]] constexpr double right() const { return x + w; }  ///< x + w, rounded once
  [[nodiscard]] constexpr double bottom() const { return y + h; }  ///< y + h, rounded once
  [[nodiscard]] constexpr Vec2 position() const { return {x, y}; }  ///< the top-left corner
  [[nodiscard]] constexpr Vec2 size() const { return {w, h}; }      ///< {w, h}
  /// The same size with its top-left corner at `p`.
  [[nodiscard]] constexpr Rect at(Vec2 p) const { return {p.x, p.y, w, h}; }
  [[nodiscard]] constexpr Vec2 center() const { return {x + w * 0.5, y + h * 0.5}; }  ///< middle
  /// Exact comparison of the four fields.
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

inline constexpr double kMaxMagnitude = 0x1p500;  ///< ≈ 3.27e150

/// True when |v| <= kMaxMagnitude (false for NaN and infinities).
[[nodiscard]] inline bool inRange(double v) { return std::fabs(v) <= kMaxMagnitude; }

/// True when every field is finite.
[[nodiscard]] inline bool isFinite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
/// True when x, y, w and h are all finite.
[[nodiscard]] inline bool isFinite(const Rect& r) {
  return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.w) && std::isfinite(r.h);
}

}  // namespace tv
