// Moving solids (tv/solid.hpp): one axis at a time, the bodies in the way are pushed to the
// solid's new leading edge (a row of bodies by a chain of pushes), the solid is placed, and the
// riders follow, each placed from the solid's edge. A push that falls short clips the solid's
// goal to where that body stopped, and the axis is done again from the start with the clipped
// goal, so that no body is pushed further than the solid ends up going.

#include "tv/solid.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "tv/error.hpp"
#include "tv/world.hpp"

namespace tv {

namespace {

constexpr std::string_view kWhere = "tv::moveSolid";

// Coordinates along one axis: x (horizontal move) or y (vertical).
struct Axis {
  bool horizontal;
  [[nodiscard]] double pos(const Rect& r) const { return horizontal ? r.x : r.y; }
  [[nodiscard]] double size(const Rect& r) const { return horizontal ? r.w : r.h; }
  [[nodiscard]] double farEdge(const Rect& r) const { return horizontal ? r.right() : r.bottom(); }
  [[nodiscard]] Vec2 with(Vec2 p, double v) const {
    return horizontal ? Vec2{v, p.y} : Vec2{p.x, v};
  }
  [[nodiscard]] Rect at(const Rect& r, double v) const { return r.at(with(r.position(), v)); }
};

// Standing on top: where a contact with the top puts a body (placeBefore: its bottom edge on the
// top bit for bit whenever a double allows it, else the nearest position short of it),
// overlapping it horizontally.
bool standsOn(const Rect& b, const Rect& s) {
  return (b.bottom() == s.y || b.y == placeBefore(s.y, b.h)) && b.x < s.right() &&
         s.x < b.right();
}
// Holding on a side: an edge on the side's, overlapping it vertically.
bool holdsSide(const Rect& b, const Rect& s) {
  return (b.right() == s.x || b.x == s.right()) && b.y < s.bottom() && s.y < b.bottom();
}

class SolidMover {
 public:
  SolidMover(World& w, ItemId solid, const SolidOptions& o, SolidMove& out)
      : w_(w), solid_(solid), o_(o), out_(out) {}

  // Moves the solid along `axis` to `target` (its coordinate on that axis).
  void along(Axis axis, double target) {
    const Rect s0 = w_.rect(solid_);
    const double p0 = axis.pos(s0);
    if (target == p0) return;
    const bool forward = target > p0;
    // Riders are those of the solid as it stood before this axis's move.
    riders_.clear();
    for (const ItemId b : o_.bodies) {
      const Rect r = w_.rect(b);
      if (standsOn(r, s0) || (o_.carrySides && !o_.oneWay && holdsSide(r, s0)))
        riders_.push_back(b);
    }
    saved_.clear();
    for (const ItemId b : o_.bodies) saved_.push_back(w_.rect(b));
    double goal = target;
    // Each failed attempt clips the goal to where a squished body stopped and starts the axis
    // again; the clip only shrinks the move, and a body stops it at most once per goal.
    for (std::size_t attempt = 0;; ++attempt) {
      const std::optional<double> clip = attemptPushes(axis, s0, goal, forward);
      if (!clip) break;
      restoreBodies();
      // Never back past where the solid started: a body it could not free from an overlap it
      // started in is reported, and the solid stays.
      const double next = forward ? std::max(p0, std::min(*clip, goal))
                                  : std::min(p0, std::max(*clip, goal));
      if (next == goal || next == p0 || attempt > o_.bodies.size()) {
        goal = p0;  // no room at all (or no progress): the solid stays on this axis
        break;
      }
      goal = next;
    }
    if (goal == p0) return;
    const Rect s1 = axis.at(s0, goal);
    w_.update(solid_, s1);
    for (const ItemId b : pushedNow_) note(out_.pushed, b);
    carryRiders(axis, s0, s1);
  }

 private:
  // Pushes every body in the way of s0 -> goal; the solid's clipped coordinate if one fell short.
  std::optional<double> attemptPushes(Axis axis, const Rect& s0, double goal, bool forward) {
    const Rect s1 = axis.at(s0, goal);
    const Rect swept = unite(s0, s1);
    inWay_.clear();
    for (std::size_t i = 0; i < o_.bodies.size(); ++i) {
      const ItemId b = o_.bodies[i];
      const Rect r = w_.rect(b);
      if (!overlaps(r, swept)) continue;
      bool ahead;
      if (o_.oneWay) {
        // Only a body entirely above the top at the start, met by the top rising into it.
        ahead = !axis.horizontal && !forward && r.bottom() <= s0.y;
      } else {
        // Some of it beyond the old leading edge: the solid would pass into it.
        ahead = forward ? axis.farEdge(r) > axis.farEdge(s0) : axis.pos(r) < axis.pos(s0);
      }
      if (ahead) inWay_.push_back(i);
    }
    // Nearest first, along the move; ties by add order.
    std::sort(inWay_.begin(), inWay_.end(), [&](std::size_t a, std::size_t b) {
      const Rect ra = w_.rect(o_.bodies[a]), rb = w_.rect(o_.bodies[b]);
      const double da = forward ? axis.pos(ra) : -axis.farEdge(ra);
      const double db = forward ? axis.pos(rb) : -axis.farEdge(rb);
      if (da != db) return da < db;
      return w_.order(o_.bodies[a]) < w_.order(o_.bodies[b]);
    });
    busy_.assign(o_.bodies.size(), false);
    pushedNow_.clear();
    const double edge = forward ? axis.farEdge(s1) : axis.pos(s1);
    for (const std::size_t i : inWay_) {
      const std::optional<double> reached = push(axis, i, edge, forward);
      if (reached) {
        // The solid's coordinate that puts its leading edge on the body's reached face.
        return forward ? placeBefore(*reached, axis.size(s0)) : *reached;
      }
    }
    return std::nullopt;
  }

  // Pushes body i so that its near face is at `edge`; nullopt when it got there, else the
  // coordinate its near face reached.
  std::optional<double> push(Axis axis, std::size_t i, double edge, bool forward) {
    const ItemId b = o_.bodies[i];
    const Rect r = w_.rect(b);
    const double want = forward ? edge : placeBefore(edge, axis.size(r));
    if (forward ? axis.pos(r) >= want : axis.pos(r) <= want) return std::nullopt;  // clear
    busy_[i] = true;
    const Vec2 goal = axis.with(r.position(), want);
    for (std::size_t tries = 0; tries <= o_.bodies.size(); ++tries) {
      const MoveResult m = w_.move(b, goal, pushFilter());
      if (m.position == goal) {
        pushedNow_.push_back(b);
        return std::nullopt;
      }
      // Stopped short: by a body that can be pushed on in turn (a row), or by something else.
      const Collision* stop = nullptr;
      for (const Collision& c : m.collisions)
        if (c.response != response::cross) stop = &c;
      const std::size_t k = stop ? indexOf(stop->other) : o_.bodies.size();
      const Rect now = w_.rect(b);
      if (k < o_.bodies.size() && !busy_[k]) {
        // Push that one on first (it may get all or part of the way), then try again: it is
        // busy now, so a second stop against it is a squish, just behind where it got to.
        const double farFace = forward ? axis.farEdge(axis.at(now, want)) : want;
        (void)push(axis, k, farFace, forward);
        continue;
      }
      out_.squished.push_back(
          {b, stop ? stop->other : ItemId{},
           axis.with({0, 0}, forward ? 1.0 : -1.0)});
      return forward ? axis.pos(now) : axis.farEdge(now);
    }
    return forward ? axis.pos(w_.rect(b)) : axis.farEdge(w_.rect(b));
  }

  void carryRiders(Axis axis, const Rect& s0, const Rect& s1) {
    const double delta = axis.pos(s1) - axis.pos(s0);
    for (const ItemId b : riders_) {
      if (std::find(pushedNow_.begin(), pushedNow_.end(), b) != pushedNow_.end()) continue;
      const Rect r = w_.rect(b);
      Vec2 goal;
      if (standsOn(r, s0) && !axis.horizontal) {
        goal = {r.x, placeBefore(s1.y, r.h)};  // back on the top, from its edge
      } else if (axis.horizontal && r.right() == s0.x) {
        goal = {placeBefore(s1.x, r.w), r.y};  // holding its left side
      } else if (axis.horizontal && r.x == s0.right()) {
        goal = {s1.right(), r.y};  // holding its right side
      } else {
        goal = axis.with(r.position(), axis.pos(r) + delta);
      }
      (void)w_.move(b, goal, pushFilter());
      note(out_.carried, b);
    }
  }

  Filter pushFilter() {
    return Filter(filterFn_);
  }

  std::size_t indexOf(ItemId id) const {
    for (std::size_t i = 0; i < o_.bodies.size(); ++i)
      if (o_.bodies[i] == id) return i;
    return o_.bodies.size();
  }

  static void note(std::vector<ItemId>& list, ItemId b) {
    if (std::find(list.begin(), list.end(), b) == list.end()) list.push_back(b);
  }

  void restoreBodies() {
    for (std::size_t i = 0; i < o_.bodies.size(); ++i) {
      if (w_.rect(o_.bodies[i]) != saved_[i]) w_.update(o_.bodies[i], saved_[i]);
    }
    pushedNow_.clear();
  }

  struct PushFilter {
    const SolidMover* self;
    ResponseId operator()(ItemId item, ItemId other) const {
      if (other == self->solid_) return response::ignore;
      const ResponseId r = self->o_.filter(item, other);
      // A push or a carry goes to one point: a bounce would send the body elsewhere.
      return r == response::bounce ? response::touch : r;
    }
  };

  World& w_;
  ItemId solid_;
  const SolidOptions& o_;
  SolidMove& out_;
  PushFilter filterFn_{this};
  std::vector<ItemId> riders_;
  std::vector<Rect> saved_;
  std::vector<std::size_t> inWay_;
  std::vector<bool> busy_;
  std::vector<ItemId> pushedNow_;
};

}  // namespace

SolidMove moveSolid(World& world, ItemId solid, Vec2 goal, const SolidOptions& o) {
  // Everything is checked before anything moves.
  if (!world.has(solid)) fail(kWhere, "the solid is not in the world (never added, or removed)");
  requireFinite(kWhere, "goal.x", goal.x);
  requireFinite(kWhere, "goal.y", goal.y);
  requireInRange(kWhere, "goal.x", goal.x);
  requireInRange(kWhere, "goal.y", goal.y);
  for (std::size_t i = 0; i < o.bodies.size(); ++i) {
    const ItemId b = o.bodies[i];
    if (b == solid) fail(kWhere, "bodies[" + std::to_string(i) + "] is the solid itself");
    if (!world.has(b)) {
      fail(kWhere, "bodies[" + std::to_string(i) + "] is not in the world (never added, or removed)");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (o.bodies[j] == b) {
        fail(kWhere, "bodies[" + std::to_string(i) + "] repeats bodies[" + std::to_string(j) + "]");
      }
    }
  }
  // Undone whole if anything throws part way (the filter, a rect the world refuses).
  const Rect solidBefore = world.rect(solid);
  std::vector<Rect> before;
  before.reserve(o.bodies.size());
  for (const ItemId b : o.bodies) before.push_back(world.rect(b));
  SolidMove out;
  try {
    SolidMover m(world, solid, o, out);
    m.along(Axis{true}, goal.x);
    m.along(Axis{false}, goal.y);
  } catch (...) {
    world.update(solid, solidBefore);
    for (std::size_t i = 0; i < o.bodies.size(); ++i) {
      if (world.rect(o.bodies[i]) != before[i]) world.update(o.bodies[i], before[i]);
    }
    throw;
  }
  out.position = world.rect(solid).position();
  return out;
}

}  // namespace tv
