#pragma once
/// A still: the debugger's picture of a source at a moment — a scene (or level) at a tick, with
/// one mover or several compared, or a recording at a frame and call, alone or beside a what-if
/// re-run — as tv-render draws it and as tv-debugger's screenshot mode draws it, from the same
/// flags. Sharing this one composition (the session and the view) is what lets a test demand
/// that both programs give the same pixels. With --first-failure the moment is the run's first
/// failure, found by the debugger's own checks: what a game's CI keeps as the picture of it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/picture_options.hpp"
#include "tv/ui/session.hpp"
#include "tv/ui/view.hpp"

namespace tv::ui {

class ReplaySource;

/// The flags that pick a recording's picture.
struct RecordingFlags {
  std::string path;                   ///< --open FILE (or, for tv-debugger, FILE.tvrec)
  std::uint64_t frame = 0;            ///< --frame N
  std::optional<std::string> item;    ///< --item LABEL: the item traced
  std::optional<std::uint32_t> call;  ///< --call K: the call of the frame selected
  std::optional<MoverSpec> whatIf;    ///< --what-if MOVER: re-run beside the recorded run
  bool updatesAsMoves = false;        ///< --updates-as-moves: for the what-if run
  /// "--frame" or "--call" when either was given (--first-failure picks both), else empty.
  std::string placedBy;
};

/// --first-failure found nothing to show: nothing in the run failed. Not an error: the programs
/// say so and write no image.
struct NoFailure {
  std::string message;
};

/// Takes --open, --frame, --item, --call, --what-if and --updates-as-moves (and, with
/// `positional`, a lone argument ending in .tvrec) out of argv; the other arguments go to `rest`,
/// argv[0] first. Returns the flags when a recording was named; UsageError for a flag without
/// its value, --frame/--item/--call/--what-if without a recording, or --updates-as-moves
/// without --what-if.
[[nodiscard]] std::optional<RecordingFlags> extractRecordingFlags(int argc, char** argv,
                                                                  bool positional,
                                                                  std::vector<char*>& rest);
/// UsageError naming the first flag of `o` that picks a built-in scene (--scene, --mover,
/// --tick, a scene parameter...), which a recording does not take.
void rejectSceneFlags(const PictureOptions& o);

/// UsageError when --first-failure comes with a flag that places the picture itself (--tick,
/// --ticks, --frame, --call): the first failure picks the moment.
void checkFirstFailure(const PictureOptions& o, const std::optional<RecordingFlags>& r);

/// The registered scene `o.scene` or the file's; UsageError listing the valid names otherwise.
[[nodiscard]] const sim::SceneDef& sceneFor(const PictureOptions& o);
/// The scene's defaults with every `--NAME VALUE` of `o` applied; UsageError naming the flag.
[[nodiscard]] sim::Params paramsFor(const sim::SceneDef& scene, const PictureOptions& o);
/// The overlays after `--hide` and `--show`; UsageError naming an unknown overlay. A recording
/// has no render rate: its physics, render and pixel positions coincide, so the three-way
/// marker is off unless --show names it.
[[nodiscard]] Overlays overlaysFor(const PictureOptions& o, bool recording = false);

/// One source per mover of `o` (the first is the primary), at tick 0, tracing `o.body`.
/// UsageError naming the flag for a bad scene, parameter, mover or body, or a tick that would
/// take too long.
[[nodiscard]] std::vector<std::unique_ptr<Source>> sceneSources(const PictureOptions& o);
/// Shows frame `r.frame`, call `r.call`, tracing `r.item`; UsageError naming the flag when the
/// recording has no such thing.
void showRecorded(Session& session, const RecordingFlags& r);

class Still {
 public:
  /// A scene's picture (`o`), or a recording's when `r` is given (with a what-if re-run beside
  /// it for --what-if). With --first-failure, or a what-if run, the run's checks run to the end
  /// first and fill the Failures tab; --first-failure then shows the earliest. Throws
  /// UsageError naming the flag, tv::Error for a file that does not open, NoFailure when
  /// --first-failure finds none.
  explicit Still(const PictureOptions& o, const std::optional<RecordingFlags>& r = {});
  ~Still();

  /// Every panel runs to `tick` (at `o.renderHz`); UsageError when it cannot. A recording's
  /// frame is chosen by its flags, a first failure's by the failure: then this does nothing.
  /// A run that takes over a second says how far it has got on stderr, each line starting
  /// with `tool`.
  void advanceTo(std::uint64_t tick, const char* tool = "tv-render");
  /// Fresh per-image state (camera, overlays, title) for the current tick: call once per
  /// image, before its frames.
  void beginImage();
  /// The windows of one ImGui frame filling `display` (between NewFrame and Render).
  void drawFrame(ImVec2 display);

  [[nodiscard]] Session& session() { return *session_; }
  [[nodiscard]] bool recording() const { return recorded_.has_value(); }
  /// The failure shown (--first-failure): its index in the failures found.
  [[nodiscard]] std::optional<std::size_t> failureShown() const { return shown_; }
  /// The failures the checks found (empty unless --first-failure or a what-if run asked).
  [[nodiscard]] const FailureList& failures() const { return failures_; }

 private:
  void findFailures();

  PictureOptions o_;
  std::optional<RecordingFlags> recorded_;
  std::unique_ptr<Session> session_;
  ViewState view_;
  bool checked_ = false;  // the checks ran: failures_ is the run's whole list
  FailureList failures_;
  std::optional<std::size_t> shown_;
};

}  // namespace tv::ui
