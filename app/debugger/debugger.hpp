#pragma once
// The debugger: one session over any source — a built-in scene, a level file, a recording, a
// game streaming live — one panel or several in lockstep (movers compared, what-if runs), the
// time controls over them, and everything drawn around the view: the menu bar, the timeline,
// the pickers, Help and the substep sweep. Checks beside the view (tv/ui/checks.hpp) find where the
// run fails; "go" and the Failures tab take the person straight there.
//
// [debugger.cpp]     model: opening sources, time, selection, tuning, commands
// [debugger_ui.cpp]  windows: the frame, keys, menu bar, timeline, pickers, what-if dialog

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gl_window.hpp"
#include "options.hpp"
#include "settings.hpp"
#include "shortcuts.hpp"
#include "substep_sweep.hpp"
#include "tv/app/scene_source.hpp"
#include "tv/mover.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/checks.hpp"
#include "tv/ui/session.hpp"
#include "tv/ui/view.hpp"

namespace tv {
class LiveReceiver;
}
namespace tv::ui {
class LiveSource;
}

namespace tv::viewer {

/// The File > Open recording... dialog: a path to type, and the .tvrec files of the folder it
/// names (or the current one) to click. Returns the path chosen, once.
class OpenRecordingDialog {
 public:
  void open() { open_ = true; }
  [[nodiscard]] std::optional<std::string> draw();
  /// The path was changed since the last call (an error about the old one no longer applies).
  [[nodiscard]] bool takeEdited() { return std::exchange(edited_, false); }

 private:
  bool open_ = false;
  bool edited_ = false;
  std::string path_;
};

class Debugger {
 public:
  /// Opens what the command line names, with `settings` (may be null) filling in what it does
  /// not. Throws ui::UsageError on a bad command line, tv::Error for a file that does not open.
  Debugger(const ViewerOptions& options, const Settings* settings);
  ~Debugger();
  Debugger(const Debugger&) = delete;
  Debugger& operator=(const Debugger&) = delete;

  /// One frame (between ImGui::NewFrame and ImGui::Render): input, time, then every window.
  /// `seconds` of wall time passed since the last frame.
  void frame(double seconds, std::span<const KeyPress> keys);
  [[nodiscard]] bool wantsQuit() const { return quit_; }
  /// Puts what should survive a restart into `s`.
  void store(Settings& s) const;
  /// Freezes anything that reads a clock out of the picture (screenshots), and runs the checks
  /// to their end before anything is drawn.
  void setPinned(bool pinned);
  void openHelp() {
    showHelp_ = true;
    helpFollows_ = true;
  }
  /// What a command does, as its key or menu item would (tests drive the debugger with it).
  void command(Command c) { run(c); }
  /// What a parameter's slider does on release: sets the draft and re-runs to the same tick.
  /// False (with the reason in message()) when the value is refused; nothing else changes.
  bool tune(const std::string& param, double value);
  /// Applies a max substep length picked in the substep sweep: to every substep mover through
  /// the parameter; without one, a comparison gains a substep panel and keeps its others.
  void useSubstepLength(double length);
  /// Opens a recording in place of what is open; tv::Error for a file that does not open
  /// (nothing changes). `tryOpenRecording` shows the error instead (a dropped file).
  void openRecording(const std::string& path);
  void tryOpenRecording(const std::string& path);
  /// Opens a Tiled map or a scene file (File > Open level file..., Ctrl+O, or dropped on the window); a bad
  /// file is reported in the window and changes nothing.
  void openFile(const std::string& path);
  /// The same source re-run by `movers` beside it (a scene's comparison, a recording's what-if
  /// runs); empty: the source alone.
  void compareWith(const std::vector<MoverSpec>& movers, bool updatesAsMoves = false);
  /// What a click on a row of the Failures tab does: that frame (and call), the item traced,
  /// centred and zoomed on, the inspector showing the failing panel.
  void goToFailure(std::size_t index);
  /// What "go" beside "runs differ" does: that frame, the item that differs traced and followed.
  void goToDifference();
  /// Where a recording's replay differs from it, as every part of the debugger says it (status
  /// bar, timeline mark, inspector, the picture's label): the earlier of the validation's first
  /// divergence (untraced, then traced) and the one under the picture on screen
  /// (ReplaySource::pictureDivergence). None for a scene, a what-if panel, or a faithful replay.
  [[nodiscard]] std::optional<tv::Divergence> divergence() const;
  /// What "go" beside "DIVERGED" does: that frame and call, its item traced.
  void goToDivergence();
  /// Said after a divergence the validation found only in its traced pass; empty otherwise.
  [[nodiscard]] std::string tracedOnlyWords(const tv::Divergence& d) const;
  /// Waits for games streaming live at `address` ([HOST:]PORT) in place of what is open; tv::Error
  /// for an address that is malformed or taken (nothing changes). `tryListen` shows it instead.
  void listen(const std::string& address, std::uint64_t keepFrames = 0,
              std::uint64_t keepMegabytes = 256);
  void tryListen(const std::string& address);
  /// A live game is shown.
  [[nodiscard]] bool live() const;
  /// The view goes to each newest frame as it arrives (a live game, until paused or scrubbed).
  [[nodiscard]] bool followingLive() const { return live() && !paused_; }
  /// Writes a live game's kept frames to `path` (File > Save the stream); false with the reason
  /// in message() when it cannot.
  bool saveStream(const std::string& path);
  /// Shows frame `f`, call `k` of it, tracing the item labelled `item` (a recording's
  /// --frame/--call/--item); UsageError naming the flag when it has no such thing.
  void show(std::uint64_t f, std::optional<std::uint32_t> k, const std::optional<std::string>& item);

  // Read-only views of the state, for tests and for whatever is drawn beside the debugger.
  [[nodiscard]] const std::vector<ui::DebuggerState>& panels() const { return view_.panels; }
  [[nodiscard]] const ui::ViewState& view() const { return view_; }
  [[nodiscard]] ui::Session& session() { return *session_; }
  [[nodiscard]] const ui::Session& session() const { return *session_; }
  /// Each panel's mover (a recording's first panel: as recorded, `recorded` false).
  [[nodiscard]] std::vector<MoverSpec> movers() const;
  [[nodiscard]] const ui::Checks& checks() const { return checks_; }
  [[nodiscard]] std::uint64_t currentTick() const { return session_->frame(); }
  [[nodiscard]] bool paused() const { return paused_; }
  [[nodiscard]] bool following() const { return follow_; }
  [[nodiscard]] const std::string& message() const { return message_; }
  [[nodiscard]] const std::string& notice() const { return notice_; }
  [[nodiscard]] bool helpOpen() const { return showHelp_; }
  /// Paused with nothing computing in the background: the window may wait for input.
  [[nodiscard]] bool idle() const;
  /// What the status bar says now, in order (tests read it; the bar drops what does not fit).
  [[nodiscard]] std::vector<std::string> status() const;
  /// The status when no mover failed where another did not: "no failure in N ticks", or how
  /// many failures the movers share.
  [[nodiscard]] std::string noFailureWords() const;

 private:
  // -- sources and time (debugger.cpp) -------------------------------------------------------
  /// Builds a scene's session (one panel per mover) and lands on `landOn`.
  void buildScene(const sim::SceneDef& scene, const sim::Params& params,
                  std::vector<MoverSpec> movers, std::uint64_t landOn, ui::SourceKind kind);
  void loadScene(const sim::SceneDef& scene);
  void setMovers(std::vector<MoverSpec> movers);
  /// After a new session: fresh checks, views for its panels.
  void adopt(std::unique_ptr<ui::Session> session, bool keepCamera);
  [[nodiscard]] bool isScene() const { return session_->primary().sim() != nullptr; }
  /// Every panel to frame `f` (with `stopAtEnd`, no further than a scene's end).
  void goTo(std::uint64_t f, bool stopAtEnd = false);
  void advance(double seconds);
  void select(std::optional<ItemId> item);
  void selectCall(std::optional<std::uint32_t> k);
  void applyActions(const ui::Actions& a);
  /// The same, but a restart known to be slow is announced and run on the next frame.
  void applyOrDefer(const ui::Actions& a);
  void restartFromDraft(bool sameTick);
  void run(Command c);
  void frameAll();
  void traceBusiest();
  void reportError(const std::string& what);
  /// Takes back what reportError said (the person changed what it was about).
  void clearError();
  /// A live game: what arrived, and the newest frame while following.
  void refreshLive();
  [[nodiscard]] ui::LiveSource* liveSource();
  [[nodiscard]] const ui::LiveSource* liveSource() const;

  // -- windows (debugger_ui.cpp) -------------------------------------------------------------
  void handleKeys(std::span<const KeyPress> keys);
  float drawMenuBar();
  void drawTimeline(ImVec2 display, float height);
  void drawPicker();
  void drawSweep();
  void drawWhatIfDialog();
  void drawLiveDialogs();
  void syncCameras();
  /// The mover the substep sweep varies: the first substep mover compared, else the first.
  [[nodiscard]] MoverSpec sweptMover() const;

  std::unique_ptr<ui::Session> session_;
  ui::ViewState view_;
  ui::Checks checks_;

  // A scene or level: what it was built from (files keep their scenes alive: the background
  // checks may still point at an earlier one).
  const sim::SceneDef* scene_ = nullptr;
  std::vector<app::SceneSource> files_;
  sim::Params params_;
  // A recording's what-if runs (its re-runs' movers).
  bool updatesAsMoves_ = false;

  bool paused_ = true;
  // Playing back the frames a live game sent after it left (Space with no game connected): the
  // kept frames play as a recording's do, not followed to the newest.
  bool playingBack_ = false;
  double speed_ = 1.0;
  double clock_ = 0.0;    // simulated seconds not yet drawn
  double frameMs_ = 0.0;  // wall time per frame, smoothed, for the menu bar
  bool follow_ = false;
  bool showHelp_ = false;
  bool helpFollows_ = true;  // Help stays over the column's tabs until the person moves it
  bool showSweep_ = false;
  bool showWhatIf_ = false;
  bool openPicker_ = false;
  bool focusPath_ = false;  // File > Open level file...: the picker opens with its path field focused
  bool quit_ = false;
  bool pinned_ = false;
  bool waited_ = false;     // the last frame waited for input (its time is not a frame's cost)
  bool deferred_ = false;   // a slow re-run announced last frame, run at the next
  bool deferredRestart_ = false;  // ... a Restart (to tick 0), not an edit (same tick)
  std::string pickerFilter_;
  std::string pickerPath_;
  std::string message_;  // the last error, shown in the timeline bar
  std::string notice_;   // news that is not an error ("the scene had ended"), until the next
  OpenRecordingDialog recordingDialog_;
  SubstepSweep sweep_;
  // A live game: the receiver (shared with its source), where to listen and save.
  std::shared_ptr<LiveReceiver> receiver_;
  bool openListen_ = false, openSave_ = false;
  bool jumpToNewest_ = false;  // a step was asked: show its frame when it comes
  double liveChecksAt_ = 0.0;  // seconds of following since the checks last looked
  std::string listenAddress_ = "127.0.0.1:7720";
  std::string savePath_ = "live.tvrec";
  // The what-if dialog's draft.
  MoverSpec draftWhatIf_{.kind = MoverKind::discrete};
  double draftSubstep_ = 0.0;  // 0: half the smallest item
  bool draftUpdates_ = false;
};

}  // namespace tv::viewer
