#pragma once
/// Collision records and responses, in the manner of bump.lua: a filter picks a response for
/// each (item, other) pair; the response turns the first collision of a leg into the next leg.

#include <cstdint>
#include <type_traits>
#include <utility>

#include "tv/geometry.hpp"
#include "tv/item.hpp"

namespace tv {

/// A response by number: the built-ins below, then those `World::addResponse` registers.
using ResponseId = std::uint16_t;

/// The built-in responses. Users register more with `World::addResponse`.
namespace response {
inline constexpr ResponseId touch = 0;   ///< stop at the contact
inline constexpr ResponseId cross = 1;   ///< report, pass through, keep going
inline constexpr ResponseId slide = 2;   ///< stop on the normal's axis, keep the other
inline constexpr ResponseId bounce = 3;  ///< reflect the rest of the move about the normal
inline constexpr ResponseId ignore = 0xFFFF;  ///< from a filter: the pair does not interact
inline constexpr ResponseId kBuiltinCount = 4;  ///< ids from here on are user responses
}  // namespace response

/// One collision, with everything the debugger draws.
struct Collision {
  ItemId item;        ///< the mover (invalid for `World::project`)
  ItemId other;       ///< what it met
  bool overlaps = false;  ///< the leg started inside `other`
  bool corner = false;    ///< exact corner hit (see Sweep::corner)
  double ti = 0.0;    ///< time of impact along the leg in [0, 1); minus the overlap area if overlaps
  Vec2 move;          ///< the leg's displacement (goal - start)
  Vec2 normal;        ///< axis normal, from other towards item
  Vec2 touch;         ///< item position at contact, placed from other's edge
  Rect itemRect;      ///< item at the start of the leg
  Rect otherRect;     ///< what it met, as it stood
  ResponseId response = response::slide;  ///< what the filter chose for the pair
  /// The response's own data: where it sends the item next (slide or bounce target; the touch
  /// point for touch; the unchanged goal for cross).
  Vec2 target;
};

/// What a response hands back: the next leg of the move.
struct Leg {
  Vec2 start;  ///< where the next leg begins (the collision's touch point, usually)
  Vec2 goal;   ///< where it aims
  bool passThrough = false;  ///< exclude `other` from the rest of this move (cross)
  /// Bump semantics only (MoveSemantics::bump): the response found nothing more in its way, so
  /// the move ends at `goal` (bump's response returned no collisions). Otherwise the next leg
  /// runs from `start` to `goal`.
  bool stop = false;
};

/// A response: given the first collision of the current leg and that leg's goal, the next leg.
/// It must not place the item inside `other`; starting the next leg at `c.touch` ensures that.
using ResponseFn = Leg (*)(const Collision& c, Vec2 goal);

/// The built-ins, exposed so custom responses can build on them.
///
///     // "stick": stop at the contact, as touch does, but only when moving down
///     tv::Leg stick(const tv::Collision& c, tv::Vec2 goal) {
///       return c.normal.y < 0 ? tv::touchResponse(c, goal) : tv::slideResponse(c, goal);
///     }
///     tv::ResponseId id = world.addResponse("stick", &stick);
[[nodiscard]] Leg touchResponse(const Collision& c, Vec2 goal);
/// Passes through `other` (excluded from the rest of the move) and keeps the goal.
[[nodiscard]] Leg crossResponse(const Collision& c, Vec2 goal);
/// From the touch point, keeps the goal's coordinate along the surface and stops on the normal.
[[nodiscard]] Leg slideResponse(const Collision& c, Vec2 goal);
/// From the touch point, the rest of the move reflected about the surface.
[[nodiscard]] Leg bounceResponse(const Collision& c, Vec2 goal);

/// Chooses the response for a pair, or `response::ignore`. A non-owning reference to any
/// callable `ResponseId(ItemId item, ItemId other)`; the default makes everything slide. It
/// never allocates, so it may be passed a temporary lambda for the duration of a call.
class Filter {
 public:
  constexpr Filter() = default;
  /// Refers to `f` (not copied): `f` must outlive every call that uses this filter.
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, Filter> &&
             std::is_invocable_r_v<ResponseId, F&, ItemId, ItemId>)
  Filter(F&& f)  // NOLINT(google-explicit-constructor): a filter is passed as a lambda
      : ctx_(const_cast<void*>(static_cast<const void*>(&f))),
        fn_([](void* ctx, ItemId a, ItemId b) -> ResponseId {
          return (*static_cast<std::remove_reference_t<F>*>(ctx))(a, b);
        }) {}

  /// Every pair gets the same response.
  static Filter all(ResponseId r) {
    Filter f;
    f.ctx_ = reinterpret_cast<void*>(static_cast<std::uintptr_t>(r));
    f.fn_ = [](void* ctx, ItemId, ItemId) {
      return static_cast<ResponseId>(reinterpret_cast<std::uintptr_t>(ctx));
    };
    return f;
  }

  /// The response for `item` meeting `other` (response::slide with no callable).
  [[nodiscard]] ResponseId operator()(ItemId item, ItemId other) const {
    return fn_ ? fn_(ctx_, item, other) : response::slide;
  }

 private:
  void* ctx_ = nullptr;
  ResponseId (*fn_)(void*, ItemId, ItemId) = nullptr;
};

}  // namespace tv
