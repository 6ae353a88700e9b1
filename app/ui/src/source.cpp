// What every source shares: framing the traced move and picking the item under the cursor.
#include "tv/ui/source.hpp"

#include <algorithm>
#include <limits>

namespace tv::ui {

const char* sourceKindName(SourceKind k) {
  switch (k) {
    case SourceKind::scene:
      return "scene";
    case SourceKind::level:
      return "level";
    case SourceKind::recording:
      return "recording";
    case SourceKind::live:
      return "live game";
  }
  return "?";
}

const char* failureKindName(FailureKind k) {
  switch (k) {
    case FailureKind::tunnelled:
      return "tunnelled";
    case FailureKind::overlapping:
      return "ended inside";
    case FailureKind::snagged:
      return "snagged";
    case FailureKind::escaped:
      return "escaped";
    case FailureKind::jittered:
      return "jittered";
    case FailureKind::diverged:
      return "diverged";
    case FailureKind::busy:
      return "many responses";
    case FailureKind::dropped:
      return "dropped";
    case FailureKind::popped:
      return "popped";
  }
  return "?";
}

bool tracesAMove(CallKind k) {
  return isOneSweep(k);
}

Rect Source::followView(double minSide) const {
  Rect box;
  const auto moves = history();
  if (!moves.empty()) {
    // The last move only: earlier ones trail off the edge rather than shrink the action.
    const MoveTrace& t = moves.back().trace;
    box = unite(t.start, t.start.at(t.goal));
    box = unite(box, t.start.at(t.final));
    for (const Collision& c : t.hits) box = unite(box, c.otherRect);
  } else if (const auto id = traced(); id && world().has(*id)) {
    box = world().rect(*id);
  } else {
    return home();
  }
  const double pad = std::max(box.w, box.h) * 0.25;
  box = {box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad};
  const Vec2 c = box.center();
  const double w = std::max(box.w, minSide), h = std::max(box.h, minSide);
  return {c.x - w * 0.5, c.y - h * 0.5, w, h};
}

std::optional<ItemId> Source::itemAt(Vec2 p) {
  // What is drawn as a body (it moves, or it is traced) before what is drawn as a solid; among
  // those, the smallest: a 2 px bullet in front of the tile behind it.
  const WorldPicture pic = picture();
  std::optional<ItemId> best;
  double bestArea = std::numeric_limits<double>::infinity();
  for (const sim::Body& b : pic.bodies) {
    if (!contains(b.rect, p)) continue;
    if (b.rect.w * b.rect.h < bestArea) {
      best = b.item;
      bestArea = b.rect.w * b.rect.h;
    }
  }
  if (best) return best;
  world().forEachItem([&](ItemId id, const Rect& r) {
    if (contains(r, p) && r.w * r.h < bestArea) {
      best = id;
      bestArea = r.w * r.h;
    }
  });
  return best;
}

}  // namespace tv::ui
