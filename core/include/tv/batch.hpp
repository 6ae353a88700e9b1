#pragma once
/// Moving versus moving: a set of items moved through one tick together, with continuous
/// relative motion, so that two movers that cross during the tick meet instead of each being
/// tested against the other's frozen position.

#include <cstdint>
#include <span>
#include <vector>

#include "tv/world.hpp"

namespace tv {

struct BatchMove {
  ItemId item;
  Vec2 goal;  ///< where it would be at the end of the tick if nothing stopped it
};

struct BatchOutcome {
  Vec2 position;
  std::span<const Collision> collisions;  ///< in time order; valid until the next step
};

/// Earliest time of impact first: every mover travels along its own path through the tick; the
/// earliest contact (mover–mover by relative motion, or mover–static) among all pairs is found,
/// everyone advances to that instant, the collision's responses (one per side, chosen by the
/// filter for (item, other)) change the movers' remaining paths, and the search repeats.
/// A mover–mover collision is reported to both sides, each with its own normal. Items of the
/// world that are not in the batch stand still.
/// Cost: each event checks every moving body against the world and tests the pairs whose
/// remaining hulls meet (found by sorting the hulls), and events grow with the movers, so a tick
/// grows about as N²: meant for up to a few hundred movers that must meet each other (bullets
/// and enemies), not for a crowd of 10^4.
class Batch {
 public:
  /// Throws tv::Error on unknown items, duplicates or non-finite goals, changing nothing.
  void step(World& world, std::span<const BatchMove> moves, Filter filter = {},
            int maxEvents = 4096);

  [[nodiscard]] std::size_t size() const { return bodies_.size(); }
  [[nodiscard]] BatchOutcome outcome(std::size_t i) const;

 private:
  struct Body {
    ItemId item;
    Rect rect;  // at the current event time
    Vec2 goal;  // where its remaining path ends at t = 1
    bool stopped = false;
    std::size_t first = 0, count = 0;  // its collisions, once gathered
  };
  std::vector<Body> bodies_;
  std::vector<Collision> events_;  // raw, in time order, with the body index in `owner_`
  std::vector<std::size_t> owner_;
  std::vector<Collision> collisions_;   // grouped by body
  std::vector<std::uint64_t> crossed_;  // (a, b) body-pair keys excluded after a cross
  std::vector<std::uint64_t> order_;    // each body's add order: the tie-break
  std::vector<Rect> startRects_;        // where each body began, to undo a failed step
  static constexpr std::uint32_t kNoBody = 0xFFFFFFFFu;
  std::vector<std::uint32_t> bodyBySlot_;  // world slot -> body, kNoBody for the rest
  std::vector<Rect> hulls_;                // per body, its remaining path's bounding box
  std::vector<std::uint32_t> byX_;         // bodies by their hull's left edge
};

}  // namespace tv
