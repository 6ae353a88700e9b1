// The batch step as its specification reads, with nothing to make it fast: a tick is a loop
// of "find the earliest event among every body against the world and every pair of bodies,
// run it". Each body keeps the path it took at its last event (its rect then, that instant
// t0, its goal at t = 1); a time found for a body or a pair depends on those paths alone.
// tv::Batch must give the same outcomes bit for bit, ties included.
#include "batch_reference.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>

namespace tv::reference {

namespace {

struct Body {
  ItemId item;
  Rect rect;  // at t0
  Vec2 goal;  // at t = 1
  double t0 = 0;
  std::uint64_t order = 0;
};

Vec2 at(const Body& b, double t) {
  const Vec2 p = b.rect.position();
  if (t == b.t0 || b.goal == p) return p;
  return p + (b.goal - p) * ((t - b.t0) / (1.0 - b.t0));
}

// The least event so far: (t, pair, first order, second order) compared in that order.
struct Best {
  bool found = false;
  double t = 0;
  bool pair = false;
  std::uint64_t first = 0, second = 0;
  std::size_t i = 0, j = 0;  // a pair: i added before j
  Collision hit;             // a static hit
  Sweep sweep;               // a pair's
  double from = 0;
  Vec2 pi, pj;
  bool beats(double t2, bool pair2, std::uint64_t first2, std::uint64_t second2) const {
    if (!found) return true;
    if (t2 != t) return t2 < t;
    if (pair2 != pair) return !pair2;
    return first2 != first ? first2 < first : second2 < second;
  }
};

}  // namespace

std::vector<Outcome> batchStep(World& world, std::span<const BatchMove> moves, Filter filter,
                               int maxEvents, std::vector<double>* instants) {
  std::vector<Body> bodies;
  std::set<std::uint32_t> batchSlots;
  for (const BatchMove& m : moves) {
    bodies.push_back({m.item, world.rect(m.item), m.goal, 0, world.order(m.item)});
    batchSlots.insert(m.item.index);
  }
  std::set<std::pair<std::size_t, std::size_t>> crossedPairs;
  std::set<std::pair<std::size_t, std::uint32_t>> crossedStatics;
  std::vector<std::pair<std::size_t, Collision>> events;

  bool finished = false;
  double last = 0;
  for (int e = 0;; ++e) {
    Best best;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = bodies[i];
      if (b.goal == b.rect.position()) continue;
      const auto statics = [&](ItemId, ItemId other) {
        if (batchSlots.count(other.index) || crossedStatics.count({i, other.index})) {
          return response::ignore;
        }
        return filter(b.item, other);
      };
      const MoveResult r =
          world.project(b.rect, b.goal, Filter(statics), {BroadPhase::swept, nullptr, 1});
      if (r.collisions.empty()) continue;
      const Collision& c = r.collisions.front();
      const double t = b.t0 + std::max(c.ti, 0.0) * (1.0 - b.t0);
      if (best.beats(t, false, b.order, world.order(c.other))) {
        best = {true, t, false, b.order, world.order(c.other), i, 0, c, {}, 0, {}, {}};
        best.hit.item = b.item;
      }
    }
    for (std::size_t i0 = 0; i0 < bodies.size(); ++i0) {
      for (std::size_t j0 = i0 + 1; j0 < bodies.size(); ++j0) {
        const std::size_t i = bodies[i0].order < bodies[j0].order ? i0 : j0;
        const std::size_t j = i == i0 ? j0 : i0;
        if (crossedPairs.count({i0, j0})) continue;
        const Body& a = bodies[i];
        const Body& b = bodies[j];
        const double from = std::max(a.t0, b.t0);
        const Vec2 pa = at(a, from), pb = at(b, from);
        if (!overlaps(unite(a.rect.at(pa), a.rect.at(a.goal)),
                      unite(b.rect.at(pb), b.rect.at(b.goal)))) {
          continue;
        }
        if (filter(a.item, b.item) == response::ignore &&
            filter(b.item, a.item) == response::ignore) {
          continue;
        }
        const Sweep s = sweepRect(a.rect.at(pa), pa + ((a.goal - pa) - (b.goal - pb)), b.rect.at(pb));
        if (s.kind == SweepKind::miss) continue;
        const double t = from + std::max(s.ti, 0.0) * (1.0 - from);
        if (best.beats(t, true, a.order, b.order)) {
          best = {true, t, true, a.order, b.order, i, j, {}, s, from, pa, pb};
        }
      }
    }
    if (!best.found) {
      finished = true;
      break;
    }
    if (e == maxEvents) break;
    last = best.t;
    if (instants) instants->push_back(best.t);

    if (!best.pair) {
      Body& b = bodies[best.i];
      Collision c = best.hit;
      const Leg next = world.respond(c, b.goal);
      c.target = next.goal;
      events.push_back({best.i, c});
      if (next.passThrough) crossedStatics.insert({best.i, c.other.index});
      b.rect = b.rect.at(next.start);
      b.goal = next.goal;
      b.t0 = best.t;
      continue;
    }

    // b comes to the instant on its path; a is placed against b's edges there.
    Body& a = bodies[best.i];
    Body& b = bodies[best.j];
    const Sweep& s = best.sweep;
    const Rect aStart = a.rect.at(best.pi), bStart = b.rect.at(best.pj);
    const Vec2 da = a.goal - best.pi, db = b.goal - best.pj;
    const Rect bAt = b.rect.at(at(b, best.t));
    Vec2 pa = at(a, best.t);
    if (s.normal.x < 0) pa.x = placeBefore(bAt.x, a.rect.w);
    if (s.normal.x > 0) pa.x = bAt.right();
    if (s.normal.y < 0) pa.y = placeBefore(bAt.y, a.rect.h);
    if (s.normal.y > 0) pa.y = bAt.bottom();
    a.rect = a.rect.at(pa);
    b.rect = bAt;
    a.t0 = b.t0 = best.t;
    const auto tell = [&](std::size_t self, const Body& other, Vec2 normal, Vec2 move,
                          const Rect& selfStart, const Rect& otherStart) {
      Body& me = bodies[self];
      Collision c;
      c.item = me.item;
      c.other = other.item;
      c.overlaps = s.kind == SweepKind::overlap;
      c.corner = s.corner;
      c.ti = s.ti;
      c.move = move;
      c.normal = normal;
      c.touch = me.rect.position();
      c.itemRect = selfStart;
      c.otherRect = otherStart;
      c.response = filter(me.item, other.item);
      if (c.response == response::ignore) return true;  // not told, and done with the other
      const Leg next = world.respond(c, me.goal);
      c.target = next.goal;
      events.push_back({self, c});
      me.rect = me.rect.at(next.start);
      me.goal = next.goal;
      return next.passThrough;
    };
    const bool passA = tell(best.i, b, s.normal, da, aStart, bStart);
    const bool passB = tell(best.j, a, s.normal * -1.0, db, bStart, aStart);
    if (passA || passB) crossedPairs.insert({std::min(best.i, best.j), std::max(best.i, best.j)});
  }

  std::vector<Outcome> out;
  for (Body& b : bodies) {
    b.rect = b.rect.at(finished ? b.goal : at(b, last));
    world.update(b.item, b.rect);
    out.push_back({b.rect.position(), {}});
  }
  for (const auto& [owner, c] : events) out[owner].collisions.push_back(c);
  return out;
}

}  // namespace tv::reference
