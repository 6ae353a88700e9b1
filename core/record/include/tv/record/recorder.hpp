#pragma once
/// Recording a game: attach a Recorder to the game's World and every call the game makes, with
/// its result and the filter's answers, goes into a `.tvrec` file (core/record/FORMAT.md) that
/// tv-replay validates and tv-debugger opens.
///
///   tv::Recorder rec("game.tvrec");        // throws tv::Error if the path cannot be written
///   world.attach(rec);                      // snapshot of the world as it is now
///   rec.label(player, "player", "player");  // names for the debugger (optional)
///   rec.attach(fixedStep);                  // a frame per rendered frame; or rec.frame()
///   ... play ...
///   world.detach();                         // or let rec go out of scope: the file is closed
///
/// A recorder records one attachment: after detach (or close) it records nothing more. Detach it
/// (or close it) before the world or the FixedStep it watches is destroyed.
///
/// A frame's calls are written and flushed when the frame ends, so the file of a game that
/// crashed replays up to its last whole frame. An I/O error mid-game (disk full) stops the
/// recording — `ok()` turns false and `error()` says why — and the game goes on.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"  // what they throw
#include "tv/observer.hpp"
#include "tv/timestep.hpp"

namespace tv {

/// How a Recorder writes.
struct RecorderOptions {
  /// Frames between keyframes (whole-world snapshots), so that seeking costs at most this many
  /// frames of replay. Range [1, 2^20]; default 64.
  std::uint32_t keyframeEvery = 64;
};

/// Writes everything a game asks of the World it is attached to, with the results, into a
/// `.tvrec` file (or memory), one chunk per frame. See the file's overview for the five lines a
/// game adds.
class Recorder final : public WorldObserver {
 public:
  /// Creates (or truncates) `path` and writes the header. Throws tv::Error naming the path and
  /// the system's reason when it cannot be written.
  explicit Recorder(const std::string& path, RecorderOptions options = {});
  /// Records into memory (tests, benchmarks): `bytes()` is then the whole file.
  explicit Recorder(RecorderOptions options = {});
  /// Detaches from its world and FixedStep if still attached, ends the frame, closes the file.
  ~Recorder() override;
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Ends the current frame (writes and flushes its chunk) and begins the next. An attached
  /// FixedStep does this at every advance.
  void frame();
  /// `step.attach(this)`, remembered so that the destructor and close() detach it again (a
  /// FixedStep attached by hand must be detached by hand before the recorder dies).
  void attach(FixedStep& step);
  /// Names an item for the debugger ("player", "tile 12,4") with a category ("player",
  /// "tile", "bullet"). Recorded in the current frame; a later label replaces an earlier one.
  void label(ItemId id, std::string_view label, std::string_view category = {});
  /// Ends the frame, writes the end mark and closes the file; detaches from the world and the
  /// FixedStep it was attached to. The recorder records nothing after it.
  void close();

  /// False once writing failed (disk full...): the recording stopped there, the game goes on.
  [[nodiscard]] bool ok() const { return error_.empty(); }
  /// Why writing failed, naming the file and the system's reason; empty while ok().
  [[nodiscard]] const std::string& error() const { return error_; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }  ///< frames ended so far
  [[nodiscard]] std::uint64_t calls() const { return calls_; }    ///< calls recorded so far
  /// Moves recorded so far (World::move, check, project, Mover::move; a Batch::step's bodies).
  [[nodiscard]] std::uint64_t moves() const { return moves_; }
  /// Bytes written so far (file size once closed).
  [[nodiscard]] std::uint64_t size() const { return size_; }
  /// The whole recording, for a recorder made without a path.
  [[nodiscard]] const std::vector<std::uint8_t>& bytes() const { return memory_; }

  // WorldObserver: what the world reports, recorded (documented there)
  void attached(const World& world) override;
  void detached(const World& world) override;
  void added(ItemId id, const Rect& r) override;
  void removed(ItemId id) override;
  void updated(ItemId id, const Rect& r) override;
  void moved(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) override;
  void checked(ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r) override;
  void projected(const Rect& rect, Vec2 goal, const MoveOptions& o, const MoveResult& r) override;
  void queriedRect(const Rect& r, ItemId skip, std::span<const ItemId> found) override;
  void queriedPoint(Vec2 p, std::span<const ItemId> found) override;
  void queriedSegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits) override;
  void askedOverlap(const Rect& r, ItemId skip, bool any) override;
  void responseAdded(std::string_view name, ResponseId id) override;
  void moverMoved(const Mover& mover, ItemId id, const Rect& start, Vec2 goal,
                  const MoveResult& r) override;
  void batchStepped(std::span<const BatchMove> moves, int maxEvents, const Batch& batch) override;
  void advanced(double frameTime, int ticks) override;
  void filtered(ItemId item, ItemId other, ResponseId answer) override;
  void responded(const Collision& c, Vec2 goal, const Leg& leg) override;
  void failed() override;
  void sourceGone(const void* source) override;

 private:
  void writeBytes(const std::uint8_t* data, std::size_t n);
  struct Impl;  // encoder state, file, keyframe bookkeeping (core/record/src)
  std::unique_ptr<Impl> impl_;
  std::vector<std::uint8_t> memory_;
  std::string error_;
  std::uint64_t frames_ = 0, calls_ = 0, moves_ = 0, size_ = 0;
};

}  // namespace tv
