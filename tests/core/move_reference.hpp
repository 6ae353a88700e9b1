#pragma once
// A move as tv/world.hpp specifies it, written the obvious way and independently of the world's
// broad phase: every leg is swept against every item of the world. What a move must give —
// position, collisions and the filter's questions — whatever path the world takes:
//
// - a short move (its bounding box meets at most 4 cells of the grid) first asks the filter
//   about every item whose interior meets the box, in slot order;
// - a leg's hits are the items (not the mover, not one it crossed earlier in the move) that the
//   exact sweep says it meets, put in one order that depends on them alone: rounded ti, then
//   ordinary hits before exact corners, then add order;
// - going down that list, each hit that would lead at its turn (comes before the current leader
//   by the exact hit order) is answered — by the filter, asked then, unless the move asked
//   about it already — and the last kept one leads;
// - its response gives the next leg; a move out of responses stops at the last safe start.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "hit_order.hpp"
#include "tv/response.hpp"
#include "tv/sweep.hpp"
#include "tv/world.hpp"

namespace tv::test {

struct ReferenceResult {
  Vec2 position;
  std::vector<Collision> collisions;
};

/// `responses[id]` is the function of each response id the filter may return (the world's,
/// passed in so that the reference never calls into the world, which would report user
/// responses to an attached recorder).
inline ReferenceResult referenceMove(const World& w, ItemId self, const Rect& r, Vec2 goal,
                                     const Filter& filter, int maxResponses,
                                     std::span<const ResponseFn> responses) {
  struct Hit {
    Sweep sweep;
    Rect rect;
    ItemId id;
    std::uint64_t order;
  };
  ReferenceResult out;
  std::vector<std::uint32_t> crossed;
  std::vector<std::pair<std::uint32_t, ResponseId>> asked;  // by slot, once a move
  const auto ask = [&](ItemId other) {
    const ResponseId a = filter(self, other);
    asked.push_back({other.index, a});
    return a;
  };
  const auto answered = [&](ItemId other) -> const ResponseId* {
    for (const auto& [slot, a] : asked)
      if (slot == other.index) return &a;
    return nullptr;
  };
  const Rect end = r.at(goal);
  const double x0 = std::min(r.x, end.x), y0 = std::min(r.y, end.y);
  const double x1 = std::max(r.right(), end.right()), y1 = std::max(r.bottom(), end.bottom());
  if (w.grid().cellsHolding(x0, y0, x1, y1).count() <= 4) {
    bool kept = false;
    w.forEachItem([&](ItemId id, const Rect& o) {  // in slot order
      if (id == self || !(o.x < x1 && x0 < o.right() && o.y < y1 && y0 < o.bottom())) return;
      kept = ask(id) != response::ignore || kept;
    });
    if (!kept) return {goal, {}};
  }
  std::vector<Hit> hits;
  Vec2 start = r.position();
  Vec2 safe = start;
  for (int i = 0;; ++i) {
    if (i == maxResponses) {
      goal = safe;
      break;
    }
    const Rect leg = r.at(start);
    hits.clear();
    // A hit meets the leg's bounding box: the test before the sweep, for speed alone.
    const Rect g = leg.at(goal);
    const double lx0 = std::min(leg.x, g.x), ly0 = std::min(leg.y, g.y);
    const double lx1 = std::max(leg.right(), g.right()), ly1 = std::max(leg.bottom(), g.bottom());
    w.forEachItem([&](ItemId id, const Rect& o) {
      if (id == self || !(o.x < lx1 && lx0 < o.right() && o.y < ly1 && ly0 < o.bottom())) return;
      if (std::find(crossed.begin(), crossed.end(), id.index) != crossed.end()) return;
      const Sweep s = sweepRect(leg, goal, o);
      if (s.kind != SweepKind::miss) hits.push_back({s, o, id, w.order(id)});
    });
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
      if (a.sweep.ti != b.sweep.ti) return a.sweep.ti < b.sweep.ti;
      if (a.sweep.corner != b.sweep.corner) return !a.sweep.corner;
      return a.order < b.order;
    });
    const Hit* lead = nullptr;
    ResponseId leadResponse = response::ignore;
    for (const Hit& h : hits) {
      if (lead != nullptr &&
          !detail::hitBefore(leg, goal, h.sweep, h.rect, lead->sweep, lead->rect,
                             [&] { return h.order < lead->order; })) {
        continue;
      }
      const ResponseId* known = answered(h.id);
      const ResponseId answer = known ? *known : ask(h.id);
      if (answer == response::ignore) continue;
      lead = &h;
      leadResponse = answer;
    }
    if (lead == nullptr) break;
    Collision c;
    c.item = self;
    c.other = lead->id;
    c.overlaps = lead->sweep.kind == SweepKind::overlap;
    c.corner = lead->sweep.corner;
    c.ti = lead->sweep.ti;
    c.move = goal - leg.position();
    c.normal = lead->sweep.normal;
    c.touch = lead->sweep.touch;
    c.itemRect = leg;
    c.otherRect = lead->rect;
    c.response = leadResponse;
    const Leg next = responses[leadResponse](c, goal);
    c.target = next.goal;
    out.collisions.push_back(c);
    if (next.passThrough) crossed.push_back(c.other.index);
    start = next.start;
    goal = next.goal;
    if (!c.overlaps) safe = start;
  }
  out.position = goal;
  return out;
}

/// anyOverlap as specified: the items whose interior meets `r` (not `skip`), asked about in slot
/// order until one is not ignored.
inline bool referenceAnyOverlap(const World& w, const Rect& r, ItemId skip, const Filter& filter) {
  bool any = false;
  w.forEachItem([&](ItemId id, const Rect& o) {  // in slot order
    if (!any && id != skip && overlaps(r, o)) any = filter(skip, id) != response::ignore;
  });
  return any;
}

}  // namespace tv::test
