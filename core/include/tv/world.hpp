#pragma once
/// The swept-AABB world, in the manner of bump.lua: items are rects in a spatial hash; `move`
/// sweeps an item towards a goal, resolves collisions with responses chosen by a filter, and
/// reports them.
///
/// Guarantees (see geometry.hpp for the tolerance model):
/// - a move never passes through anything its filter does not ignore or cross, at any speed;
/// - contact is exact: after touch or slide the item's edge equals the obstacle's edge;
/// - sliding along floors and walls made of separate tiles never catches on a seam;
/// - collisions are ordered by their exact time of impact (compared without rounding, so of
///   two faces an ulp apart the nearer comes first even when their rounded ti are equal), then
///   ordinary hits before exact corner hits, then by the order in which items were added —
///   never by address or hash order;
/// - the steady-state move path allocates nothing (buffers are kept and reused);
/// - bad input throws tv::Error naming the value and leaves the world unchanged;
/// - all of this within the range of geometry.hpp: coordinates, sizes and goals within ±2^500,
///   cell sizes in [2^-485, 2^500], rects with an interior; beyond it input is refused.
/// Not thread-safe: queries reuse internal scratch buffers.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/grid.hpp"
#include "tv/item.hpp"
#include "tv/observer.hpp"
#include "tv/response.hpp"
#include "tv/sweep.hpp"
#include "tv/trace.hpp"

namespace tv {

namespace detail {
class SpatialHash;
}

/// Which cells a move's broad phase visits.
enum class BroadPhase : std::uint8_t {
  swept,   ///< only the cells the moving rect crosses: cost follows path length
  bounds,  ///< every cell of the move's bounding box, as bump.lua does
};

/// Whose rules a move, check or project follows.
enum class MoveSemantics : std::uint8_t {
  tunnelvision,  ///< the core's (above): exact sweep, any number of visits, add-order ties
  /// bump.lua 3.1.7's, for games written against it (tv/bump.hpp): its collision tests, order,
  /// responses and `visited` rule. `broad` and `maxResponses` do not apply (every item is met at
  /// most once, which bounds a move).
  bump,
};

/// How World::move, check and project search, trace and stop.
struct MoveOptions {
  BroadPhase broad = BroadPhase::swept;  ///< which cells are searched (default: the path's)
  MoveTrace* trace = nullptr;  ///< optional record of what the move did
  /// Responses per move before the item stops where it is (acute pockets, bounce between
  /// walls closer than the move). Range [1, 4096].
  int maxResponses = 64;
  MoveSemantics semantics = MoveSemantics::tunnelvision;  ///< whose rules (default: the core's)
};

/// What a move did: where the item ended and what it met on the way.
struct MoveResult {
  Vec2 position;  ///< where the item ends (its goal if nothing was hit)
  /// Collisions in the order the responses ran; valid until the next call on the world.
  std::span<const Collision> collisions;
};

/// Everything that decides how a world behaves next: its items with their handles and add
/// order, the free slots (what the next add returns) and the responses' names. What a recording
/// opens with, and what a replay seeks to.
struct WorldState {
  /// One slot of the world: a live item, or a free (or retired) slot.
  struct Slot {
    Rect rect;                     ///< alive slots only
    std::uint64_t order = 0;       ///< add order, alive slots only
    std::uint32_t generation = 0;  ///< the live item's, or the next one for a free slot
    bool alive = false;            ///< holds a live item
  };
  double cellSize = 64.0;  ///< the world's cell size, world units
  std::vector<Slot> slots;  ///< by slot index
  std::vector<std::uint32_t>
      freeSlots;                       ///< reused from the back; a dead slot not listed is retired
  std::uint64_t nextOrder = 0;         ///< add order of the next add
  std::vector<std::string> responses;  ///< response names by ResponseId, built-ins first
};

/// An item whose open interior meets a query segment, with where the segment enters and exits.
struct SegmentHit {
  ItemId item;  ///< the item crossed
  /// @name Entry and exit times
  /// @{
  double t0 = 0.0, t1 = 0.0;  ///< along the segment, 0 at its start and 1 at its end
  /// @}
  /// @name Entry and exit points
  /// @{
  Vec2 entry, exit;  ///< where the segment enters and leaves the interior, world units
  /// @}
};

/// Items (axis-aligned rects) in a spatial hash, moved by exact sweeps with responses, and
/// queried — bump.lua's world, with exact contact and no tunnelling.
///
///     tv::World world(32);
///     tv::ItemId floor = world.add({0, 200, 640, 16});
///     tv::ItemId player = world.add({40, 180, 10, 13.7});
///     tv::MoveResult r = world.move(player, {43.5, 190});   // slides along the floor
///
/// Every call checks its input and throws tv::Error naming the bad value (an unknown item, a
/// NaN, a rect out of range), changing nothing. A World is not thread-safe: its queries share
/// scratch buffers, so one thread at a time.
class World {
 public:
  /// `cellSize`: side of a spatial-hash cell in world units, in [2^-485, 2^500] ≈ [1e-146,
  /// 3.27e150] (the range of geometry.hpp). Default 64.
  /// A size near the typical item or tile size keeps candidates per move low.
  explicit World(double cellSize = 64.0);

  // -- items ---------------------------------------------------------------------------------
  /// Adds a rect and returns its handle. The rect must be finite with w > 0 and h > 0, every
  /// field within ±2^500 (geometry.hpp), with an interior (x + w > x and y + h > y once
  /// rounded), cell indices below 2^52, and meet at most 2^24 cells.
  ItemId add(const Rect& r);
  /// Removes the item; its handle is never valid again. A slot is reused by later adds with a
  /// new generation, up to 2^32 − 1 times, then retired (a few bytes that are never reused).
  void remove(ItemId id);
  /// Testing only: `add` into a new slot whose generation starts at `generation`, so that the
  /// retirement of a slot near 2^32 removes can be tested without 2^32 iterations.
  ItemId addAtGenerationForTesting(const Rect& r, std::uint32_t generation);
  /// Teleports (and may resize) an item; no collision is checked.
  void update(ItemId id, const Rect& r);
  /// Teleports an item, keeping its size; no collision is checked.
  void update(ItemId id, Vec2 position);
  /// True when `id` names a live item of this world.
  [[nodiscard]] bool has(ItemId id) const;
  /// The item's rect; throws tv::Error for an id that is not live.
  [[nodiscard]] Rect rect(ItemId id) const;
  [[nodiscard]] std::size_t count() const { return count_; }  ///< live items
  /// Cells holding at least one item. An item is registered in every cell its half-open
  /// extent [x, right) × [y, bottom) meets: a tile whose right edge lies on a cell line is not
  /// in the cell beyond it. Cells are freed as they empty.
  [[nodiscard]] std::size_t countCells() const;
  /// Bytes the world holds on the heap (capacities of its items, cells and scratch buffers).
  [[nodiscard]] std::size_t memoryBytes() const;
  /// Add order of an item: the stable tie-break among collisions at the same ti.
  [[nodiscard]] std::uint64_t order(ItemId id) const;
  /// Smallest width or height among the items (0 when empty); substep movers default to half.
  [[nodiscard]] double minExtent() const;

  // -- grid ----------------------------------------------------------------------------------
  [[nodiscard]] const Grid& grid() const { return grid_; }  ///< the cell arithmetic
  [[nodiscard]] double cellSize() const { return grid_.cellSize(); }  ///< world units
  /// The cell holding `p`; throws tv::Error when p is not finite or too far out for the grid.
  [[nodiscard]] Cell toCell(Vec2 p) const;
  /// The top-left corner of a cell, world units.
  [[nodiscard]] Vec2 toWorld(Cell c) const { return grid_.origin(c); }
  /// Slots of the items registered in a cell (see idAt), empty if the cell was never used.
  [[nodiscard]] std::vector<std::uint32_t> cellItems(Cell c) const;
  /// Calls f(Cell, std::size_t itemCount) for every occupied cell, in a stable order.
  template <class F>
  void forEachOccupiedCell(F&& f) const {
    visitOccupiedCells(
        [](void* ctx, Cell c, std::size_t n) {
          (*static_cast<std::remove_reference_t<F>*>(ctx))(c, n);
        },
        const_cast<void*>(static_cast<const void*>(&f)));
  }
  /// Calls f(ItemId, const Rect&) for every item, in slot order.
  template <class F>
  void forEachItem(F&& f) const {
    for (std::uint32_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].alive) f(ItemId{i, slots_[i].generation}, slots_[i].rect);
  }
  /// Handle of the live item stored in a slot (as listed by cellItems); throws tv::Error when
  /// the slot holds no item.
  [[nodiscard]] ItemId idAt(std::uint32_t slot) const;

  // -- moving --------------------------------------------------------------------------------
  /// What `move` would do, without doing it.
  [[nodiscard]] MoveResult check(ItemId id, Vec2 goal, Filter filter = {},
                                 const MoveOptions& options = {}) const;
  /// Sweeps the item towards `goal`, applies responses, and leaves it where it ended.
  MoveResult move(ItemId id, Vec2 goal, Filter filter = {}, const MoveOptions& options = {});
  /// `check` for a rect that is not in the world (collisions carry an invalid `item`).
  [[nodiscard]] MoveResult project(const Rect& r, Vec2 goal, Filter filter = {},
                                   const MoveOptions& options = {}) const;

  /// Every hit of the one straight leg `r` → `goal`, in the order a move takes them, each with
  /// the response the filter chose: bump.lua's `World:project`, which Lua's `world:project`
  /// calls. `self` is the item the rect stands for, left out of the hits (an invalid id for a
  /// rect that is not an item); `r` need not be its rect.
  ///
  /// The hits are those a move of `r` to `goal` meets on its first leg, found as a move finds
  /// them (the cells `options.broad` walks, the exact sweep) and ordered as a move orders them:
  /// by the exact time of impact (of two faces a rounding apart, the nearer first although
  /// their rounded ti are equal), then ordinary hits before exact corner hits, then add order.
  /// So the first is the first collision of `move` and `check` with the same filter, and a move
  /// whose filter crosses everything meets them all in this order. The filter is asked once
  /// about each item hit, in that order; pairs it ignores are left out; `target` is the touch
  /// (no response has run). With `options.semantics` bump: bump.lua's rules and order
  /// (tv::bump::project). `options.trace` is not filled; `maxResponses` does not apply.
  ///
  /// `out` is cleared first and its memory reused. Not reported to an observer: a replay needs
  /// nothing from a query that changes nothing. Bad input (an id that is neither invalid nor
  /// live, a rect or goal out of range, bad options, an answer that is not a registered
  /// response) throws tv::Error naming the value, with `out` left empty.
  void hitsAlong(ItemId self, const Rect& r, Vec2 goal, Filter filter, std::vector<Collision>& out,
                 const MoveOptions& options = {}) const;

  // -- responses -----------------------------------------------------------------------------
  /// Registers a response that filters can then return. Names must be unique and non-empty,
  /// and not "ignore" (the special response::ignore).
  ResponseId addResponse(std::string name, ResponseFn fn);
  /// The same for a response that takes a context: `fn(context, collision, goal)` at every
  /// call. `context` is not owned: it must outlive the world's use of the response (a copy of
  /// the world shares it).
  ResponseId addResponse(std::string name, ResponseWithContextFn fn, void* context);
  /// The name a response was registered under ("slide"...); throws tv::Error for an unknown id.
  [[nodiscard]] std::string_view responseName(ResponseId id) const;
  /// Runs the response `c.response` on a collision: the next leg of the move.
  [[nodiscard]] Leg respond(const Collision& c, Vec2 goal) const;
  /// The response registered under `name`; throws tv::Error if there is none.
  [[nodiscard]] ResponseId responseId(std::string_view name) const;
  /// While a response runs inside a move with bump semantics: the items the move has met so far
  /// (bump's `visited`), which projections the response makes must leave out. Empty otherwise.
  [[nodiscard]] std::span<const ItemId> metThisMove() const { return bumpMet_; }

  // -- queries -------------------------------------------------------------------------------
  /// Items whose interior overlaps `r` (touching is not enough), in add order. `skip` is left
  /// out (e.g. the item asking).
  [[nodiscard]] std::vector<ItemId> queryRect(const Rect& r, ItemId skip = {}) const;
  /// The same into `out` (cleared first), reusing its memory.
  void queryRect(const Rect& r, std::vector<ItemId>& out, ItemId skip = {}) const;
  /// True when an item other than `skip` overlaps `r` and the filter does not ignore the pair
  /// (asked as filter(skip, other) about the overlapping items in the order of their handles'
  /// indices, until one is not ignored). No allocation once warm; the cheap "is this spot
  /// free?".
  [[nodiscard]] bool anyOverlap(const Rect& r, ItemId skip = {}, Filter filter = {}) const;
  /// Items containing `p` in the half-open sense [x, right) × [y, bottom), in add order.
  [[nodiscard]] std::vector<ItemId> queryPoint(Vec2 p) const;
  /// Items whose interior the segment a→b crosses, sorted along it (ties in add order).
  [[nodiscard]] std::vector<SegmentHit> querySegment(Vec2 a, Vec2 b) const;

  /// Hash of every item (handle, add order, rect bits), the free slots and next add order (what
  /// the next add returns), and the cell size: two worlds that compare equal here behave the same.
  [[nodiscard]] std::uint64_t stateHash() const;

  // -- state and recording ------------------------------------------------------------------
  /// A copy of everything that decides how the world behaves next (see WorldState).
  [[nodiscard]] WorldState state() const;
  /// Replaces every item by those of `s` (same handles, add orders and free slots), so that this
  /// world then behaves as the one `s` was taken from. `s.cellSize` must equal this world's and
  /// `s.responses` the names registered here, in order (register user responses first). `s` may
  /// come from a file: it is checked whole (finite rects, slot counts, free-slot list, orders)
  /// and refused with a tv::Error naming what is wrong, changing nothing.
  void restore(const WorldState& s);
  /// Reports every call from now on to `observer` (which first sees the world's current state),
  /// until `detach`. One observer at a time: attaching another detaches the first.
  void attach(WorldObserver& observer);
  /// Stops reporting; the observer hears `detached`.
  void detach();
  [[nodiscard]] WorldObserver* observer() const { return observer_.get(); }  ///< or null

 private:
  static constexpr std::uint32_t kLastGeneration = 0xFFFFFFFFu;

  static constexpr double kMaxItemCells = 16777216.0;  // 2^24 cells per item

  // What every call reads about an item, 40 bytes; its add order (read to break exact ties and
  // sort query results) is kept apart in orders_.
  struct Slot {
    Rect rect;
    std::uint32_t generation = 0;
    bool alive = false;
  };

  // The spatial hash (core/src/spatial_hash.hpp) by pointer, so that its storage stays out of
  // this header; copies are deep.
  class Hash {
   public:
    explicit Hash(double cellSize);
    Hash(const Hash& other);
    Hash(Hash&& other) noexcept;
    Hash& operator=(const Hash& other);
    Hash& operator=(Hash&& other) noexcept;
    ~Hash();
    detail::SpatialHash* operator->() const { return p_; }
    detail::SpatialHash& operator*() const { return *p_; }

   private:
    detail::SpatialHash* p_;
  };

  // The checks every call makes, inline for the common case; the refusals (which name the value
  // and throw tv::Error) out of line.
  const Slot& slot(ItemId id, std::string_view where) const {
    // An invalid id's index (kNone) is beyond every slot: the world holds at most 2^31.
    if (id.index >= slots_.size() || !slots_[id.index].alive ||
        slots_[id.index].generation != id.generation) [[unlikely]] {
      refuseItem(id, where);
    }
    return slots_[id.index];
  }
  void validateRect(const Rect& r, std::string_view where) const {
    // The common case in one test. Sizes within 2^500 keep every edge finite; a rect under 4000
    // cells a side spans fewer than 2^24 cells.
    if (r.w > 0.0 && r.h > 0.0 && inRange(r.x) && inRange(r.y) && inRange(r.w) && inRange(r.h) &&
        r.right() > r.x && r.bottom() > r.y && grid_.fits(r) &&
        r.w * grid_.inverse() <= 4000.0 && r.h * grid_.inverse() <= 4000.0) [[likely]] {
      return;
    }
    refuseRect(r, where);
  }
  void validateGoal(const Rect& r, Vec2 goal, std::string_view where) const {
    // The common case in one test: a finite far edge means a finite goal (w and h are finite).
    if (const Rect g = r.at(goal); std::isfinite(g.right()) && std::isfinite(g.bottom()) &&
                                   grid_.fits(g) && inRange(goal.x) && inRange(goal.y)) [[likely]] {
      return;
    }
    refuseGoal(r, goal, where);
  }
  void validateOptions(const MoveOptions& o, std::string_view where) const {
    if (o.maxResponses < 1 || o.maxResponses > 4096) [[unlikely]]
      refuseOptions(o, where);
  }
  [[noreturn]] void refuseItem(ItemId id, std::string_view where) const;
  // Throws naming what is wrong; returns when nothing is (the fast test is only a shortcut).
  void refuseRect(const Rect& r, std::string_view where) const;
  // Throws naming what is wrong; returns when nothing is (the fast test is only a shortcut).
  void refuseGoal(const Rect& r, Vec2 goal, std::string_view where) const;
  [[noreturn]] void refuseOptions(const MoveOptions& o, std::string_view where) const;

  std::uint32_t newSlot();
  ItemId fill(std::uint32_t index, const Rect& r);  // add into a free slot, validated
  void place(std::uint32_t index, const Rect& r);   // update without validation
  void visitOccupiedCells(void (*fn)(void*, Cell, std::size_t), void* ctx) const;
  void addExtent(const Rect& r);
  void dropExtent(const Rect& r);

  // A move's bounding box by its edges (not rounded out into a Rect).
  struct Box {
    double x0, y0, x1, y1;
    [[nodiscard]] bool meets(const Rect& o) const {
      return o.x < x1 && x0 < o.right() && o.y < y1 && y0 < o.bottom();
    }
    [[nodiscard]] bool holds(const Rect& r, Vec2 goal) const {
      return std::min(r.x, goal.x) >= x0 && std::min(r.y, goal.y) >= y0 &&
             std::max(r.right(), goal.x + r.w) <= x1 && std::max(r.bottom(), goal.y + r.h) <= y1;
    }
  };
  // One move of the rect `r` (the item `self`, or an invalid id for a projection): check, move
  // and project, traced or not, are this one path.
  MoveResult run(ItemId self, const Rect& r, Vec2 goal, Filter filter, const MoveOptions& o) const;
  // run's legs, once something the filter keeps may be met (apart, so that a move that meets
  // nothing pays for none of it): with `listed`, candidates_ holds every item meeting that box.
  MoveResult legs(ItemId self, const Rect& r, Vec2 goal, Filter filter, const MoveOptions& o,
                  const Box* listed, MoveTrace* trace) const;
  // Where a short move finds what it can meet: the cells its item is in (when its goal stays in
  // them: `own`), or the few cells of its box (at most kReachCells: `box`); `walk` for a longer
  // move, whose legs walk their own cells. Sets stayed_.
  static constexpr std::int64_t kReachCells = 4;
  struct Reach {
    enum Kind : std::uint8_t { walk, own, box } kind;
    CellRange cells;
  };
  Reach reach(std::uint32_t self, const Rect& to, const Box& box) const;
  // Calls f(slot, generation, const Rect&) once for each item but `self` whose interior meets
  // the box, from the cells of `reach` (not walk).
  template <class F>
  void forEachInReach(const Reach& reach, std::uint32_t self, const Box& box, MoveTrace* trace,
                      F&& f) const;
  // An item that may be hit, as the spatial hash holds it, and the filter's answer about it
  // (kUnasked until the filter is asked).
  static constexpr ResponseId kUnasked = response::ignore - 1;
  struct Candidate {
    Rect rect;
    std::uint32_t slot;
    std::uint32_t generation;
    ResponseId answer;
  };
  // The first hit of a leg among the items `visit` gives (f(slot, generation, rect, answer)):
  // with `known`, the answers are those given (the ignored are not swept); without, the filter
  // is asked about the hits in the order they happen, as far as needed to find the first kept.
  template <class Visit>
  bool firstHitAmong(ItemId self, const Rect& r, Vec2 goal, Filter filter, bool known,
                     MoveTrace* trace, Collision& best, Visit&& visit) const;
  // A leg's hit before the filter is asked about it.
  struct Hit {
    Sweep sweep;
    Rect rect;
    ItemId id;
    ResponseId answer;
  };
  // The first hit of a leg among every item the spatial hash gives for the cells it walks.
  bool firstHit(ItemId self, const Rect& r, Vec2 goal, Filter filter, BroadPhase broad,
                MoveTrace* trace, Collision& best) const;
  // The filter's answer about (self, other), reported to the trace; refuses an answer that is not
  // a registered response.
  ResponseId ask(ItemId self, ItemId other, Filter filter, MoveTrace* trace) const;
  [[noreturn]] static void refuseAnswer(ResponseId resp);
  // The answer this move got about the item in `slot` (kUnasked if it was not asked).
  [[nodiscard]] ResponseId answered(std::uint32_t slot) const;
  // Appends every hit of the leg r -> goal among the items but `self` (unordered; response and
  // filter left alone): the candidates and tests of a move's leg, for hitsAlong.
  void sweepLeg(std::uint32_t self, const Rect& r, Vec2 goal, BroadPhase broad,
                std::vector<Collision>& out) const;
  /// Calls f(slot, generation, const Rect&) once for each item registered in the cells the
  /// move visits.
  template <class F>
  void forEachCandidate(std::uint32_t self, const Rect& r, Vec2 goal, const Rect& hull,
                        BroadPhase broad, MoveTrace* trace, F&& f) const;
  std::uint32_t nextEpoch() const;
  // bump.lua's move (MoveSemantics::bump), core/src/bump_move.cpp.
  MoveResult bumpRun(std::uint32_t self, const Rect& r, Vec2 goal, Filter filter,
                     const MoveOptions& o) const;
  bool bumpFirstHit(ItemId self, const Rect& at, Vec2 goal, Filter filter, MoveTrace* trace,
                    Collision& out) const;
  bool bumpGuard(const Rect& at, Vec2 goal, const Collision* first, Collision& out) const;

  Grid grid_;
  Hash hash_;
  std::vector<Slot> slots_;
  std::vector<std::uint64_t> orders_;  // by slot: add order, alive slots only
  std::vector<std::uint32_t> freeSlots_;
  std::size_t count_ = 0;
  std::uint64_t nextOrder_ = 0;
  std::map<double, std::size_t> extents_;  // min(w, h) -> how many items

  struct NamedResponse {
    std::string name;
    ResponseFn fn = nullptr;                      // a response without a context, or
    ResponseWithContextFn withContext = nullptr;  // one with `context`
    void* context = nullptr;
  };
  ResponseId addNamed(NamedResponse r);
  std::vector<NamedResponse> responses_;
  detail::ObserverLink observer_;  // a copy of a world reports to no one

  // Scratch reused by every move (hence `mutable`: check and project are logically const).
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t epoch_ = 0;
  mutable std::vector<Collision> collisions_;
  mutable std::vector<std::uint32_t> excluded_;
  mutable std::vector<std::uint32_t> queryScratch_;
  mutable std::vector<std::uint32_t> overlapping_;  // anyOverlap's, apart: its filter may query
  mutable std::vector<Candidate> candidates_;
  mutable std::vector<Hit> hits_;
  mutable Collision hit_;        // the current leg's first hit
  mutable bool stayed_ = false;  // the last run's goal lies in the cells its item is in
  // bump's move: a leg's candidates, what it met (ids, the answer for each, and whether it may
  // not be entered again), kept apart from the core's own scratch.
  mutable std::vector<ItemId> bumpFound_;
  mutable std::vector<Collision> bumpHits_;
  mutable std::vector<ItemId> bumpMet_;
  mutable std::vector<ResponseId> bumpMetResponse_;
  mutable std::vector<bool> bumpMetGuard_;
};

}  // namespace tv
