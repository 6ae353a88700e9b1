#pragma once
/// Collision records and responses, in the manner of bump.lua: a filter picks a response for
/// each (item, other) pair; the response turns the first collision of a leg into the next leg.

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>
#include <type_traits>
#include <utility>

#include "tv/geometry.hpp"
#include "tv/item.hpp"

namespace tv {

/// A response by number: the built-ins (kBuiltinResponses, below), then those
/// `World::addResponse` registers.
using ResponseId = std::uint16_t;

/// The built-in responses' ids: their places in kBuiltinResponses (checked below). Users register
/// more with `World::addResponse`.
namespace response {
inline constexpr ResponseId touch = 0;   ///< stop at the contact
inline constexpr ResponseId cross = 1;   ///< report, pass through, keep going
inline constexpr ResponseId slide = 2;   ///< stop on the normal's axis, keep the other
inline constexpr ResponseId bounce = 3;  ///< reflect the rest of the move about the normal
/// a one-way (jump-through) platform: slide when the item was entirely above it, else cross
inline constexpr ResponseId oneway = 4;
inline constexpr ResponseId ignore = 0xFFFF;  ///< from a filter: the pair does not interact
}  // namespace response

/// One collision, with everything the debugger draws.
struct Collision {
  ItemId item;            ///< the mover (invalid for `World::project`)
  ItemId other;           ///< what it met
  bool overlaps = false;  ///< the leg started inside `other`
  bool corner = false;    ///< exact corner hit (see Sweep::corner)
  double ti = 0.0;  ///< time of impact along the leg in [0, 1); minus the overlap area if overlaps
  Vec2 move;        ///< the leg's displacement (goal - start)
  Vec2 normal;      ///< axis normal, from other towards item
  Vec2 touch;       ///< item position at contact, placed from other's edge
  Rect itemRect;    ///< item at the start of the leg
  Rect otherRect;   ///< what it met, as it stood
  ResponseId response = response::slide;  ///< what the filter chose for the pair
  /// The response's own data: where it sends the item next (slide or bounce target; the touch
  /// point for touch; the unchanged goal for cross).
  Vec2 target;
};

/// What a response hands back: the next leg of the move.
struct Leg {
  Vec2 start;                ///< where the next leg begins (the collision's touch point, usually)
  Vec2 goal;                 ///< where it aims
  bool passThrough = false;  ///< exclude `other` from the rest of this move (cross)
  /// Bump semantics only (MoveSemantics::bump): the response found nothing more in its way, so
  /// the move ends at `goal` (bump's response returned no collisions). Otherwise the next leg
  /// runs from `start` to `goal`.
  bool stop = false;
};

/// A response: given the first collision of the current leg and that leg's goal, the next leg.
/// It must not place the item inside `other`; starting the next leg at `c.touch` ensures that.
using ResponseFn = Leg (*)(const Collision& c, Vec2 goal);
/// A response with a context of its own, as a Filter's callable has: `context` is the pointer
/// registered with it (World::addResponse(name, fn, context)), handed back at every call, so a
/// binding or a replay finds its state there instead of in a global.
using ResponseWithContextFn = Leg (*)(void* context, const Collision& c, Vec2 goal);

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

/// True when a one-way platform blocks this collision: the item met its top (normal (0, −1))
/// without overlapping it, and was entirely above it when the leg began (its bottom edge at or
/// above the top, compared exactly). A body below, beside or inside the platform passes.
[[nodiscard]] constexpr bool onewayBlocks(const Collision& c) {
  return !c.overlaps && c.normal.x == 0.0 && c.normal.y == -1.0 &&
         c.itemRect.bottom() <= c.otherRect.y;
}
/// A one-way platform: slideResponse when onewayBlocks, else crossResponse (the platform is
/// passed and left out of the rest of the move, so a body jumping up through it is never
/// snagged on its top). A drop-through is the filter answering `cross` for the platform while
/// the body drops.
[[nodiscard]] Leg onewayResponse(const Collision& c, Vec2 goal);

/// What a collision does to a body's velocity (any unit per time, returned in the same): the
/// rule a game, and tv::sim, applies beside the response that moved the body. A component already
/// leaving the obstacle is always kept, so a body pushed out of an overlap is not sent back in.
using VelocityFn = Vec2 (*)(Vec2 velocity, const Collision& c);

/// Leaves the velocity alone (cross, and user responses unless they say otherwise).
[[nodiscard]] Vec2 keepVelocity(Vec2 v, const Collision& c);
/// Stops the body: zero velocity (touch).
[[nodiscard]] Vec2 stopVelocity(Vec2 v, const Collision& c);
/// Zeroes the component along the normal when it points into the obstacle (slide).
[[nodiscard]] Vec2 slideVelocity(Vec2 v, const Collision& c);
/// Reverses the component along the normal when it points into the obstacle (bounce).
[[nodiscard]] Vec2 reflectVelocity(Vec2 v, const Collision& c);
/// slideVelocity when the one-way platform blocked the body (onewayBlocks), else keeps it.
[[nodiscard]] Vec2 onewayVelocity(Vec2 v, const Collision& c);

/// One built-in response: everything any part of the project needs to know about it.
struct ResponseDef {
  std::string_view name;     ///< what filters, scene files, recordings and Lua call it
  ResponseFn fn;             ///< the next leg of a move (see ResponseFn)
  VelocityFn velocity;       ///< what it does to a body's velocity
  std::string_view summary;  ///< one line, for documentation and the debugger
};

/// The built-in responses, by ResponseId: the one list that the world registers, the recording
/// format checks names against, scene files and the Lua module look names up in, and tv::sim
/// takes velocity rules from. A new built-in is one entry here.
inline constexpr ResponseDef kBuiltinResponses[] = {
    {"touch", &touchResponse, &stopVelocity, "stop at the contact"},
    {"cross", &crossResponse, &keepVelocity, "report the contact and pass through"},
    {"slide", &slideResponse, &slideVelocity, "stop on the normal's axis, keep moving along it"},
    {"bounce", &bounceResponse, &reflectVelocity, "reflect the rest of the move about the normal"},
    {"oneway", &onewayResponse, &onewayVelocity,
     "a jump-through platform: slide if the body was entirely above it, else pass through"},
};

namespace response {
/// Ids from here on are user responses.
inline constexpr ResponseId kBuiltinCount = static_cast<ResponseId>(std::size(kBuiltinResponses));
}  // namespace response

static_assert(kBuiltinResponses[response::touch].name == "touch" &&
                  kBuiltinResponses[response::cross].name == "cross" &&
                  kBuiltinResponses[response::slide].name == "slide" &&
                  kBuiltinResponses[response::bounce].name == "bounce" &&
                  kBuiltinResponses[response::oneway].name == "oneway",
              "the response ids are the table's order");

/// The built-in named `name`, or response::ignore when no built-in is ("ignore" itself is not a
/// response: see World::responseId).
[[nodiscard]] constexpr ResponseId builtinResponseId(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kBuiltinResponses); ++i) {
    if (kBuiltinResponses[i].name == name) return static_cast<ResponseId>(i);
  }
  return response::ignore;
}

/// The velocity after a collision, by its response's rule: a built-in's from kBuiltinResponses;
/// any other response keeps it.
[[nodiscard]] inline Vec2 velocityAfter(Vec2 v, const Collision& c) {
  return c.response < response::kBuiltinCount ? kBuiltinResponses[c.response].velocity(v, c) : v;
}

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
