#pragma once
/// A still of a recording: the debugger's picture of a recorded game at a frame (and call), as
/// `tv-render --open FILE` draws it and as `tv-debugger FILE --screenshot` draws it, from the
/// same flags. With `--what-if MOVER` the still is the debugger's what-if view: the recorded run
/// beside its re-run under another mover, with the report; `--first-failure` picks the first
/// re-run move that tunnelled or ended inside a solid (a game's CI draws what failed).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"
#include "tv/ui/picture_options.hpp"
#include "tv/ui/recording_session.hpp"
#include "tv/ui/recording_view.hpp"
#include "tv/ui/what_if_view.hpp"

namespace tv::ui {

/// The flags that pick a recording's picture.
struct RecordingFlags {
  std::string path;                   ///< --open FILE (or, for tv-debugger, FILE.tvrec)
  std::uint64_t frame = 0;            ///< --frame N
  std::optional<std::string> item;    ///< --item LABEL: the item traced
  std::optional<std::uint32_t> call;  ///< --call K: the call of the frame selected
  std::optional<MoverSpec> whatIf;    ///< --what-if MOVER: re-run beside the recorded run
  bool updatesAsMoves = false;        ///< --updates-as-moves: for the what-if run
  /// --first-failure: with --what-if, the frame and call of the first re-run move that
  /// tunnelled or ended inside a solid (instead of --frame and --call).
  bool firstFailure = false;
};

/// `--first-failure` found nothing to show: no re-run move tunnelled or ended inside a solid.
struct NoFailure {
  std::string message;
};

/// Takes --open, --frame, --item, --call, --what-if, --updates-as-moves and --first-failure (and,
/// with `positional`, a lone argument ending in .tvrec) out of argv; the other arguments go to
/// `rest`, argv[0] first. Returns the flags when a recording was named; UsageError for a flag
/// without its value, --frame/--item/--call without a recording, --updates-as-moves or
/// --first-failure without --what-if, and --first-failure with --frame or --call.
[[nodiscard]] std::optional<RecordingFlags> extractRecordingFlags(int argc, char** argv,
                                                                  bool positional,
                                                                  std::vector<char*>& rest);
/// UsageError naming the first flag of `o` that picks a built-in scene (--scene, --mover,
/// --tick, a scene parameter...), which a recording does not take.
void rejectSceneFlags(const PictureOptions& o);

/// Opens `path` for the debugger (the view is at frame 0); tv::Error naming the file and what
/// is wrong with it.
[[nodiscard]] RecordingSession openRecording(const std::string& path);

class RecordingStill {
 public:
  /// Opens the recording and shows the frame, item and call the flags name (with --what-if, runs
  /// the re-run to the end first); tv::Error for a bad file, UsageError for a frame, item or call
  /// it does not have, NoFailure for --first-failure when nothing failed.
  RecordingStill(const RecordingFlags& r, const PictureOptions& o);

  /// Fresh per-image state (camera, overlays): call once per image, before its frames.
  void beginImage();
  /// The windows of one ImGui frame filling `display` (between NewFrame and Render).
  void drawFrame(ImVec2 display);
  [[nodiscard]] RecordingSession& session() { return session_; }

 private:
  void showBoth();

  RecordingFlags r_;
  PictureOptions o_;
  RecordingSession session_;
  RecordingViewState state_;
  // --what-if: the re-run, its whole-run report and its view.
  struct WhatIf {
    MoverSpec mover;
    WhatIfReport report;
    std::unique_ptr<RecordingSession> session;
    DebuggerState view;
  };
  std::unique_ptr<WhatIf> whatIf_;
  std::optional<ItemId> failedItem_;  // --first-failure: the item whose move failed
};

/// The overlays for a recording: as `overlaysFor`, but without the physics/render/pixel marker
/// (a recording has no render rate) unless --show names it.
[[nodiscard]] Overlays recordingOverlays(const PictureOptions& o);

/// The framing a still uses for a view kind: the whole world, the traced move, or a rect.
[[nodiscard]] Rect recordingView(const RecordingSession& s, const PictureOptions& o);

}  // namespace tv::ui
