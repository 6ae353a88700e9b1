#pragma once
/// Movers: policies that move an item through the same World, chosen at run time, so that the
/// debugger and the benchmarks can compare them on the same scene. Each says what it costs and
/// when it fails.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tv/world.hpp"

namespace tv {

/// The movement policies, from the naive negative control to the exact sweep.
enum class MoverKind : std::uint8_t {
  /// Teleport to the goal, then push out of every overlap along its shallowest axis — the
  /// naive mover many games write. Cost: one rect query. Fails: tunnels whenever a step
  /// carries the mover past an obstacle (step ≥ mover + obstacle thickness), is pushed out of
  /// the far side when it ends past an obstacle's middle, and catches on tile seams. Kept as
  /// the negative control.
  discrete,
  /// One swept move whose broad phase is the move's whole bounding box, as bump.lua's
  /// world:move. Never tunnels; candidates grow with the bounding box's area (a long diagonal
  /// costs far more than the same length along an axis).
  sweep,
  /// The move cut into pieces no longer than `maxStep`, each made by the inner mover (discrete
  /// or sweep) from where the last one ended — the usual patch. With a discrete inner step it
  /// tunnels once maxStep >= the thinnest obstacle + mover, and even with short pieces it ends
  /// past walls: a piece landing near a wall's end is pushed out sideways past it, and as every
  /// piece keeps the move's direction, a shot pushed back climbs the face and goes round the
  /// end (tv-bench tunnel measures it). Cost grows with speed / maxStep, and the pieces add
  /// rounding that a single exact sweep does not have.
  substep,
  /// One exact swept move whose broad phase visits only the cells the moving rect crosses:
  /// cost follows path length, not bounding-box area. Never tunnels; zero error.
  continuous,
  /// Integer steps with a sub-pixel remainder, one pixel at a time, each checked for overlap
  /// (Celeste/TowerFall style). Exact on integer scenes; cost grows linearly with speed (one
  /// query per pixel), so it is the cost-per-pixel baseline, not a choice for bullets. Refuses
  /// moves over 2^24 px on an axis. Never tunnels through bodies and obstacles at least 1 px
  /// thick; a thinner one can fit between two consecutive pixel positions and be stepped over.
  pixel,
  /// Continuous, made cheap where bodies rest and walk: a body moving back into what its last
  /// move ended against (resting on a floor under gravity, walking along it, pressed to a
  /// wall) reads its move's bounding box once — when the box spans at most 4 cells, or the
  /// move is shorter than `safetyFraction` of the smallest extent of the mover and the world —
  /// and slides from that one read: what its filter does not ignore there is all that its legs
  /// can meet while they slide, touch or cross. Every other move, and one that meets a bounce
  /// or a user's response, goes to World::move (whose lean path decides a free move in one
  /// scan). Same results as continuous, bit for bit.
  adaptive,
};

/// A mover by kind and options; `parseMover("substep-sweep")` gives one by name.
struct MoverSpec {
  MoverKind kind = MoverKind::continuous;  ///< the policy (default: the exact sweep)
  /// substep: longest piece in world units, finite and >= 0; 0 means half the world's smallest
  /// item extent (tile / 2 in a tile map, the article's choice).
  double maxStep = 0.0;
  /// substep: how each piece moves, `discrete` or `sweep`.
  MoverKind inner = MoverKind::discrete;
  /// adaptive: fraction of the smallest extent below which a pressing move reads its bounding
  /// box however many cells it spans. Range (0, 1], default 0.25.
  double safetyFraction = 0.25;

  /// Stable name: "discrete", "sweep", "substep-discrete", "substep-sweep", "continuous",
  /// "pixel", "adaptive".
  [[nodiscard]] std::string name() const;
};

/// One entry of the mover table.
struct MoverEntry {
  std::string_view name;  ///< as in moverNames(), tables, CSV columns and every tool's flags
  MoverSpec spec;         ///< its kind (and inner step), every option at its default
  std::string_view description;  ///< one line on what it does and when it fails
};
/// Every mover once, in the order of the comparison tables: the one list every tool reads to
/// list, parse and describe movers.
[[nodiscard]] std::span<const MoverEntry> moverTable();

/// Parses a name from `moverNames()`; throws tv::Error listing the valid names otherwise.
[[nodiscard]] MoverSpec parseMover(std::string_view name);
/// Every mover name, in the order of the comparison tables.
[[nodiscard]] std::span<const std::string_view> moverNames();
/// One line on what the named mover does and when it fails.
[[nodiscard]] std::string_view moverDescription(std::string_view name);

/// A mover: moves items of any World by its policy, keeping per-item state where the policy
/// has some (the pixel mover's sub-pixel remainders).
///
///     tv::Mover naive(tv::parseMover("discrete"));
///     tv::MoveResult r = naive.move(world, bullet, {x + 32, y});   // may tunnel: compare it
class Mover {
 public:
  /// Throws tv::Error on a spec out of range (names the field and value).
  explicit Mover(MoverSpec spec = {});

  [[nodiscard]] const MoverSpec& spec() const { return spec_; }  ///< as constructed

  /// Moves `id` towards `goal` by this policy. Collisions are valid until the next move by this
  /// mover or the world. Throws tv::Error on bad input, leaving the world unchanged.
  MoveResult move(World& world, ItemId id, Vec2 goal, Filter filter = {},
                  MoveTrace* trace = nullptr);

  /// Forgets per-item state (the pixel mover's remainders), e.g. when a scene restarts.
  void reset() {
    remainder_.clear();
    contact_.clear();
  }

 private:
  MoveResult observedMove(WorldObserver& o, World& world, ItemId id, Vec2 goal, Filter filter,
                          MoveTrace* trace);
  MoveResult policyMove(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace);
  MoveResult discrete(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace,
                      std::vector<Collision>& out);
  MoveResult substep(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace);
  MoveResult pixel(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace);
  MoveResult adaptive(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace);
  bool settleFromOneScan(World& world, ItemId id, const Rect& start, Vec2 goal, Filter filter,
                         MoveTrace* trace, MoveResult& out);

  MoverSpec spec_;
  std::string name_;
  std::vector<Collision> collisions_;
  std::vector<Collision> pieceCollisions_;  // one substep piece's, before they join collisions_
  std::vector<ItemId> overlapping_;
  struct Remainder {
    Vec2 rest;
    std::uint32_t generation = 0;
  };
  std::vector<Remainder> remainder_;  // pixel: sub-pixel remainder per item slot
  struct Reached {  // adaptive: an item in a move's bounding box that its filter does not ignore
    ItemId id;
    Rect rect;
    ResponseId response = response::slide;
    bool crossed = false;  // passed through earlier in this move
  };
  std::vector<Reached> reached_;
  struct Contact {
    Vec2 normal;                   // of the last move's last collision
    std::uint32_t generation = 0;  // the item's + 1; 0: its last move met nothing
  };
  std::vector<Contact> contact_;  // adaptive, per item slot
};

}  // namespace tv
