#include "tv/geometry.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace tv {

namespace {

// The extent from `lo` whose far edge lo + extent reaches `hi`: hi - lo rounded can land the far
// edge an ulp short (a tie rounding to even), and a hull short of its rects misses obstacles.
double extentReaching(double lo, double hi) {
  double e = hi - lo;
  while (lo + e < hi) e = std::nextafter(e, HUGE_VAL);
  return e;
}

}  // namespace

Rect unite(const Rect& a, const Rect& b) {
  const double x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const double x1 = std::max(a.right(), b.right()), y1 = std::max(a.bottom(), b.bottom());
  return {x0, y0, extentReaching(x0, x1), extentReaching(y0, y1)};
}

namespace {

// Doubles mapped to unsigned integers in the same order, so "the next double" is "+1".
constexpr std::uint64_t kSign = 0x8000000000000000ull;
std::uint64_t orderedKey(double d) {
  const auto u = std::bit_cast<std::uint64_t>(d);
  return (u & kSign) ? ~u : (u | kSign);
}
double fromKey(std::uint64_t k) {
  return std::bit_cast<double>((k & kSign) ? (k & ~kSign) : ~k);
}

}  // namespace

double placeBefore(double edge, double size) {
  // edge - size is within a rounding of the answer. When it does not land exactly, move the
  // least distance that does; when the coordinate's ulp is much finer than the edge's,
  // thousands of coordinates round to the same far edge, so gallop to a bracket and bisect
  // instead of stepping one ulp at a time.
  const auto farEdge = [&](std::uint64_t k) { return fromKey(k) + size; };
  const std::uint64_t k0 = orderedKey(edge - size);
  const double e0 = farEdge(k0);
  if (e0 == edge) return fromKey(k0);
  std::uint64_t lo, hi;  // farEdge(lo) <= edge < ... the bracket's meaning depends on the side
  std::uint64_t step = 1;
  if (e0 > edge) {
    // Largest k below k0 whose far edge does not pass `edge`.
    hi = k0;
    for (int i = 0; i < 64 && farEdge(hi - step) > edge; ++i, step *= 2) hi -= step;
    lo = hi - step;
    while (hi - lo > 1) {
      const std::uint64_t mid = lo + (hi - lo) / 2;
      (farEdge(mid) <= edge ? lo : hi) = mid;
    }
    return fromKey(lo);
  }
  // Smallest k above k0 whose far edge reaches `edge`: take it if it lands exactly, otherwise
  // the one before it, which stays short.
  lo = k0;
  for (int i = 0; i < 64 && farEdge(lo + step) < edge; ++i, step *= 2) lo += step;
  hi = lo + step;
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (farEdge(mid) < edge ? lo : hi) = mid;
  }
  return farEdge(hi) == edge ? fromKey(hi) : fromKey(lo);
}

}  // namespace tv
