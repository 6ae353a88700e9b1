#pragma once
/// Moving solids — lifts, crushers, doors, moving platforms: items the game moves by script, which
/// carry the bodies riding them, push the bodies in their way and report the bodies they squish,
/// as Celeste's Solid moves its Actors, but exact in floats at any speed:
///
/// - a rider (a body standing on the solid's top: its bottom edge equals the top bit for bit and
///   the two overlap horizontally) moves with the solid, and is placed back on the top from the
///   top's edge, so it is never dropped (left behind by a sinking or fast solid) nor popped (left
///   inside a rising one), whatever the speed;
/// - a body in the solid's way (the region it sweeps, ahead of its old leading edge) is pushed to
///   the new leading edge, placed from that edge;
/// - a pushed body that cannot get there (a wall, a ceiling) is squished: the solid stops where
///   that body is pressed between the obstacle and the solid, so no body is ever left inside it;
///   `SolidMove::squished` says which body, against what;
/// - a one-way solid (SolidOptions::oneWay: solid from above only, a jump-through platform)
///   carries its riders and pushes only bodies that were entirely above it at the start of the
///   move; bodies below or inside it are neither pushed nor carried.
///
/// Every body moves through the World's own exact sweep (World::move) and the solid through
/// World::update, so a recording of the game replays a solid's move bit for bit with no calls of
/// its own. The move is made along x, then along y (as Celeste's MoveH, MoveV).
///
///     tv::SolidOptions o;
///     o.bodies = actors;            // the game's bodies: what may ride or be pushed
///     tv::SolidMove m = tv::moveSolid(world, lift, {lx, ly - 4}, o);
///     for (const tv::Squish& s : m.squished) kill(s.body);
///
/// Defined cases: a solid moves through other solids and static items (only the listed bodies are
/// carried or pushed); a body listed twice, or the solid itself in `bodies`, is refused; a body
/// riding two solids is carried by each solid's move. A call that throws (bad input, or the
/// filter throwing) leaves every item where it was.

#include <cstdint>
#include <span>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

class World;

/// How moveSolid treats the bodies.
struct SolidOptions {
  /// The bodies that may ride the solid or be pushed by it (the game's actors). Any order: they
  /// are handled in a fixed order of their own (nearest to farthest along the move, ties by add
  /// order). Items not listed are neither carried nor pushed: the solid moves through them.
  std::span<const ItemId> bodies;
  /// What a carried or pushed body meets on its way, as the game's moves ask: `ignore` passes,
  /// `cross` passes and is reported by nothing, any other answer stops the body at the contact
  /// (a push goes along one axis, where slide and touch agree). The solid itself is never asked.
  Filter filter;
  /// Solid from above only (a jump-through platform): see the header's comment.
  bool oneWay = false;
  /// Also carry bodies holding on to its left or right side (touching it, overlapping it
  /// vertically), as a wall-climber expects. Default false: only bodies standing on top ride.
  bool carrySides = false;
};

/// A body that a solid could not push out of its way.
struct Squish {
  ItemId body;     ///< the body pressed between the solid and `against`
  ItemId against;  ///< what stopped it (invalid if the world's edge of range did)
  Vec2 normal;     ///< the axis the solid was moving along, pointing the way it moved
};

/// What moveSolid did.
struct SolidMove {
  Vec2 position;                 ///< where the solid ended: its goal unless a squish stopped it
  std::vector<ItemId> carried;   ///< riders moved along, in the order they were moved
  std::vector<ItemId> pushed;    ///< bodies pushed out of its way, in the order they were moved
  std::vector<Squish> squished;  ///< bodies that stopped it, in the order they did
};

/// Moves `solid` towards `goal` (its top-left corner) carrying, pushing and reporting squishes
/// as described at the top of this header. Throws tv::Error for an unknown solid or body, the
/// solid among the bodies, a body listed twice, or a goal out of range, changing nothing.
[[nodiscard]] SolidMove moveSolid(World& world, ItemId solid, Vec2 goal, const SolidOptions& o = {});

}  // namespace tv
