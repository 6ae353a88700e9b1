#pragma once
/// A recording opened for the debugger: a tv::Replay, the frame on screen, the call selected in
/// it, and the item whose moves are traced. Like a Session for a built-in scene, it never
/// computes a collision itself: every trace it shows is the one core filled while the replay
/// re-executed the recorded call.
///
/// Time has two levels: frames (the game's), and within a frame its calls. Showing frame f puts
/// the world after f's last call; selecting call k of f puts it just after call k, which was
/// stepped with a trace. Either way the traced item's moves over the few frames before are
/// re-traced, so the history overlay shows how it got there however the frame was reached.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "tv/record/replay.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/overlays.hpp"

namespace tv::ui {

/// True for the calls that move an item and leave a MoveTrace (move, check, project, a
/// Mover's move).
[[nodiscard]] bool tracesAMove(CallKind k);

class RecordingSession {
 public:
  /// Takes the replay; `name` is what the HUD calls it (the file name). Shows frame 0.
  RecordingSession(Replay replay, std::string name);

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const Replay& replay() const { return replay_; }
  [[nodiscard]] std::uint64_t frames() const { return replay_.frames(); }
  /// The last frame that can be shown (frames() - 1, or 0 for an empty recording).
  [[nodiscard]] std::uint64_t lastFrame() const;

  // -- time --------------------------------------------------------------------------------------
  /// Shows frame `f` (clamped to the last) as it ended; no call selected.
  void goTo(std::uint64_t f);
  /// Shows the world just after call `k` of the current frame, with that call's trace; none:
  /// the frame's end. Out-of-range indices are ignored.
  void selectCall(std::optional<std::uint32_t> k);
  [[nodiscard]] std::uint64_t frame() const { return frame_; }
  [[nodiscard]] std::optional<std::uint32_t> call() const { return call_; }
  /// The current frame's calls, in order.
  [[nodiscard]] std::span<const CallInfo> calls() const { return calls_; }

  // -- selection ---------------------------------------------------------------------------------
  /// Traces another item (or none); the view is rebuilt at the same frame and call.
  void select(std::optional<ItemId> item);
  [[nodiscard]] std::optional<ItemId> selected() const { return selected_; }
  /// The recorded item with this label, if any (the first, if several share it).
  [[nodiscard]] std::optional<ItemId> findLabel(std::string_view label) const;
  /// The item under world point `p`: a moving item before a still one, the smallest first.
  [[nodiscard]] std::optional<ItemId> itemAt(Vec2 p) const;
  /// True for the calls whose re-run leaves a MoveTrace: moves, checks, projects, a Mover's
  /// moves, and in a what-if run with updatesAsMoves the updates it makes moves.
  [[nodiscard]] bool traces(const CallInfo& c) const;
  /// True for items that move somewhere in the recording (drawn as bodies); the rest are solids.
  [[nodiscard]] bool moves(ItemId id) const;

  // -- what is shown -----------------------------------------------------------------------------
  [[nodiscard]] const World& world() const { return replay_.world(); }
  /// The traced item's recent moves, oldest first, each tagged with its frame; with a call
  /// selected the last one is that call's.
  [[nodiscard]] std::span<const TracedMove> history() const { return moves_; }
  /// The selected call's trace (a move, check or project), if one is selected.
  [[nodiscard]] const MoveTrace* callTrace() const;
  /// The first divergence in the frame on screen (a call's recorded result differs from what
  /// core returned), if any.
  [[nodiscard]] const std::optional<Divergence>& divergence() const { return divergence_; }
  /// What the world view draws now (valid until the next call that changes the session).
  [[nodiscard]] WorldPicture picture();
  /// True when the last picture() drew an item in its category's colour (the legend then
  /// says what that colour means).
  [[nodiscard]] bool pictureHasCategories() const;
  /// The world rect that frames the selected call's move (or the traced item's last move),
  /// padded and at least `minSide` a side; the whole world if none.
  [[nodiscard]] Rect followView(double minSide) const;
  /// Everything in the world at this frame, padded (a default square for an empty world).
  [[nodiscard]] Rect bounds() const;
  /// The item's label, or "item <index>.<generation>".
  [[nodiscard]] std::string describe(ItemId id) const;
  /// A typical item size: the smallest extent of the moving items (else of all), for framing.
  [[nodiscard]] double typicalSize() const;

 private:
  void rebuild();
  void stepFrame(std::uint64_t f, const std::vector<CallInfo>& calls, std::size_t end);
  void trimHistory();

  Replay replay_;
  std::string name_;
  std::uint64_t frame_ = 0;
  std::optional<std::uint32_t> call_;
  std::vector<CallInfo> calls_;
  std::optional<ItemId> selected_;
  std::vector<TracedMove> moves_;
  bool callTraced_ = false;
  bool primed_ = false;  // the replay stands at the end of frame_, nothing selected in it
  std::optional<Divergence> divergence_;
  std::unordered_map<ItemId, std::size_t> recorded_;  // item -> index in replay.items()
  // The picture's storage.
  std::vector<sim::Solid> solids_;
  std::vector<ImU32> bodyFills_;  // per body of the last picture: its category's colour, or 0
  std::string terrain_;           // the category of the level's geometry (drawn as solids)
  std::vector<sim::Body> bodies_;
  std::size_t history_ = 8;  // frames re-traced before the one on screen
};

}  // namespace tv::ui
