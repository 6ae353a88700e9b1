#pragma once
// The debugger: one scene, one or more movers run in lockstep (one ui::Session each), the time
// controls over them, and everything drawn around the drawing layer's layouts — the menus,
// the timeline, the scene picker, Help and the substep sweep.
//
// Time travel: the sessions' simulations keep a ring of snapshots. Going to tick t restores
// (or re-runs up to) t - h and ticks the last h ticks again with tracing on, so the inspector
// and the history overlay show the moves that led to t however it was reached; determinism
// makes the re-run identical to the first run.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <span>

#include "divergence.hpp"
#include "gl_window.hpp"
#include "options.hpp"
#include "recording_debugger.hpp"
#include "settings.hpp"
#include "shortcuts.hpp"
#include "substep_sweep.hpp"
#include "tv/app/scene_source.hpp"
#include "tv/mover.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/session.hpp"

namespace tv::viewer {

class Debugger {
 public:
  /// Opens what the command line names, with `settings` (may be null) filling in what it does
  /// not. Throws ui::UsageError on a bad command line.
  Debugger(const ViewerOptions& options, const Settings* settings);

  /// One frame (between ImGui::NewFrame and ImGui::Render): input, time, then every window.
  /// `seconds` of wall time passed since the last frame.
  void frame(double seconds, std::span<const KeyPress> keys);
  [[nodiscard]] bool wantsQuit() const {
    return quit_ || (recording_ && recording_->wantsQuit());
  }
  /// Puts what should survive a restart into `s`.
  void store(Settings& s) const;
  /// Freezes anything that reads a clock out of the picture (screenshots).
  void setPinned(bool pinned) { pinned_ = pinned; }
  void openHelp() { showHelp_ = true; }
  /// What a command does, as its key or menu item would (tests drive the debugger with it).
  void command(Command c) { run(c); }
  /// What a parameter's slider does on release: sets the draft and re-runs to the same tick.
  /// False (with the reason in message()) when the value is refused; nothing else changes.
  bool tune(const std::string& param, double value);
  /// Applies a max substep length picked in the substep sweep: to every substep mover through
  /// the parameter; without one, a comparison gains a substep panel and keeps its others.
  void useSubstepLength(double length);
  /// Shows a recording instead of the scenes (recording_debugger.hpp); tv::Error for a file
  /// that does not open. `tryOpenRecording` shows the error instead (a dropped file).
  RecordingDebugger& openRecording(const std::string& path);
  void tryOpenRecording(const std::string& path);

  // Read-only views of the state, for tests and for whatever is drawn beside the debugger.
  [[nodiscard]] const std::vector<ui::DebuggerState>& panels() const { return states_; }
  [[nodiscard]] const std::vector<MoverSpec>& movers() const { return movers_; }
  [[nodiscard]] const Divergence& divergence() const { return divergence_; }
  [[nodiscard]] std::uint64_t currentTick() const { return tick(); }
  [[nodiscard]] bool paused() const { return paused_; }
  [[nodiscard]] const std::string& message() const { return message_; }
  [[nodiscard]] const std::string& notice() const { return notice_; }
  [[nodiscard]] bool helpOpen() const { return showHelp_; }

  /// Opens a Tiled map or a scene file (File > Open..., or dropped on the window); a bad file
  /// is reported in the window and changes nothing.
  void openFile(const std::string& path);
  /// Paused with nothing computing in the background: the window may wait for input.
  [[nodiscard]] bool idle() const {
    if (recording_) return recording_->idle();
    return paused_ && !deferred_ && divergence_.done() && (!showSweep_ || sweep_.pending() == 0);
  }

 private:
  // -- sessions and time (debugger.cpp) ----------------------------------------------------
  void build(const sim::SceneDef& scene, const sim::Params& params, std::vector<MoverSpec> movers,
             std::uint64_t landOn);
  void loadScene(const sim::SceneDef& scene);
  void setMovers(std::vector<MoverSpec> movers);
  /// Runs to tick `t`; with `stopAtEnd`, no further than the end of a scene that ends first.
  void goTo(std::uint64_t t, bool stopAtEnd = false);
  void stepOnce();
  void advance(double seconds);
  void select(std::optional<std::size_t> body);
  void applyActions(const ui::Actions& a);
  /// The same, but a restart known to be slow is announced and run on the next frame.
  void applyOrDefer(const ui::Actions& a);
  void run(Command c);
  [[nodiscard]] std::uint64_t tick() const;
  [[nodiscard]] bool compare() const { return sessions_.size() > 1; }
  [[nodiscard]] Rect followRect() const;
  void reportError(const std::string& what);

  // -- windows (debugger_ui.cpp) -----------------------------------------------------------
  void handleKeys(std::span<const KeyPress> keys);
  float drawMenuBar();
  void drawTimeline(ImVec2 display, float height);
  void drawMain(ImVec2 origin, ImVec2 size);
  void drawCompareSideBySide(ImVec2 origin, ImVec2 size);
  void drawOverlaid();
  void drawPicker();
  void drawSweep();
  void syncCameras();
  /// The mover the substep sweep varies: the first substep mover compared, else the first.
  [[nodiscard]] const MoverSpec& sweptMover() const;

  const sim::SceneDef* scene_ = nullptr;
  // Files opened this session (the command line's first): each keeps its scene alive, since
  // scene_ and the background studies may still point at an earlier one.
  std::vector<app::SceneSource> files_;
  std::string pickerPath_;
  bool focusPath_ = false;  // File > Open file...: the picker opens with its path field focused
  sim::Params params_;
  std::vector<MoverSpec> movers_;
  std::vector<std::unique_ptr<ui::Session>> sessions_;
  std::vector<ui::DebuggerState> states_;  // one per session; states_[0] holds the controls
  std::optional<std::size_t> selected_;
  std::size_t inspected_ = 0;  // the comparison panel whose inspector is shown

  bool paused_ = true;
  double speed_ = 1.0;
  double clock_ = 0.0;  // simulated seconds not yet drawn
  double frameMs_ = 0.0;  // wall time per frame, smoothed, for the menu bar
  std::uint64_t furthest_ = 0;
  bool follow_ = false;
  bool overlay_ = false;
  bool showHelp_ = false;
  bool showSweep_ = false;
  bool openPicker_ = false;
  bool quit_ = false;
  bool pinned_ = false;
  std::string pickerFilter_;
  std::string message_;  // the last error, shown in the timeline bar
  std::string notice_;   // news that is not an error ("the scene had ended"), until the next
  bool waited_ = false;  // the last frame waited for input (its time is not a frame's cost)
  bool deferred_ = false;  // a slow restart announced last frame, run at the next

  Divergence divergence_;
  SubstepSweep sweep_;

  // A recording, when one is open, takes over the window (recording_debugger.cpp).
  std::unique_ptr<RecordingDebugger> recording_;
  OpenRecordingDialog recordingDialog_;
};

}  // namespace tv::viewer
