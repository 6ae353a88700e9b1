#include "tv/batch.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <initializer_list>
#include <string>

#include "batch_hull_grid.hpp"
#include "tv/error.hpp"

namespace tv {

namespace {

constexpr std::string_view kWhere = "tv::Batch::step";
constexpr std::uint32_t kNoBody = 0xFFFFFFFFu;

std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

// A static obstacle crossed by a body: (body, other slot), in the same key space but tagged.
std::uint64_t staticKey(std::uint32_t body, std::uint32_t slot) {
  return 0x8000000000000000ull | (std::uint64_t{body} << 32) | slot;
}

// The pairs (and body–static pairs) that crossed: excluded for the rest of the tick. Open
// addressing, kept between steps; most ticks insert nothing, and then a lookup is one branch.
class KeySet {
 public:
  void clear() {
    if (size_ == 0) return;
    std::fill(keys_.begin(), keys_.end(), kEmpty);
    size_ = 0;
  }
  [[nodiscard]] bool contains(std::uint64_t k) const {
    if (size_ == 0) return false;
    for (std::size_t i = slotOf(k);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == k) return true;
      if (keys_[i] == kEmpty) return false;
    }
  }
  void insert(std::uint64_t k) {
    if ((size_ + 1) * 2 > keys_.size()) {
      std::vector<std::uint64_t> old(std::max<std::size_t>(16, keys_.size() * 2), kEmpty);
      old.swap(keys_);
      size_ = 0;
      for (const std::uint64_t o : old)
        if (o != kEmpty) place(o);
    }
    place(k);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~0ull;  // no body index reaches 2^31 - 1 with slot ~0
  [[nodiscard]] std::size_t slotOf(std::uint64_t k) const {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 32) & (keys_.size() - 1);
  }
  void place(std::uint64_t k) {
    std::size_t i = slotOf(k);
    while (keys_[i] != kEmpty) {
      if (keys_[i] == k) return;
      i = (i + 1) & (keys_.size() - 1);
    }
    keys_[i] = k;
    ++size_;
  }
  std::vector<std::uint64_t> keys_;
  std::size_t size_ = 0;
};

// A body's position at time t on its path: it left `start` at t0 and reaches `goal` at t = 1.
Vec2 pathAt(const Rect& start, Vec2 goal, double t0, double t) {
  const Vec2 p = start.position();
  if (t == t0 || goal == p) return p;
  return p + (goal - p) * ((t - t0) / (1.0 - t0));
}

// An event waiting in the queue. It is stale once either body's version moved on.
struct Event {
  double t = 0;                         // absolute, in [0, 1]
  std::uint64_t first = 0, second = 0;  // add orders of the two sides: the tie-break
  std::uint32_t a = 0, b = 0;           // bodies (a pair: a was added first)
  std::uint32_t va = 0, vb = 0;         // their versions when it was found
  bool pair = false;
};

// The queue's order, as a "runs after" for a min-heap: time, then statics before pairs, then
// the sides' add orders. Valid events never compare equal, so which one runs first is never
// left to the order they were found in.
struct RunsAfter {
  bool operator()(const Event& x, const Event& y) const {
    if (x.t != y.t) return x.t > y.t;
    if (x.pair != y.pair) return x.pair;
    if (x.first != y.first) return x.first > y.first;
    return x.second > y.second;
  }
};

}  // namespace

// [SECTION] the search --------------------------------------------------------------------------

struct Batch::Search {
  // Per step.
  World* world = nullptr;
  const Filter* filter = nullptr;
  std::vector<Body>* bodies = nullptr;

  // Per body.
  std::vector<std::uint64_t> order;  // add order: the tie-break
  std::vector<Rect> start;           // where it began, to undo a step whose last write fails
  std::vector<Collision> staticHit;  // its first static hit, for its current version
  std::vector<Rect> clear;           // a hull that meets no static it may hit (or empty)
  std::vector<Rect> hulls;           // its loose hull, while building the grid
  std::vector<std::uint32_t> visit;  // the bodies in spatial order (see BatchHullGrid)
  std::vector<std::uint32_t> seen;   // the validation's duplicate check, by slot
  std::uint32_t seenEpoch = 0;
  std::vector<std::uint32_t> bodyBySlot;  // world slot -> body, kNoBody for the rest

  std::vector<Collision> events;  // raw, in the order they ran, with the body in `owner`
  std::vector<std::uint32_t> owner;
  std::vector<std::size_t> counts;
  std::vector<Event> queue;  // a heap by RunsAfter
  KeySet crossed;
  detail::BatchHullGrid grid;
  std::uint32_t asking = 0;  // the body whose static hit is being searched

  struct PairSweep {
    bool hit = false;
    std::uint32_t a = 0, b = 0;  // a added first: the pair is swept from a's side
    double from = 0, t = 0;      // the later of their paths' starts; the event's instant
    Vec2 pa, pb;                 // their positions at `from`
    Sweep sweep;
  };

  Body& body(std::uint32_t i) { return (*bodies)[i]; }

  void push(const Event& e) {
    queue.push_back(e);
    std::push_heap(queue.begin(), queue.end(), RunsAfter{});
  }

  [[nodiscard]] bool stale(const Event& e) {
    if (body(e.a).version != e.va) return true;
    return e.pair && body(e.b).version != e.vb;
  }

  // The path's bounding box, loosened (so its own rounding does not matter).
  static Rect looseHull(const Body& b) {
    const double x0 = std::min(b.rect.x, b.goal.x), y0 = std::min(b.rect.y, b.goal.y);
    const double x1 = std::max(b.rect.x, b.goal.x) + b.rect.w;
    const double y1 = std::max(b.rect.y, b.goal.y) + b.rect.h;
    return detail::BatchHullGrid::loosen({x0, y0, x1 - x0, y1 - y0});
  }

  // Against the world, bodies see only what is not in the batch (bodies meet by relative
  // motion below) and not already crossed.
  [[nodiscard]] ResponseId staticAnswer(ItemId other) const {
    if (other.index < bodyBySlot.size() && bodyBySlot[other.index] != kNoBody) {
      return response::ignore;
    }
    if (crossed.contains(staticKey(asking, other.index))) return response::ignore;
    return (*filter)((*bodies)[asking].item, other);
  }

  // Body i's first static hit along its current path, queued.
  void findStatic(std::uint32_t i) {
    const Body& b = body(i);
    if (b.goal == b.rect.position()) return;
    asking = i;
    const auto answer = [this](ItemId, ItemId other) { return staticAnswer(other); };
    // Nothing that could stop it meets the path's hull (no item outside the batch that it has
    // not crossed): no hit, decided without the sweep and without asking the filter — which is
    // asked only about what the sweep below hits, in its order, so that its questions do not
    // depend on the order the world's cells list their items in. A hull inside one already
    // found clear is clear too (what may stop a body can only shrink as pairs cross), and a
    // slide or touch keeps a body inside its first hull.
    const Rect hull = unite(b.rect, b.rect.at(b.goal));
    const Rect& was = clear[i];
    if (hull.x >= was.x && hull.y >= was.y && hull.right() <= was.right() &&
        hull.bottom() <= was.bottom()) {
      return;
    }
    const auto mayStop = [this](ItemId, ItemId other) {
      const bool body = other.index < bodyBySlot.size() && bodyBySlot[other.index] != kNoBody;
      return body || crossed.contains(staticKey(asking, other.index)) ? response::ignore
                                                                      : response::slide;
    };
    if (!world->anyOverlap(hull, {}, Filter(mayStop))) {
      clear[i] = hull;
      return;
    }
    const MoveResult r =
        world->project(b.rect, b.goal, Filter(answer), {BroadPhase::swept, nullptr, 1});
    if (r.collisions.empty()) return;
    Collision c = r.collisions.front();
    c.item = b.item;
    staticHit[i] = c;
    const double t = b.t0 + std::max(c.ti, 0.0) * (1.0 - b.t0);
    push({t, order[i], world->order(c.other), i, 0, b.version, 0, false});
  }

  // The pair, earlier-added side first, where both are when their current paths both begin.
  [[nodiscard]] PairSweep pairStart(std::uint32_t i, std::uint32_t j) {
    PairSweep p;
    p.a = order[i] < order[j] ? i : j;
    p.b = p.a == i ? j : i;
    const Body& a = body(p.a);
    const Body& b = body(p.b);
    p.from = std::max(a.t0, b.t0);
    p.pa = pathAt(a.rect, a.goal, a.t0, p.from);
    p.pb = pathAt(b.rect, b.goal, b.t0, p.from);
    return p;
  }

  // The pair's relative sweep over the part of the tick both current paths share.
  [[nodiscard]] PairSweep sweepPair(std::uint32_t i, std::uint32_t j) {
    PairSweep p = pairStart(i, j);
    const Body& a = body(p.a);
    const Body& b = body(p.b);
    p.sweep =
        sweepRect(a.rect.at(p.pa), p.pa + ((a.goal - p.pa) - (b.goal - p.pb)), b.rect.at(p.pb));
    p.hit = p.sweep.kind != SweepKind::miss;
    p.t = p.from + std::max(p.sweep.ti, 0.0) * (1.0 - p.from);
    return p;
  }

  // Queues the pair's next event, if its remaining hulls meet, it did not cross, and one side
  // at least does not ignore the other.
  void findPair(std::uint32_t i, std::uint32_t j) {
    if (crossed.contains(pairKey(i, j))) return;
    const PairSweep p = pairStart(i, j);
    const Body& a = body(p.a);
    const Body& b = body(p.b);
    const Rect ra = a.rect.at(p.pa), rb = b.rect.at(p.pb);
    if (!overlaps(unite(ra, a.rect.at(a.goal)), unite(rb, b.rect.at(b.goal)))) return;
    if ((*filter)(a.item, b.item) == response::ignore &&
        (*filter)(b.item, a.item) == response::ignore) {
      return;
    }
    const Sweep s = sweepRect(ra, p.pa + ((a.goal - p.pa) - (b.goal - p.pb)), rb);
    if (s.kind == SweepKind::miss) return;
    const double t = p.from + std::max(s.ti, 0.0) * (1.0 - p.from);
    push({t, order[p.a], order[p.b], p.a, p.b, a.version, b.version, true});
  }

  // The bodies in `changed` took a new path: their static hits and their pairs with every hull
  // neighbour are searched again (a pair of two changed bodies once).
  void refresh(std::initializer_list<std::uint32_t> changed) {
    for (const std::uint32_t k : changed) findStatic(k);
    for (const std::uint32_t k : changed) grid.update(k, looseHull(body(k)));
    for (auto it = changed.begin(); it != changed.end(); ++it) {
      const std::uint32_t k = *it;
      const Rect hull = looseHull(body(k));
      grid.forEachNear(k, hull, [&](std::uint32_t j) {
        if (std::find(changed.begin(), it, j) != it) return;
        if (!meets(hull, grid.registered(j))) return;
        findPair(k, j);
      });
    }
  }

  // Closed overlap: the loose hulls hold every rect the pair search derives, so hulls that do
  // not even touch cannot hold a hit.
  static bool meets(const Rect& a, const Rect& b) {
    return a.x <= b.right() && b.x <= a.right() && a.y <= b.bottom() && b.y <= a.bottom();
  }

  // A user response must hand back a leg the world can hold.
  void checkLeg(const Body& b, const Collision& c, const Leg& next) const {
    const Grid& g = world->grid();
    if (!isFinite(next.start) || !isFinite(next.goal) || !g.fits(b.rect.at(next.start)) ||
        !g.fits(b.rect.at(next.goal)) || !inRange(next.start.x) || !inRange(next.start.y) ||
        !inRange(next.goal.x) || !inRange(next.goal.y)) [[unlikely]] {
      fail(kWhere, "response '" + std::string(world->responseName(c.response)) +
                       "' returned the leg {" + formatNumber(next.start.x) + ", " +
                       formatNumber(next.start.y) + "} -> {" + formatNumber(next.goal.x) + ", " +
                       formatNumber(next.goal.y) +
                       "}, which is not finite or too far from the origin (beyond 2^500 or the "
                       "grid)");
    }
  }

  void takeLeg(std::uint32_t i, double t, const Leg& next) {
    Body& b = body(i);
    b.rect = b.rect.at(next.start);
    b.goal = next.goal;
    b.t0 = t;
  }

  void runStatic(const Event& e) {
    Body& b = body(e.a);
    Collision c = staticHit[e.a];
    const Leg next = world->respond(c, b.goal);
    checkLeg(b, c, next);
    c.target = next.goal;
    events.push_back(c);
    owner.push_back(e.a);
    if (next.passThrough) crossed.insert(staticKey(e.a, c.other.index));
    takeLeg(e.a, e.t, next);
    ++b.version;
    refresh({e.a});
  }

  // Mover meets mover: b advances to the instant; a is placed against b's new edges exactly.
  void runPair(const Event& e) {
    const PairSweep p = sweepPair(e.a, e.b);
    assert(p.hit && p.t == e.t);
    Body& a = body(p.a);
    Body& b = body(p.b);
    const Sweep& s = p.sweep;
    const Rect aStart = a.rect.at(p.pa), bStart = b.rect.at(p.pb);
    const Vec2 da = a.goal - p.pa, db = b.goal - p.pb;
    const Rect bAt = b.rect.at(pathAt(b.rect, b.goal, b.t0, e.t));
    Vec2 pa = pathAt(a.rect, a.goal, a.t0, e.t);
    if (s.normal.x < 0) pa.x = placeBefore(bAt.x, a.rect.w);
    if (s.normal.x > 0) pa.x = bAt.right();
    if (s.normal.y < 0) pa.y = placeBefore(bAt.y, a.rect.h);
    if (s.normal.y > 0) pa.y = bAt.bottom();
    a.rect = a.rect.at(pa);
    a.t0 = e.t;
    b.rect = bAt;
    b.t0 = e.t;
    const auto record = [&](std::uint32_t self, const Body& other, Vec2 normal, Vec2 move,
                            const Rect& selfStart, const Rect& otherStart) {
      Body& me = body(self);
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
      c.response = (*filter)(me.item, other.item);
      if (c.response == response::ignore) return true;  // this side is not told
      const Leg next = world->respond(c, me.goal);
      checkLeg(me, c, next);
      c.target = next.goal;
      events.push_back(c);
      owner.push_back(self);
      takeLeg(self, e.t, next);
      return next.passThrough;
    };
    const bool passA = record(p.a, b, s.normal, da, aStart, bStart);
    const bool passB = record(p.b, a, s.normal * -1.0, db, bStart, aStart);
    // A side that does not yield would push into the other at the same instant forever: once
    // either side passes through, the pair is done for this tick.
    if (passA || passB) crossed.insert(pairKey(p.a, p.b));
    ++a.version;
    ++b.version;
    refresh({p.a, p.b});
  }

  // Runs the tick's events; false when maxEvents ran out first, with `last` the instant of the
  // last one that ran.
  bool run(int maxEvents, double& last) {
    hulls.clear();
    for (const Body& b : *bodies) hulls.push_back(looseHull(b));
    grid.build(hulls);
    grid.spatialOrder(visit);
    for (const std::uint32_t i : visit) findStatic(i);
    for (const std::uint32_t i : visit) {
      grid.forEachNear(i, [&](std::uint32_t j) {
        if (j > i && meets(hulls[i], hulls[j])) findPair(i, j);
      });
    }
    int ran = 0;
    while (!queue.empty()) {
      const Event e = queue.front();
      if (stale(e)) {
        std::pop_heap(queue.begin(), queue.end(), RunsAfter{});
        queue.pop_back();
        continue;
      }
      if (ran == maxEvents) return false;
      std::pop_heap(queue.begin(), queue.end(), RunsAfter{});
      queue.pop_back();
      ++ran;
      last = e.t;
      if (e.pair) {
        runPair(e);
      } else {
        runStatic(e);
      }
    }
    return true;
  }
};

Batch::SearchPtr::~SearchPtr() {
  delete p_;
}

Batch::Search& Batch::SearchPtr::get() {
  if (p_ == nullptr) p_ = new Search;
  return *p_;
}

// [SECTION] the step ----------------------------------------------------------------------------

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
  Search& s = search_.get();
  // Validate everything before changing anything.
  if (++s.seenEpoch == 0) {
    std::fill(s.seen.begin(), s.seen.end(), 0u);
    s.seenEpoch = 1;
  }
  s.start.clear();
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const Rect r = world.rect(moves[i].item);  // throws on unknown or removed items
    s.start.push_back(r);
    requireFinite(kWhere, "goal.x", moves[i].goal.x);
    requireFinite(kWhere, "goal.y", moves[i].goal.y);
    requireInRange(kWhere, "goal.x", moves[i].goal.x);
    requireInRange(kWhere, "goal.y", moves[i].goal.y);
    if (!world.grid().fits(r.at(moves[i].goal))) {
      fail(kWhere, "goal {" + formatNumber(moves[i].goal.x) + ", " + formatNumber(moves[i].goal.y) +
                       "} is too far from the origin for the world's cell size");
    }
    const std::uint32_t slot = moves[i].item.index;
    if (s.seen.size() <= slot) s.seen.resize(slot + 1, 0u);
    if (s.seen[slot] == s.seenEpoch) {
      fail(kWhere, "item index " + std::to_string(slot) + " appears twice");
    }
    s.seen[slot] = s.seenEpoch;
  }
  if (maxEvents < 1) fail(kWhere, "maxEvents must be >= 1, but was " + std::to_string(maxEvents));

  bodies_.clear();
  s.world = &world;
  s.filter = &filter;
  s.bodies = &bodies_;
  s.order.clear();
  s.events.clear();
  s.owner.clear();
  s.queue.clear();
  s.crossed.clear();
  s.staticHit.resize(moves.size());
  s.clear.assign(moves.size(), Rect{0, 0, -1, -1});  // contains nothing
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const BatchMove& m = moves[i];
    bodies_.push_back({m.item, s.start[i], m.goal});
    s.order.push_back(world.order(m.item));
    if (s.bodyBySlot.size() <= m.item.index) s.bodyBySlot.resize(m.item.index + 1, kNoBody);
    s.bodyBySlot[m.item.index] = static_cast<std::uint32_t>(bodies_.size() - 1);
  }
  // Forget the slots again however this step ends (the map is kept to reuse its memory).
  struct Unmap {
    Batch& batch;
    Search& s;
    ~Unmap() {
      for (const Body& b : batch.bodies_) s.bodyBySlot[b.item.index] = kNoBody;
    }
  } unmap{*this, s};

  // Nothing is written into the world until the paths are final, so a throw part way (a
  // filter answer that is not a response) leaves it as it was; a last write that fails puts
  // back those made before it.
  double last = 0;
  const bool finished = s.run(maxEvents, last);
  for (Body& b : bodies_) {
    // Out of events: everyone stays where they are at the last event's instant.
    b.rect = b.rect.at(finished ? b.goal : pathAt(b.rect, b.goal, b.t0, last));
  }
  std::size_t written = 0;
  try {
    for (std::size_t k = 0; k < bodies_.size(); ++k, ++written) {
      // A body that ends exactly (bit for bit: -0 is not 0 in a state hash) where it began
      // leaves the world as it is.
      const Rect& r = bodies_[k].rect;
      const Rect& was = s.start[k];
      if (std::bit_cast<std::uint64_t>(r.x) == std::bit_cast<std::uint64_t>(was.x) &&
          std::bit_cast<std::uint64_t>(r.y) == std::bit_cast<std::uint64_t>(was.y)) {
        continue;
      }
      world.update(bodies_[k].item, r);
    }
  } catch (...) {
    for (std::size_t k = 0; k < written; ++k) world.update(bodies_[k].item, s.start[k]);
    throw;
  }

  // Group the events by body, keeping time order.
  s.counts.assign(bodies_.size() + 1, 0);
  for (const std::uint32_t k : s.owner) ++s.counts[k + 1];
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    s.counts[k + 1] += s.counts[k];
    bodies_[k].first = s.counts[k];
    bodies_[k].count = s.counts[k + 1] - s.counts[k];
  }
  collisions_.resize(s.events.size());
  for (std::size_t e = 0; e < s.events.size(); ++e)
    collisions_[s.counts[s.owner[e]]++] = s.events[e];
}

}  // namespace tv
