#pragma once
/// What one move did, recorded by the move itself so that the debugger draws what the game
/// got instead of recomputing it. Off unless a MoveTrace is passed; recording never changes
/// results. When tv is built with TV_TRACE=OFF the pointer is ignored and the recording code
/// is compiled out. `Mover::move` clears the trace first; `World::move`, `check` and `project`
/// append to it (so a substep mover's pieces land in one record) — clear it between moves.

#include <string_view>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/grid.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

/// False when tv was built with TV_TRACE=OFF: a MoveTrace passed to a move then stays empty.
#ifdef TV_TRACE_DISABLED
inline constexpr bool kTraceCompiledIn = false;
#else
inline constexpr bool kTraceCompiledIn = true;
#endif

/// One swept leg: the rect at its start and the position it aimed for.
struct TraceLeg {
  Rect start;  ///< the rect where the leg began
  Vec2 goal;   ///< the position it aimed for
};

/// The filter's answer for one pair it was asked about. Only items the move could meet are
/// asked (in a swept move, those that would be hit first), so a candidate may have no answer.
struct TraceAnswer {
  ItemId other;                           ///< the item asked about
  ResponseId response = response::slide;  ///< what the filter answered
};

/// Everything one move visited, tested, asked and hit: what the debugger draws.
///
///     tv::MoveTrace t;
///     world.move(player, goal, filter, {.trace = &t});
///     for (const tv::Cell& c : t.cells) ...   // the broad phase's cells
struct MoveTrace {
  ItemId item;  ///< the item moved (invalid for World::project)
  std::string_view mover;          ///< name of the mover that made the move
  Rect start;                      ///< item before the move
  Vec2 goal;                       ///< what was asked
  Vec2 final;                      ///< where it ended
  std::vector<Cell> cells;         ///< cells the broad phase visited (repeats across legs)
  std::vector<ItemId> candidates;  ///< items the narrow phase tested
  std::vector<TraceLeg> legs;      ///< swept legs, in order (responses start new legs)
  std::vector<Vec2> substeps;      ///< substep boundaries (positions asked for), substep movers
  std::vector<Collision> hits;     ///< collisions, in the order the responses ran
  std::vector<TraceAnswer> answers;  ///< the filter's answers, in the order it gave them

  /// Empties every field, keeping the vectors' memory.
  void clear() {
    item = {};
    mover = {};
    start = {};
    goal = final = {};
    cells.clear();
    candidates.clear();
    legs.clear();
    substeps.clear();
    hits.clear();
    answers.clear();
  }
};

/// The trace to record into: null when tracing is compiled out, so every recording site folds
/// away.
[[nodiscard]] constexpr MoveTrace* activeTrace(MoveTrace* t) {
  if constexpr (kTraceCompiledIn) {
    return t;
  } else {
    (void)t;
    return nullptr;
  }
}

}  // namespace tv
