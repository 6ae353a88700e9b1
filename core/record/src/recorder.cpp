// The recorder, on the game's side: each observer report is copied as it came into the capture
// pipe (capture.hpp) — no encoding, no checksum, no I/O here — and a frame's end hands the
// frame over to the writer (writer.cpp), which encodes and writes it on its own thread.
//
// Index: [SECTION] life · [SECTION] frames · [SECTION] observer reports

#include "tv/record/recorder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unordered_map>

#include "capture.hpp"
#include "crash_flush.hpp"
#include "format.hpp"
#include "live_sink.hpp"
#include "tv/batch.hpp"
#include "tv/mover.hpp"
#include "tv/world.hpp"
#include "writer.hpp"

namespace tv {

namespace {

bool sameSpec(const MoverSpec& a, const MoverSpec& b) {
  return a.kind == b.kind && a.inner == b.inner && rec::sameBits(a.maxStep, b.maxStep) &&
         rec::sameBits(a.safetyFraction, b.safetyFraction);
}

void checkOptions(const RecorderOptions& options) {
  if (options.keyframeEvery < 1 || options.keyframeEvery > (1u << 20)) {
    fail("tv::Recorder",
         "keyframeEvery must be in [1, 2^20], but was " + std::to_string(options.keyframeEvery));
  }
}

}  // namespace

struct Recorder::Impl {
  RecorderOptions options;
  World* world = nullptr;
  FixedStep* step = nullptr;
  bool started = false;  // header and frame 0 handed over
  bool stopped = false;  // closed, or the writer failed: nothing more is captured
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
  struct PendingLabel {
    ItemId id;
    std::string label, category;
  };
  std::vector<PendingLabel> pending;  // labels given before attach
  std::vector<rec::BodyRec> bodies;   // batch scratch
  std::vector<Collision> batchCollisions;

  std::unique_ptr<rec::LiveSink> live;  // the writer and the pipe's thread use it: last to go
  bool liveOnly = false;                // no file, no memory: copy calls only while streaming
  bool capturing = true;                // false while a live-only recorder has no receiver
  std::unique_ptr<rec::Writer> writer;
  std::unique_ptr<rec::Pipe> pipe;  // declared last: stopped (its thread joined) first
  rec::CrashWatch crash;
  bool watched = false;

  void open(std::FILE* file, const std::string& path, std::vector<std::uint8_t>* memory) {
    writer = std::make_unique<rec::Writer>(options.keyframeEvery, file, path, memory, live.get());
    pipe = std::make_unique<rec::Pipe>([w = writer.get()](const rec::Block& b) { w->consume(b); },
                                       options.background, options.maxQueueBytes);
    if (file && options.flushOnCrash) {
      crash.written = &writer->framesWritten();
      crash.writer = pipe->writerThread();
      crash.writerSystemId = &pipe->writerSystemId();
      rec::watchForCrash(&crash);
      watched = true;
    }
  }

  // -- capture ------------------------------------------------------------------------------
  // A record: head, body, then each array padded to 8 bytes (capture.hpp).
  template <class Body, class... A>
  void put(rec::Tag tag, std::uint8_t flag, const Body& body, std::span<const A>... arrays) {
    const std::size_t bytes = sizeof(rec::Head) + rec::round8(sizeof(Body)) +
                              (std::size_t{0} + ... + rec::round8(arrays.size_bytes()));
    std::byte* p = pipe->reserve(bytes);
    const rec::Head h{tag, flag, 0, static_cast<std::uint32_t>(bytes)};
    std::memcpy(p, &h, sizeof h);
    p += sizeof h;
    std::memcpy(p, &body, sizeof body);
    p += rec::round8(sizeof body);
    (
        [&] {
          if (!arrays.empty()) std::memcpy(p, arrays.data(), arrays.size_bytes());
          p += rec::round8(arrays.size_bytes());
        }(),
        ...);
  }
  void text(rec::Tag tag, ItemId id, std::string_view a, std::string_view b) {
    a = a.substr(0, rec::kMaxName);
    b = b.substr(0, rec::kMaxName);
    put(tag, 0,
        rec::TextRec{id, static_cast<std::uint32_t>(a.size()),
                     static_cast<std::uint32_t>(b.size())},
        std::span<const char>(a.data(), a.size()), std::span<const char>(b.data(), b.size()));
  }
  // The hot one (every move of every body): most moves met nothing and asked nothing, and
  // their record is a fixed size, written in place.
  void move(rec::Tag tag, ItemId id, std::uint32_t mover, const Rect& rect, Vec2 goal,
            const MoveOptions* o, const MoveResult& r) {
    constexpr std::size_t kFixed = sizeof(rec::Head) + rec::round8(sizeof(rec::MoveRec));
    const int maxResponses = o ? o->maxResponses : rec::kDefaultMaxResponses;
    const BroadPhase broad = o ? o->broad : BroadPhase::swept;
    const MoveSemantics semantics = o ? o->semantics : MoveSemantics::tunnelvision;
    if (r.collisions.empty() && answers.empty() && legs.empty()) [[likely]] {
      std::byte* p = pipe->reserve(kFixed);
      ::new (p) rec::Head{tag, 0, 0, static_cast<std::uint32_t>(kFixed)};
      ::new (p + sizeof(rec::Head))
          rec::MoveRec{id, mover, maxResponses, rect, goal, r.position, 0, 0, 0, broad, semantics};
      return;
    }
    moveWithArrays(tag,
                   rec::MoveRec{id, mover, maxResponses, rect, goal, r.position,
                                static_cast<std::uint32_t>(r.collisions.size()),
                                static_cast<std::uint32_t>(answers.size()),
                                static_cast<std::uint32_t>(legs.size()), broad, semantics},
                   r.collisions);
  }
  [[gnu::noinline]] void moveWithArrays(rec::Tag tag, const rec::MoveRec& m,
                                        std::span<const Collision> collisions) {
    put(tag, 0, m, collisions, std::span<const rec::Answer>(answers), std::span<const Leg>(legs));
    answers.clear();
    legs.clear();
  }
  // The id of a mover the last move did not use; false past 4096 different movers.
  [[gnu::noinline]] bool moverId(const Mover& mover, std::uint32_t& mid) {
    const MoverSpec& spec = mover.spec();
    auto it = movers.find(&mover);
    if (it != movers.end() && sameSpec(it->second.spec, spec)) {
      mid = it->second.id;
    } else if (specs.size() < rec::kMaxMovers) {
      // An id per Mover object: a replay keeps each one's state (a pixel mover's remainders).
      mid = static_cast<std::uint32_t>(specs.size());
      specs.push_back(spec);
      movers[&mover] = {mid, spec};
      put(rec::Tag::moverSpec, 0, rec::SpecRec{mid, spec});
    } else {  // a game that makes a mover per move: share the ids by spec
      mid = 0;
      while (mid < specs.size() && !sameSpec(specs[mid], spec)) ++mid;
      if (mid == specs.size()) return false;
    }
    lastMover = &mover;
    lastEntry = {mid, spec};
    return true;
  }
  // The writer failed (it says why in error()): stop capturing for it.
  bool writerFailed() {
    if (writer && writer->failed()) stopped = true;
    return stopped;
  }
};

// [SECTION] life ----------------------------------------------------------------------------------

Recorder::Recorder(const std::string& path, RecorderOptions options)
    : impl_(std::make_unique<Impl>()) {
  checkOptions(options);
  impl_->options = options;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) fail("tv::Recorder", "cannot write '" + path + "': " + std::strerror(errno));
  impl_->open(file, path, nullptr);
}

Recorder::Recorder(RecorderOptions options) : impl_(std::make_unique<Impl>()) {
  checkOptions(options);
  impl_->options = options;
  impl_->open(nullptr, {}, &memory_);
}

Recorder::Recorder(const LiveOptions& live, RecorderOptions options)
    : impl_(std::make_unique<Impl>()) {
  checkOptions(options);
  impl_->options = options;
  impl_->live = std::make_unique<rec::LiveSink>(live);
  impl_->liveOnly = true;
  impl_->capturing = false;
  impl_->open(nullptr, {}, nullptr);
}

void Recorder::stream(const LiveOptions& live) {
  Impl& d = *impl_;
  if (d.started || d.stopped) {
    fail("tv::Recorder::stream", "call it before the recorder attaches to a world");
  }
  if (d.live) fail("tv::Recorder::stream", "this recorder streams already");
  d.live = std::make_unique<rec::LiveSink>(live);
  d.writer->setLive(d.live.get());
}

LiveStatus Recorder::liveStatus() const {
  const Impl& d = *impl_;
  return d.live ? d.live->status() : LiveStatus{};
}

Recorder::~Recorder() {
  try {
    close();
  } catch (...) {  // a destructor must not throw; error() already says what went wrong
  }
}

void Recorder::attached(const World& world) {
  Impl& d = *impl_;
  if (d.started || d.stopped) {
    // One recording, one attachment: another would need another header.
    if (error_.empty())
      error_ = "tv::Recorder: attached again after it was closed; make a new Recorder";
    return;
  }
  d.world = const_cast<World*>(&world);  // attach() took the world non-const
  d.started = true;
  std::uint8_t flags = rec::kKeyframeNow;
  if (d.live) {
    (void)d.live->takeKeyframeRequest();  // frame 0 is a keyframe anyway
    if (d.liveOnly) d.capturing = d.live->connected();
    if (!d.capturing) flags |= rec::kNoLiveStart;  // nobody listens: frame 0 will lack calls
  }
  // Frame 0 opens with the world as it is.
  d.put(rec::Tag::start, flags, rec::StateRec{new WorldState(world.state()), world.cellSize()});
  for (const Impl::PendingLabel& l : d.pending) d.text(rec::Tag::label, l.id, l.label, l.category);
  d.pending.clear();
}

void Recorder::detached(const World&) {
  Impl& d = *impl_;
  d.world = nullptr;  // close() must not detach again
  close();
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
  d.text(rec::Tag::label, id, label, category);
}

void Recorder::sourceGone(const void* source) {
  // The game destroyed its world or FixedStep first: nothing to detach from any more.
  Impl& d = *impl_;
  if (source == d.world) d.world = nullptr;
  if (source == d.step) d.step = nullptr;
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
  if (!d.pipe) return;  // closed already
  if (d.started && !d.stopped) {
    // The last frame, then the end mark: a file without it was cut short.
    d.put(rec::Tag::close, 0, rec::StateRec{nullptr, 0.0});
    ++frames_;
    d.crash.handed.fetch_add(1, std::memory_order_release);
  }
  d.stopped = true;
  d.pipe->stop();
  if (d.live) d.live->stop();  // after the writer: the last frame and the end mark go out
  if (d.watched) {
    rec::unwatch(&d.crash);
    d.watched = false;
  }
  size_ = d.writer->size();
  stalls_ = d.pipe->stalls();
  if (error_.empty()) error_ = d.writer->error();
  d.pipe.reset();
  d.writer.reset();  // closes the file if the close record never came
}

void Recorder::sync() const {
  Impl& d = *impl_;
  if (d.pipe) d.pipe->drain();
}

bool Recorder::ok() const {
  return error().empty();
}

const std::string& Recorder::error() const {
  const Impl& d = *impl_;
  if (error_.empty() && d.writer && d.writer->failed()) error_ = d.writer->error();
  return error_;
}

std::uint64_t Recorder::size() const {
  const Impl& d = *impl_;
  if (!d.writer) return size_;
  sync();
  return d.writer->size();
}

const std::vector<std::uint8_t>& Recorder::bytes() const {
  sync();
  return memory_;
}

std::uint64_t Recorder::stalls() const {
  const Impl& d = *impl_;
  return d.pipe ? d.pipe->stalls() : stalls_;
}

// [SECTION] frames --------------------------------------------------------------------------------

void Recorder::frame() {
  Impl& d = *impl_;
  if (!d.started || d.stopped || d.writerFailed()) return;
  ++d.frame;
  bool key = d.frame % d.options.keyframeEvery == 0;
  std::uint8_t flags = 0;
  if (d.live) {
    if (d.live->takeKeyframeRequest()) {
      key = true;  // a receiver joined (its run begins here) or asked for one
      flags = rec::kLiveStart;
    }
    if (d.liveOnly) {
      if (!d.live->connected()) {
        // Nobody listens: nothing is copied until someone does. The frame that begins now
        // will lack its calls, so it ends the copying without a keyframe to start a run with.
        if (d.capturing) {
          d.put(rec::Tag::frame, rec::kNoLiveStart, rec::StateRec{nullptr, 0.0});
          d.pipe->handOver();
          d.capturing = false;
        }
        return;
      }
      if (!d.capturing) key = true;  // the first frame copied since: a keyframe
      d.capturing = true;
    }
  }
  if (key) flags |= rec::kKeyframeNow;
  d.put(rec::Tag::frame, flags,
        rec::StateRec{key && d.world ? new WorldState(d.world->state()) : nullptr, 0.0});
  ++frames_;
  d.crash.handed.fetch_add(1, std::memory_order_release);
  d.pipe->handOver();
  if (d.live) d.live->waitWhilePaused();  // a receiver that holds the game holds it here
}

// [SECTION] observer reports ----------------------------------------------------------------------

#define TV_RECORDING()                                 \
  Impl& d = *impl_;                                    \
  if (!d.started || d.stopped || !d.capturing) return; \
  ++calls_

void Recorder::added(ItemId id, const Rect& r) {
  TV_RECORDING();
  d.put(rec::Tag::add, 0, rec::ItemRectRec{id, r});
}

void Recorder::removed(ItemId id) {
  TV_RECORDING();
  d.put(rec::Tag::remove, 0, rec::ItemRectRec{id, {}});
}

void Recorder::updated(ItemId id, const Rect& r) {
  TV_RECORDING();
  d.put(rec::Tag::update, 0, rec::ItemRectRec{id, r});
}

void Recorder::moved(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  ++moves_;
  d.move(rec::Tag::move, id, 0, {}, goal, &o, r);
}

void Recorder::checked(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  d.move(rec::Tag::check, id, 0, {}, goal, &o, r);
}

void Recorder::projected(const Rect& rect, Vec2 goal, const MoveOptions& o, const MoveResult& r) {
  TV_RECORDING();
  d.move(rec::Tag::project, {}, 0, rect, goal, &o, r);
}

void Recorder::queriedRect(const Rect& r, ItemId skip, std::span<const ItemId> found) {
  TV_RECORDING();
  d.put(rec::Tag::queryRect, 0,
        rec::QueryRec{r, {}, {}, skip, static_cast<std::uint32_t>(found.size()), 0, false}, found);
}

void Recorder::queriedPoint(Vec2 p, std::span<const ItemId> found) {
  TV_RECORDING();
  d.put(rec::Tag::queryPoint, 0,
        rec::QueryRec{{}, p, {}, {}, static_cast<std::uint32_t>(found.size()), 0, false}, found);
}

void Recorder::queriedSegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits) {
  TV_RECORDING();
  d.put(rec::Tag::querySegment, 0,
        rec::QueryRec{{}, a, b, {}, static_cast<std::uint32_t>(hits.size()), 0, false}, hits);
}

void Recorder::askedOverlap(const Rect& r, ItemId skip, bool any) {
  TV_RECORDING();
  d.put(rec::Tag::anyOverlap, 0,
        rec::QueryRec{r, {}, {}, skip, 0, static_cast<std::uint32_t>(d.answers.size()), any},
        std::span<const ItemId>(), std::span<const rec::Answer>(d.answers));
  d.answers.clear();
}

void Recorder::contacted(ItemId item, bool forget, std::span<const ContactEvent> events) {
  TV_RECORDING();
  d.put(rec::Tag::contacts, 0,
        rec::ContactsRec{item, static_cast<std::uint32_t>(events.size()),
                         static_cast<std::uint32_t>(d.answers.size()), forget},
        events, std::span<const rec::Answer>(d.answers));
  d.answers.clear();
}

void Recorder::cornerNudged(ItemId item, const CornerNudge& nudge) {
  TV_RECORDING();
  d.put(rec::Tag::cornerNudge, 0, rec::NudgeRec{item, nudge.hit.other, nudge.hit.touch, nudge.dx});
}

void Recorder::responseAdded(std::string_view name, ResponseId) {
  TV_RECORDING();
  d.text(rec::Tag::addResponse, {}, name, {});
}

void Recorder::moverMoved(const Mover& mover, ItemId id, const Rect& start, Vec2 goal,
                          const MoveResult& r) {
  TV_RECORDING();
  ++moves_;
  const MoverSpec& spec = mover.spec();
  std::uint32_t mid;
  if (d.lastMover == &mover && sameSpec(d.lastEntry.spec, spec)) [[likely]] {
    mid = d.lastEntry.id;
  } else if (!d.moverId(mover, mid)) {
    error_ = "tv::Recorder: more than 4096 different movers";
    d.stopped = true;
    return;
  }
  d.move(rec::Tag::moverMove, id, mid, start, goal, nullptr, r);
}

void Recorder::batchStepped(std::span<const BatchMove> moves, int maxEvents, const Batch& batch) {
  TV_RECORDING();
  moves_ += moves.size();
  d.bodies.clear();
  d.batchCollisions.clear();
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const BatchOutcome o = batch.outcome(i);
    d.bodies.push_back({o.position, static_cast<std::uint32_t>(d.batchCollisions.size()),
                        static_cast<std::uint32_t>(o.collisions.size())});
    d.batchCollisions.insert(d.batchCollisions.end(), o.collisions.begin(), o.collisions.end());
  }
  d.put(rec::Tag::batchStep, 0,
        rec::BatchRec{maxEvents, static_cast<std::uint32_t>(moves.size()),
                      static_cast<std::uint32_t>(d.batchCollisions.size()),
                      static_cast<std::uint32_t>(d.answers.size()),
                      static_cast<std::uint32_t>(d.legs.size())},
        moves, std::span<const rec::BodyRec>(d.bodies),
        std::span<const Collision>(d.batchCollisions), std::span<const rec::Answer>(d.answers),
        std::span<const Leg>(d.legs));
  d.answers.clear();
  d.legs.clear();
}

void Recorder::advanced(double frameTime, int ticks) {
  Impl& d = *impl_;
  if (!d.started || d.stopped) return;
  frame();
  if (d.stopped || !d.capturing) return;
  d.put(rec::Tag::advance, 0, rec::AdvanceRec{frameTime, ticks});
}

void Recorder::filtered(ItemId item, ItemId other, ResponseId answer) {
  Impl& d = *impl_;
  if (d.stopped || !d.capturing) return;
  d.answers.push_back({item, other, answer});
}

void Recorder::responded(const Collision&, Vec2, const Leg& leg) {
  Impl& d = *impl_;
  // A direct World::respond is not part of a call.
  if (d.stopped || !d.capturing || !busy()) return;
  d.legs.push_back(leg);
}

void Recorder::failed() {
  impl_->answers.clear();
  impl_->legs.clear();
}

#undef TV_RECORDING

}  // namespace tv
