#pragma once
/// What the debugger looks at: a built-in scene, a level file, a recording or a game streaming
/// live. A Source gives frames, the calls made in a frame, the items with their names and
/// categories, and a traced re-execution of any call through core; everything above it (the
/// session, the views, the timeline, the inspector, the Failures window) exists once and reads
/// only this.
///
/// Time has two levels: frames (a scene's ticks, a game's frames) and, within a frame, its
/// calls. Showing frame f puts the world at f's end; selecting call k of f traces that call.
/// Either way the traced item's moves over the few frames before are re-traced, so the history
/// overlay shows how it got there however the frame was reached. A source never computes a
/// collision itself: every trace is the one core filled while it re-ran the move.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/mover.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/world.hpp"

namespace tv::ui {

class SimSource;
class ReplaySource;

enum class SourceKind { scene, level, recording, live };

/// "scene", "level", "recording", "live game".
[[nodiscard]] const char* sourceKindName(SourceKind k);

/// An item as the outliner lists it.
struct ItemRow {
  ItemId id;
  std::string name;      ///< "bullet 4" (a recording's label, a map object's name), "body 3"
  std::string category;  ///< "projectile", "wall", a game's category; may be empty
  bool moves = false;    ///< moves somewhere in the run (drawn as a body)
  std::uint64_t moveCount = 0, hits = 0;  ///< where the source knows them (recordings)
  std::uint64_t firstFrame = 0, lastFrame = 0;  ///< frames it exists in, where known
};

/// Where a move went wrong, for the Failures window and the timeline.
enum class FailureKind : std::uint8_t {
  tunnelled,    ///< passed through something it should have hit
  overlapping,  ///< ended inside a solid it did not start in
  snagged,      ///< caught on a seam between tiles while walking along them
  escaped,      ///< left the space that encloses it
  jittered,     ///< a resting body moved with nothing pushing it
  diverged,     ///< the replay's result differs from the recording
  busy,         ///< made more responses than the threshold in one move
  dropped,      ///< a rider that fell into or through the platform it stood on
  popped,       ///< a rider left above its platform, not on it (thrown or left behind)
};
[[nodiscard]] const char* failureKindName(FailureKind k);

struct Failure {
  std::uint64_t frame = 0;
  std::optional<std::uint32_t> call;  ///< the call in the frame, where known
  ItemId item;                        ///< invalid when the failure is not one item's
  FailureKind kind = FailureKind::tunnelled;
  std::string what;  ///< in words: "tunnelled through wall", "14 responses in one move"
};

class Source {
 public:
  virtual ~Source() = default;

  // -- what it is --------------------------------------------------------------------------------
  [[nodiscard]] virtual SourceKind kind() const = 0;
  /// What the HUD calls it: the scene's name, the file's name, "live: 127.0.0.1:7777".
  [[nodiscard]] virtual std::string name() const = 0;
  /// Who moved things: the mover's name for a scene, "recorded" for a recording as recorded,
  /// the what-if mover's name for a re-run.
  [[nodiscard]] virtual std::string moverName() const = 0;
  /// The same source with every move made by `mover` (a comparison's panel, a what-if run).
  /// A scene re-runs closed-loop (its rules react); a recording replays its calls open-loop.
  /// Throws tv::Error when the mover cannot run it.
  [[nodiscard]] virtual std::unique_ptr<Source> rerun(const MoverSpec& mover) const = 0;
  /// Open-loop: a re-run of recorded calls whose outcomes the game never saw.
  [[nodiscard]] virtual bool openLoop() const { return false; }

  // -- time --------------------------------------------------------------------------------------
  [[nodiscard]] virtual std::uint64_t frame() const = 0;
  /// The oldest frame that can be shown (a live stream drops its oldest).
  [[nodiscard]] virtual std::uint64_t firstFrame() const { return 0; }
  /// The newest frame that can be shown now (a scene: the furthest tick run so far).
  [[nodiscard]] virtual std::uint64_t lastFrame() const = 0;
  /// Nothing comes after lastFrame(): the scene has ended, the file is read to its end.
  [[nodiscard]] virtual bool ended() const = 0;
  /// Shows frame `f` as it ended (clamped to what can be shown, or run forward to it for a
  /// scene); no call selected.
  virtual void goTo(std::uint64_t f) = 0;
  /// One frame of playback: the next frame (a scene at a render rate draws one rendered frame
  /// through its fixed-step accumulator, which may run no tick).
  virtual void play() { goTo(frame() + 1); }
  /// Seconds one play() stands for.
  [[nodiscard]] virtual double playSeconds() const { return 1.0 / 60.0; }

  /// The current frame's calls, in order (a scene's: each body's move in this tick).
  [[nodiscard]] virtual std::span<const CallInfo> calls() const = 0;
  [[nodiscard]] virtual std::optional<std::uint32_t> call() const = 0;
  /// Selects call `k` of the current frame (traced; its item becomes the traced one), or none:
  /// the frame's end. Out-of-range indices are ignored.
  virtual void selectCall(std::optional<std::uint32_t> k) = 0;
  /// True for the calls whose re-run leaves a MoveTrace.
  [[nodiscard]] virtual bool traces(const CallInfo& c) const = 0;

  // -- what is traced ----------------------------------------------------------------------------
  /// Traces another item (or none); the view is rebuilt at the same frame and call. An item
  /// that does not exist is refused with tv::Error naming it.
  virtual void trace(std::optional<ItemId> item) = 0;
  [[nodiscard]] virtual std::optional<ItemId> traced() const = 0;
  /// The traced item's recent moves, oldest first, each tagged with its frame; with a call
  /// selected the last one is that call's.
  [[nodiscard]] virtual std::span<const TracedMove> history() const = 0;
  /// The selected call's trace, if one is selected and traced.
  [[nodiscard]] virtual const MoveTrace* callTrace() const = 0;
  /// The failure the run counted for a traced move, if it counted one (what the inspector and
  /// the world say about it).
  [[nodiscard]] virtual std::optional<Failure> failureOf(const TracedMove& m) const {
    (void)m;
    return std::nullopt;
  }

  // -- what is shown -----------------------------------------------------------------------------
  [[nodiscard]] virtual const World& world() const = 0;
  /// What the world view draws now (valid until the next call that changes the source).
  [[nodiscard]] virtual WorldPicture picture() = 0;
  /// The contact events of the frame on screen (up to the selected call), each with where both
  /// items stood at the update: a scene's bodies that read their contacts, a recording's
  /// Contacts::update calls. Empty where nothing reads contacts, and in a what-if (its re-run
  /// world is not the one the game's events came from).
  [[nodiscard]] virtual std::span<const sim::ContactAt> contactEvents() const { return {}; }
  /// What `id` stands on after its last contacts update, where known.
  [[nodiscard]] virtual std::optional<Ground> ground(ItemId id) const {
    (void)id;
    return std::nullopt;
  }
  /// True when items here read their contacts (the legend lists the contact colours): a scene's
  /// bodies with Body::contacts; a recording once a Contacts::update has been replayed.
  [[nodiscard]] virtual bool hasContacts() const { return false; }
  /// "Frame everything": a scene's camera, a recording's whole world.
  [[nodiscard]] virtual Rect home() const = 0;
  /// The least side of a followed view: a few movers' widths, so a 2 px bullet's move is seen
  /// with what is around it.
  [[nodiscard]] virtual double followMinSide() const = 0;
  /// The world rect that frames the traced move (start, goal, end and what it hit), padded and
  /// at least `minSide` a side; the traced item, or home(), when there is no move.
  [[nodiscard]] Rect followView(double minSide) const;
  [[nodiscard]] Rect followView() const { return followView(followMinSide()); }

  // -- items -------------------------------------------------------------------------------------
  /// Its name ("bullet 4", "Block 12", "body 3", "solid 17").
  [[nodiscard]] virtual std::string describe(ItemId id) const = 0;
  [[nodiscard]] virtual std::string category(ItemId id) const = 0;
  /// Everything the outliner lists.
  [[nodiscard]] virtual std::vector<ItemRow> items() const = 0;
  /// The item under world point `p`: a moving item before a still one, the smallest first.
  [[nodiscard]] std::optional<ItemId> itemAt(Vec2 p);
  /// What the source wants the person to know (a file cut short, a map with nothing solid).
  [[nodiscard]] virtual std::vector<std::string> notes() const { return {}; }

  // -- capabilities ------------------------------------------------------------------------------
  /// A simulation the person can tune (scenes and levels), or null.
  [[nodiscard]] virtual SimSource* sim() { return nullptr; }
  [[nodiscard]] const SimSource* sim() const { return const_cast<Source*>(this)->sim(); }
  /// A replay (recordings and live games), or null.
  [[nodiscard]] virtual ReplaySource* replay() { return nullptr; }
  [[nodiscard]] const ReplaySource* replay() const { return const_cast<Source*>(this)->replay(); }
};

/// True for the calls that move an item and leave a MoveTrace (move, check, project, a
/// Mover's move).
[[nodiscard]] bool tracesAMove(CallKind k);

}  // namespace tv::ui
