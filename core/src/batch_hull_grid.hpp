#pragma once
// The batch step's broad phase: a uniform grid over the bodies' swept hulls, so that a body's
// pair search reads only the bodies whose hulls share a cell with its own, not all N.
//
// - Each body is registered with a *loose* hull: its path's bounding box widened by far more
//   than the rounding of any position computed along that path (see `loosen`), so that every
//   rect the batch derives from the path, at any instant, lies inside it. The exact hull test
//   is the pair search's own; this grid only has to return a superset of the bodies it keeps.
// - Cell indices are clamped to the grid: a hull that leaves the box the grid was built over
//   (a bounce sends a body back out of its first hull) lands in the border cells. Clamping is
//   monotone, so two hulls that meet still share a cell.
// - A body whose new path stays inside its registered hull keeps it (slide and touch never
//   leave it); only one that leaves it is registered again.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tv/geometry.hpp"

namespace tv::detail {

class BatchHullGrid {
 public:
  /// The hull of a path widened so that it holds every position computed along it.
  [[nodiscard]] static Rect loosen(const Rect& hull);

  /// Registers body i with `hulls[i]` (already loosened), over a grid sized for them.
  void build(std::span<const Rect> hulls);
  /// Body i's path changed: registers it again unless `hull` (loosened) is inside its own.
  void update(std::uint32_t i, const Rect& hull);
  [[nodiscard]] const Rect& registered(std::uint32_t i) const { return hulls_[i]; }

  /// Calls f(body) once for every body other than `self` registered in a cell that `r` meets.
  template <class F>
  void forEachNear(std::uint32_t self, const Rect& r, F&& f) {
    forEachIn(self, rangeOf(r), f);
  }
  /// The same for body i's registered hull.
  template <class F>
  void forEachNear(std::uint32_t i, F&& f) {
    forEachIn(i, ranges_[i], f);
  }
  /// Every body once, in the order of the first cell each is registered in: neighbours in
  /// space come close together, so work done body by body reads memory in spatial order.
  void spatialOrder(std::vector<std::uint32_t>& out);

 private:
  struct Range {
    std::int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  };
  template <class F>
  void forEachIn(std::uint32_t self, const Range& c, F& f) {
    const std::uint32_t epoch = nextEpoch();
    for (std::int32_t cy = c.y0; cy <= c.y1; ++cy) {
      for (std::int32_t cx = c.x0; cx <= c.x1; ++cx) {
        for (const std::uint32_t j : cell(cx, cy)) {
          if (j == self || stamp_[j] == epoch) continue;
          stamp_[j] = epoch;
          f(j);
        }
      }
    }
  }
  // Clamped first, so the truncation is a floor (and never overflows).
  [[nodiscard]] std::int32_t column(double x) const {
    const double c = std::clamp((x - x0_) * inverseX_, 0.0, static_cast<double>(nx_ - 1));
    return static_cast<std::int32_t>(c);
  }
  [[nodiscard]] std::int32_t row(double y) const {
    const double c = std::clamp((y - y0_) * inverseY_, 0.0, static_cast<double>(ny_ - 1));
    return static_cast<std::int32_t>(c);
  }
  [[nodiscard]] Range rangeOf(const Rect& r) const {
    return {column(r.x), row(r.y), column(r.right()), row(r.bottom())};
  }
  std::vector<std::uint32_t>& cell(std::int32_t cx, std::int32_t cy) {
    return cells_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx_) +
                  static_cast<std::size_t>(cx)];
  }
  void insert(std::uint32_t i);
  void erase(std::uint32_t i);
  std::uint32_t nextEpoch();

  double x0_ = 0, y0_ = 0, inverseX_ = 0, inverseY_ = 0;  // the corner, 1 / cell sides
  std::int32_t nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;  // row-major; kept to reuse their memory
  std::vector<Rect> hulls_;                        // per body, as registered
  std::vector<Range> ranges_;                      // per body, the cells it is in
  std::vector<std::uint32_t> stamp_;               // per body, the last query that saw it
  std::uint32_t epoch_ = 0;
};

}  // namespace tv::detail
