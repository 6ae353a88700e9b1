#pragma once
/// Moving versus moving: a set of items moved through one tick together, with continuous
/// relative motion, so that two movers that cross during the tick meet instead of each being
/// tested against the other's frozen position.

#include <cstdint>
#include <span>
#include <vector>

#include "tv/world.hpp"

namespace tv {

/// One body of a Batch::step: an item of the world and where it is heading this tick.
struct BatchMove {
  ItemId item;  ///< an item of the world, at most once per step
  Vec2 goal;  ///< where it would be at the end of the tick if nothing stopped it
};

/// Where one body of the last step ended, and what it met.
struct BatchOutcome {
  Vec2 position;  ///< the item's position after the step (top-left), world units
  std::span<const Collision> collisions;  ///< in time order; valid until the next step
};

/// Earliest time of impact first: every mover travels along its own path through the tick; the
/// earliest contact (mover–mover by relative motion, or mover–static) among all pairs is found,
/// the collision's responses (one per side, chosen by the filter for (item, other)) change the
/// paths of the movers in it, and the search goes on from that instant. A mover–mover collision
/// is reported to both sides, each with its own normal. Items of the world that are not in the
/// batch stand still.
///
/// Time is absolute within the tick, t in [0, 1]. A body's path is its rect at the instant t0
/// it last changed and its goal at t = 1; its position at t is p0 + (goal − p0)·(t − t0)/(1 − t0),
/// computed from that path alone, so a body is re-based only by an event it takes part in.
/// Events at the same instant run statics first, then pairs, each in add order, and a pair is
/// swept from its earlier-added side: the outcome never depends on the order of `moves`. A
/// collision's `ti`, `itemRect` and `move` describe the leg it ended: from the body's rect when
/// the pair's later path began (or its own path's start, against a static) to its goal.
/// The world holds the batch's items where they began until the step ends, then where they
/// ended (a filter that reads their rects during the step sees their starts).
///
/// Cost: each body's first static hit is searched once at the start and again only when an
/// event changes its path; pairs are searched among bodies whose swept hulls share a cell of a
/// grid over the hulls; events wait in a priority queue, and an event re-examines only the
/// bodies it changed and their hull neighbours. A tick costs about N·(static search + hull
/// neighbours) + events·(the same for two bodies)·log N: on bump-crowd (`tv-bench scale`, all
/// movers sliding against each other) 0.2 M instructions a tick for 100 movers, 2.1 M for 10^3
/// (~0.4 ms), 32 M for 10^4 (7 ms on a quiet machine), about a third of it in the world's own
/// queries and the final World::update of every body.
class Batch {
 public:
  /// Throws tv::Error on unknown items, duplicates or non-finite goals, changing nothing.
  /// `maxEvents` (≥ 1): once that many events have run and another is due, every body stays
  /// where it is at the last event's instant.
  void step(World& world, std::span<const BatchMove> moves, Filter filter = {},
            int maxEvents = 4096);

  /// Bodies in the last step (as many as its `moves`).
  [[nodiscard]] std::size_t size() const { return bodies_.size(); }
  /// Body `i` of the last step, in the order of its `moves`; i < size().
  [[nodiscard]] BatchOutcome outcome(std::size_t i) const;

 private:
  struct Body {
    ItemId item;
    Rect rect;       // at t0: where its current path starts (at the end: where it ended)
    Vec2 goal;       // where its current path ends, at t = 1
    double t0 = 0;   // when its current path began
    std::uint32_t version = 0;  // bumped when its path changes: queued events become stale
    std::size_t first = 0, count = 0;  // its collisions, once gathered
  };
  // The search's working state (core/src/batch.cpp), kept between steps to reuse its memory;
  // a copied Batch starts with its own.
  struct Search;
  class SearchPtr {
   public:
    SearchPtr() = default;
    SearchPtr(const SearchPtr&) {}
    SearchPtr& operator=(const SearchPtr&) { return *this; }
    ~SearchPtr();
    Search& get();

   private:
    Search* p_ = nullptr;
  };
  std::vector<Body> bodies_;
  std::vector<Collision> collisions_;  // grouped by body
  SearchPtr search_;
};

}  // namespace tv
