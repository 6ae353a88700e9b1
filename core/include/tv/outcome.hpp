#pragma once
/// What a finished move did to the items around it, judged from where it started and where it
/// ended. A move that tunnels leaves no hit behind to say so (its mover never saw the wall), so
/// the debugger and the recording checks ask this instead of guessing from the trace.
///
///        start            end                 passed through: the mover's rect is wholly on
///      +----+    |##|    +----+               one side of `wall` before the move and wholly
///      |    | -> |##| -> |    |               on the other side after it, overlapping it
///      +----+    |##|    +----+               across the move's other axis at both ends.
///                wall
///
/// Items the filter ignores or crosses (`response::ignore`, `response::cross`) are not counted:
/// passing through those is what the game asked for.

#include <cstdint>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

class World;

/// What judgeMove found: the item a move passed through, and the one it ended inside.
struct MoveOutcome {
  /// An item the move passed clean through (the one nearest its start), or invalid.
  ItemId passedThrough;
  /// An item the mover ended inside of without having started in it, or invalid.
  ItemId endedInside;
};

/// Judges the move of `item` from `start` to `end` against `world` as it is after the move.
/// Cost: one rect query over the move's hull; a hull over 65536 cells (a teleport across the
/// world) is not judged (both invalid).
[[nodiscard]] MoveOutcome judgeMove(const World& world, ItemId item, const Rect& start,
                                    const Rect& end, const Filter& filter = {});

}  // namespace tv
