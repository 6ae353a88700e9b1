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
/// The game's thread only copies each call's inputs and results into memory; a thread of the
/// recorder's own encodes them, checksums each frame and writes it (flushed) once the frame is
/// handed over — at `frame()`, or a FixedStep's advance. So the file of a game that crashed
/// replays up to its last whole frame handed over: when a file recorder is open, a fatal signal
/// (SIGSEGV, SIGABRT, ...), an unhandled fault on Windows, std::terminate or exit() first waits
/// (at most a few seconds) for the writer to write what it was given (see
/// RecorderOptions::flushOnCrash for what is covered on each system).
/// An I/O error mid-game (disk full) stops the recording — `ok()` turns false and `error()` says
/// why, once the writer has met it — and the game goes on.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"  // what they throw
#include "tv/observer.hpp"
#include "tv/record/live.hpp"
#include "tv/timestep.hpp"

namespace tv {

/// How a Recorder writes.
struct RecorderOptions {
  /// Frames between keyframes (whole-world snapshots), so that seeking costs at most this many
  /// frames of replay. Range [1, 2^20]; default 64.
  std::uint32_t keyframeEvery = 64;
  /// Encode and write on a thread of the recorder's own (the game's thread only copies each
  /// call into memory). false: everything on the game's thread, at each frame's end. The bytes
  /// written are the same either way.
  bool background = true;
  /// Most bytes of captured calls waiting for the writer (at least 2 MiB; default 64 MiB). A
  /// game that makes calls faster than they can be written waits at this bound rather than
  /// fill memory (`stalls()` counts the waits).
  std::size_t maxQueueBytes = std::size_t{64} << 20;
  /// For a recorder writing a file: when the game dies, first wait up to 2 s (exit(): 5 s) for
  /// the writer to write every frame handed over, then let the process end as it would have.
  /// The handlers are in place only while such a recorder is open. What is covered:
  /// - POSIX systems: the fatal signals SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT,
  ///   SIGTERM, SIGHUP (each only where the game left the default action: a game's own
  ///   handler, or a sanitizer's, is left alone); std::terminate (an uncaught exception);
  ///   exit().
  /// - Windows: the C runtime's signals SIGSEGV, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM (each
  ///   only where its handler was SIG_DFL); faults that reach no handler — an access violation,
  ///   a stack overflow, in any thread or DLL — through SetUnhandledExceptionFilter (not under
  ///   a debugger, nor when the game sets a filter of its own later); a console closed, a
  ///   log-off, a shutdown; std::terminate; exit(), except in a DLL (the Lua module), whose exit
  ///   handlers run after Windows has ended the writer's thread: close the recorder first.
  /// - Nowhere: SIGKILL or TerminateProcess, _exit, a crash of the writer's own thread, the
  ///   frame being played, the end mark.
  bool flushOnCrash = true;
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
  /// Streams to a receiver only (tv/record/live.hpp), keeping nothing: while nobody listens it
  /// copies no call at all. Throws tv::Error when `live` is malformed (names the address).
  explicit Recorder(const LiveOptions& live, RecorderOptions options = {});
  /// Detaches from its world and FixedStep if still attached, ends the frame, closes the file.
  ~Recorder() override;
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Ends the current frame (writes and flushes its chunk) and begins the next. An attached
  /// FixedStep does this at every advance. With a live stream whose receiver paused the game
  /// (LiveOptions::control), it waits here until the receiver steps or resumes it.
  void frame();
  /// Also streams the recording to a receiver (tv/record/live.hpp). Call it before the world
  /// attaches. Throws tv::Error when `live` is malformed or the recorder streams already.
  void stream(const LiveOptions& live);
  /// Where the live stream stands (all false and 0 without one).
  [[nodiscard]] LiveStatus liveStatus() const;
  /// `step.attach(this)`, remembered so that the destructor and close() detach it again (a
  /// FixedStep attached by hand must be detached by hand before the recorder dies).
  void attach(FixedStep& step);
  /// Names an item for the debugger ("player", "tile 12,4") with a category ("player",
  /// "tile", "bullet"). Recorded in the current frame; a later label replaces an earlier one.
  void label(ItemId id, std::string_view label, std::string_view category = {});
  /// Ends the frame, writes the end mark and closes the file; detaches from the world and the
  /// FixedStep it was attached to. The recorder records nothing after it.
  void close();

  /// False once the recording stopped on an error (disk full...): the recording stopped there,
  /// the game goes on. The game's thread learns of an error once the writer has met it; after
  /// close(), of every error.
  [[nodiscard]] bool ok() const;
  /// Why the recording stopped, naming the file and the system's reason; empty while ok().
  [[nodiscard]] const std::string& error() const;
  /// Waits until the writer has written every frame handed over so far.
  void sync() const;
  /// Frames handed over so far (each frame() or FixedStep advance; close() hands over the last).
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t calls() const { return calls_; }  ///< calls recorded so far
  /// Moves recorded so far: World::move and Mover::move calls, and each body of a Batch::step
  /// (checks and projections are calls, not moves).
  [[nodiscard]] std::uint64_t moves() const { return moves_; }
  /// Bytes written of the frames handed over (waits for the writer); the file size once closed.
  [[nodiscard]] std::uint64_t size() const;
  /// The recording so far (waits for the writer), for a recorder made without a path: the
  /// whole file once closed. The reference stays valid, unchanged, until the next frame ends.
  [[nodiscard]] const std::vector<std::uint8_t>& bytes() const;
  /// Times the game's thread waited because the writer was maxQueueBytes behind.
  [[nodiscard]] std::uint64_t stalls() const;

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
  void contacted(ItemId item, bool forget, std::span<const ContactEvent> events) override;
  void cornerNudged(ItemId item, const CornerNudge& nudge) override;
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
  struct Impl;  // the capture pipe, the writer and its thread (core/record/src)
  std::unique_ptr<Impl> impl_;
  std::vector<std::uint8_t> memory_;  // written by the writer's thread
  mutable std::string error_;
  std::uint64_t frames_ = 0, calls_ = 0, moves_ = 0, size_ = 0, stalls_ = 0;
};

}  // namespace tv
