#include "tv/world.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <utility>

#include "hit_order.hpp"
#include "spatial_hash.hpp"
#include "tv/error.hpp"

namespace tv {

namespace {

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::string describe(const Rect& r) {
  return "{x=" + formatNumber(r.x) + ", y=" + formatNumber(r.y) + ", w=" + formatNumber(r.w) +
         ", h=" + formatNumber(r.h) + "}";
}

bool withinMagnitude(Vec2 p) {
  return inRange(p.x) && inRange(p.y);
}

std::string describe(ItemId id) {
  return "{index=" + std::to_string(id.index) + ", generation=" + std::to_string(id.generation) +
         "}";
}

constexpr std::string_view kAdd = "tv::World::add";
constexpr std::string_view kUpdate = "tv::World::update";
constexpr std::string_view kMove = "tv::World::move";

// Runs `call` as an outermost observed call: what it calls inside is part of it, user code's
// answers are reported as they come, and `report` sees the result once the call has succeeded.
template <class Call, class Report>
decltype(auto) observed(WorldObserver& o, Call&& call, Report&& report) {
  const WorldObserver::Scope scope(o);
  try {
    if constexpr (std::is_void_v<decltype(call())>) {
      call();
      report();
    } else {
      decltype(auto) result = call();
      report(result);
      return result;
    }
  } catch (...) {
    o.failed();
    throw;
  }
}

}  // namespace

namespace {
double checkedCellSize(double cellSize) {
  requirePositive("tv::World", "cellSize", cellSize);
  // Cells below 2^-485 only hold coordinates below 2^-433, where exactness may round
  // (geometry.hpp); at 5e-324, 1 / cellSize is infinite and every rect would be refused.
  if (!(cellSize >= 0x1p-485 && cellSize <= kMaxMagnitude)) {
    fail("tv::World", "cellSize must be in [2^-485, 2^500] (about 1e-146 to 3.27e150), but was " +
                          formatNumber(cellSize));
  }
  return cellSize;
}
}  // namespace

World::World(double cellSize) : grid_(checkedCellSize(cellSize)), hash_(cellSize) {
  // The built-ins, from their one table, at their ids.
  responses_.reserve(response::kBuiltinCount);
  for (const ResponseDef& d : kBuiltinResponses) responses_.push_back({std::string(d.name), d.fn});
}

World::Hash::Hash(double cellSize) : p_(new detail::SpatialHash(cellSize)) {}
World::Hash::Hash(const Hash& other) : p_(new detail::SpatialHash(*other.p_)) {}
World::Hash::Hash(Hash&& other) noexcept : p_(std::exchange(other.p_, nullptr)) {}
World::Hash& World::Hash::operator=(const Hash& other) {
  if (this == &other) return *this;
  if (p_ == nullptr) {  // moved from: assignable again, as a world of vectors would be
    p_ = new detail::SpatialHash(*other.p_);
  } else {
    *p_ = *other.p_;
  }
  return *this;
}
World::Hash& World::Hash::operator=(Hash&& other) noexcept {
  std::swap(p_, other.p_);
  return *this;
}
World::Hash::~Hash() {
  delete p_;
}

// [SECTION] validation --------------------------------------------------------------------------

void World::refuseItem(ItemId id, std::string_view where) const {
  fail(where, "item " + describe(id) + " is not in the world (never added, or removed)");
}

void World::refuseRect(const Rect& r, std::string_view where) const {
  requireFinite(where, "x", r.x);
  requireFinite(where, "y", r.y);
  requirePositive(where, "w", r.w);
  requirePositive(where, "h", r.h);
  if (!std::isfinite(r.right()) || !std::isfinite(r.bottom()) || !grid_.fits(r)) {
    fail(where, "rect " + describe(r) + " is too far from the origin for cell size " +
                    formatNumber(grid_.cellSize()));
  }
  requireInRange(where, "x", r.x);
  requireInRange(where, "y", r.y);
  requireInRange(where, "w", r.w);
  requireInRange(where, "h", r.h);
  // A size below half an ulp of the coordinate leaves no interior: nothing could ever hit it.
  if (!(r.right() > r.x)) {
    fail(where, "w=" + formatNumber(r.w) + " is below the resolution of x=" + formatNumber(r.x) +
                    ": x + w rounds to x, leaving the rect no interior");
  }
  if (!(r.bottom() > r.y)) {
    fail(where, "h=" + formatNumber(r.h) + " is below the resolution of y=" + formatNumber(r.y) +
                    ": y + h rounds to y, leaving the rect no interior");
  }
  // An item is registered in every cell it meets: refuse one that would fill memory.
  const CellRange c = grid_.cellsOf(r);
  const double cells = static_cast<double>(c.x1 - c.x0 + 1) * static_cast<double>(c.y1 - c.y0 + 1);
  if (cells > kMaxItemCells) {
    fail(where, "rect " + describe(r) + " spans " + formatNumber(cells) + " cells of size " +
                    formatNumber(grid_.cellSize()) + "; at most 2^24 (choose a larger cell size)");
  }
}

void World::refuseGoal(const Rect& r, Vec2 goal, std::string_view where) const {
  requireFinite(where, "goal.x", goal.x);
  requireFinite(where, "goal.y", goal.y);
  const Rect g = r.at(goal);
  if (!std::isfinite(g.right()) || !std::isfinite(g.bottom()) || !grid_.fits(g)) {
    fail(where, "goal {" + formatNumber(goal.x) + ", " + formatNumber(goal.y) +
                    "} is too far from the origin for cell size " + formatNumber(grid_.cellSize()));
  }
  requireInRange(where, "goal.x", goal.x);
  requireInRange(where, "goal.y", goal.y);
}

void World::refuseOptions(const MoveOptions& o, std::string_view where) const {
  fail(where, "maxResponses must be in [1, 4096], but was " + std::to_string(o.maxResponses));
}

// [SECTION] items -------------------------------------------------------------------------------

ItemId World::add(const Rect& r) {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { return add(r); }, [&](ItemId id) { observer_->added(id, r); });
  }
  validateRect(r, kAdd);
  std::uint32_t index;
  if (!freeSlots_.empty()) {
    index = freeSlots_.back();
    freeSlots_.pop_back();
  } else {
    index = newSlot();
  }
  return fill(index, r);
}

ItemId World::addAtGenerationForTesting(const Rect& r, std::uint32_t generation) {
  validateRect(r, kAdd);
  const std::uint32_t index = newSlot();
  slots_[index].generation = generation;
  return fill(index, r);
}

std::uint32_t World::newSlot() {
  if (slots_.size() >= detail::HashEntry::kShared) fail(kAdd, "the world holds 2^31 items already");
  const auto index = static_cast<std::uint32_t>(slots_.size());
  slots_.emplace_back();
  orders_.push_back(0);
  stamp_.push_back(0);
  return index;
}

ItemId World::fill(std::uint32_t index, const Rect& r) {
  Slot& s = slots_[index];
  s.rect = r;
  orders_[index] = nextOrder_++;
  s.alive = true;
  hash_->insert(index, s.generation, r);
  addExtent(r);
  ++count_;
  return {index, s.generation};
}

void World::remove(ItemId id) {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { remove(id); }, [&] { observer_->removed(id); });
  }
  slot(id, "tv::World::remove");
  Slot& s = slots_[id.index];
  hash_->erase(id.index);
  dropExtent(s.rect);
  s.alive = false;
  // A generation that wrapped would make the oldest handles of this slot valid again: a slot
  // whose generations are used up is retired (never reused) instead.
  if (s.generation != kLastGeneration) {
    ++s.generation;
    freeSlots_.push_back(id.index);
  }
  --count_;
}

void World::update(ItemId id, const Rect& r) {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { update(id, r); }, [&] { observer_->updated(id, r); });
  }
  slot(id, kUpdate);
  validateRect(r, kUpdate);
  place(id.index, r);
}

void World::place(std::uint32_t index, const Rect& r) {
  Slot& s = slots_[index];
  hash_->update(index, r);
  if (r.w != s.rect.w || r.h != s.rect.h) {
    dropExtent(s.rect);
    addExtent(r);
  }
  s.rect = r;
}

void World::update(ItemId id, Vec2 position) {
  update(id, slot(id, kUpdate).rect.at(position));
}

bool World::has(ItemId id) const {
  return id.valid() && id.index < slots_.size() && slots_[id.index].alive &&
         slots_[id.index].generation == id.generation;
}

Rect World::rect(ItemId id) const {
  return slot(id, "tv::World::rect").rect;
}

std::uint64_t World::order(ItemId id) const {
  slot(id, "tv::World::order");
  return orders_[id.index];
}

double World::minExtent() const {
  return extents_.empty() ? 0.0 : extents_.begin()->first;
}

void World::addExtent(const Rect& r) {
  ++extents_[std::min(r.w, r.h)];
}

void World::dropExtent(const Rect& r) {
  const auto it = extents_.find(std::min(r.w, r.h));
  assert(it != extents_.end());
  if (--it->second == 0) extents_.erase(it);
}

Cell World::toCell(Vec2 p) const {
  constexpr std::string_view where = "tv::World::toCell";
  requireFinite(where, "x", p.x);
  requireFinite(where, "y", p.y);
  if (!grid_.fits({p.x, p.y, 0, 0})) {
    fail(where, "point {" + formatNumber(p.x) + ", " + formatNumber(p.y) +
                    "} is too far from the origin for cell size " + formatNumber(grid_.cellSize()));
  }
  return grid_.cellAt(p);
}

ItemId World::idAt(std::uint32_t slot) const {
  if (slot >= slots_.size() || !slots_[slot].alive) {
    fail("tv::World::idAt", "slot " + std::to_string(slot) + " holds no item (the world has " +
                                std::to_string(slots_.size()) + " slots)");
  }
  return {slot, slots_[slot].generation};
}

// [SECTION] spatial hash ------------------------------------------------------------------------

std::size_t World::countCells() const {
  return hash_->occupiedCells();
}

void World::visitOccupiedCells(void (*fn)(void*, Cell, std::size_t), void* ctx) const {
  hash_->forEachOccupiedCell([&](Cell c, std::size_t n) { fn(ctx, c, n); });
}

std::vector<std::uint32_t> World::cellItems(Cell c) const {
  std::vector<std::uint32_t> out;
  for (const detail::HashEntry& e : hash_->items(c)) out.push_back(e.slot());
  return out;
}

std::size_t World::memoryBytes() const {
  std::size_t bytes =
      hash_->memoryBytes() + slots_.capacity() * sizeof(Slot) +
      freeSlots_.capacity() * sizeof(std::uint32_t) + stamp_.capacity() * sizeof(std::uint32_t) +
      orders_.capacity() * sizeof(std::uint64_t) + collisions_.capacity() * sizeof(Collision) +
      (excluded_.capacity() + queryScratch_.capacity() + overlapping_.capacity()) *
          sizeof(std::uint32_t) +
      hits_.capacity() * sizeof(Hit) + candidates_.capacity() * sizeof(Candidate) +
      responses_.capacity() * sizeof(NamedResponse);
  // A std::map node: the value and three pointers and a colour, rounded up by the allocator.
  bytes += extents_.size() * (sizeof(std::pair<const double, std::size_t>) + 4 * sizeof(void*));
  return bytes;
}

std::uint32_t World::nextEpoch() const {
  if (++epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    epoch_ = 1;
  }
  return epoch_;
}

// [SECTION] moving ------------------------------------------------------------------------------

template <class F>
void World::forEachCandidate(std::uint32_t self, const Rect& r, Vec2 goal, const Rect& hull,
                             BroadPhase broad, MoveTrace* trace, F&& f) const {
  const std::uint32_t epoch = nextEpoch();
  if (self != ItemId::kNone) stamp_[self] = epoch;
  const detail::SpatialHash& hash = *hash_;
  const auto visit = [&](Cell c) {
    if (trace) trace->cells.push_back(c);
    for (const detail::HashEntry& e : hash.items(c)) {
      const std::uint32_t slot = e.slot();
      if (e.shared() || slot == self) {
        if (stamp_[slot] == epoch) continue;
        stamp_[slot] = epoch;
      }
      f(slot, e.generation, e.rect);
    }
  };
  // Nothing lies outside the cells that ever held an item: both walks are clipped to them.
  const CellRange box = hash.live(grid_.cellsOf(hull));
  // The swept walk pays only where it skips cells of the bounding box: not along an axis (the
  // hull is the box), nor when the box spans a few cells (it would skip one or two, for more
  // arithmetic than those cost to scan).
  constexpr std::int64_t kDirectCells = 4;
  const bool alongAnAxis = goal.x == r.x || goal.y == r.y;
  if (broad == BroadPhase::swept && box.count() > kDirectCells && !alongAnAxis) {
    grid_.forEachSweptCell(r, goal, visit, hash.liveBox());
  } else {
    Grid::forEachCell(box, visit);
  }
}

namespace {

// Collision order: overlaps (deepest first, ti is minus the area), then the exact time of
// impact, then ordinary hits before exact corner hits, then add order.
// The separating-axis test of a diagonal leg against an obstacle, along the leg's normal.
class Slant {
 public:
  Slant(const Rect& r, Vec2 goal) : nx_(goal.y - r.y), ny_(r.x - goal.x) {
    active_ = nx_ != 0.0 && ny_ != 0.0;
    if (active_) shadow(r, lo_, hi_);
  }
  [[nodiscard]] bool separates(const Rect& o) const {
    if (!active_) return false;
    double lo = 0.0, hi = 0.0;
    shadow(o, lo, hi);
    // Each projection is two products and a sum, each rounded: a few ulps of the largest term.
    const double scale =
        std::max(std::fabs(lo), std::fabs(hi)) + std::max(std::fabs(lo_), std::fabs(hi_));
    const double slack = (scale + (std::fabs(o.x) + std::fabs(o.right())) * std::fabs(nx_) +
                          (std::fabs(o.y) + std::fabs(o.bottom())) * std::fabs(ny_)) *
                         0x1p-48;
    return hi < lo_ - slack || lo > hi_ + slack;
  }

 private:
  void shadow(const Rect& q, double& lo, double& hi) const {
    const double ax = q.x * nx_, bx = q.right() * nx_, ay = q.y * ny_, by = q.bottom() * ny_;
    lo = std::min(ax, bx) + std::min(ay, by);
    hi = std::max(ax, bx) + std::max(ay, by);
  }
  double nx_, ny_;
  bool active_ = false;
  double lo_ = 0.0, hi_ = 0.0;
};

}  // namespace

void World::refuseAnswer(ResponseId resp) {
  fail(kMove, "filter returned response " + std::to_string(resp) + ", which is not registered");
}

inline ResponseId World::ask(ItemId self, ItemId other, Filter filter, MoveTrace* trace) const {
  const ResponseId resp = filter(self, other);
  if (trace) trace->answers.push_back({other, resp});
  if (resp != response::ignore && resp >= responses_.size()) [[unlikely]] refuseAnswer(resp);
  return resp;
}

template <class Visit>
bool World::firstHitAmong(ItemId self, const Rect& r, Vec2 goal, Filter filter, bool known,
                          MoveTrace* trace, Collision& best, Visit&& visit) const {
  // Only what meets the leg's bounding box (by its exact edges) can be hit: four compares
  // before the exact test.
  const Rect g = r.at(goal);
  const Box legBox{std::min(r.x, g.x), std::min(r.y, g.y), std::max(r.right(), g.right()),
                   std::max(r.bottom(), g.bottom())};
  // A diagonal leg sweeps a hexagon, not its bounding box: an obstacle beyond a slanted side is
  // separated along the leg's normal n, on which the moving rect's shadow never changes. One
  // interval test rejects it before the exact sweep; it rejects only by more than the rounding
  // of the projections, so it never drops a hit.
  const Slant slant(r, goal);
  hits_.clear();
  visit([&](std::uint32_t other, std::uint32_t generation, const Rect& otherRect,
            ResponseId answer) {
    const ItemId otherId{other, generation};
    if (trace) trace->candidates.push_back(otherId);
    if (answer == response::ignore && known) return;
    if (!legBox.meets(otherRect) || slant.separates(otherRect)) return;
    if (!excluded_.empty() &&
        std::find(excluded_.begin(), excluded_.end(), other) != excluded_.end()) {
      return;
    }
    const Sweep s = sweepRect(r, goal, otherRect);
    if (s.kind == SweepKind::miss) return;
    hits_.push_back({s, otherRect, otherId, answer});
  });
  // The hits are put in one order that depends on them alone — their rounded times, then exact
  // corners last, then add order — and, where the filter's answers are not known yet, it is
  // asked about each that would lead at its turn: so the pairs asked do not depend on the order
  // the candidates came in (the cells' walk, a restored world's cells), and a recording's
  // answers serve a replay. The leader is still chosen on exact times; near-ties in the rounded
  // order only mean one more pair asked. Add order breaks ties only, so the slots' orders (a
  // cache miss each) are read only then.
  if (hits_.size() > 1) {
    std::sort(hits_.begin(), hits_.end(), [&](const Hit& a, const Hit& b) {
      if (a.sweep.ti != b.sweep.ti) return a.sweep.ti < b.sweep.ti;
      if (a.sweep.corner != b.sweep.corner) return !a.sweep.corner;
      return orders_[a.id.index] < orders_[b.id.index];
    });
  }
  const Hit* lead = nullptr;
  ResponseId leadResponse = response::ignore;
  for (const Hit& h : hits_) {
    if (lead != nullptr &&
        !detail::hitBefore(r, goal, h.sweep, h.rect, lead->sweep, lead->rect,
                           [&] { return orders_[h.id.index] < orders_[lead->id.index]; })) {
      continue;
    }
    ResponseId resp = h.answer;
    if (!known) {
      // Asked once a move: a short move's first read, or an earlier leg, may have asked.
      resp = answered(h.id.index);
      if (resp == kUnasked) {
        resp = ask(self, h.id, filter, trace);
        candidates_.push_back({h.rect, h.id.index, h.id.generation, resp});
      }
    }
    if (resp == response::ignore) continue;
    lead = &h;
    leadResponse = resp;
  }
  if (lead == nullptr) return false;
  best.item = self;
  best.other = lead->id;
  best.overlaps = lead->sweep.kind == SweepKind::overlap;
  best.corner = lead->sweep.corner;
  best.ti = lead->sweep.ti;
  best.move = goal - r.position();
  best.normal = lead->sweep.normal;
  best.touch = lead->sweep.touch;
  best.itemRect = r;
  best.otherRect = lead->rect;
  best.response = leadResponse;
  return true;
}


bool World::firstHit(ItemId self, const Rect& r, Vec2 goal, Filter filter, BroadPhase broad,
                     MoveTrace* trace, Collision& best) const {
  const Rect hull = unite(r, r.at(goal));
  return firstHitAmong(self, r, goal, filter, false, trace, best, [&](const auto& f) {
    forEachCandidate(self.index, r, goal, hull, broad, trace,
                     [&](std::uint32_t slot, std::uint32_t generation, const Rect& rect) {
                       f(slot, generation, rect, kUnasked);
                     });
  });
}

void World::sweepLeg(std::uint32_t self, const Rect& r, Vec2 goal, BroadPhase broad,
                     std::vector<Collision>& out) const {
  // The candidates and the tests a move's leg makes (firstHit, firstHitAmong): the cells the
  // broad phase walks, the leg's box by its exact edges, the slanted sides, the exact sweep.
  const Rect g = r.at(goal);
  const Box legBox{std::min(r.x, g.x), std::min(r.y, g.y), std::max(r.right(), g.right()),
                   std::max(r.bottom(), g.bottom())};
  const Slant slant(r, goal);
  forEachCandidate(self, r, goal, unite(r, g), broad, nullptr,
                   [&](std::uint32_t other, std::uint32_t generation, const Rect& otherRect) {
                     if (!legBox.meets(otherRect) || slant.separates(otherRect)) return;
                     const Sweep s = sweepRect(r, goal, otherRect);
                     if (s.kind == SweepKind::miss) return;
                     Collision& c = out.emplace_back();
                     c.other = {other, generation};
                     c.overlaps = s.kind == SweepKind::overlap;
                     c.corner = s.corner;
                     c.ti = s.ti;
                     c.move = goal - r.position();
                     c.normal = s.normal;
                     c.touch = s.touch;
                     c.target = s.touch;
                     c.itemRect = r;
                     c.otherRect = otherRect;
                   });
}

ResponseId World::answered(std::uint32_t slot) const {
  // What this move asked already: a short move's first read, and the hits of earlier legs.
  for (const Candidate& c : candidates_)
    if (c.slot == slot) return c.answer;
  return kUnasked;
}

inline World::Reach World::reach(std::uint32_t self, const Rect& to, const Box& box) const {
  const detail::SpatialHash& hash = *hash_;
  stayed_ = self != ItemId::kNone && hash.staysInCells(self, to);
  if (stayed_) return {Reach::own, {}};
  // By the grid alone (not by which cells are occupied now, which depends on history), so that
  // which pairs the filter is asked about does not depend on it either.
  const CellRange cells = grid_.cellsHolding(box.x0, box.y0, box.x1, box.y1);
  if (cells.count() > kReachCells) return {Reach::walk, {}};
  // Items are registered in the cells their half-open extent meets, so an item whose interior
  // meets the box shares one of the cells the half-open box meets.
  return {Reach::box, hash.live(cells)};
}

template <class F>
void World::forEachInReach(const Reach& reach, std::uint32_t self, const Box& box,
                           MoveTrace* trace, F&& f) const {
  const detail::SpatialHash& hash = *hash_;
  // Each item whose interior meets the box, once: an item in several of the cells is listed in
  // each, and is taken from the first only.
  const auto take = [&](const detail::HashEntry& e) {
    if (!box.meets(e.rect)) return false;
    const std::uint32_t slot = e.slot();
    if (slot == self) return false;
    if (e.shared()) {
      for (const Candidate& c : candidates_)
        if (c.slot == slot) return false;
    }
    f(slot, e.generation, e.rect);
    return false;
  };
  if (reach.kind == Reach::own) {
    // The box lies in the cells the item is registered in: read them without finding them.
    if (trace) hash.forEachCellOf(self, [&](Cell c) { trace->cells.push_back(c); });
    (void)hash.anyInOwnCells(self, take);
  } else {
    if (trace) Grid::forEachCell(reach.cells, [&](Cell c) { trace->cells.push_back(c); });
    (void)hash.anyIn(reach.cells, take);
  }
}

MoveResult World::run(ItemId self, const Rect& r, Vec2 goal, Filter filter,
                      const MoveOptions& o) const {
  MoveTrace* trace = activeTrace(o.trace);
  collisions_.clear();
  excluded_.clear();
  candidates_.clear();
  if (trace) {
    trace->item = self;
    trace->start = r;
    trace->goal = goal;
  }
  // A short move (its bounding box meets at most kReachCells cells) reads those cells once (the
  // cells its item is in, when its goal stays in them), lists the items whose interior meets
  // the box and asks the filter about each, in slot order, before anything is swept. A move
  // that meets nothing the filter keeps ends there. Every leg that stays inside the box (the
  // legs of the built-in responses do, but a bounce's or a push out of an overlap the move
  // starts in may not) is swept against the kept ones. A leg that leaves the box, and every leg
  // of a longer move, walks the cells of that leg and asks the filter about its hits in the
  // order they happen (firstHitAmong), once about each pair in a move. Which pairs are asked,
  // in which order, follows from the world's items and the move alone — not from the order the
  // cells list their items in, not from which cells were ever occupied, not from a trace.
  const Rect to = r.at(goal);
  const Box box{std::min(r.x, to.x), std::min(r.y, to.y), std::max(r.right(), to.right()),
                std::max(r.bottom(), to.bottom())};
  const Reach near = reach(self.index, to, box);
  if (near.kind != Reach::walk) {
    forEachInReach(near, self.index, box, trace,
                   [&](std::uint32_t slot, std::uint32_t generation, const Rect& rect) {
                     candidates_.push_back({rect, slot, generation, kUnasked});
                   });
    // In slot order (by insertion when they are few, as they mostly are).
    const auto bySlot = [](const Candidate& a, const Candidate& b) { return a.slot < b.slot; };
    if (candidates_.size() > 16) {
      std::sort(candidates_.begin(), candidates_.end(), bySlot);
    } else {
      for (std::size_t i = 1; i < candidates_.size(); ++i) {
        const Candidate c = candidates_[i];
        std::size_t j = i;
        for (; j > 0 && bySlot(c, candidates_[j - 1]); --j) candidates_[j] = candidates_[j - 1];
        candidates_[j] = c;
      }
    }
    bool kept = false;
    for (Candidate& c : candidates_) {
      c.answer = ask(self, {c.slot, c.generation}, filter, trace);
      kept = kept || c.answer != response::ignore;
    }
    if (!kept) {
      // Nothing it may meet: the move ends at its goal.
      if (trace) {
        trace->legs.push_back({r, goal});
        trace->final = goal;
      }
      return {goal, {}};
    }
  }
  return legs(self, r, goal, filter, o, near.kind != Reach::walk ? &box : nullptr, trace);
}

MoveResult World::legs(ItemId self, const Rect& r, Vec2 goal, Filter filter,
                       const MoveOptions& o, const Box* listed, MoveTrace* trace) const {
  Vec2 start = r.position();
  // The last leg start known to be outside everything the move did not start in: a contact
  // placed from an obstacle's edge is; a push out of an overlap may land in a neighbour.
  Vec2 safe = start;
  Collision& c = hit_;  // firstHit fills every field but target, for each leg
  for (int i = 0;; ++i) {
    if (i == o.maxResponses) {
      goal = safe;  // out of responses (acute pockets, bouncing in a slot): stop where safe
      break;
    }
    const Rect leg = r.at(start);
    if (trace) trace->legs.push_back({leg, goal});
    const bool hit =
        listed != nullptr && listed->holds(leg, goal)
            ? firstHitAmong(self, leg, goal, filter, true, trace, c,
                            [&](const auto& f) {
                              for (const Candidate& k : candidates_)
                                f(k.slot, k.generation, k.rect, k.answer);
                            })
            : firstHit(self, leg, goal, filter, o.broad, trace, c);
    if (!hit) break;
    const Leg next = respond(c, goal);
    // A response of the user's must hand back a leg the world can sweep: refuse it before
    // anything moves, naming the response.
    if (!isFinite(next.start) || !isFinite(next.goal) || !grid_.fits(r.at(next.start)) ||
        !grid_.fits(r.at(next.goal)) || !withinMagnitude(next.start) || !withinMagnitude(next.goal))
        [[unlikely]] {
      fail(kMove, "response '" + std::string(responseName(c.response)) + "' returned the leg {" +
                      formatNumber(next.start.x) + ", " + formatNumber(next.start.y) + "} -> {" +
                      formatNumber(next.goal.x) + ", " + formatNumber(next.goal.y) +
                      "}, which is not finite or too far from the origin (beyond 2^500 or the "
                      "grid)");
    }
    c.target = next.goal;
    collisions_.push_back(c);
    if (trace) trace->hits.push_back(c);
    if (next.passThrough) excluded_.push_back(c.other.index);
    start = next.start;
    goal = next.goal;
    if (!c.overlaps) safe = start;
  }
  if (trace) trace->final = goal;
  return {goal, collisions_};
}

MoveResult World::check(ItemId id, Vec2 goal, Filter filter, const MoveOptions& options) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    const WorldObserver::Watched watched{filter, *observer_};
    return observed(
        *observer_, [&] { return check(id, goal, Filter(watched), options); },
        [&](const MoveResult& r) { observer_->checked(id, goal, options, r); });
  }
  const Slot& s = slot(id, "tv::World::check");
  validateGoal(s.rect, goal, "tv::World::check");
  validateOptions(options, "tv::World::check");
  if (options.semantics == MoveSemantics::bump) return bumpRun(id.index, s.rect, goal, filter, options);
  return run(id, s.rect, goal, filter, options);
}

MoveResult World::move(ItemId id, Vec2 goal, Filter filter, const MoveOptions& options) {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    const WorldObserver::Watched watched{filter, *observer_};
    return observed(
        *observer_, [&] { return move(id, goal, Filter(watched), options); },
        [&](const MoveResult& r) { observer_->moved(id, goal, options, r); });
  }
  const Slot& s = slot(id, kMove);
  validateGoal(s.rect, goal, kMove);
  validateOptions(options, kMove);
  if (options.semantics == MoveSemantics::bump) {
    const MoveResult result = bumpRun(id.index, s.rect, goal, filter, options);
    place(id.index, s.rect.at(result.position));
    return result;
  }
  const Rect from = s.rect;
  const MoveResult result = run(id, from, goal, filter, options);
  const Rect to = from.at(result.position);
  if (stayed_ && result.collisions.empty()) {
    // It ended at its goal, in the cells it is registered in: rewrite its entries in place.
    hash_->rewrite(id.index, to);
    slots_[id.index].rect = to;
  } else {
    place(id.index, to);  // every leg was checked as it was made
  }
  return result;
}

MoveResult World::project(const Rect& r, Vec2 goal, Filter filter,
                          const MoveOptions& options) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    const WorldObserver::Watched watched{filter, *observer_};
    return observed(
        *observer_, [&] { return project(r, goal, Filter(watched), options); },
        [&](const MoveResult& m) { observer_->projected(r, goal, options, m); });
  }
  validateRect(r, "tv::World::project");
  validateGoal(r, goal, "tv::World::project");
  validateOptions(options, "tv::World::project");
  if (options.semantics == MoveSemantics::bump) return bumpRun(ItemId::kNone, r, goal, filter, options);
  return run(ItemId{}, r, goal, filter, options);
}

// [SECTION] responses ---------------------------------------------------------------------------

ResponseId World::addResponse(std::string name, ResponseFn fn) {
  if (fn == nullptr) fail("tv::World::addResponse", "response '" + name + "' has no function");
  return addNamed({std::move(name), fn});
}

ResponseId World::addResponse(std::string name, ResponseWithContextFn fn, void* context) {
  if (fn == nullptr) fail("tv::World::addResponse", "response '" + name + "' has no function");
  return addNamed({std::move(name), nullptr, fn, context});
}

ResponseId World::addNamed(NamedResponse r) {
  constexpr std::string_view where = "tv::World::addResponse";
  if (r.name.empty()) fail(where, "name must not be empty");
  if (r.name == "ignore") {
    fail(where, "the name 'ignore' is reserved for response::ignore (responseId(\"ignore\"))");
  }
  for (const auto& k : responses_) {
    if (k.name == r.name) fail(where, "a response named '" + r.name + "' is already registered");
  }
  if (responses_.size() >= response::ignore) fail(where, "too many responses");
  responses_.push_back(std::move(r));
  const auto id = static_cast<ResponseId>(responses_.size() - 1);
  if (observer_ && !observer_->busy()) observer_->responseAdded(responses_.back().name, id);
  return id;
}

std::string_view World::responseName(ResponseId id) const {
  if (id == response::ignore) return "ignore";
  if (id >= responses_.size()) {
    fail("tv::World::responseName", "response " + std::to_string(id) + " is not registered");
  }
  return responses_[id].name;
}

Leg World::respond(const Collision& c, Vec2 goal) const {
  if (c.response >= responses_.size()) {
    fail("tv::World::respond", "response " + std::to_string(c.response) + " is not registered");
  }
  const NamedResponse& r = responses_[c.response];
  const Leg leg = r.withContext ? r.withContext(r.context, c, goal) : r.fn(c, goal);
  if (observer_ && c.response >= response::kBuiltinCount) [[unlikely]] {
    observer_->responded(c, goal, leg);
  }
  return leg;
}

ResponseId World::responseId(std::string_view name) const {
  for (std::size_t i = 0; i < responses_.size(); ++i) {
    if (responses_[i].name == name) return static_cast<ResponseId>(i);
  }
  if (name == "ignore") return response::ignore;
  fail("tv::World::responseId", "no response is named '" + std::string(name) + "'");
}

// [SECTION] queries -----------------------------------------------------------------------------

void World::queryRect(const Rect& r, std::vector<ItemId>& out, ItemId skip) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { queryRect(r, out, skip); },
        [&] { observer_->queriedRect(r, skip, out); });
  }
  constexpr std::string_view where = "tv::World::queryRect";
  requireFinite(where, "x", r.x);
  requireFinite(where, "y", r.y);
  requireFinite(where, "w", r.w);
  requireFinite(where, "h", r.h);
  if (r.w < 0 || r.h < 0) {
    fail(where, "w and h must be >= 0, but the rect was " + describe(r));
  }
  if (!grid_.fits(r)) fail(where, "rect " + describe(r) + " is too far from the origin");
  requireInRange(where, "x", r.x);
  requireInRange(where, "y", r.y);
  requireInRange(where, "w", r.w);
  requireInRange(where, "h", r.h);
  out.clear();
  queryScratch_.clear();
  const std::uint32_t self = has(skip) ? skip.index : ItemId::kNone;
  forEachCandidate(self, r, r.position(), r, BroadPhase::bounds, nullptr,
                   [&](std::uint32_t other, std::uint32_t, const Rect& rect) {
                     if (overlaps(r, rect)) queryScratch_.push_back(other);
                   });
  std::sort(queryScratch_.begin(), queryScratch_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return orders_[a] < orders_[b]; });
  for (const std::uint32_t k : queryScratch_) out.push_back({k, slots_[k].generation});
}

std::vector<ItemId> World::queryRect(const Rect& r, ItemId skip) const {
  std::vector<ItemId> out;
  queryRect(r, out, skip);
  return out;
}

bool World::anyOverlap(const Rect& r, ItemId skip, Filter filter) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    const WorldObserver::Watched watched{filter, *observer_};
    return observed(
        *observer_, [&] { return anyOverlap(r, skip, Filter(watched)); },
        [&](bool any) { observer_->askedOverlap(r, skip, any); });
  }
  if (!isFinite(r) || r.w < 0 || r.h < 0 || !inRange(r.x) || !inRange(r.y) || !inRange(r.w) ||
      !inRange(r.h) || !grid_.fits(r)) {
    fail("tv::World::anyOverlap",
         "rect " + describe(r) +
             " is not finite, has a negative size, or is out of range (within ±2^500, cell "
             "indices below 2^52)");
  }
  const std::uint32_t self = has(skip) ? skip.index : ItemId::kNone;
  // The items whose interior meets r are gathered first and the filter is asked about them in
  // slot order (as a move's first read asks), until one is not ignored: which pairs it is asked about then depends on the
  // world's items alone, not on the order its cells list them in (a world restored from a
  // snapshot, as a replay's keyframe, lists them in another order).
  overlapping_.clear();
  const detail::SpatialHash& hash = *hash_;
  // A small rect reads its few cells directly: items are registered in the cells their
  // half-open extent meets, and an item whose interior meets r shares one of the cells r's
  // half-open extent meets. Only an item in several cells needs a visit stamp.
  const CellRange cells = hash.live(grid_.cellsHolding(r));
  if (cells.count() <= kReachCells) {
    const std::uint32_t epoch = cells.count() > 1 ? nextEpoch() : 0;
    (void)hash.anyIn(cells, [&](const detail::HashEntry& e) {
      if (e.slot() == self || !overlaps(r, e.rect)) return false;
      if (epoch != 0 && e.shared()) {
        if (stamp_[e.slot()] == epoch) return false;
        stamp_[e.slot()] = epoch;
      }
      overlapping_.push_back(e.slot());
      return false;
    });
  } else {
    forEachCandidate(self, r, r.position(), r, BroadPhase::bounds, nullptr,
                     [&](std::uint32_t other, std::uint32_t, const Rect& rect) {
                       if (overlaps(r, rect)) overlapping_.push_back(other);
                     });
  }
  if (overlapping_.size() > 1) std::sort(overlapping_.begin(), overlapping_.end());
  for (const std::uint32_t k : overlapping_) {
    if (filter(skip, ItemId{k, slots_[k].generation}) != response::ignore) return true;
  }
  return false;
}

std::vector<ItemId> World::queryPoint(Vec2 p) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { return queryPoint(p); },
        [&](const std::vector<ItemId>& found) { observer_->queriedPoint(p, found); });
  }
  constexpr std::string_view where = "tv::World::queryPoint";
  requireFinite(where, "x", p.x);
  requireFinite(where, "y", p.y);
  if (!grid_.fits({p.x, p.y, 0, 0})) {
    fail(where, "point {" + formatNumber(p.x) + ", " + formatNumber(p.y) +
                    "} is too far from the origin for cell size " + formatNumber(grid_.cellSize()));
  }
  requireInRange(where, "x", p.x);
  requireInRange(where, "y", p.y);
  queryScratch_.clear();
  for (const detail::HashEntry& e : hash_->items(grid_.cellAt(p))) {
    if (contains(e.rect, p)) queryScratch_.push_back(e.slot());
  }
  std::sort(queryScratch_.begin(), queryScratch_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return orders_[a] < orders_[b]; });
  std::vector<ItemId> out;
  for (const std::uint32_t k : queryScratch_) out.push_back({k, slots_[k].generation});
  return out;
}

std::vector<SegmentHit> World::querySegment(Vec2 a, Vec2 b) const {
  if (observer_ && !observer_->busy()) [[unlikely]] {
    return observed(
        *observer_, [&] { return querySegment(a, b); },
        [&](const std::vector<SegmentHit>& hits) { observer_->queriedSegment(a, b, hits); });
  }
  constexpr std::string_view where = "tv::World::querySegment";
  requireFinite(where, "a.x", a.x);
  requireFinite(where, "a.y", a.y);
  requireFinite(where, "b.x", b.x);
  requireFinite(where, "b.y", b.y);
  const Rect p{a.x, a.y, 0.0, 0.0};
  if (!grid_.fits(p) || !grid_.fits(p.at(b))) {
    fail(where, "segment {" + formatNumber(a.x) + ", " + formatNumber(a.y) + "} -> {" +
                    formatNumber(b.x) + ", " + formatNumber(b.y) +
                    "} is too far from the origin for cell size " + formatNumber(grid_.cellSize()));
  }
  requireInRange(where, "a.x", a.x);
  requireInRange(where, "a.y", a.y);
  requireInRange(where, "b.x", b.x);
  requireInRange(where, "b.y", b.y);
  std::vector<SegmentHit> out;
  forEachCandidate(
      ItemId::kNone, p, b, unite(p, p.at(b)), BroadPhase::swept, nullptr,
      [&](std::uint32_t other, std::uint32_t generation, const Rect& rect) {
        const SegmentClip c = clipSegment(a, b, rect);
        if (!c.hit) return;
        out.push_back({{other, generation}, c.t0, c.t1, a + (b - a) * c.t0, a + (b - a) * c.t1});
      });
  std::sort(out.begin(), out.end(), [&](const SegmentHit& x, const SegmentHit& y) {
    if (x.t0 != y.t0) return x.t0 < y.t0;
    return orders_[x.item.index] < orders_[y.item.index];
  });
  return out;
}

// [SECTION] state -------------------------------------------------------------------------------

std::uint64_t World::stateHash() const {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto feed = [&h](std::uint64_t v) { h = mix(h ^ v) + 0x9E3779B97F4A7C15ull; };
  feed(std::bit_cast<std::uint64_t>(grid_.cellSize()));
  feed(count_);
  feed(responses_.size());
  // What the next add returns (slot, generation, add order) is part of how the world behaves.
  feed(nextOrder_);
  for (const std::uint32_t k : freeSlots_) feed((std::uint64_t{slots_[k].generation} << 32) | k);
  forEachItem([&](ItemId id, const Rect& r) {
    feed((std::uint64_t{id.generation} << 32) | id.index);
    feed(orders_[id.index]);
    feed(std::bit_cast<std::uint64_t>(r.x));
    feed(std::bit_cast<std::uint64_t>(r.y));
    feed(std::bit_cast<std::uint64_t>(r.w));
    feed(std::bit_cast<std::uint64_t>(r.h));
  });
  return h;
}

}  // namespace tv

// [SECTION] state and recording -----------------------------------------------------------------

namespace tv {

WorldState World::state() const {
  WorldState s;
  s.cellSize = grid_.cellSize();
  s.slots.reserve(slots_.size());
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const Slot& slot = slots_[i];
    s.slots.push_back({slot.alive ? slot.rect : Rect{}, slot.alive ? orders_[i] : 0,
                       slot.generation, slot.alive});
  }
  s.freeSlots = freeSlots_;
  s.nextOrder = nextOrder_;
  for (const NamedResponse& r : responses_) s.responses.push_back(r.name);
  return s;
}

void World::restore(const WorldState& s) {
  constexpr std::string_view where = "tv::World::restore";
  if (std::bit_cast<std::uint64_t>(s.cellSize) != std::bit_cast<std::uint64_t>(grid_.cellSize())) {
    fail(where, "cellSize " + formatNumber(s.cellSize) + " differs from this world's " +
                    formatNumber(grid_.cellSize()));
  }
  if (s.responses.size() != responses_.size()) {
    fail(where, "the state has " + std::to_string(s.responses.size()) + " responses, this world " +
                    std::to_string(responses_.size()) +
                    " (register the user responses first, in the same order)");
  }
  for (std::size_t i = 0; i < responses_.size(); ++i) {
    if (s.responses[i] != responses_[i].name) {
      fail(where, "response " + std::to_string(i) + " is '" + s.responses[i] + "' in the state, '" +
                      responses_[i].name + "' in this world");
    }
  }
  if (s.slots.size() >= detail::HashEntry::kShared) fail(where, "more than 2^31 slots");
  // Every check before any change: a state may come from an untrusted file.
  std::vector<std::uint64_t> orders;
  for (std::size_t i = 0; i < s.slots.size(); ++i) {
    const WorldState::Slot& slot = s.slots[i];
    if (!slot.alive) continue;
    try {
      validateRect(slot.rect, where);
    } catch (const Error& e) {
      fail(where, "slot " + std::to_string(i) + ": " + e.what());
    }
    if (slot.order >= s.nextOrder) {
      fail(where, "slot " + std::to_string(i) + " has add order " + std::to_string(slot.order) +
                      ", not below nextOrder " + std::to_string(s.nextOrder));
    }
    orders.push_back(slot.order);
  }
  std::sort(orders.begin(), orders.end());
  if (std::adjacent_find(orders.begin(), orders.end()) != orders.end()) {
    fail(where, "two items share an add order");
  }
  std::vector<bool> listed(s.slots.size(), false);
  for (const std::uint32_t k : s.freeSlots) {
    if (k >= s.slots.size() || s.slots[k].alive || listed[k]) {
      fail(where, "free slot " + std::to_string(k) + " is out of range, alive or listed twice");
    }
    listed[k] = true;
  }

  World fresh(grid_.cellSize());
  fresh.responses_ = responses_;
  fresh.slots_.resize(s.slots.size());
  fresh.orders_.assign(s.slots.size(), 0);
  fresh.stamp_.assign(s.slots.size(), 0);
  for (std::uint32_t i = 0; i < s.slots.size(); ++i) {
    const WorldState::Slot& in = s.slots[i];
    Slot& out = fresh.slots_[i];
    out.generation = in.generation;
    if (!in.alive) continue;
    out.rect = in.rect;
    fresh.orders_[i] = in.order;
    out.alive = true;
    fresh.hash_->insert(i, in.generation, in.rect);
    fresh.addExtent(in.rect);
    ++fresh.count_;
  }
  fresh.freeSlots_ = s.freeSlots;
  fresh.nextOrder_ = s.nextOrder;
  *this = std::move(fresh);  // the observer link stays this world's
}

void World::attach(WorldObserver& observer) {
  detach();
  observer_.set(&observer, this);
  try {
    observer.attached(*this);
  } catch (...) {
    observer_.set(nullptr, nullptr);
    throw;
  }
}

void World::detach() {
  WorldObserver* o = observer_.get();
  if (o == nullptr) return;
  observer_.set(nullptr, nullptr);
  o->detached(*this);
}

}  // namespace tv
