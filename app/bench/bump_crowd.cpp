#include "bump_crowd.hpp"

#include <linux/perf_event.h>
#include <malloc.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <bit>

#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"

namespace tv::bench {

namespace {

std::size_t heapInUse() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

}  // namespace

std::string filterName(CrowdFilter f) {
  return f == CrowdFilter::tiles ? "tiles" : "all";
}

BumpCrowd::BumpCrowd(const BumpCrowdSpec& spec) : world_(spec.cellSize) {
  const sim::SceneDef& scene = sim::findScene("bump-crowd");
  sim::Params p = scene.defaults();
  p.set(sim::param::count, static_cast<double>(spec.movers));
  p.set(sim::param::cell, spec.cellSize);
  p.set(sim::param::seed, static_cast<double>(spec.seed % 1000000));
  const sim::SceneSetup s = scene.build(p);
  dt_ = p.get(sim::param::dt);
  movers_.reserve(s.bodies.size());  // the benchmark's own list, outside the world's bytes
  const std::size_t heap0 = heapInUse();
  for (const sim::Solid& solid : s.solids) (void)world_.add(solid.rect);
  tiles_ = s.solids.size();
  firstMoverSlot_ = static_cast<std::uint32_t>(tiles_);
  for (const sim::Body& b : s.bodies)
    movers_.push_back({world_.add(b.rect), b.rect.position(), b.velocity});
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
    const MoveResult r = world_.move(m.item, m.position + m.velocity * dt_, f, options);
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
  for (const Mover& m : movers_) batchMoves_.push_back({m.item, m.position + m.velocity * dt_});
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
