#pragma once
// Which of two hits of the same leg comes first, decided on the exact times of impact: two
// faces a rounding apart have the same rounded ti, and the farther one must not win.

#include "tv/sweep.hpp"

namespace tv::detail {

/// Sign of ti(a) − ti(b), exactly, for two hits (SweepKind::hit) of `mover` swept to `goal`
/// against the obstacles `oa` and `ob`.
[[nodiscard]] int compareHitTimes(const Rect& mover, Vec2 goal, const Sweep& a, const Rect& oa,
                                  const Sweep& b, const Rect& ob);

/// True when hit a (against oa) comes before hit b (against ob) in the order a move takes the
/// hits of one leg: the exact time of impact (overlaps first, deepest first), then ordinary hits
/// before exact corner hits, then add order (asked of `aWasAddedFirst` only for exact ties).
template <class EarlierAdded>
[[nodiscard]] bool hitBefore(const Rect& mover, Vec2 goal, const Sweep& a, const Rect& oa,
                             const Sweep& b, const Rect& ob, EarlierAdded aWasAddedFirst) {
  if (a.kind == SweepKind::hit && b.kind == SweepKind::hit) {
    if (const int c = compareHitTimes(mover, goal, a, oa, b, ob); c != 0) return c < 0;
  } else if (a.ti != b.ti) {
    return a.ti < b.ti;
  }
  if (a.corner != b.corner) return !a.corner;
  return aWasAddedFirst();
}

}  // namespace tv::detail
