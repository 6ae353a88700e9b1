#include "tv/outcome.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "tv/world.hpp"

namespace tv {

namespace {

// [a0, a1) wholly before [o0, o1) at the start and wholly after it at the end, or the reverse.
bool through(double s0, double s1, double e0, double e1, double o0, double o1) {
  return (s1 <= o0 && e0 >= o1) || (e1 <= o0 && s0 >= o1);
}

bool spans(double a0, double a1, double o0, double o1) {
  return a0 < o1 && o0 < a1;
}

constexpr double kMaxCells = 65536.0;

}  // namespace

MoveOutcome judgeMove(const World& world, ItemId item, const Rect& start, const Rect& end,
                      const Filter& filter) {
  MoveOutcome out;
  const Rect hull = unite(start, end);
  const double cell = world.cellSize();
  const double across = std::floor(hull.right() / cell) - std::floor(hull.x / cell) + 1.0;
  const double down = std::floor(hull.bottom() / cell) - std::floor(hull.y / cell) + 1.0;
  if (!(across * down <= kMaxCells)) return out;
  std::vector<ItemId> found;
  world.queryRect(hull, found, item);
  double nearest = std::numeric_limits<double>::infinity();
  for (const ItemId o : found) {
    const ResponseId a = filter(item, o);
    if (a == response::ignore || a == response::cross) continue;
    const Rect r = world.rect(o);
    if (!out.endedInside.valid() && overlaps(end, r) && !overlaps(start, r)) out.endedInside = o;
    const bool acrossX = through(start.x, start.right(), end.x, end.right(), r.x, r.right()) &&
                         spans(start.y, start.bottom(), r.y, r.bottom()) &&
                         spans(end.y, end.bottom(), r.y, r.bottom());
    const bool acrossY = through(start.y, start.bottom(), end.y, end.bottom(), r.y, r.bottom()) &&
                         spans(start.x, start.right(), r.x, r.right()) &&
                         spans(end.x, end.right(), r.x, r.right());
    if (!acrossX && !acrossY) continue;
    // The one the move reached first: nearest the start's centre.
    const Vec2 d = r.center() - start.center();
    const double dist = d.x * d.x + d.y * d.y;
    if (dist < nearest) {
      nearest = dist;
      out.passedThrough = o;
    }
  }
  return out;
}

}  // namespace tv
