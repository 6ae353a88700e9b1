#pragma once
/// A still: the debugger's picture of a source at a moment — a scene (or level) at a tick, with
/// one mover or several compared, or a recording at a frame and call — as tv-render draws it
/// and as tv-debugger's screenshot mode draws it, from the same flags. Sharing this one
/// composition (the session and the view) is what lets a test demand that both programs give
/// the same pixels.

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
  std::optional<MoverSpec> whatIf;    ///< --what-if MOVER: re-run beside it (tv-debugger)
  bool updatesAsMoves = false;        ///< --updates-as-moves: for the what-if run
};

/// Takes --open, --frame, --item, --call, --what-if and --updates-as-moves (and, with
/// `positional`, a lone argument ending in .tvrec) out of argv; the other arguments go to `rest`,
/// argv[0] first. Returns the flags when a recording was named; UsageError for a flag without
/// its value, or --frame/--item/--call without a recording.
[[nodiscard]] std::optional<RecordingFlags> extractRecordingFlags(int argc, char** argv,
                                                                  bool positional,
                                                                  std::vector<char*>& rest);
/// UsageError naming the first flag of `o` that picks a built-in scene (--scene, --mover,
/// --tick, a scene parameter...), which a recording does not take.
void rejectSceneFlags(const PictureOptions& o);

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
  /// A scene's picture (`o`), or a recording's when `r` is given. Throws UsageError naming the
  /// flag, or tv::Error for a file that does not open.
  explicit Still(const PictureOptions& o, const std::optional<RecordingFlags>& r = {});
  ~Still();

  /// Every panel runs to `tick` (at `o.renderHz`); UsageError when it cannot. A recording's
  /// frame is chosen by its flags.
  void advanceTo(std::uint64_t tick);
  /// Fresh per-image state (camera, overlays, title) for the current tick: call once per
  /// image, before its frames.
  void beginImage();
  /// The windows of one ImGui frame filling `display` (between NewFrame and Render).
  void drawFrame(ImVec2 display);

  [[nodiscard]] Session& session() { return *session_; }
  [[nodiscard]] bool recording() const { return recorded_.has_value(); }

 private:
  PictureOptions o_;
  std::optional<RecordingFlags> recorded_;
  std::unique_ptr<Session> session_;
  ViewState view_;
};

}  // namespace tv::ui
