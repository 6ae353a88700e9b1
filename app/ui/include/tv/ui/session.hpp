#pragma once
/// The session: what the debugger shows, whatever the source. One panel or several in lockstep
/// — a scene compared across movers, a recording beside its what-if re-runs — at one frame, one
/// call and one traced item. The debugger and tv-render drive it the same way, so a picture
/// from either shows the same thing.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tv/ui/source.hpp"

namespace tv::ui {

class Session {
 public:
  /// One panel: `primary` (a scene with its mover, a recording as recorded).
  explicit Session(std::unique_ptr<Source> primary);
  /// Several panels in lockstep, the first the primary (all at frame 0).
  explicit Session(std::vector<std::unique_ptr<Source>> panels);

  // -- panels ------------------------------------------------------------------------------------
  [[nodiscard]] std::size_t size() const { return panels_.size(); }
  [[nodiscard]] Source& panel(std::size_t k) { return *panels_.at(k); }
  [[nodiscard]] const Source& panel(std::size_t k) const { return *panels_.at(k); }
  [[nodiscard]] Source& primary() { return *panels_.front(); }
  [[nodiscard]] const Source& primary() const { return *panels_.front(); }
  /// Panels in order, as raw pointers (for views that take a span).
  [[nodiscard]] std::vector<Source*> panels();
  /// More than one panel.
  [[nodiscard]] bool comparing() const { return panels_.size() > 1; }
  /// The panels after the first are open-loop re-runs of a recording (what-if).
  [[nodiscard]] bool whatIf() const { return comparing() && panels_[1]->openLoop(); }

  /// Replaces every panel (the first is the primary) and brings them to frame `landOn` (as far
  /// as they go), tracing the same item. Nothing changes on a throw.
  void setPanels(std::vector<std::unique_ptr<Source>> panels, std::uint64_t landOn);
  /// The primary and one re-run per mover of `others`, at the current frame: a scene compared
  /// across movers (closed-loop), a recording beside its what-if runs (open-loop). Empty: the
  /// primary alone. tv::Error (nothing changed) when a mover cannot run the source.
  void compareWith(const std::vector<MoverSpec>& others);
  /// The primary and `others` (re-runs the caller built, e.g. what-ifs with options of their
  /// own), brought to the current frame, call and traced item.
  void compareWith(std::vector<std::unique_ptr<Source>> others);

  // -- time --------------------------------------------------------------------------------------
  [[nodiscard]] std::uint64_t frame() const { return primary().frame(); }
  [[nodiscard]] std::uint64_t firstFrame() const { return primary().firstFrame(); }
  /// The newest frame any panel can show now.
  [[nodiscard]] std::uint64_t lastFrame() const;
  /// Every panel has ended (nothing more can happen).
  [[nodiscard]] bool ended() const;
  /// Every panel to frame `f` (or as far as it goes), the call and trace re-done. With
  /// `stopAtEnd` a scene that ends before `f` stops at its end: every panel is then brought to
  /// the furthest frame any reached. Returns the frame reached.
  std::uint64_t goTo(std::uint64_t f, bool stopAtEnd = false);
  /// One frame of playback in every panel.
  void play();
  [[nodiscard]] double playSeconds() const { return primary().playSeconds(); }

  /// The primary's calls in this frame.
  [[nodiscard]] std::span<const CallInfo> calls() const { return primary().calls(); }
  [[nodiscard]] std::optional<std::uint32_t> call() const { return primary().call(); }
  /// Selects call `k` of the primary's frame in every panel (a recording's re-runs make the same
  /// calls; a scene's other movers trace the same item in the same tick). None: the frame's end.
  void selectCall(std::optional<std::uint32_t> k);
  /// The next (+1) or previous (-1) call, across frames: past a frame's last call, the next
  /// frame's first.
  void stepCall(int direction);

  // -- tracing -----------------------------------------------------------------------------------
  /// Traces `item` (or none) in every panel.
  void trace(std::optional<ItemId> item);
  [[nodiscard]] std::optional<ItemId> traced() const { return primary().traced(); }

  /// Shows failure `f` in every panel: its frame, its item traced, the failing call selected (a
  /// recording's own call; a scene's, that item's move in the tick). What every "go" to a
  /// failure does to the session. Throws what goTo and trace throw.
  void showFailure(const Failure& f);

  /// The world rect that frames every panel's traced move.
  [[nodiscard]] Rect followView() const;

 private:
  std::vector<std::unique_ptr<Source>> panels_;
};

}  // namespace tv::ui
