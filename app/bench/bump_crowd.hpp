#pragma once
// bump-crowd: bump.lua's own benchmark scene, so that our figures compare with the numbers its
// users know. A square world of 16×16 static tiles: a solid one-tile border, plus random
// horizontal platforms 3–12 tiles long (clipped inside the border) until 30% of the grid is
// solid, one item per tile. N 8×8 movers at random free spots (overlapping no tile and no other
// mover), each with a random direction and a speed uniform in [30, 240] px/s. Every tick
// (dt 1/60) each mover makes one `World::move` with `slide` and flips the velocity component of
// each collision normal it reports (a component already leaving the obstacle is kept).
//
// Two filters: `tiles` (movers ignore each other) and `all` (movers also slide against each
// other). `tickBatched` moves the same bodies through one tv::Batch instead (moving versus
// moving, every pair sweeping by relative motion).

#include <cstdint>
#include <string>
#include <vector>

#include "tv/batch.hpp"
#include "tv/world.hpp"

namespace tv::bench {

enum class CrowdFilter : std::uint8_t { tiles, all };

[[nodiscard]] std::string filterName(CrowdFilter f);

struct BumpCrowdSpec {
  double worldSide = 2000.0;  ///< px; 6320 for 10^5 movers at the same density
  std::int64_t movers = 1000;
  double cellSize = 32.0;
  std::uint64_t seed = 1;
};

/// bump.lua's side for N movers: 2000 px up to 10^4, 6320 px (ten times the area) beyond.
[[nodiscard]] double bumpWorldSide(std::int64_t movers);

class BumpCrowd {
 public:
  /// Throws tv::Error when the movers do not fit.
  explicit BumpCrowd(const BumpCrowdSpec& spec);

  /// Every mover makes one World::move, in a fixed order.
  void tick(CrowdFilter filter, MoveTrace* trace = nullptr);
  /// Every mover through one Batch::step (mover–mover by relative motion under `filter`).
  void tickBatched(CrowdFilter filter);

  [[nodiscard]] const World& world() const { return world_; }
  [[nodiscard]] std::size_t movers() const { return movers_.size(); }
  [[nodiscard]] std::size_t tiles() const { return tiles_; }
  /// The world's heap (malloc'd bytes) right after it was filled, over its items.
  [[nodiscard]] double bytesPerItem() const { return bytesPerItem_; }
  /// Hash of the world and every mover's velocity: two runs that agree here behaved the same.
  [[nodiscard]] std::uint64_t stateHash() const;

 private:
  struct Mover {
    ItemId item;
    Vec2 position;  // kept beside the world, as a game keeps its entities' positions
    Vec2 velocity;
  };
  static Vec2 flip(Vec2 v, std::span<const Collision> collisions);

  World world_;
  std::vector<Mover> movers_;
  std::vector<BatchMove> batchMoves_;
  Batch batch_;
  std::size_t tiles_ = 0;
  std::uint32_t firstMoverSlot_ = 0;  // tiles come first, and nothing is ever removed
  double bytesPerItem_ = 0.0;
};

/// Instructions retired by this thread, from the CPU's counter where the kernel exposes it
/// (perf_event_open); `available()` is false elsewhere (VMs, containers).
class InstructionCounter {
 public:
  InstructionCounter();
  ~InstructionCounter();
  InstructionCounter(const InstructionCounter&) = delete;
  InstructionCounter& operator=(const InstructionCounter&) = delete;
  [[nodiscard]] bool available() const { return fd_ >= 0; }
  /// Instructions since construction (0 when unavailable).
  [[nodiscard]] std::uint64_t read() const;

 private:
  int fd_ = -1;
};

}  // namespace tv::bench
