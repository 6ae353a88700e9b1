#pragma once
/// The spatial hash's cell arithmetic, shared by the world's broad phase, the debugger's cell
/// overlay and the tests. Cell (cx, cy) covers [cx·size, (cx+1)·size) × [cy·size, (cy+1)·size).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "tv/geometry.hpp"

namespace tv {

/// A cell of the spatial hash by its indices: [x·size, (x+1)·size) × [y·size, (y+1)·size).
struct Cell {
  std::int64_t x = 0;  ///< column index
  std::int64_t y = 0;  ///< row index
  /// Same column and row.
  friend constexpr bool operator==(Cell a, Cell b) = default;
};

/// Inclusive range of cells.
struct CellRange {
  /// @name First and last column and row, inclusive
  /// @{
  std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;  ///< cell indices; default: empty
  /// @}
  /// True when it holds no cell (x1 < x0 or y1 < y0).
  [[nodiscard]] constexpr bool empty() const { return x1 < x0 || y1 < y0; }
  /// Cells it holds (0 when empty).
  [[nodiscard]] constexpr std::int64_t count() const {
    return empty() ? 0 : (x1 - x0 + 1) * (y1 - y0 + 1);
  }
  /// True when `c` is in the range.
  [[nodiscard]] constexpr bool contains(Cell c) const {
    return x0 <= c.x && c.x <= x1 && y0 <= c.y && c.y <= y1;
  }
  /// Same bounds (two empty ranges with different bounds are not equal).
  friend constexpr bool operator==(const CellRange& a, const CellRange& b) = default;
};

/// Cell coordinates stay well inside int64 and exactly representable in a double.
inline constexpr double kMaxCellIndex = 4503599627370496.0;  // 2^52

/// Every cell a world can hold.
inline constexpr CellRange kEveryCell{-(std::int64_t{1} << 53), -(std::int64_t{1} << 53),
                                      std::int64_t{1} << 53, std::int64_t{1} << 53};

/// Cell arithmetic for one cell size: which cells a point, a rect or a moving rect meets.
///
///     tv::Grid g(32);
///     g.cellsOf({40, 0, 30, 10});   // columns 1..2, row 0
class Grid {
 public:
  /// `cellSize` in world units, finite and > 0 (checked by the world).
  explicit constexpr Grid(double cellSize) : size_(cellSize), inverse_(1.0 / cellSize) {}

  [[nodiscard]] constexpr double cellSize() const { return size_; }  ///< world units
  /// 1 / cellSize, rounded.
  [[nodiscard]] constexpr double inverse() const { return inverse_; }

  /// The cell holding coordinate v. Monotone in v, so two closed intervals that meet always
  /// share a cell, whatever the rounding of v · (1 / size). Precondition: v finite with
  /// |v / size| < 2^52 (see `fits`; World::toCell checks it and throws tv::Error).
  [[nodiscard]] std::int64_t index(double v) const {
    // floor() without the libm call: truncate, then step down for negative non-integers.
    // Exact for every |v · inverse| < 2^63, far beyond the 2^52 the world allows.
    const double q = v * inverse_;
    const auto t = static_cast<std::int64_t>(q);
    return static_cast<double>(t) > q ? t - 1 : t;
  }
  /// The cell holding point `p` (the same precondition as `index`).
  [[nodiscard]] Cell cellAt(Vec2 p) const { return {index(p.x), index(p.y)}; }
  /// World position of a cell's top-left corner.
  [[nodiscard]] Vec2 origin(Cell c) const {
    return {static_cast<double>(c.x) * size_, static_cast<double>(c.y) * size_};
  }
  /// The square a cell covers, world units.
  [[nodiscard]] Rect bounds(Cell c) const {
    const Vec2 o = origin(c);
    return {o.x, o.y, size_, size_};
  }
  /// Cells meeting the closed rect.
  [[nodiscard]] CellRange cellsOf(const Rect& r) const {
    return {index(r.x), index(r.y), index(r.right()), index(r.bottom())};
  }
  /// Cells an item is registered in: those its half-open extent [x, right) × [y, bottom)
  /// meets, so an edge on a cell line does not reach into the next cell. Two rects whose
  /// interiors overlap share one of these cells; a rect narrower than the rounding of its
  /// coordinates still has the cell of its top-left corner.
  [[nodiscard]] CellRange cellsHolding(const Rect& r) const {
    return cellsHolding(r.x, r.y, r.right(), r.bottom());
  }
  /// The same for the half-open box [left, right) × [top, bottom) given by its edges.
  [[nodiscard]] CellRange cellsHolding(double left, double top, double right,
                                       double bottom) const {
    const std::int64_t x0 = index(left), y0 = index(top);
    return {x0, y0, std::max(x0, index(justBelow(right))), std::max(y0, index(justBelow(bottom)))};
  }
  /// True when the rect's cell indices fit the hash (|coordinate / cellSize| < 2^52).
  [[nodiscard]] bool fits(const Rect& r) const {
    const double lo = std::min(r.x, r.y) * inverse_;
    const double hi = std::max(r.right(), r.bottom()) * inverse_;
    return std::fabs(lo) < kMaxCellIndex && std::fabs(hi) < kMaxCellIndex;
  }

  /// Calls f(Cell) for every cell that the rect meets while moving from `start` to `goal`
  /// (its swept hull), column by column along the dominant axis. The cost follows the cells
  /// the rect actually crosses, not the area of the move's bounding box. Conservative: a cell
  /// the hull only nearly meets may be visited too. Cells outside `clip` are skipped (the world
  /// passes the range that has ever held an item, so a long move through empty space costs
  /// nothing for the emptiness).
  template <class F>
  void forEachSweptCell(const Rect& start, Vec2 goal, F&& f,
                        const CellRange& clip = kEveryCell) const;

  /// Calls f(Cell) for every cell of the range, row by row.
  template <class F>
  static void forEachCell(const CellRange& range, F&& f) {
    for (std::int64_t cy = range.y0; cy <= range.y1; ++cy)
      for (std::int64_t cx = range.x0; cx <= range.x1; ++cx) f(Cell{cx, cy});
  }

 private:
  // The largest double below v (v finite): the last coordinate a half-open extent holds.
  static double justBelow(double v) {
    if (v == 0.0) return -std::numeric_limits<double>::denorm_min();
    const auto bits = std::bit_cast<std::uint64_t>(v);
    return std::bit_cast<double>(v > 0.0 ? bits - 1 : bits + 1);
  }

  double size_;
  double inverse_;
};

template <class F>
void Grid::forEachSweptCell(const Rect& start, Vec2 goal, F&& f, const CellRange& clip) const {
  const Rect end = start.at(goal);
  const double dx = goal.x - start.x;
  const double dy = goal.y - start.y;
  // Walk along the axis that moves more, in cell units; `u` is that axis, `v` the other.
  const bool alongX = std::fabs(dx) >= std::fabs(dy);
  const double u0 = alongX ? start.x : start.y, u1 = alongX ? start.right() : start.bottom();
  const double e0 = alongX ? end.x : end.y, e1 = alongX ? end.right() : end.bottom();
  const double v0 = alongX ? start.y : start.x, v1 = alongX ? start.bottom() : start.right();
  const double w0 = alongX ? end.y : end.x, w1 = alongX ? end.bottom() : end.right();
  const double du = e0 - u0;
  const double uMin = std::min(u0, e0), uMax = std::max(u1, e1);
  const std::int64_t c0 = std::max(index(uMin), alongX ? clip.x0 : clip.y0);
  const std::int64_t c1 = std::min(index(uMax), alongX ? clip.x1 : clip.y1);
  const std::int64_t rMin = alongX ? clip.y0 : clip.x0, rMax = alongX ? clip.y1 : clip.x1;
  // Times come from one reciprocal and vs from the start and end edges. A column's bounds
  // (c · size) and index() round at the scale of the walked coordinate u, not of v: where a cell
  // is only a few ulps of u wide they are off by a good part of a cell, which shifts the column's
  // time window by as much as ulps(u) / |du| and the v it allows by ulps(u) · |dv| / |du| <=
  // ulps(u), the walk's axis being the one that moves more. So the margin is a few ulps of the
  // largest magnitude of either axis (fixed for the whole walk): conservative without an
  // absolute epsilon, and far below a cell at any ordinary scale.
  const double inv = du != 0.0 ? 1.0 / du : 0.0;
  const double dv0 = w0 - v0, dv1 = w1 - v1;
  const double scale =
      std::max({std::fabs(v0), std::fabs(v1), std::fabs(w0), std::fabs(w1), std::fabs(dv0),
                std::fabs(u0), std::fabs(u1), std::fabs(e0), std::fabs(e1), size_});
  const double slack = scale * 0x1p-45;
  const double vFloor = std::min(v0, w0), vCeil = std::max(v1, w1);
  for (std::int64_t c = c0; c <= c1; ++c) {
    // The slice of the column the hull can occupy, then the times the rect spends in it.
    const double lo = std::max(uMin, static_cast<double>(c) * size_);
    const double hi = std::min(uMax, static_cast<double>(c + 1) * size_);
    double t0 = 0.0, t1 = 1.0;
    if (du != 0.0) {
      // Rect's u-interval [u0 + t·du, u1 + t·du] meets [lo, hi].
      const double ta = du > 0 ? (lo - u1) * inv : (hi - u0) * inv;
      const double tb = du > 0 ? (hi - u0) * inv : (lo - u1) * inv;
      t0 = std::clamp(ta, 0.0, 1.0);
      t1 = std::clamp(tb, 0.0, 1.0);
    }
    const double vLo = std::max(std::min(v0 + t0 * dv0, v0 + t1 * dv0) - slack, vFloor);
    const double vHi = std::min(std::max(v1 + t0 * dv1, v1 + t1 * dv1) + slack, vCeil);
    const std::int64_t r0 = std::max(index(vLo), rMin), r1 = std::min(index(vHi), rMax);
    for (std::int64_t r = r0; r <= r1; ++r) f(alongX ? Cell{c, r} : Cell{r, c});
  }
}

}  // namespace tv
