#pragma once
// The exact reference for the pareto study: a slide move computed in exact rationals (GMP), by
// brute force over the obstacles near the path, with no rounding until the final position.
//
// Model (tv/geometry.hpp and tv/sweep.hpp, without their doubles): the mover is the rect
// [x, x + w] × [y, y + h] with x + w exact; it travels in a straight line; it hits an obstacle
// when the open interiors first intersect at some t in [0, 1); the normal is on the axis entered
// last (an exact tie is a corner: ordinary hits sort first, a corner takes the x normal, as tv
// does); the contact coordinate on the normal's axis is exactly the obstacle's edge − size (or
// its far edge); the other coordinate is start + t·move, exactly; the slide's next leg keeps the
// goal's other coordinate. After 64 responses the mover stays at its last contact.

#include <vector>

#include "tv/geometry.hpp"

namespace tv::bench {

struct ExactHit {
  Rect obstacle;
  Vec2 normal;
};

struct ExactMove {
  Vec2 position;               ///< the exact end, rounded to the nearest doubles once
  std::vector<ExactHit> hits;  ///< what stopped it, in order
};

/// Slides a mover of `size` from `start` towards `goal` among `obstacles` (none overlapping the
/// start rect).
[[nodiscard]] ExactMove exactSlide(const std::vector<Rect>& obstacles, Vec2 size, Vec2 start,
                                   Vec2 goal);

}  // namespace tv::bench
