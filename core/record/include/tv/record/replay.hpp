#pragma once
/// Replaying a recording (`.tvrec`, core/record/FORMAT.md): open it, rebuild the world at any
/// frame from the nearest keyframe, re-execute each recorded call on that world (with tracing,
/// for the debugger) and compare its result with the recorded one bit for bit. The first
/// difference is a divergence. With `ReplayOptions::mover` the recorded moves are made again by
/// another mover instead (what-if): the runs then differ on purpose, and `whatIf` says where.
///
/// A file is untrusted: every malformed, truncated, tampered or hostile file gets a tv::Error
/// naming the byte offset, the frame and what was wrong — never a crash, never an allocation
/// the file's own size does not justify. A file cut inside a frame replays up to its last whole
/// frame, with a warning.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tv/error.hpp"  // what they throw
#include "tv/mover.hpp"
#include "tv/record/calls.hpp"  // CallKind, the recorded calls
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {

/// One recorded call, as listed in the debugger's frame view.
struct CallInfo {
  CallKind kind = CallKind::move;  ///< what the call was
  std::uint64_t frame = 0;         ///< the frame it was made in (0-based)
  std::uint32_t index = 0;   ///< within its frame
  ItemId item;               ///< the item it concerns (invalid for project and the queries)
  std::uint64_t offset = 0;  ///< byte offset of its record in the file
  Rect start;                ///< moves: the item before the call
  Vec2 goal;                 ///< moves: what was asked
  Vec2 position;             ///< moves: where the recording says it ended
  std::uint32_t hits = 0;    ///< moves: collisions recorded; queries: items found
  std::string mover;         ///< moverMove: the mover's name
  std::string summary;       ///< one line: "move player (12, 40) -> (15, 40): 2 hits"
};

/// An item that appears in the recording, for the outliner.
struct RecordedItem {
  ItemId id;             ///< its id in the recorded world (and in the replay's)
  std::string label;     ///< the game's label, or "item <index>.<generation>"
  std::string category;  ///< the game's category, or empty
  /// @name The frames it is in the world (first added .. last seen)
  /// @{
  std::uint64_t firstFrame = 0, lastFrame = 0;  ///< frames, 0-based, inclusive
  /// @}
  /// @name Its recorded moves, and the collisions they had
  /// @{
  std::uint64_t moves = 0, hits = 0;  ///< counts over the whole recording
  /// @}
  /// Updates that changed its rect: a game that moves its bodies itself (x += v*dt, update,
  /// push out) moves them by updates, not moves.
  std::uint64_t updates = 0;
  double maxSpeed = 0.0;  ///< longest single move, in world units
  std::uint64_t endedOverlapping = 0;  ///< moves that ended overlapping a solid (not ignored)
};

/// The first call whose result differs from the recording.
struct Divergence {
  std::uint64_t frame = 0;         ///< the frame of the call (0-based)
  std::uint32_t call = 0;          ///< the call's index within its frame
  CallKind kind = CallKind::move;  ///< what the call was
  std::string item;      ///< label of the item concerned
  std::string what;      ///< "position", "collision 1 ti", "queryRect result"...
  std::string expected;  ///< as recorded
  std::string got;       ///< as replayed
  std::uint64_t offset = 0;  ///< byte offset of the call's record in the file
  [[nodiscard]] std::string report() const;  ///< the whole thing on a few lines
};

/// How a recording is replayed: exactly (the default), or a what-if under another mover.
struct ReplayOptions {
  /// What-if: every recorded move (World::move and Mover::move) is made by this mover instead.
  std::optional<MoverSpec> mover;
  /// What-if: also treat each recorded `update` of an item that changes only its position as a
  /// move to that position (games that move bodies themselves, x += v*dt, then push out).
  bool updatesAsMoves = false;
  /// Stop decoding at the first frame whose chunk is bad instead of throwing (the debugger
  /// opens what can be opened and shows the error); truncation is always tolerated.
  bool tolerant = false;
  /// Most cells the replayed world's items may be registered in at once (each add, update and
  /// keyframe is checked before the world is touched): a hostile file of huge rects is refused
  /// instead of filling memory. Default 2^22 (about 200 MB of cell entries).
  std::uint64_t maxCells = std::uint64_t{1} << 22;
  /// validate() also counts, per item, the moves that ended overlapping a solid
  /// (RecordedItem::endedOverlapping): one rect query per move.
  bool itemStats = false;
};

/// Totals over the whole recording, known once it is open.
struct ReplaySummary {
  /// @name Counts over the frames read
  /// @{
  std::uint64_t frames = 0, calls = 0, moves = 0, collisions = 0, queries = 0,
                keyframes = 0;  ///< counts
  /// @}
  std::uint64_t bytes = 0;  ///< file size
  /// Bytes of whole frames read (header included): less than `bytes` when the file is damaged.
  std::uint64_t bytesRead = 0;
  /// Where a cut or damaged file stopped being read: frames after it are not in the replay.
  std::optional<std::uint64_t> damagedAt;
  /// True when the file ends with its end mark: the game closed the recording. A game that
  /// crashed or was killed leaves whole frames and no end mark (or a frame cut short).
  bool closed = false;
};

/// A move whose what-if outcome differs from the recorded one.
struct MoveDifference {
  std::uint64_t frame = 0;  ///< the frame of the move (0-based)
  std::uint32_t call = 0;   ///< the move's call index within its frame
  ItemId item;              ///< the item moved
  /// @name Where the recorded run and the re-run ended
  /// @{
  Vec2 recorded, got;  ///< positions (top-left), world units
  /// @}
  double distance = 0.0;  ///< between the two ends, world units (> 0)
  bool tunnelled = false;    ///< passed through a solid the recorded filter does not ignore
  bool overlapping = false;  ///< ended overlapping such a solid
  /// The solid it passed through (tunnelled), else the one it ended inside; invalid for a move
  /// that only ended elsewhere.
  ItemId solid;
};

/// What a what-if run (Replay::whatIf) found, against the recorded run.
struct WhatIfReport {
  std::uint64_t moves = 0;  ///< moves re-run (with updatesAsMoves, updates made moves included)
  std::vector<MoveDifference> differences;  ///< every move that ended elsewhere, in order
  std::optional<std::uint64_t> firstDifferentFrame;  ///< the first frame where the runs differ
  /// First frame where a re-run body is more than `farAway` from where the recording goes on:
  /// from there the recorded goals (the game's reactions) no longer make sense.
  std::optional<std::uint64_t> firstImplausibleFrame;
  /// @name The re-run's moves that tunnelled, and that ended inside a solid
  /// Counted in moves, not bodies: a bullet that passes a wall in one move and a tile beyond it
  /// in a later one counts twice. Tunnelled: the move's start and end lie on opposite sides of
  /// an item its recorded filter neither ignores nor crosses; inside a solid: it ended
  /// overlapping such an item it did not overlap at its start. Where the filter was never asked
  /// (an update made a move), the item's most common recorded answer stands in, or with none,
  /// items that move somewhere in the recording are ignored and the others are solid.
  /// @{
  std::uint64_t tunnelled = 0, overlapping = 0;  ///< counts of moves
  /// @}
  /// @name The same two checks on the recorded run itself
  /// Its moves, and with updatesAsMoves its updates: what the what-if run is compared against.
  /// A game that moves bodies itself (x += v*dt, update, push out) updates them into solids
  /// before pushing them out, so each such update counts as ending inside a solid.
  /// @{
  std::uint64_t recordedTunnelled = 0, recordedOverlapping = 0;  ///< counts of moves
  /// @}
  /// The recorded run's moves behind those two counts, in order (`recorded` and `got` are both
  /// where the move ended; `distance` is 0).
  std::vector<MoveDifference> recordedFailures;
  /// Calls the what-if world refused (e.g. a pixel move over 2^24 px); they changed nothing.
  std::uint64_t failedCalls = 0;
};

/// A recording opened for replay: what is in it, a world at any frame and call, a call-by-call
/// step with traces, and whole-file validation and what-if runs.
///
///     tv::Replay r = tv::Replay::open("game.tvrec");   // tv::Error naming the byte if bad
///     if (auto d = r.validate()) std::cerr << d->report();
///     r.seek(62, 2);                                    // just before call 2 of frame 62
///     tv::MoveTrace t;
///     r.step(&t);                                       // that call, traced
class Replay {
 public:
  /// `seek`'s call index for "after the frame's last call".
  static constexpr std::uint32_t kEndOfFrame = 0xFFFFFFFFu;

  /// Reads and indexes a recording (header, frame chunks with checksums, keyframes). Throws
  /// tv::Error naming the file and the system's reason when it cannot be read, and the byte
  /// offset, the frame and what is wrong when its contents are bad (a cut file is not an error:
  /// it replays up to its last whole frame, with a warning).
  [[nodiscard]] static Replay open(const std::string& path, ReplayOptions options = {});
  /// As `open`, from the bytes of a recording in memory (Recorder::bytes()).
  [[nodiscard]] static Replay fromBytes(std::vector<std::uint8_t> bytes,
                                        ReplayOptions options = {});
  Replay(Replay&&) noexcept;             ///< moves the whole replay (no copy: it owns a world)
  Replay& operator=(Replay&&) noexcept;  ///< moves the whole replay
  ~Replay();

  // -- what is in it ---------------------------------------------------------------------------
  [[nodiscard]] std::uint64_t frames() const;  ///< whole frames read (the summary's `frames`)
  [[nodiscard]] double cellSize() const;       ///< the recorded world's cell size, world units
  [[nodiscard]] std::uint64_t fileSize() const;  ///< bytes
  /// What was wrong but tolerated: a cut file, no end mark, bytes after the end mark...
  [[nodiscard]] std::span<const std::string> warnings() const;
  /// Every item that appears in the recording, in the order first seen.
  [[nodiscard]] std::span<const RecordedItem> items() const;
  /// The label of an item ("player"), or "item <index>.<generation>" when it has none.
  [[nodiscard]] std::string label(ItemId id) const;
  /// The category the game gave an item ("bullet"), or empty.
  [[nodiscard]] std::string category(ItemId id) const;
  /// The calls recorded in a frame, in order.
  [[nodiscard]] std::vector<CallInfo> calls(std::uint64_t frame) const;
  [[nodiscard]] const ReplayOptions& options() const;  ///< as given to open
  [[nodiscard]] const ReplaySummary& summary() const;  ///< totals, known once open
  /// Calls recorded in a frame (labels and FixedStep advances included).
  [[nodiscard]] std::uint32_t callCount(std::uint64_t frame) const;

  // -- where it is -----------------------------------------------------------------------------
  /// Puts the world just before call `call` of `frame` (kEndOfFrame: after the frame's last
  /// call). Starts from the nearest keyframe at or before it: O(keyframe interval).
  void seek(std::uint64_t frame, std::uint32_t call = kEndOfFrame);
  /// The frame a seek to `frame` rebuilds the world at: the nearest keyframe at or before it (0
  /// for a what-if, or a recording with stateful movers, which replay from the start). Stepping
  /// from there with step() compares every call on the way, which a seek does not.
  [[nodiscard]] std::uint64_t seekStart(std::uint64_t frame) const;
  [[nodiscard]] std::uint64_t frame() const;  ///< the frame the replay stands in
  [[nodiscard]] std::uint32_t call() const;  ///< index of the next call in frame()
  /// The replayed world as it stands (read only: the replay owns it).
  [[nodiscard]] const World& world() const;
  /// True once the last call of the last frame has been stepped.
  [[nodiscard]] bool atEnd() const;

  /// Re-executes the next call (tracing it into `trace` when given) and compares its result
  /// with the recording. Returns the divergence, if this call diverges. Moves to the next
  /// frame at a frame's end.
  std::optional<Divergence> step(MoveTrace* trace = nullptr);

  // -- whole-file checks -----------------------------------------------------------------------
  /// How validate() re-runs the calls.
  enum class Tracing : std::uint8_t {
    off,  ///< as the game made them: call after call, untraced
    on,   ///< as the debugger shows them: every call traced, and from each keyframe on a world
          ///< rebuilt from its snapshot (after checking that the world got there), as a seek does
  };
  /// Replays everything from the start; the first divergence, if any. `progress(frame)` may
  /// return false to cancel (then the result is empty and `cancelled()` true).
  [[nodiscard]] std::optional<Divergence> validate(
      const std::function<bool(std::uint64_t)>& progress = {}, Tracing tracing = Tracing::off);
  [[nodiscard]] bool cancelled() const;  ///< the last validate() was cancelled by its progress
  /// What-if (options().mover set): the whole run against the recording.
  [[nodiscard]] WhatIfReport whatIf(double farAway = 64.0);
  /// The recorded run's own moves (with options().updatesAsMoves, its position-only updates
  /// too) judged as whatIf judges them, with no other mover: only recordedTunnelled,
  /// recordedOverlapping and recordedFailures are filled. With or without options().mover. What
  /// a debugger lists as a recording's failures.
  [[nodiscard]] WhatIfReport checkRecorded();

  struct Impl;  // opaque: core/record/src/replay_impl.hpp

 private:
  explicit Replay(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tv
