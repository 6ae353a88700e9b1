// Corner correction (tv/corner.hpp): the move is first checked; when its first blocking hit is a
// ceiling corner clipped by at most maxNudge and the strip beside it is free, the body moves to
// the contact, slides sideways past the corner's edge and goes on — three World::move calls, so
// a recording replays them as the game made them.

#include "tv/corner.hpp"

#include <cmath>

#include "tv/error.hpp"
#include "tv/observer.hpp"
#include "tv/world.hpp"

namespace tv {

namespace {

constexpr std::string_view kWhere = "tv::moveCornered";

void append(std::vector<Collision>& out, const MoveResult& r) {
  out.insert(out.end(), r.collisions.begin(), r.collisions.end());
}

// Where a body meeting the bottom of `ceiling` goes to clear the end it sticks out past (placed
// exactly, not start + dx, which may round); its own x when there is no such end.
double nudgedX(const Rect& body, const Rect& ceiling) {
  if (body.x < ceiling.x && body.right() <= ceiling.right()) {
    return placeBefore(ceiling.x, body.w);  // round the left end: right edge on its left edge
  }
  if (body.right() > ceiling.right() && body.x >= ceiling.x) return ceiling.right();
  return body.x;
}

}  // namespace

double cornerNudgeDx(const Rect& body, const Rect& ceiling) {
  return nudgedX(body, ceiling) - body.x;
}

CornerMove moveCornered(World& world, ItemId id, Vec2 goal, const CornerOptions& o) {
  requireFinite(kWhere, "maxNudge", o.maxNudge);
  if (o.maxNudge < 0) fail(kWhere, "maxNudge must be >= 0, but was " + formatNumber(o.maxNudge));

  CornerMove out;
  const auto plain = [&] {
    const MoveResult r = world.move(id, goal, o.filter);
    out.position = r.position;
    append(out.collisions, r);
    return out;
  };
  if (o.maxNudge == 0) return plain();

  // The first hit the body does not pass through (check refuses bad ids and goals here).
  const MoveResult seen = world.check(id, goal, o.filter);
  const Collision* hit = nullptr;
  for (const Collision& c : seen.collisions) {
    if (c.response != response::cross) {
      hit = &c;
      break;
    }
  }
  if (!hit || hit->overlaps || hit->normal.x != 0 || hit->normal.y != 1) return plain();

  const Collision c = *hit;
  const Rect t = c.itemRect.at(c.touch);  // the body where it meets the ceiling
  const Rect& ceiling = c.otherRect;
  const double newX = nudgedX(t, ceiling);
  const double dx = newX - t.x;
  // Over the whole width, past both ends, or moving the other way: no nudge.
  if (dx == 0 || (dx < 0 && c.move.x > 0) || (dx > 0 && c.move.x < 0)) return plain();
  if (!(std::fabs(dx) <= o.maxNudge)) return plain();

  // The strip it slides through must be free of anything that blocks it.
  const Rect moved = t.at({newX, t.y});
  const auto blocks = [&](ItemId a, ItemId b) {
    const ResponseId r = o.filter(a, b);
    return r == response::cross ? response::ignore : r;
  };
  if (world.anyOverlap(unite(t, moved), id, Filter(blocks))) return plain();

  // To the contact (the first leg's line, so what it crossed on the way is met again), round the
  // corner, then the rest shifted by the nudge. Every leg up to the first blocking hit aims at the
  // call's goal (cross keeps it), so the rest aims at goal + dx.
  const Vec2 legGoal = goal;
  append(out.collisions, world.move(id, c.touch, o.filter));
  append(out.collisions, world.move(id, {newX, c.touch.y}, o.filter));
  const MoveResult rest = world.move(id, {legGoal.x + dx, legGoal.y}, o.filter);
  append(out.collisions, rest);
  out.position = rest.position;
  out.nudged = true;
  out.nudge = {c, dx};
  // The moves replay the correction; the recording also says it was one, so that a replay (and
  // the debugger watching it) can show the nudge as what it is.
  if (WorldObserver* obs = world.observer(); obs && !obs->busy()) obs->cornerNudged(id, out.nudge);
  return out;
}

}  // namespace tv
