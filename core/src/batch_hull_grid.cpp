#include "batch_hull_grid.hpp"

#include <algorithm>
#include <cmath>

namespace tv::detail {

namespace {

// A grid of at most this many cells per body: enough that a crowd's bodies share a cell with
// only their neighbours, few enough that building it costs about what registering them does.
constexpr double kCellsPerBody = 1.0;
constexpr std::int32_t kMaxSide = 1 << 14;

}  // namespace

Rect BatchHullGrid::loosen(const Rect& h) {
  // A position along a path is p + (goal - p)·f, three roundings of at most 2^-53 of the
  // magnitudes involved; 2^-40 of them is thousands of times that, and still far below any
  // distance that matters to the broad phase. The tiny constant covers paths at 0.
  const double mx = (std::fabs(h.x) + std::fabs(h.right())) * 0x1p-40 + 0x1p-1000;
  const double my = (std::fabs(h.y) + std::fabs(h.bottom())) * 0x1p-40 + 0x1p-1000;
  return {h.x - mx, h.y - my, h.w + 4 * mx, h.h + 4 * my};
}

void BatchHullGrid::build(std::span<const Rect> hulls) {
  for (const Range& r : ranges_) {  // empty the cells the last step used, keeping their memory
    for (std::int32_t cy = r.y0; cy <= r.y1; ++cy)
      for (std::int32_t cx = r.x0; cx <= r.x1; ++cx) cell(cx, cy).clear();
  }
  hulls_.assign(hulls.begin(), hulls.end());
  ranges_.assign(hulls.size(), Range{});
  stamp_.assign(hulls.size(), 0);
  epoch_ = 0;
  if (hulls.empty()) {
    // One empty cell: what spatialOrder and forEachNear read, even on a grid never built before
    // (a step of no bodies on a new Batch read a cell that did not exist).
    nx_ = ny_ = 1;
    if (cells_.empty()) cells_.resize(1);
    return;
  }

  double left = hulls[0].x, top = hulls[0].y, right = hulls[0].right(), bottom = hulls[0].bottom();
  double extent = 0;
  for (const Rect& h : hulls) {
    left = std::min(left, h.x);
    top = std::min(top, h.y);
    right = std::max(right, h.right());
    bottom = std::max(bottom, h.bottom());
    extent += std::max(h.w, h.h);
  }
  const double n = static_cast<double>(hulls.size());
  const double width = right - left, height = bottom - top;
  // Cells about twice as large as a typical hull (most hulls then meet one to four cells, two
  // on average), and not more of them than kCellsPerBody a body.
  double cell = std::max(2 * extent / n, std::sqrt(width * height / (kCellsPerBody * n)));
  if (!(cell > 0) || !std::isfinite(cell)) cell = std::max(width, height);
  if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
  const auto side = [&](double length) {
    const double k = std::ceil(length / cell);
    return static_cast<std::int32_t>(std::clamp(std::isfinite(k) ? k : 1.0, 1.0, double{kMaxSide}));
  };
  nx_ = side(width);
  ny_ = side(height);
  while (static_cast<double>(nx_) * ny_ > kCellsPerBody * n + 64) {
    nx_ = std::max(1, (nx_ + 1) / 2);
    ny_ = std::max(1, (ny_ + 1) / 2);
  }
  x0_ = left;
  y0_ = top;
  // Per axis, so the grid spans the box exactly; a box of no width is one column.
  inverseX_ = width > 0 ? nx_ / width : 0.0;
  inverseY_ = height > 0 ? ny_ / height : 0.0;
  const std::size_t count = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  if (cells_.size() < count) cells_.resize(count);
  for (std::uint32_t i = 0; i < hulls.size(); ++i) insert(i);
}

void BatchHullGrid::insert(std::uint32_t i) {
  const Range c = rangeOf(hulls_[i]);
  ranges_[i] = c;
  for (std::int32_t cy = c.y0; cy <= c.y1; ++cy)
    for (std::int32_t cx = c.x0; cx <= c.x1; ++cx) cell(cx, cy).push_back(i);
}

void BatchHullGrid::erase(std::uint32_t i) {
  const Range c = ranges_[i];
  for (std::int32_t cy = c.y0; cy <= c.y1; ++cy) {
    for (std::int32_t cx = c.x0; cx <= c.x1; ++cx) {
      std::vector<std::uint32_t>& here = cell(cx, cy);
      const auto it = std::find(here.begin(), here.end(), i);
      *it = here.back();
      here.pop_back();
    }
  }
  ranges_[i] = Range{};
}

void BatchHullGrid::update(std::uint32_t i, const Rect& hull) {
  const Rect& old = hulls_[i];
  if (hull.x >= old.x && hull.y >= old.y && hull.right() <= old.right() &&
      hull.bottom() <= old.bottom()) {
    return;
  }
  erase(i);
  hulls_[i] = hull;
  insert(i);
}

void BatchHullGrid::spatialOrder(std::vector<std::uint32_t>& out) {
  out.clear();
  for (std::int32_t cy = 0; cy < ny_; ++cy) {
    for (std::int32_t cx = 0; cx < nx_; ++cx) {
      for (const std::uint32_t j : cell(cx, cy))
        if (ranges_[j].x0 == cx && ranges_[j].y0 == cy) out.push_back(j);
    }
  }
}

std::uint32_t BatchHullGrid::nextEpoch() {
  if (++epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    epoch_ = 1;
  }
  return epoch_;
}

}  // namespace tv::detail
