#pragma once
/// What a simulation moves: bodies (an item of the world plus a velocity and a little state),
/// and what it counts. Everything here is plain data, copied into the snapshot ring each tick.

#include <cstddef>
#include <cstdint>
#include <span>

#include "tv/contact.hpp"
#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv::sim {

/// What a body is in its scene; the debugger colours by it. Behaviour comes from the scene's
/// rules, not from the role.
enum class BodyRole : std::uint8_t { projectile, enemy, ball, walker, player, crowd, block };

/// Collision layers: a body meets what its `mask` shares a bit with (solids are `kLayerSolid`).
inline constexpr std::uint32_t kLayerSolid = 1u << 0;
inline constexpr std::uint32_t kLayerProjectile = 1u << 1;  ///< bullets and shots
inline constexpr std::uint32_t kLayerEnemy = 1u << 2;       ///< what projectiles are aimed at
inline constexpr std::uint32_t kLayerCrowd = 1u << 3;       ///< crowd movers (among each other)
inline constexpr std::uint32_t kLayerPlayer = 1u << 4;      ///< players and walkers

/// A moving body: its item in the world, its velocity and the little state the rules keep.
struct Body {
  ItemId item;    ///< its item in the simulation's world (set when the scene is built)
  Rect rect;      ///< where it is (always equal to the world's rect for `item`)
  Vec2 velocity;  ///< px/s
  ResponseId response = response::slide;  ///< how it responds to whatever it meets
  BodyRole role = BodyRole::block;   ///< what it is, for the debugger's colours
  std::uint32_t layer = 0;           ///< what it is (one kLayer* bit)
  std::uint32_t mask = kLayerSolid;  ///< what it collides with
  std::uint32_t group = 0;           ///< scene-defined, constant: lane, slot, pair...
  std::int32_t state = 0;            ///< scene-defined, changes: walk direction, contact flags...
  bool falls = false;                ///< gravity applies
  bool active = true;                ///< moves each tick; false once it is done (stopped, resolved)
  /// A moving solid (a lift, a platform): moved by tv::moveSolid, before the other bodies each
  /// tick, carrying the bodies that ride it and pushing those in its way, instead of by the mover.
  bool solid = false;
  /// Solid from above only (a jump-through platform): a body meets it only if it was entirely
  /// above it when its move began; as a moving solid, it pushes nothing from below.
  bool oneWay = false;
  /// Corner correction (tv/corner.hpp): when > 0, the body moves by tv::moveCornered with this
  /// largest nudge (World::move's exact sweep, nudged round a ceiling corner it clips by at most
  /// this much), whatever the simulation's mover; 0: by the mover. Its moves are not traced
  /// (tv::moveCornered keeps no MoveTrace).
  double maxNudge = 0.0;
  /// Reads its contacts after each of its moves, as a platformer's player does (tv::Contacts,
  /// with the move's collisions as `met`, the scene's one-way items and moving solids listed):
  /// the simulation keeps each tick's contact events and the body's ground
  /// (Simulation::contactEvents, Simulation::ground). A query: it changes nothing. Not read in
  /// a batched scene (tv::Batch moves every body at once).
  bool contacts = false;
};

/// What the scenes count. Each scene documents which counters it uses and what they mean;
/// `moves` and `collisions` are kept by the simulation for every scene. All are part of the
/// state hash and of every snapshot.
struct Counters {
  std::uint64_t moves = 0;        ///< body moves made (one per active body per tick)
  std::uint64_t collisions = 0;   ///< collision records those moves reported
  std::uint64_t hits = 0;         ///< scene: what was supposed to be hit and was
  std::uint64_t tunnelled = 0;    ///< scene: ended on the far side of what it should have hit
  std::uint64_t farPushOuts = 0;  ///< of `tunnelled`: the mover saw the obstacle but pushed the
                                  ///< body out of its far side (the discrete mover's failure)
  std::uint64_t misses = 0;       ///< scene: crossings or shots that should have met and did not
  std::uint64_t escapes = 0;      ///< scene: bodies that left the space that encloses them
  std::uint64_t overlaps = 0;     ///< moves that ended inside a solid the body did not start in
  std::uint64_t jitter = 0;       ///< ticks a resting body moved although nothing pushed it free
  std::uint64_t snags = 0;        ///< horizontal hits on a floor's seams while walking along it
  std::uint64_t jumps = 0;        ///< platformer: jumps taken
  std::uint64_t landings = 0;     ///< platformer: landings after a jump or fall
  std::uint64_t respawns = 0;     ///< platformer: falls out of the level
  std::uint64_t drops = 0;        ///< platforms: riders that ended a tick below their platform's top
  std::uint64_t pops = 0;         ///< platforms: riders that ended a tick above it, not on it
  std::uint64_t squishes = 0;     ///< bodies a moving solid could not push out of its way

  /// Equal when every counter is.
  friend bool operator==(const Counters&, const Counters&) = default;
};

/// What a moving solid did to a body (tv::moveSolid's SolidMove, body by body).
enum class SolidAct : std::uint8_t {
  carried,   ///< it rode the solid (stood on it) and was moved along
  pushed,    ///< it was in the solid's way and was pushed to its leading edge
  squished,  ///< it was pressed between the solid and something that would not give
};

/// One thing a moving solid did in a tick: to which body, and from where to where.
struct SolidContact {
  std::size_t solid = 0;  ///< the moving solid's body index
  std::size_t body = 0;   ///< the body it carried, pushed or squished
  SolidAct act = SolidAct::carried;  ///< what the solid did to it
  Rect from;  ///< the body before that solid's move
  Rect to;    ///< the body after it (a squished body: where it was pressed)
};

/// A corner correction made in a tick (tv::moveCornered): a body nudged round a ceiling's corner.
struct CornerNudgeAt {
  std::size_t body = 0;  ///< the body nudged
  ItemId ceiling;        ///< the ceiling whose corner it clipped
  Rect from;             ///< the body where it met the corner
  Rect to;               ///< the body nudged beside it (from, moved by dx)
};

/// A counter the scene's rules raised, and whose move raised it.
enum class Counted : std::uint8_t {
  tunnelled,       ///< Counters::tunnelled
  farPushOut,      ///< Counters::farPushOuts
  missed,          ///< Counters::misses
  escaped,         ///< Counters::escapes
  overlapped,      ///< Counters::overlaps
  jittered,        ///< Counters::jitter
  snagged,         ///< Counters::snags
  dropped,         ///< Counters::drops
  popped,          ///< Counters::pops
  manyCollisions,  ///< not a counter: a move reported more than `manyCollisions()` collisions
};

/// Something counted in a tick: the tools list these to go straight to what failed.
struct TickEvent {
  std::uint64_t tick = 0;  ///< the tick's number once it has run (ticks() after it)
  /// The body whose move the rules were judging when they counted (afterMove), or the body the
  /// rules named (TickContext::count); -1 when counted after every body moved (afterTick)
  /// without naming one.
  std::int64_t body = -1;
  Counted what = Counted::tunnelled;  ///< which counter rose
  std::uint64_t count = 1;  ///< how much the counter rose
  /// What the move passed through (tunnelled, farPushOut) or ended inside (overlapped), as
  /// tv::judgeMove finds it with the simulation's filter, or what the rules named (the
  /// platform a rider dropped through); invalid when unknown or not asked.
  ItemId other;
  std::size_t collisions = 0;  ///< collisions the move reported
};

/// A contact event of a body that reads its contacts (Body::contacts), with where the two
/// items stood when it was read.
struct ContactAt {
  std::size_t body = 0;  ///< the body whose contacts were read
  ContactEvent event;    ///< begin, persist or end; the other item; the normal towards the body
  Rect bodyRect;         ///< the body at the update
  Rect otherRect;        ///< the other item at the update (an end: where it is now)
};

/// The velocity after one collision, by the collision's response (all in px/s):
/// - touch stops the body: zero velocity;
/// - slide zeroes the component along the normal, if the velocity points into the obstacle;
/// - bounce reflects that component, if the velocity points into the obstacle;
/// - cross and user responses leave the velocity alone.
/// A component already leaving the obstacle is kept, so a body pushed out of an overlap is not
/// sent back in.
[[nodiscard]] Vec2 respondVelocity(Vec2 velocity, const Collision& c);
/// `respondVelocity` for each collision of a move, in order.
[[nodiscard]] Vec2 respondVelocity(Vec2 velocity, std::span<const Collision> collisions);

}  // namespace tv::sim
