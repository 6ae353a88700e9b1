#include "bump_crowd.hpp"

#include <linux/perf_event.h>
#include <malloc.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "tv/error.hpp"
#include "tv/sim/rng.hpp"

namespace tv::bench {

namespace {

constexpr double kTile = 16.0;
constexpr double kMover = 8.0;
constexpr double kDt = 1.0 / 60.0;

std::size_t heapInUse() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

}  // namespace

std::string filterName(CrowdFilter f) {
  return f == CrowdFilter::tiles ? "tiles" : "all";
}

double bumpWorldSide(std::int64_t movers) {
  return movers > 10000 ? 6320.0 : 2000.0;
}

BumpCrowd::BumpCrowd(const BumpCrowdSpec& spec) : world_(spec.cellSize) {
  const auto side = static_cast<std::int64_t>(spec.worldSide / kTile);
  if (side < 4) fail("bump-crowd", "the world must be at least 4 tiles wide");
  sim::Rng rng(spec.seed);
  // The grid: border, then platforms until 30% of it is solid.
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(side * side), 0);
  std::int64_t solidCount = 0;
  const auto set = [&](std::int64_t x, std::int64_t y) {
    std::uint8_t& s = solid[static_cast<std::size_t>(y * side + x)];
    if (s == 0) ++solidCount;
    s = 1;
  };
  for (std::int64_t k = 0; k < side; ++k) {
    set(k, 0);
    set(k, side - 1);
    set(0, k);
    set(side - 1, k);
  }
  const auto target = static_cast<std::int64_t>(std::ceil(0.3 * static_cast<double>(side * side)));
  const auto inner = static_cast<std::uint64_t>(side - 2);
  while (solidCount < target) {
    const auto length = 3 + static_cast<std::int64_t>(rng.below(10));
    const auto y = 1 + static_cast<std::int64_t>(rng.below(inner));
    const auto x0 = 1 + static_cast<std::int64_t>(rng.below(inner));
    for (std::int64_t x = x0; x < std::min(x0 + length, side - 1); ++x) set(x, y);
  }
  const std::size_t heap0 = heapInUse();
  for (std::int64_t y = 0; y < side; ++y) {
    for (std::int64_t x = 0; x < side; ++x) {
      if (solid[static_cast<std::size_t>(y * side + x)] == 0) continue;
      (void)world_.add({static_cast<double>(x) * kTile, static_cast<double>(y) * kTile, kTile, kTile});
      ++tiles_;
    }
  }
  firstMoverSlot_ = static_cast<std::uint32_t>(tiles_);
  // Movers at random free spots inside the border.
  const double lo = kTile, hi = static_cast<double>(side - 1) * kTile - kMover;
  const std::int64_t attempts = 1000 + 100 * spec.movers;
  std::int64_t tried = 0;
  while (static_cast<std::int64_t>(movers_.size()) < spec.movers) {
    if (++tried > attempts) {
      fail("bump-crowd", "could not place " + std::to_string(spec.movers) + " movers in a " +
                             formatNumber(spec.worldSide) + " px world");
    }
    const Rect r{rng.uniform(lo, hi), rng.uniform(lo, hi), kMover, kMover};
    if (world_.anyOverlap(r)) continue;
    const double angle = 2.0 * std::numbers::pi * rng.uniform();
    const double speed = rng.uniform(30.0, 240.0);
    movers_.push_back({world_.add(r), r.position(), Vec2{std::cos(angle), std::sin(angle)} * speed});
  }
  const std::size_t items = tiles_ + movers_.size();
  bytesPerItem_ = static_cast<double>(heapInUse() - heap0) / static_cast<double>(items);
}

Vec2 BumpCrowd::flip(Vec2 v, std::span<const Collision> collisions) {
  for (const Collision& c : collisions) {
    if (v.x * c.normal.x < 0.0) v.x = -v.x;
    if (v.y * c.normal.y < 0.0) v.y = -v.y;
  }
  return v;
}

void BumpCrowd::tick(CrowdFilter filter, MoveTrace* trace) {
  const std::uint32_t first = firstMoverSlot_;
  const auto tilesOnly = [first](ItemId, ItemId other) {
    return other.index >= first ? response::ignore : response::slide;
  };
  const Filter f = filter == CrowdFilter::tiles ? Filter(tilesOnly) : Filter::all(response::slide);
  MoveOptions options;
  options.trace = trace;
  for (Mover& m : movers_) {
    const MoveResult r = world_.move(m.item, m.position + m.velocity * kDt, f, options);
    m.position = r.position;
    m.velocity = flip(m.velocity, r.collisions);
  }
}

void BumpCrowd::tickBatched(CrowdFilter filter) {
  const std::uint32_t first = firstMoverSlot_;
  const auto tilesOnly = [first](ItemId, ItemId other) {
    return other.index >= first ? response::ignore : response::slide;
  };
  const Filter f = filter == CrowdFilter::tiles ? Filter(tilesOnly) : Filter::all(response::slide);
  batchMoves_.clear();
  for (const Mover& m : movers_)
    batchMoves_.push_back({m.item, m.position + m.velocity * kDt});
  batch_.step(world_, batchMoves_, f);
  for (std::size_t i = 0; i < movers_.size(); ++i) {
    const BatchOutcome out = batch_.outcome(i);
    movers_[i].position = out.position;
    movers_[i].velocity = flip(movers_[i].velocity, out.collisions);
  }
}

std::uint64_t BumpCrowd::stateHash() const {
  std::uint64_t h = world_.stateHash();
  for (const Mover& m : movers_) {
    for (const double v : {m.velocity.x, m.velocity.y}) {
      h ^= std::bit_cast<std::uint64_t>(v);
      h *= 0x100000001B3ull;
    }
  }
  return h;
}

InstructionCounter::InstructionCounter() {
  perf_event_attr attr{};
  attr.type = PERF_TYPE_HARDWARE;
  attr.size = sizeof(attr);
  attr.config = PERF_COUNT_HW_INSTRUCTIONS;
  attr.exclude_kernel = 1;
  attr.exclude_hv = 1;
  fd_ = static_cast<int>(syscall(SYS_perf_event_open, &attr, 0, -1, -1, 0));
  if (fd_ >= 0 && ioctl(fd_, PERF_EVENT_IOC_ENABLE, 0) != 0) {
    close(fd_);
    fd_ = -1;
  }
}

InstructionCounter::~InstructionCounter() {
  if (fd_ >= 0) close(fd_);
}

std::uint64_t InstructionCounter::read() const {
  std::uint64_t n = 0;
  if (fd_ < 0 || ::read(fd_, &n, sizeof(n)) != static_cast<ssize_t>(sizeof(n))) return 0;
  return n;
}

}  // namespace tv::bench
