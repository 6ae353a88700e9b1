#pragma once
// What the game's thread hands the recorder's writer: each observer report copied, as it came,
// into a record of a block of memory (no encoding, no checksum, no I/O on the game's thread), and
// the blocks handed over through a bounded queue to the writer's thread (writer.hpp), which
// encodes them with the same Encoder and so writes the same bytes.
//
// A record is a Head, a fixed body, then the body's arrays, each padded to 8 bytes so that the
// writer reads Collisions, Answers and Legs in place. These records never leave the process:
// their layout is free to change (FORMAT.md is the file's).
//
// Index: [SECTION] records · [SECTION] the pipe

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <type_traits>
#include <vector>

#include "format.hpp"

namespace tv::rec {

// [SECTION] records -------------------------------------------------------------------------------

enum class Tag : std::uint8_t {
  start,      // attached: the world's state (owned); header and frame 0 follow
  frame,      // the current frame ends, the next begins (a keyframe when a state is given)
  moverSpec,  // a mover id's spec, the first time the game uses it
  add,
  remove,
  update,
  move,
  check,
  project,
  queryRect,
  queryPoint,
  querySegment,
  anyOverlap,
  addResponse,
  moverMove,
  batchStep,
  label,
  advance,
  contacts,
  cornerNudge,
  close,  // the last frame ends; the end mark; the file is closed
};

struct Head {
  Tag tag;
  std::uint8_t flag = 0;  // per tag
  std::uint16_t unused = 0;
  std::uint32_t bytes = 0;  // the whole record, head included; a multiple of 8
};
static_assert(sizeof(Head) == 8);

inline constexpr std::size_t round8(std::size_t n) {
  return (n + 7) & ~std::size_t{7};
}

// Frame flags. kNoLiveStart: the frame begins as a live-only recorder stops copying calls
// (nobody listens): its chunk will lack them, so no live run may begin with it.
enum : std::uint8_t { kKeyframeNow = 1, kLiveStart = 2, kNoLiveStart = 4 };

struct StateRec {
  WorldState* state;  // owned by the record: the writer deletes it (null: no keyframe)
  double cellSize;
};
struct SpecRec {
  std::uint32_t id;
  MoverSpec spec;
};
struct ItemRectRec {
  ItemId id;
  Rect rect;
};
// move, check, project and moverMove; followed by Collision[], Answer[], Leg[].
struct MoveRec {
  ItemId id;            // invalid for project
  std::uint32_t mover;  // moverMove
  std::int32_t maxResponses;
  Rect rect;  // project: its rect; moverMove: the item before the move
  Vec2 goal, position;
  std::uint32_t collisions, answers, legs;
  BroadPhase broad;
  MoveSemantics semantics;  // every MoveOptions field but the trace (which is not recorded)
};
// queryRect, queryPoint, querySegment, anyOverlap; followed by ItemId[] or SegmentHit[], Answer[].
struct QueryRec {
  Rect rect;  // queryRect, anyOverlap
  Vec2 a, b;  // queryPoint: a; querySegment: a to b
  ItemId skip;
  std::uint32_t found, answers;
  bool any;
};
// label (a, b: the label's and the category's lengths), addResponse (a: the name's); chars follow.
struct TextRec {
  ItemId id;
  std::uint32_t a, b;
};
// Followed by ContactEvent[events], Answer[answers].
struct ContactsRec {
  ItemId id;
  std::uint32_t events, answers;
  bool forget;
};
// A corner nudge (tv::moveCornered): the body, the ceiling, where it met the corner, dx.
struct NudgeRec {
  ItemId id, ceiling;
  Vec2 touch;
  double dx;
};
struct AdvanceRec {
  double frameTime;
  std::int32_t ticks;
};
// Followed by BatchMove[moves], BodyRec[moves], Collision[collisions], Answer[], Leg[].
struct BatchRec {
  std::int32_t maxEvents;
  std::uint32_t moves, collisions, answers, legs;
};
struct BodyRec {
  Vec2 position;
  std::uint32_t first, count;
};

// The writer reads these in place, from bytes copied by memcpy.
static_assert(std::is_trivially_copyable_v<Collision> && alignof(Collision) <= 8);
static_assert(std::is_trivially_copyable_v<Answer> && alignof(Answer) <= 8);
static_assert(std::is_trivially_copyable_v<Leg> && alignof(Leg) <= 8);
static_assert(std::is_trivially_copyable_v<SegmentHit> && alignof(SegmentHit) <= 8);
static_assert(std::is_trivially_copyable_v<BatchMove> && alignof(BatchMove) <= 8);
static_assert(std::is_trivially_copyable_v<ContactEvent> && alignof(ContactEvent) <= 8);
static_assert(std::is_trivially_copyable_v<ItemId> && std::is_trivially_copyable_v<MoverSpec>);

// Reads one record's body and arrays, in the order they were put.
class RecordReader {
 public:
  explicit RecordReader(const std::byte* record) : p_(record + sizeof(Head)) {}
  template <class T>
  T body() {
    T t;
    std::memcpy(&t, p_, sizeof(T));
    p_ += round8(sizeof(T));
    return t;
  }
  template <class T>
  std::span<const T> array(std::size_t n) {
    const auto* t = reinterpret_cast<const T*>(p_);
    p_ += round8(n * sizeof(T));
    return {t, n};
  }
  std::string_view text(std::size_t n) {
    const auto* t = reinterpret_cast<const char*>(p_);
    p_ += round8(n);
    return {t, n};
  }

 private:
  const std::byte* p_;
};

// [SECTION] the pipe ------------------------------------------------------------------------------

struct Block {
  std::unique_ptr<std::byte[]> data;
  std::size_t capacity = 0, used = 0;
};

// Blocks from the game's thread to the writer's. The game fills the current block and hands it
// over when it is full or a frame ends; the writer consumes blocks in order on its own thread
// (or, unthreaded, at once on the game's). The blocks in flight are bounded: a game that makes
// calls faster than they can be written waits for the writer rather than fill memory.
class Pipe {
 public:
  using Consume = std::function<void(const Block&)>;
  static constexpr std::size_t kBlockSize = std::size_t{1} << 20;

  // `maxBytes`: most bytes of blocks handed over and not yet consumed.
  Pipe(Consume consume, bool threaded, std::size_t maxBytes);
  ~Pipe();
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;

  // Game thread: room for a record of `bytes` (a multiple of 8), contiguous.
  std::byte* reserve(std::size_t bytes) {
    if (cur_.capacity - cur_.used < bytes) nextBlock(bytes);
    std::byte* p = cur_.data.get() + cur_.used;
    cur_.used += bytes;
    return p;
  }
  // Game thread: the current block goes to the writer (nothing when it is empty).
  void handOver();
  // Game thread: hands over, then waits until the writer has consumed everything.
  void drain();
  // Hands over, drains and ends the writer's thread; the pipe consumes nothing after it.
  void stop();
  [[nodiscard]] bool threaded() const { return thread_.joinable(); }
  // Times the game waited for room (the writer fell behind by maxBytes).
  [[nodiscard]] std::uint64_t stalls() const { return stalls_; }
  // The writer's thread, for the crash flush (it must not wait for itself).
  [[nodiscard]] std::thread::id writerThread() const { return writerId_; }
  // The system's id of the writer's thread once it runs (0 before, and on POSIX systems): on
  // Windows the crash flush asks whether it still runs (crash_flush.hpp).
  [[nodiscard]] const std::atomic<std::uint32_t>& writerSystemId() const { return systemId_; }

 private:
  void nextBlock(std::size_t bytes);
  Block takeFree(std::size_t bytes, std::unique_lock<std::mutex>& lock);
  void run();

  Consume consume_;
  std::size_t maxBytes_;
  Block cur_;
  std::mutex m_;
  std::condition_variable work_;  // the writer waits for blocks
  std::condition_variable room_;  // the game waits for room, or for the writer to catch up
  std::deque<Block> full_;
  std::vector<Block> free_;
  std::size_t inFlight_ = 0;  // bytes handed over and not yet consumed
  std::uint64_t handed_ = 0, consumed_ = 0;
  bool stopping_ = false;
  std::uint64_t stalls_ = 0;
  std::thread thread_;
  std::thread::id writerId_;
  std::atomic<std::uint32_t> systemId_{0};
};

}  // namespace tv::rec
