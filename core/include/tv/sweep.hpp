#pragma once
/// Pure swept-rect functions: the exact narrow phase. No world, no allocation.
///
/// A mover's edges travel linearly from its start rect to its goal rect; the obstacle stands
/// still. On each axis the mover's interior overlaps the obstacle's during an open time
/// interval; a *hit* is when the two intervals intersect somewhere before the goal. Entry and
/// exit times are kept as fractions and compared exactly (products formed without rounding),
/// so exact corner hits, grazes and touching contacts are decided exactly whenever the edge
/// differences are exact — as they are on any tile grid of dyadic sizes.

#include "tv/geometry.hpp"

namespace tv {

/// What a sweep found.
enum class SweepKind : std::uint8_t {
  miss,     ///< the interiors never intersect on the way to the goal
  hit,      ///< they first intersect at `ti` in [0, 1)
  overlap,  ///< they already intersect at the start
};

/// The result of sweeping one rect against one obstacle (sweepRect).
struct Sweep {
  SweepKind kind = SweepKind::miss;  ///< miss, hit or overlap
  /// hit: time of impact in [0, 1) along the move; overlap: minus the intersection area, so
  /// that deeper overlaps sort first (as in bump.lua).
  double ti = 1.0;
  /// Unit axis normal pointing from the obstacle towards the mover.
  Vec2 normal;
  /// Mover position at contact. The coordinate on the normal's axis comes from the obstacle's
  /// edge (see `placeBefore`), never from start + ti·move — or stays the start's when the mover
  /// already rests on that edge (ti 0), so a resting body is never stepped back; for an overlap
  /// it is the smallest push out of the obstacle.
  Vec2 touch;
  /// Entered on both axes at the same instant: an exact corner hit. Such a hit sorts after an
  /// ordinary hit at the same ti, so a neighbour tile's corner never pre-empts the face the
  /// mover is landing on (no seam snags).
  bool corner = false;
};

/// Sweeps `mover` from its position to `goal` (a position, not a displacement) against a
/// static `obstacle`.
[[nodiscard]] Sweep sweepRect(const Rect& mover, Vec2 goal, const Rect& obstacle);

/// Where a segment crosses a rect's open interior.
struct SegmentClip {
  bool hit = false;  ///< the segment crosses the interior (t0 and t1 are valid)
  double t0 = 0.0;  ///< entry, in [0, 1] along the segment
  double t1 = 0.0;  ///< exit, in [t0, 1]
};

/// Clips the segment a→b against the interior of `r`. A segment running along an edge, or
/// through a corner point only, does not hit.
[[nodiscard]] SegmentClip clipSegment(Vec2 a, Vec2 b, const Rect& r);

}  // namespace tv
