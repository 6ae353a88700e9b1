// A move by bump.lua 3.1.7's rules (MoveSemantics::bump): its `World:check` loop — project the
// straight leg, take the first collision in bump's order, hand it to the response, leave what
// was met out of the rest of the move — over the geometry of tv/bump.hpp. What this adds to
// bump is said there: add order on exact ties, a contact never inside what it touched, and no
// passing into something already met.

#include <algorithm>
#include <cmath>
#include <string>

#include "tv/bump.hpp"
#include "tv/error.hpp"
#include "tv/world.hpp"

#include "spatial_hash.hpp"

namespace tv {

namespace {

// bump's order of a leg's collisions, with the add order where bump's is a hash order.
struct Key {
  double ti, distance;
  std::uint64_t order;
  friend bool operator<(const Key& a, const Key& b) {
    if (a.ti != b.ti) return a.ti < b.ti;
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.order < b.order;
  }
};

}  // namespace

bool World::bumpFirstHit(ItemId self, const Rect& at, Vec2 goal, Filter filter, MoveTrace* trace,
                         Collision& out) const {
  const bump::Cells cells = bump::cellsOfLeg(grid_.cellSize(), at, goal);
  const double size = grid_.cellSize();
  // bump's cell (cx, cy), 1-based, covers the core's cell (cx - 1, cy - 1). An item in one of
  // bump's cells of the leg has an interior that meets their area, so the spatial hash holds it
  // in one of the core's cells there; bump's own cell test then keeps exactly bump's candidates.
  const CellRange range{static_cast<std::int64_t>(cells.left) - 1,
                        static_cast<std::int64_t>(cells.top) - 1,
                        static_cast<std::int64_t>(cells.right) - 1,
                        static_cast<std::int64_t>(cells.bottom) - 1};
  if (trace) Grid::forEachCell(range, [&](Cell c) { trace->cells.push_back(c); });
  const std::uint32_t epoch = nextEpoch();
  if (self.valid()) stamp_[self.index] = epoch;
  for (const ItemId m : bumpMet_) stamp_[m.index] = epoch;  // met: left out, as bump's visited
  // An entry in one cell only is met once: it needs no stamp, only to be neither the mover nor
  // met before (a short list). Reading its stamp would be a cache miss per candidate.
  const auto leftOut = [&](std::uint32_t slot) {
    if (self.valid() && slot == self.index) return true;
    return std::any_of(bumpMet_.begin(), bumpMet_.end(),
                       [&](ItemId m) { return m.index == slot; });
  };
  // The leg's swept box, widened by a margin far beyond what bump's DELTA and the rounding of
  // its arithmetic can reach: an item wholly outside it can be neither met nor overlapped
  // (bump's detect would return nil), so it is left out before bump's cell test and detect,
  // whose divisions are most of a candidate's cost. Traced moves list every candidate.
  const double reach = 1e-6 * (1.0 + std::fabs(at.x) + std::fabs(at.y) + std::fabs(goal.x) +
                               std::fabs(goal.y) + at.w + at.h);
  const double boxL = std::min(at.x, goal.x) - reach, boxR = std::max(at.x, goal.x) + at.w + reach;
  const double boxT = std::min(at.y, goal.y) - reach, boxB = std::max(at.y, goal.y) + at.h + reach;
  const auto beyond = [&](const Rect& o) {
    const double slack = 1e-6 * (std::fabs(o.x) + std::fabs(o.y) + o.w + o.h);
    return o.x - slack > boxR || o.x + o.w + slack < boxL || o.y - slack > boxB ||
           o.y + o.h + slack < boxT;
  };
  bumpHits_.clear();
  const detail::SpatialHash& hash = *hash_;
  Grid::forEachCell(hash.live(range), [&](Cell c) {
    for (const detail::HashEntry& e : hash.items(c)) {
      if (e.shared()) {
        if (stamp_[e.slot()] == epoch) continue;
        stamp_[e.slot()] = epoch;  // in several cells: once
      } else if (leftOut(e.slot())) {
        continue;
      }
      if (trace == nullptr && beyond(e.rect)) continue;
      if (!bump::cellsOf(size, e.rect).meets(cells)) continue;  // not in bump's cells of the leg
      // The entry holds the item's rect: the slots need not be read.
      const ItemId other{e.slot(), e.generation};
      if (trace) trace->candidates.push_back(other);
      const Sweep s = bump::detect(at, goal, e.rect);
      if (s.kind == SweepKind::miss) continue;
      Collision col;
      col.item = self;
      col.other = other;
      col.overlaps = s.kind == SweepKind::overlap;
      col.ti = s.ti;
      col.move = goal - at.position();
      col.normal = s.normal;
      col.touch = s.touch;
      col.itemRect = at;
      col.otherRect = e.rect;
      bumpHits_.push_back(col);
    }
  });
  const auto key = [&](const Collision& c) {
    return Key{c.ti, bump::squareDistance(c.itemRect, c.otherRect), orders_[c.other.index]};
  };
  std::sort(bumpHits_.begin(), bumpHits_.end(),
            [&](const Collision& a, const Collision& b) { return key(a) < key(b); });
  // The filter, in that order, until it keeps one: the first of bump's sorted list.
  for (Collision& c : bumpHits_) {
    c.response = filter(self, c.other);
    if (trace) trace->answers.push_back({c.other, c.response});
    if (c.response == response::ignore) continue;
    if (c.response >= responses_.size()) [[unlikely]] {
      fail("tv::World::move", "the filter answered response " + std::to_string(c.response) +
                                  ", which is not registered");
    }
    out = c;
    return true;
  }
  return false;
}

bool World::bumpGuard(const Rect& at, Vec2 goal, const Collision* first, Collision& out) const {
  bool found = false;
  Key best{};
  for (std::size_t i = 0; i < bumpMet_.size(); ++i) {
    if (!bumpMetGuard_[i]) continue;
    const Rect o = slots_[bumpMet_[i].index].rect;
    if (overlaps(at, o)) continue;  // the leg starts inside it: bump's rules, whatever they do
    const Sweep s = bump::detect(at, goal, o);
    if (s.kind != SweepKind::hit) continue;
    const Key k{s.ti, bump::squareDistance(at, o), orders_[bumpMet_[i].index]};
    if (found && !(k < best)) continue;
    found = true;
    best = k;
    out = {};
    out.other = bumpMet_[i];
    out.ti = s.ti;
    out.move = goal - at.position();
    out.normal = s.normal;
    out.touch = s.touch;
    out.itemRect = at;
    out.otherRect = o;
    out.response = bumpMetResponse_[i];
  }
  if (!found) return false;
  if (first != nullptr &&
      !(best < Key{first->ti, bump::squareDistance(first->itemRect, first->otherRect),
                   orders_[first->other.index]})) {
    return false;
  }
  return true;
}

MoveResult World::bumpRun(std::uint32_t self, const Rect& r, Vec2 goal, Filter filter,
                          const MoveOptions& o) const {
  MoveTrace* trace = activeTrace(o.trace);
  const ItemId selfId = self == ItemId::kNone ? ItemId{} : ItemId{self, slots_[self].generation};
  collisions_.clear();
  bumpMet_.clear();
  bumpMetResponse_.clear();
  bumpMetGuard_.clear();
  // metThisMove() is empty outside a move, even one that throws.
  struct Forget {
    const World& w;
    ~Forget() { w.bumpMet_.clear(); }
  } forget{*this};
  if (trace) {
    trace->item = selfId;
    trace->start = r;
    trace->goal = goal;
  }
  const Vec2 origin = r.position();
  Vec2 start = origin;
  for (;;) {
    const Rect at = r.at(start);
    if (trace) trace->legs.push_back({at, goal});
    Collision c;
    const bool hit = bumpFirstHit(selfId, at, goal, filter, trace, c);
    Collision guard;
    if (bumpGuard(at, goal, hit ? &c : nullptr, guard)) {
      // The leg would enter what the move already met: it ends at the contact.
      guard.item = selfId;
      guard.target = guard.touch;
      goal = guard.touch;
      collisions_.push_back(guard);
      if (trace) trace->hits.push_back(guard);
      break;
    }
    if (!hit) break;
    bumpMet_.push_back(c.other);
    bumpMetResponse_.push_back(c.response);
    // A one-way platform acts as bump's slide when it blocks the body, else as its cross.
    const ResponseId act =
        c.response != response::oneway ? c.response
        : onewayBlocks(c)              ? response::slide
                                       : response::cross;
    bumpMetGuard_.push_back(!c.overlaps && act != response::cross);
    const bool moving = c.move.x != 0 || c.move.y != 0;
    bool stop = false;
    switch (act) {
      case response::touch:
        goal = c.touch;
        stop = true;
        break;
      case response::cross:
        start = origin;  // bump projects a cross from where the move began
        break;
      case response::slide:
        if (moving) {
          if (c.normal.x != 0) {
            goal.x = c.touch.x;
          } else {
            goal.y = c.touch.y;
          }
        }
        start = c.touch;
        break;
      case response::bounce:
        if (moving) {
          double bx = goal.x - c.touch.x, by = goal.y - c.touch.y;
          if (c.normal.x == 0) {
            by = -by;
          } else {
            bx = -bx;
          }
          goal = {c.touch.x + bx, c.touch.y + by};
        } else {
          goal = c.touch;
        }
        start = c.touch;
        break;
      default: {
        const Leg next = respond(c, goal);
        if (!isFinite(next.start) || !isFinite(next.goal) || !grid_.fits(r.at(next.start)) ||
            !grid_.fits(r.at(next.goal)) || !inRange(next.start.x) || !inRange(next.start.y) ||
            !inRange(next.goal.x) || !inRange(next.goal.y)) [[unlikely]] {
          fail("tv::World::move",
               "response '" + std::string(responseName(c.response)) + "' returned the leg {" +
                   formatNumber(next.start.x) + ", " + formatNumber(next.start.y) + "} -> {" +
                   formatNumber(next.goal.x) + ", " + formatNumber(next.goal.y) +
                   "}, which is not finite or too far from the origin (beyond 2^500 or the grid)");
        }
        goal = next.goal;
        start = next.start;
        stop = next.stop;
      }
    }
    c.target = goal;
    collisions_.push_back(c);
    if (trace) trace->hits.push_back(c);
    if (stop) break;
  }
  if (trace) trace->final = goal;
  return {goal, collisions_};
}

}  // namespace tv
