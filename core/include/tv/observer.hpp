#pragma once
/// The hook through which a recorder (tv::Recorder, in tv::record) sees what a game asks of a
/// World and what it got back. Core does no I/O: it only calls these functions. Detached, each
/// public call pays one predictable branch on a null pointer.
///
/// What is reported:
/// - the outermost call only: a Mover::move or Batch::step is one call, and the World calls it
///   makes inside are part of it (replaying the outer call makes them again);
/// - after the call succeeded, with its inputs and results (a call that throws changes nothing
///   and is not reported; `failed` says the answers gathered for it are void);
/// - user code's answers as they are given, inside the call: the filter's response for each
///   pair it is asked about, and the leg each user response (id >= response::kBuiltinCount)
///   returned — the two things a replay cannot recompute.
/// An observer must not call back into the world it observes, and must outlive its attachment
/// (or detach first): a World or FixedStep tells its observer when it is destroyed.

#include <cstdint>
#include <span>
#include <string_view>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

class World;
class Mover;
class Batch;
struct BatchMove;
struct MoveOptions;
struct MoveResult;
struct SegmentHit;
struct ContactEvent;
struct CornerNudge;

/// What a World, Mover, Batch and FixedStep report to the one observer attached to them (a
/// tv::Recorder). Each function is called after the call it names succeeded, with its inputs
/// and results; see the file's overview for the rules.
class WorldObserver {
 public:
  virtual ~WorldObserver() = default;

  /// `World::attach`: the world as it is now (a recording opens with its snapshot).
  virtual void attached(const World& world) = 0;
  /// `World::detach` (or another observer attached): nothing more comes from `world`.
  virtual void detached(const World& world) = 0;

  // -- outermost calls, once they have succeeded -------------------------------------------------
  /// `World::add` returned `id` for the rect `r`.
  virtual void added(ItemId id, const Rect& r) = 0;
  /// `World::remove(id)`.
  virtual void removed(ItemId id) = 0;
  /// Both `update` overloads (the position one reports the whole rect).
  virtual void updated(ItemId id, const Rect& r) = 0;
  /// `World::move(id, goal, ...)` with its options, and what it returned.
  virtual void moved(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) = 0;
  /// `World::check(id, goal, ...)`: a move that changed nothing, and what it would have done.
  virtual void checked(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) = 0;
  /// `World::project(rect, goal, ...)`: a move of a rect that is not an item.
  virtual void projected(const Rect& rect, Vec2 goal, const MoveOptions& o,
                         const MoveResult& r) = 0;
  /// `World::queryRect(r, ..., skip)` found these items, in the order it returned them.
  virtual void queriedRect(const Rect& r, ItemId skip, std::span<const ItemId> found) = 0;
  /// `World::queryPoint(p, ...)` found these items.
  virtual void queriedPoint(Vec2 p, std::span<const ItemId> found) = 0;
  /// `World::querySegment(a, b, ...)` found these hits, in order along the segment.
  virtual void queriedSegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits) = 0;
  /// `World::anyOverlap(r, ..., skip)` answered `any`.
  virtual void askedOverlap(const Rect& r, ItemId skip, bool any) = 0;
  /// `World::addResponse(name, ...)` registered a user response as `id`.
  virtual void responseAdded(std::string_view name, ResponseId id) = 0;
  /// `mover.move(world, id, goal, ...)`; `start` is the item's rect before the move.
  virtual void moverMoved(const Mover& mover, ItemId id, const Rect& start, Vec2 goal,
                          const MoveResult& r) = 0;
  /// `batch.step(world, moves, ...)`; outcomes are read from `batch`.
  virtual void batchStepped(std::span<const BatchMove> moves, int maxEvents,
                            const Batch& batch) = 0;

  /// `Contacts::update(world, item, ...)` returned `events` (`forget`: `Contacts::forget`, whose
  /// events are the ends of every contact `item` had). Not pure virtual: observers written
  /// before contact events keep compiling and ignore them.
  virtual void contacted(ItemId item, bool forget, std::span<const ContactEvent> events) {
    (void)item;
    (void)forget;
    (void)events;
  }

  /// `tv::moveCornered(world, item, ...)` nudged `item` round the corner of a ceiling: reported
  /// after the World calls the correction is made of (check, anyOverlap, the moves), which
  /// replay it; this says what they were for. Not pure virtual, as `contacted`.
  virtual void cornerNudged(ItemId item, const CornerNudge& nudge) {
    (void)item;
    (void)nudge;
  }

  /// An attached FixedStep's `advance(frameTime)` returned `ticks`: one rendered frame begins.
  virtual void advanced(double frameTime, int ticks) {
    (void)frameTime;
    (void)ticks;
  }

  // -- user code's answers, during the call --------------------------------------------------
  /// The filter was asked about (`item`, `other`) and answered `answer`.
  virtual void filtered(ItemId item, ItemId other, ResponseId answer) = 0;
  /// A user response, given collision `c` and the leg's `goal`, returned `leg`.
  virtual void responded(const Collision& c, Vec2 goal, const Leg& leg) = 0;
  /// The outermost call threw: forget the answers reported since it began.
  virtual void failed() = 0;

  /// The World or FixedStep at `source`, which this observer was attached to, is being
  /// destroyed: forget it, and call nothing on it from now on.
  virtual void sourceGone(const void* source) { (void)source; }

  /// True inside an outermost call: the calls it makes are not reported on their own.
  [[nodiscard]] bool busy() const { return depth_ > 0; }

  /// Marks an outermost call (used by World, Mover and Batch).
  class Scope {
   public:
    /// Enters an outermost call on `o` (left when the scope ends).
    explicit Scope(WorldObserver& o) : o_(o) { ++o_.depth_; }
    ~Scope() { --o_.depth_; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    WorldObserver& o_;
  };

  /// Asks a filter and reports its answer; wrap one in a Filter for the call's duration.
  struct Watched {
    const Filter& filter;     ///< the caller's filter
    WorldObserver& observer;  ///< where its answers go
    /// The filter's answer for (`item`, `other`), reported to the observer.
    ResponseId operator()(ItemId item, ItemId other) const {
      const ResponseId r = filter(item, other);
      observer.filtered(item, other, r);
      return r;
    }
  };

 private:
  int depth_ = 0;
};

namespace detail {

/// How a World or FixedStep holds its observer: a copy reports to no one (it is a new world),
/// and the observer hears when its source is destroyed, so it never calls a dangling one.
class ObserverLink {
 public:
  ObserverLink() = default;
  ObserverLink(const ObserverLink&) {}
  ObserverLink& operator=(const ObserverLink&) { return *this; }
  ~ObserverLink() {
    if (p_) p_->sourceGone(owner_);
  }
  void set(WorldObserver* p, const void* owner) {
    p_ = p;
    owner_ = owner;
  }
  [[nodiscard]] WorldObserver* get() const { return p_; }
  WorldObserver* operator->() const { return p_; }
  WorldObserver& operator*() const { return *p_; }
  explicit operator bool() const { return p_ != nullptr; }

 private:
  WorldObserver* p_ = nullptr;
  const void* owner_ = nullptr;
};

}  // namespace detail

}  // namespace tv
