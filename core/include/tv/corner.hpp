#pragma once
/// Corner correction: a body moving up that clips the corner of a ceiling by at most `maxNudge`
/// world units is nudged sideways round it and goes on up, instead of stopping dead (Celeste
/// nudges its player up to 4 px). Exact: the nudged body's edge is placed on the ceiling's edge
/// (tv::placeBefore), so it passes the corner without overlapping it and without a gap.
///
///     tv::CornerOptions o;
///     o.filter = filter;              // the game's filter for the body
///     o.maxNudge = 4;                 // Celeste's 4 px
///     tv::CornerMove m = tv::moveCornered(world, player, goal, o);
///     if (m.nudged) debugDraw(m.nudge.hit, m.nudge.dx);
///
/// Rules:
/// - only the move's first collision that the filter does not cross is corrected, when it is a
///   ceiling (normal (0, 1)) met without overlapping, and the body sticks out past one end of the
///   ceiling's bottom edge: it is nudged towards that end by the overlap, if that is ≤ maxNudge;
/// - never against the move's horizontal direction (a body moving right is not nudged left), as
///   Celeste; a body over the ceiling's whole width is not nudged;
/// - the nudge is made only when the strip the body slides through is free (nothing the filter
///   neither ignores nor crosses overlaps it); otherwise the move is World::move's;
/// - the nudge shifts the rest of the move by the same amount: the body ends at goal + (dx, 0).
///
/// It is made of World calls (check, anyOverlap, move), so a recording of the game replays it bit
/// for bit; a nudge is also reported to the world's observer (WorldObserver::cornerNudged), so a
/// recording says where one was made (its cornerNudge call) and a debugger can draw it. Bad input (an unknown item, a goal out of range, maxNudge negative, NaN or Inf)
/// throws tv::Error naming the value, changing nothing.

#include <vector>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

class World;

/// How moveCornered moves.
struct CornerOptions {
  Filter filter;          ///< the game's filter for the body
  double maxNudge = 4.0;  ///< largest nudge, world units, finite and >= 0 (0: never nudge)
};

/// A corner correction: its own kind of collision, so a debugger can draw it apart.
struct CornerNudge {
  Collision hit;    ///< the ceiling the body clipped, as the move met it (touch: where it clipped)
  double dx = 0.0;  ///< how far it was nudged: < 0 to the left, > 0 to the right
};

/// What moveCornered did.
struct CornerMove {
  Vec2 position;                      ///< where the body ended
  std::vector<Collision> collisions;  ///< every collision, in order (the clipped ceiling's not)
  bool nudged = false;                ///< a corner correction was made
  CornerNudge nudge;                  ///< valid when `nudged`
};

/// How far a body at `body`, meeting the bottom of `ceiling`, moves sideways to clear the end of
/// the ceiling it sticks out past: < 0 round the left end (its right edge placed on the
/// ceiling's left edge, tv::placeBefore), > 0 round the right end; 0 under the whole width or
/// past both ends. The rule moveCornered nudges by (it also asks that the nudge not go against
/// the move, and be at most maxNudge); a replay checks a recorded nudge with it.
[[nodiscard]] double cornerNudgeDx(const Rect& body, const Rect& ceiling);

/// Moves `id` towards `goal` as World::move does, with corner correction (see above).
[[nodiscard]] CornerMove moveCornered(World& world, ItemId id, Vec2 goal,
                                      const CornerOptions& o = {});

}  // namespace tv
