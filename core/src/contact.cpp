// Contact events and ground state (tv/contact.hpp): a body's contacts are read from the world as
// it stands (a query just wider than the body, then exact edge tests), merged in add order with
// the previous update's, so that begin / persist / end come out in one deterministic order.

#include "tv/contact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tv/error.hpp"
#include "tv/world.hpp"

namespace tv {

namespace {

constexpr std::string_view kWhere = "tv::Contacts";

// The normal of a contact between `a` (the body) and `b`, or nullopt-like {NaN} when they do not
// touch. Resting is taken as the core's contact places a body: its far edge on the edge bit for
// bit, or one rounding step short of it (placeBefore), so a body the core put there is always in
// contact with what it rests on.
bool contactNormal(const Rect& a, const Rect& b, Vec2& n) {
  if (overlaps(a, b)) {
    n = {0, 0};
    return true;
  }
  const bool xOverlap = a.x < b.right() && b.x < a.right();
  const bool yOverlap = a.y < b.bottom() && b.y < a.bottom();
  if (xOverlap) {
    if (a.bottom() == b.y || a.y == placeBefore(b.y, a.h)) {
      n = {0, -1};
      return true;
    }
    if (a.y == b.bottom()) {
      n = {0, 1};
      return true;
    }
  }
  if (yOverlap) {
    if (a.right() == b.x || a.x == placeBefore(b.x, a.w)) {
      n = {-1, 0};
      return true;
    }
    if (a.x == b.right()) {
      n = {1, 0};
      return true;
    }
  }
  return false;
}

bool listed(std::span<const ItemId> items, ItemId id) {
  return std::find(items.begin(), items.end(), id) != items.end();
}

}  // namespace

Contacts::Body* Contacts::find(ItemId item) {
  if (item.index >= bodies_.size()) return nullptr;
  Body& b = bodies_[item.index];
  return b.tracked && b.id == item ? &b : nullptr;
}

const Contacts::Body* Contacts::find(ItemId item) const {
  return const_cast<Contacts*>(this)->find(item);
}

std::span<const ContactEvent> Contacts::update(const World& world, ItemId item,
                                               const ContactOptions& o,
                                               std::span<const Collision> met) {
  if (!world.has(item)) {
    fail(kWhere, "update: item {index=" + std::to_string(item.index) +
                     ", generation=" + std::to_string(item.generation) + "} is not in the world");
  }
  if (o.coyoteUpdates < 0 || o.coyoteUpdates > (1 << 20)) {
    fail(kWhere, "coyoteUpdates must be in [0, 2^20], but was " + std::to_string(o.coyoteUpdates));
  }
  const Rect a = world.rect(item);

  // Candidates: every item the body's rect, grown by far more than a rounding step, overlaps.
  // The exact test below keeps only contacts. The query is part of this call, not one of the
  // game's (a recorder attached to the world does not see it).
  const double margin = (std::fabs(a.x) + std::fabs(a.y) + a.w + a.h) * 0x1p-40 + 0x1p-1000;
  const Rect wide{a.x - margin, a.y - margin, a.w + 2 * margin, a.h + 2 * margin};
  if (WorldObserver* obs = world.observer()) {
    const WorldObserver::Scope quiet(*obs);
    world.queryRect(wide, found_, item);
  } else {
    world.queryRect(wide, found_, item);
  }

  next_.clear();
  for (const ItemId other : found_) {
    const Rect b = world.rect(other);
    Vec2 n;
    if (!contactNormal(a, b, n)) continue;
    const ResponseId r = o.filter(item, other);
    if (r == response::ignore) continue;
    next_.push_back({{item, other, ContactPhase::begin, n, false},
                     b,
                     world.order(other),
                     r == response::cross});
  }
  // Met in passing: a contact of this update even if it no longer touches (a crossed coin).
  for (const Collision& c : met) {
    if (!world.has(c.other) || c.other == item) continue;
    const bool already = std::any_of(next_.begin(), next_.end(),
                                     [&](const Touch& t) { return t.event.other == c.other; });
    if (already) continue;
    next_.push_back({{item, c.other, ContactPhase::begin, c.normal, true},
                     world.rect(c.other),
                     world.order(c.other),
                     true});
  }
  std::sort(next_.begin(), next_.end(),
            [](const Touch& x, const Touch& y) { return x.order < y.order; });

  if (item.index >= bodies_.size()) bodies_.resize(item.index + 1);
  Body& body = bodies_[item.index];
  if (!body.tracked || body.id != item) body = Body{item, {}, {}, {}, true, {}, false};

  // Merge the previous contacts (add order) with the new ones (add order).
  events_.clear();
  Vec2 groundVelocity;
  const Touch* ground = nullptr;
  double groundOverlap = 0;
  std::size_t i = 0;
  for (Touch& t : next_) {
    while (i < body.touches.size() && body.touches[i].order < t.order) {
      ContactEvent e = body.touches[i++].event;
      e.phase = ContactPhase::end;
      events_.push_back(e);
    }
    const Touch* before = nullptr;
    if (i < body.touches.size() && body.touches[i].order == t.order) before = &body.touches[i++];
    t.event.phase = before ? ContactPhase::persist : ContactPhase::begin;
    events_.push_back(t.event);
    if (t.event.normal.y == -1 && !t.crossed && !t.event.met) {
      const double overlap =
          std::min(a.right(), t.otherRect.right()) - std::max(a.x, t.otherRect.x);
      if (!ground || overlap > groundOverlap) {
        ground = &t;
        groundOverlap = overlap;
        groundVelocity =
            before ? Vec2{t.otherRect.x - before->otherRect.x, t.otherRect.y - before->otherRect.y}
                   : Vec2{};
      }
    }
  }
  while (i < body.touches.size()) {
    ContactEvent e = body.touches[i++].event;
    e.phase = ContactPhase::end;
    events_.push_back(e);
  }

  Ground& g = body.ground;
  if (ground) {
    const ItemId gi = ground->event.other;
    g = {listed(o.solids, gi)   ? GroundKind::solid
         : listed(o.oneWay, gi) ? GroundKind::oneWay
                                : GroundKind::ground,
         gi,
         {0, -1},
         groundVelocity,
         0};
    body.lastGround = gi;
    body.jumped = false;
  } else {
    const int inAir = g.updatesInAir + 1;
    const bool coyote = body.lastGround.valid() && !body.jumped && inAir <= o.coyoteUpdates;
    g = {coyote ? GroundKind::coyote : GroundKind::air,
         coyote ? body.lastGround : ItemId{},
         {0, 0},
         {0, 0},
         std::min(inAir, 1 << 30)};
  }

  body.touches.swap(next_);
  body.view.clear();
  for (const Touch& t : body.touches) body.view.push_back(t.event);
  return events_;
}

std::span<const ContactEvent> Contacts::forget(ItemId item) {
  events_.clear();
  if (Body* b = find(item)) {
    for (const Touch& t : b->touches) {
      ContactEvent e = t.event;
      e.phase = ContactPhase::end;
      events_.push_back(e);
    }
    *b = Body{};
  }
  return events_;
}

Ground Contacts::ground(ItemId item) const {
  const Body* b = find(item);
  return b ? b->ground : Ground{};
}

void Contacts::jumped(ItemId item) {
  if (Body* b = find(item)) {
    b->jumped = true;
    if (b->ground.kind == GroundKind::coyote)
      b->ground = {GroundKind::air, {}, {0, 0}, {0, 0}, b->ground.updatesInAir};
  }
}

std::span<const ContactEvent> Contacts::current(ItemId item) const {
  const Body* b = find(item);
  return b ? std::span<const ContactEvent>(b->view) : std::span<const ContactEvent>();
}

}  // namespace tv
