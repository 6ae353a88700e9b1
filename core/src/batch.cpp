#include "tv/batch.hpp"

#include <algorithm>
#include <string>

#include "tv/error.hpp"

namespace tv {

namespace {

constexpr std::string_view kWhere = "tv::Batch::step";

std::uint64_t pairKey(std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{static_cast<std::uint32_t>(a)} << 32) | static_cast<std::uint32_t>(b);
}

// A static obstacle crossed by a body: (body, other slot), in the same key space but tagged.
std::uint64_t staticKey(std::size_t body, std::uint32_t slot) {
  return 0x8000000000000000ull | (std::uint64_t{static_cast<std::uint32_t>(body)} << 32) | slot;
}

}  // namespace

BatchOutcome Batch::outcome(std::size_t i) const {
  const Body& b = bodies_.at(i);
  return {b.rect.position(), std::span<const Collision>(collisions_).subspan(b.first, b.count)};
}

void Batch::step(World& world, std::span<const BatchMove> moves, Filter filter, int maxEvents) {
  if (WorldObserver* o = world.observer(); o && !o->busy()) [[unlikely]] {
    const WorldObserver::Scope scope(*o);
    const WorldObserver::Watched watched{filter, *o};
    try {
      step(world, moves, Filter(watched), maxEvents);
    } catch (...) {
      o->failed();
      throw;
    }
    o->batchStepped(moves, maxEvents, *this);
    return;
  }
  // Validate everything before changing anything.
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const Rect r = world.rect(moves[i].item);  // throws on unknown or removed items
    requireFinite(kWhere, "goal.x", moves[i].goal.x);
    requireFinite(kWhere, "goal.y", moves[i].goal.y);
    requireInRange(kWhere, "goal.x", moves[i].goal.x);
    requireInRange(kWhere, "goal.y", moves[i].goal.y);
    if (!world.grid().fits(r.at(moves[i].goal))) {
      fail(kWhere, "goal {" + formatNumber(moves[i].goal.x) + ", " + formatNumber(moves[i].goal.y) +
                       "} is too far from the origin for the world's cell size");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (moves[j].item == moves[i].item) {
        fail(kWhere, "item index " + std::to_string(moves[i].item.index) + " appears twice");
      }
    }
  }
  if (maxEvents < 1) fail(kWhere, "maxEvents must be >= 1, but was " + std::to_string(maxEvents));

  bodies_.clear();
  events_.clear();
  owner_.clear();
  crossed_.clear();
  order_.clear();
  startRects_.clear();
  for (const BatchMove& m : moves) {
    bodies_.push_back({m.item, world.rect(m.item), m.goal});
    startRects_.push_back(bodies_.back().rect);
    order_.push_back(world.order(m.item));
    if (bodyBySlot_.size() <= m.item.index) bodyBySlot_.resize(m.item.index + 1, kNoBody);
    bodyBySlot_[m.item.index] = static_cast<std::uint32_t>(bodies_.size() - 1);
  }
  // Forget the slots again however this step ends (the map is kept to reuse its memory).
  struct Unmap {
    Batch& batch;
    ~Unmap() {
      for (const Body& b : batch.bodies_) batch.bodyBySlot_[b.item.index] = kNoBody;
    }
  } unmap{*this};
  const auto bodyOf = [&](ItemId id) -> std::size_t {
    return id.index < bodyBySlot_.size() && bodyBySlot_[id.index] != kNoBody ? bodyBySlot_[id.index]
                                                                             : bodies_.size();
  };
  // Events at the same instant run in add order (statics before pairs), and a pair is swept
  // from its earlier-added side: the outcome never depends on the order of `moves`.
  struct EventKey {
    bool pair = false;
    std::uint64_t first = 0, second = 0;
  };
  const auto ahead = [](double u, const EventKey& k, double bestU, const EventKey& best) {
    if (u != bestU) return u < bestU;
    if (k.pair != best.pair) return !k.pair;
    return k.first != best.first ? k.first < best.first : k.second < best.second;
  };
  const auto crossed = [&](std::uint64_t key) {
    return std::find(crossed_.begin(), crossed_.end(), key) != crossed_.end();
  };
  // Against the world, bodies see only what is not in the batch (bodies meet by relative
  // motion below) and not already crossed.
  std::size_t asking = 0;
  const auto staticFilter = [&](ItemId item, ItemId other) -> ResponseId {
    if (bodyOf(other) != bodies_.size() || crossed(staticKey(asking, other.index))) {
      return response::ignore;
    }
    return filter(item, other);
  };

  // A throw part way (a filter answer that is not a response) puts every body back.
  try {
    bool finished = false;
    for (int e = 0; e < maxEvents; ++e) {
      // The earliest event over the rest of the tick; u is the fraction of what remains.
      double bestU = 2.0;
      EventKey bestKey;
      std::size_t bi = 0, bj = 0;
      bool pair = false;
      Collision bestStatic;
      Sweep bestSweep;
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const Body& b = bodies_[i];
        if (b.goal == b.rect.position()) continue;
        asking = i;
        const MoveResult r =
            world.check(b.item, b.goal, Filter(staticFilter), {BroadPhase::swept, nullptr, 1});
        if (r.collisions.empty()) continue;
        const double u = std::max(r.collisions.front().ti, 0.0);
        const EventKey key{false, order_[i], world.order(r.collisions.front().other)};
        if (ahead(u, key, bestU, bestKey)) {
          bestU = u;
          bestKey = key;
          bi = i;
          pair = false;
          bestStatic = r.collisions.front();
        }
      }
      // Pairs whose remaining hulls meet, found by sweeping the hulls sorted by their left edge
      // instead of testing all N² pairs; the earliest event is the least of a strict order
      // (time, then the pair's add orders), so the order pairs are visited in does not matter.
      hulls_.clear();
      byX_.clear();
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        hulls_.push_back(unite(bodies_[k].rect, bodies_[k].rect.at(bodies_[k].goal)));
        byX_.push_back(static_cast<std::uint32_t>(k));
      }
      std::sort(byX_.begin(), byX_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return hulls_[a].x != hulls_[b].x ? hulls_[a].x < hulls_[b].x : a < b;
      });
      for (std::size_t p = 0; p < byX_.size(); ++p) {
        const Rect& hp = hulls_[byX_[p]];
        for (std::size_t q = p + 1; q < byX_.size() && hulls_[byX_[q]].x < hp.right(); ++q) {
          const std::size_t i0 = std::min(byX_[p], byX_[q]), j0 = std::max(byX_[p], byX_[q]);
          if (!overlaps(hulls_[i0], hulls_[j0]) || crossed(pairKey(i0, j0))) continue;
          const bool swap = order_[j0] < order_[i0];
          const std::size_t i = swap ? j0 : i0, j = swap ? i0 : j0;
          const Body& a = bodies_[i];
          const Body& b = bodies_[j];
          if (filter(a.item, b.item) == response::ignore &&
              filter(b.item, a.item) == response::ignore) {
            continue;
          }
          const Vec2 da = a.goal - a.rect.position(), db = b.goal - b.rect.position();
          const Sweep s = sweepRect(a.rect, a.rect.position() + (da - db), b.rect);
          if (s.kind == SweepKind::miss) continue;
          const double u = std::max(s.ti, 0.0);
          const EventKey key{true, order_[i], order_[j]};
          if (ahead(u, key, bestU, bestKey)) {
            bestU = u;
            bestKey = key;
            bi = i;
            bj = j;
            pair = true;
            bestSweep = s;
          }
        }
      }
      if (bestU > 1.0) {
        finished = true;
        break;
      }

      // Everyone not in the event advances to its instant.
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        if (k == bi || (pair && k == bj)) continue;
        Body& b = bodies_[k];
        const Vec2 p = b.rect.position() + (b.goal - b.rect.position()) * bestU;
        b.rect = b.rect.at(p);
        world.update(b.item, b.rect);
      }

      if (!pair) {
        Body& b = bodies_[bi];
        const Leg next = world.respond(bestStatic, b.goal);
        bestStatic.target = next.goal;
        events_.push_back(bestStatic);
        owner_.push_back(bi);
        if (next.passThrough) crossed_.push_back(staticKey(bi, bestStatic.other.index));
        b.rect = b.rect.at(next.start);
        b.goal = next.goal;
        world.update(b.item, b.rect);
        continue;
      }

      // Mover meets mover: j advances; i is placed against j's new edges exactly.
      Body& a = bodies_[bi];
      Body& b = bodies_[bj];
      const Vec2 da = a.goal - a.rect.position(), db = b.goal - b.rect.position();
      const Rect aStart = a.rect, bStart = b.rect;
      const Rect bAt = b.rect.at(b.rect.position() + db * bestU);
      Vec2 pa = a.rect.position() + da * bestU;
      if (bestSweep.normal.x < 0) pa.x = placeBefore(bAt.x, a.rect.w);
      if (bestSweep.normal.x > 0) pa.x = bAt.right();
      if (bestSweep.normal.y < 0) pa.y = placeBefore(bAt.y, a.rect.h);
      if (bestSweep.normal.y > 0) pa.y = bAt.bottom();
      a.rect = a.rect.at(pa);
      b.rect = bAt;
      const auto record = [&](Body& self, std::size_t selfIndex, const Body& other, Vec2 normal,
                              Vec2 move, const Rect& selfStart, const Rect& otherStart) {
        Collision c;
        c.item = self.item;
        c.other = other.item;
        c.overlaps = bestSweep.kind == SweepKind::overlap;
        c.corner = bestSweep.corner;
        c.ti = bestSweep.ti;
        c.move = move;
        c.normal = normal;
        c.touch = self.rect.position();
        c.itemRect = selfStart;
        c.otherRect = otherStart;
        c.response = filter(self.item, other.item);
        if (c.response == response::ignore) return true;  // this side is not told
        const Leg next = world.respond(c, self.goal);
        c.target = next.goal;
        events_.push_back(c);
        owner_.push_back(selfIndex);
        self.rect = self.rect.at(next.start);
        self.goal = next.goal;
        return next.passThrough;
      };
      const bool passA = record(a, bi, b, bestSweep.normal, da, aStart, bStart);
      const bool passB = record(b, bj, a, bestSweep.normal * -1.0, db, bStart, aStart);
      // A side that does not yield would push into the other at the same instant forever: once
      // either side passes through, the pair is done for this tick.
      if (passA || passB) crossed_.push_back(pairKey(bi, bj));
      world.update(a.item, a.rect);
      world.update(b.item, b.rect);
    }

    for (Body& b : bodies_) {
      if (finished) b.rect = b.rect.at(b.goal);  // out of events: everyone stays where they are
      world.update(b.item, b.rect);
    }
  } catch (...) {
    for (std::size_t k = 0; k < bodies_.size(); ++k) world.update(bodies_[k].item, startRects_[k]);
    throw;
  }

  // Group the events by body, keeping time order.
  collisions_.clear();
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    bodies_[k].first = collisions_.size();
    for (std::size_t e = 0; e < events_.size(); ++e)
      if (owner_[e] == k) collisions_.push_back(events_[e]);
    bodies_[k].count = collisions_.size() - bodies_[k].first;
  }
}

}  // namespace tv
