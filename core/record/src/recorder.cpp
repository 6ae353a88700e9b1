// The recorder: encodes each reported call into the current frame's chunk and writes the chunk
// (length, CRC-32, payload) when the frame ends, flushed, so a crash loses at most one frame.

#include "tv/record/recorder.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unordered_map>

#include "format.hpp"
#include "tv/batch.hpp"
#include "tv/mover.hpp"
#include "tv/world.hpp"

namespace tv {

namespace {

bool sameSpec(const MoverSpec& a, const MoverSpec& b) {
  return a.kind == b.kind && a.inner == b.inner && rec::sameBits(a.maxStep, b.maxStep) &&
         rec::sameBits(a.safetyFraction, b.safetyFraction);
}

}  // namespace

struct Recorder::Impl {
  RecorderOptions options;
  std::FILE* file = nullptr;
  std::string path;
  World* world = nullptr;
  FixedStep* step = nullptr;
  bool started = false;  // header and frame 0 written
  bool stopped = false;  // closed, or an I/O error
  rec::Encoder enc;
  std::uint64_t frame = 0;
  std::vector<rec::Answer> answers;
  std::vector<Leg> legs;
  struct MoverEntry {
    std::uint32_t id;
    MoverSpec spec;
  };
  std::unordered_map<const Mover*, MoverEntry> movers;
  const Mover* lastMover = nullptr;  // most games move everything with one mover: skip the map
  MoverEntry lastEntry{};
  std::vector<MoverSpec> specs;  // by id
  std::vector<bool> defined;     // since the last keyframe
  struct PendingLabel {
    ItemId id;
    std::string label, category;
  };
  std::vector<PendingLabel> pending;  // labels given before attach
};

Recorder::Recorder(const std::string& path, RecorderOptions options)
    : impl_(std::make_unique<Impl>()) {
  if (options.keyframeEvery < 1 || options.keyframeEvery > (1u << 20)) {
    fail("tv::Recorder", "keyframeEvery must be in [1, 2^20], but was " +
                             std::to_string(options.keyframeEvery));
  }
  impl_->options = options;
  impl_->path = path;
  impl_->file = std::fopen(path.c_str(), "wb");
  if (!impl_->file) {
    fail("tv::Recorder", "cannot write '" + path + "': " + std::strerror(errno));
  }
}

Recorder::Recorder(RecorderOptions options) : impl_(std::make_unique<Impl>()) {
  if (options.keyframeEvery < 1 || options.keyframeEvery > (1u << 20)) {
    fail("tv::Recorder", "keyframeEvery must be in [1, 2^20], but was " +
                             std::to_string(options.keyframeEvery));
  }
  impl_->options = options;
}

Recorder::~Recorder() {
  try {
    close();
  } catch (...) {  // a destructor must not throw; error() already says what went wrong
  }
}

void Recorder::writeBytes(const std::uint8_t* data, std::size_t n) {
  Impl& impl = *impl_;
  std::vector<std::uint8_t>& memory = memory_;
  std::string& error = error_;
  if (impl.file) {
    if (std::fwrite(data, 1, n, impl.file) != n) {
      error = "tv::Recorder: writing '" + impl.path + "' failed: " + std::strerror(errno);
      impl.stopped = true;
    }
  } else {
    memory.insert(memory.end(), data, data + n);
  }
}

void Recorder::attached(const World& world) {
  Impl& d = *impl_;
  if (d.started || d.stopped) {
    // One recording, one attachment: another would need another header.
    if (error_.empty()) error_ = "tv::Recorder: attached again after it was closed; make a new Recorder";
    return;
  }
  d.world = const_cast<World*>(&world);  // attach() took the world non-const
  d.started = true;
  rec::Out h;
  for (const char c : rec::kMagic) h.u8(static_cast<std::uint8_t>(c));
  h.b.push_back(static_cast<std::uint8_t>(rec::kVersionMajor & 0xFF));
  h.b.push_back(static_cast<std::uint8_t>(rec::kVersionMajor >> 8));
  h.b.push_back(static_cast<std::uint8_t>(rec::kVersionMinor & 0xFF));
  h.b.push_back(static_cast<std::uint8_t>(rec::kVersionMinor >> 8));
  h.f64(world.cellSize());
  h.u32(d.options.keyframeEvery);
  h.u32(0);  // flags, none yet
  h.u32(static_cast<std::uint32_t>(::crc32(0, h.b.data(), static_cast<uInt>(h.b.size()))));
  writeBytes(h.b.data(), h.b.size());
  size_ += h.b.size();
  d.enc.model.cellSize = world.cellSize();
  d.frame = 0;
  // Begin frame 0 with the world as it is.
  d.enc.out.b.clear();
  d.enc.out.varint(0);
  d.enc.out.u8(1);
  d.enc.keyframe(world.state());
  for (const Impl::PendingLabel& l : d.pending) d.enc.label(l.id, l.label, l.category);
  d.pending.clear();
}

void Recorder::detached(const World&) {
  Impl& d = *impl_;
  d.world = nullptr;  // close() must not detach again
  close();
}

void Recorder::frame() {
  Impl& d = *impl_;
  if (!d.started || d.stopped) return;
  std::vector<std::uint8_t>& payload = d.enc.out.b;
  std::uint8_t head[8];
  const auto len = static_cast<std::uint32_t>(payload.size());
  const auto crc = static_cast<std::uint32_t>(::crc32(0, payload.data(), static_cast<uInt>(payload.size())));
  for (int i = 0; i < 4; ++i) {
    head[i] = static_cast<std::uint8_t>(len >> (8 * i));
    head[4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  }
  writeBytes(head, 8);
  writeBytes(payload.data(), payload.size());
  if (d.file && !d.stopped && std::fflush(d.file) != 0) {
    error_ = "tv::Recorder: writing '" + d.path + "' failed: " + std::strerror(errno);
    d.stopped = true;
  }
  size_ += 8 + payload.size();
  ++frames_;
  ++d.frame;
  const std::size_t last = payload.size();
  payload.clear();
  payload.reserve(last + last / 4 + 256);  // the next frame is likely as big: grow once
  d.enc.out.varint(d.frame);
  const bool key = d.frame % d.options.keyframeEvery == 0;
  d.enc.out.u8(key ? 1 : 0);
  if (key && d.world) {
    d.enc.keyframe(d.world->state());
    d.defined.assign(d.specs.size(), false);
  }
}

void Recorder::attach(FixedStep& step) {
  step.attach(this);
  impl_->step = &step;
}

void Recorder::label(ItemId id, std::string_view label, std::string_view category) {
  Impl& d = *impl_;
  if (d.stopped) return;
  if (!d.started) {
    d.pending.push_back({id, std::string(label.substr(0, rec::kMaxName)),
                         std::string(category.substr(0, rec::kMaxName))});
    return;
  }
  d.enc.label(id, label, category);
}

void Recorder::close() {
  Impl& d = *impl_;
  if (d.step) {
    d.step->attach(nullptr);
    d.step = nullptr;
  }
  if (d.world) {
    World* w = d.world;
    d.world = nullptr;
    if (w->observer() == this) w->detach();  // calls detached(), which comes back here
  }
  if (d.started && !d.stopped) {
    // The last frame, then the end mark: a file without it was cut short.
    const std::uint64_t framesBefore = frames_;
    frame();
    (void)framesBefore;
    std::uint8_t end[8] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) end[4 + i] = static_cast<std::uint8_t>(rec::kEndMark >> (8 * i));
    writeBytes(end, 8);
    size_ += 8;
    d.enc.out.b.clear();
  }
  d.stopped = true;
  if (d.file) {
    if (std::fclose(d.file) != 0 && error_.empty()) {
      error_ = "tv::Recorder: closing '" + d.path + "' failed: " + std::strerror(errno);
    }
    d.file = nullptr;
  }
}

// [SECTION] observer reports ----------------------------------------------------------------------

#define TV_RECORDING()                   \
  Impl& d = *impl_;                      \
  if (!d.started || d.stopped) return;   \
  ++calls_

void Recorder::added(ItemId id, const Rect& r) {
  TV_RECORDING();
  const std::size_t expect = d.enc.model.freeSlots.empty() ? d.enc.model.slots.size()
                                                           : d.enc.model.freeSlots.back();
  if (id.index != expect) {
    error_ = "tv::Recorder: lost track of the world's slots (add returned " +
             std::to_string(id.index) + ", expected " + std::to_string(expect) + ")";
    d.stopped = true;
    return;
  }
  d.enc.add(id, r);
}

void Recorder::removed(ItemId id) {
  TV_RECORDING();
  d.enc.remove(id);
}

void Recorder::updated(ItemId id, const Rect& r) {
  TV_RECORDING();
  d.enc.update(id, r);
}

void Recorder::moved(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  ++moves_;
  d.enc.move(CallKind::move, id, goal, o, r, d.answers, d.legs);
  d.answers.clear();
  d.legs.clear();
}

void Recorder::checked(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  d.enc.move(CallKind::check, id, goal, o, r, d.answers, d.legs);
  d.answers.clear();
  d.legs.clear();
}

void Recorder::projected(const Rect& rect, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  d.enc.project(rect, goal, o, r, d.answers, d.legs);
  d.answers.clear();
  d.legs.clear();
}

void Recorder::queriedRect(const Rect& r, ItemId skip, std::span<const ItemId> found) {
  TV_RECORDING();
  d.enc.queryRect(r, skip, found);
}

void Recorder::queriedPoint(Vec2 p, std::span<const ItemId> found) {
  TV_RECORDING();
  d.enc.queryPoint(p, found);
}

void Recorder::queriedSegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits) {
  TV_RECORDING();
  d.enc.querySegment(a, b, hits);
}

void Recorder::askedOverlap(const Rect& r, ItemId skip, bool any) {
  TV_RECORDING();
  d.enc.anyOverlap(r, skip, any, d.answers);
  d.answers.clear();
}

void Recorder::responseAdded(std::string_view name, ResponseId) {
  TV_RECORDING();
  d.enc.addResponse(name);
}

void Recorder::moverMoved(const Mover& mover, ItemId id, const Rect& start, Vec2 goal,
                          const MoveResult& r) {
  TV_RECORDING();
  ++moves_;
  const MoverSpec& spec = mover.spec();
  std::uint32_t mid;
  auto it = d.lastMover == &mover ? d.movers.end() : d.movers.find(&mover);
  if (d.lastMover == &mover && sameSpec(d.lastEntry.spec, spec)) {
    mid = d.lastEntry.id;
  } else if (it != d.movers.end() && sameSpec(it->second.spec, spec)) {
    mid = it->second.id;
  } else if (d.specs.size() < rec::kMaxMovers) {
    mid = static_cast<std::uint32_t>(d.specs.size());
    d.specs.push_back(spec);
    d.defined.push_back(false);
    d.movers[&mover] = {mid, spec};
  } else {  // a game that makes a mover per move: share the ids by spec
    mid = 0;
    while (mid < d.specs.size() && !sameSpec(d.specs[mid], spec)) ++mid;
    if (mid == d.specs.size()) {
      error_ = "tv::Recorder: more than 4096 different movers";
      d.stopped = true;
      return;
    }
  }
  d.lastMover = &mover;
  d.lastEntry = {mid, spec};
  const bool define = !d.defined[mid];
  d.defined[mid] = true;
  if (!(d.enc.model.slots[id.index].rect == start)) {
    error_ = "tv::Recorder: lost track of item " + std::to_string(id.index) + "'s position";
    d.stopped = true;
    return;
  }
  d.enc.moverMove(mid, define, spec, id, start, goal, r, d.answers, d.legs);
  d.answers.clear();
  d.legs.clear();
}

void Recorder::batchStepped(std::span<const BatchMove> moves, int maxEvents, const Batch& batch) {
  TV_RECORDING();
  moves_ += moves.size();
  d.enc.batch(moves, maxEvents, batch, d.answers, d.legs);
  d.answers.clear();
  d.legs.clear();
}

void Recorder::advanced(double frameTime, int ticks) {
  Impl& d = *impl_;
  if (!d.started || d.stopped) return;
  frame();
  d.enc.advance(frameTime, ticks);
}

void Recorder::filtered(ItemId item, ItemId other, ResponseId answer) {
  Impl& d = *impl_;
  if (d.stopped) return;
  d.answers.push_back({item, other, answer});
}

void Recorder::responded(const Collision&, Vec2, const Leg& leg) {
  Impl& d = *impl_;
  if (d.stopped || !busy()) return;  // a direct World::respond is not part of a call
  d.legs.push_back(leg);
}

void Recorder::failed() {
  impl_->answers.clear();
  impl_->legs.clear();
}

#undef TV_RECORDING

}  // namespace tv
