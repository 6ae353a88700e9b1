#pragma once
// The debugger with a recording open (tv-debugger game.tvrec, File > Open recording..., or a
// file dropped on the window): the same world view, overlays, camera and inspector as a
// built-in scene, over the recorded game's frames and, within a frame, its calls. Validation
// runs in the background and marks the divergence frame; a what-if re-runs the recording under
// another mover, side by side with the recorded run.
//
// [recording_debugger.cpp]     model: opening, time, selection, keys, what-if
// [recording_debugger_ui.cpp]  windows: menu bar, timeline, what-if panels, Help

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "gl_window.hpp"
#include "recording_jobs.hpp"
#include "tv/mover.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/picture_options.hpp"
#include "tv/ui/recording_session.hpp"
#include "tv/ui/recording_view.hpp"

namespace tv::viewer {

/// The File > Open recording... dialog: a path to type, and the .tvrec files of the folder it
/// names (or the current one) to click. Returns the path chosen, once.
class OpenRecordingDialog {
 public:
  void open() { open_ = true; }
  [[nodiscard]] std::optional<std::string> draw();

 private:
  bool open_ = false;
  std::string path_;
  std::string error_;
};

class RecordingDebugger {
 public:
  /// Opens `path` (tv::Error naming the file and what is wrong). `pinned`: a screenshot, so
  /// background checks run to the end before the first frame.
  RecordingDebugger(const std::string& path, const ui::Overlays& overlays, bool pinned);
  ~RecordingDebugger();
  RecordingDebugger(const RecordingDebugger&) = delete;
  RecordingDebugger& operator=(const RecordingDebugger&) = delete;

  /// Shows frame `f`, call `k` of it, tracing `item` (the command line's --frame/--call/--item);
  /// UsageError naming the flag when the recording has no such thing.
  void show(std::uint64_t f, std::optional<std::uint32_t> k,
            const std::optional<std::string>& item);
  /// Frames the view as --view asks: everything, the traced move (follow), or a world rect.
  void setView(const ui::PictureOptions& o);
  /// Opens another recording in place; on failure keeps the current one and shows why.
  void reopen(const std::string& path);
  /// Starts a what-if run with `mover` (and its substep length), as the panel's Run does.
  void startWhatIf(const MoverSpec& mover, bool updatesAsMoves);

  /// One frame (between ImGui::NewFrame and ImGui::Render).
  void frame(double seconds, std::span<const KeyPress> keys);
  [[nodiscard]] bool wantsQuit() const { return quit_; }
  /// Back to the built-in scenes.
  [[nodiscard]] bool wantsClose() const { return close_; }
  [[nodiscard]] bool idle() const;
  [[nodiscard]] const ui::Overlays& overlays() const { return state_.view.overlays; }
  void openHelp() { showHelp_ = true; }

 private:
  // -- model (recording_debugger.cpp) ------------------------------------------------------
  void goTo(std::uint64_t f);
  void selectCall(std::optional<std::uint32_t> k);
  void stepCall(int direction);
  void select(std::optional<ItemId> item);
  void advance(double seconds);
  void apply(const ui::RecordingActions& a);
  void handleKeys(std::span<const KeyPress> keys);
  void syncWhatIf();
  void frameAll();
  void traceBusiest();
  [[nodiscard]] Rect followRect() const;
  void report(const std::string& what);

  // -- windows (recording_debugger_ui.cpp) -------------------------------------------------
  float drawMenuBar();
  void drawTimeline(ImVec2 display, float height);
  void drawWhatIfSideBySide(ImVec2 origin, ImVec2 size);
  void drawWhatIfControls();
  void drawHelp();

  std::string path_;
  std::unique_ptr<ui::RecordingSession> session_;
  ui::RecordingViewState state_;
  bool pinned_ = false;
  bool paused_ = true;
  double speed_ = 1.0;
  double clock_ = 0.0;
  bool follow_ = false;
  bool quit_ = false;
  bool close_ = false;
  bool showHelp_ = false;
  std::string message_;
  OpenRecordingDialog dialog_;
  ValidationJob validation_;

  // What-if: the same recording replayed by another mover, kept at the same frame and call.
  struct WhatIf {
    MoverSpec mover;
    bool updatesAsMoves = false;
    std::unique_ptr<ui::RecordingSession> session;
    ui::DebuggerState view;
    WhatIfJob job;
  };
  std::unique_ptr<WhatIf> whatIf_;
  bool showWhatIf_ = false;  // the controls window
  MoverSpec draftMover_{.kind = MoverKind::discrete};
  double draftSubstep_ = 0.0;  // 0: half the smallest item
  bool draftUpdates_ = false;
};

}  // namespace tv::viewer
