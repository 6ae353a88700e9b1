#pragma once
// bump-crowd: bump.lua's own benchmark scene (tv::sim's "bump-crowd" builds the layout: a
// 2000 px world of 16×16 tiles, 30% solid, up to 10^4 movers; 6320 px beyond), driven the way
// bump.lua's benchmark drives it: every tick (dt 1/60) each 8×8 mover makes one `World::move`
// with `slide` and flips the velocity component of each collision normal it reports (a
// component already leaving the obstacle is kept) — no Simulation, no rules, no snapshots.
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
  std::int64_t movers = 1000;
  double cellSize = 32.0;
  std::uint64_t seed = 1;
};

class BumpCrowd {
 public:
  /// Throws tv::Error when the movers do not fit.
  explicit BumpCrowd(const BumpCrowdSpec& spec);

  /// Every mover makes one World::move, in a fixed order.
  void tick(CrowdFilter filter, MoveTrace* trace = nullptr);
  /// Every mover through one Batch::step (mover–mover by relative motion under `filter`).
  void tickBatched(CrowdFilter filter);

  [[nodiscard]] const World& world() const { return world_; }
  /// To attach a Recorder (tv-bench record).
  [[nodiscard]] World& world() { return world_; }
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
  double dt_ = 1.0 / 60.0;
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
