#pragma once
// Which of two hits of the same leg comes first, decided on the exact times of impact: two
// faces a rounding apart have the same rounded ti, and the farther one must not win.

#include "tv/sweep.hpp"

namespace tv::detail {

/// Sign of ti(a) − ti(b), exactly, for two hits (SweepKind::hit) of `mover` swept to `goal`
/// against the obstacles `oa` and `ob`.
[[nodiscard]] int compareHitTimes(const Rect& mover, Vec2 goal, const Sweep& a, const Rect& oa,
                                  const Sweep& b, const Rect& ob);

}  // namespace tv::detail
