#pragma once
/// A still: the debugger's picture of a scene at a tick, as tv-render draws it and as
/// tv-debugger's screenshot mode draws it, from the same PictureOptions. Sharing this one
/// composition is what lets a test demand that both programs give the same pixels.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "imgui.h"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/picture_options.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {

/// The registered scene `o.scene`; UsageError listing the valid names otherwise.
[[nodiscard]] const sim::SceneDef& sceneFor(const PictureOptions& o);
/// The scene's defaults with every `--NAME VALUE` of `o` applied; UsageError naming the flag.
[[nodiscard]] sim::Params paramsFor(const sim::SceneDef& scene, const PictureOptions& o);
/// The overlays after `--hide` and `--show`; UsageError naming an unknown overlay.
[[nodiscard]] Overlays overlaysFor(const PictureOptions& o);

class Still {
 public:
  /// One session per mover of `o`, at tick 0, tracing `o.body`. Throws UsageError.
  explicit Still(const PictureOptions& o);

  /// Every session runs to `tick` (at `o.renderHz`); UsageError when it cannot.
  void advanceTo(std::uint64_t tick);
  /// Fresh per-image state (camera, overlays, title) for the current tick: call once per
  /// image, before its frames.
  void beginImage();
  /// The windows of one ImGui frame filling `display` (between NewFrame and Render).
  void drawFrame(ImVec2 display);

  [[nodiscard]] const sim::SceneDef& scene() const { return *scene_; }
  [[nodiscard]] std::vector<std::unique_ptr<Session>>& sessions() { return sessions_; }

 private:
  PictureOptions o_;
  const sim::SceneDef* scene_;
  std::vector<std::unique_ptr<Session>> sessions_;
  std::vector<DebuggerState> states_;
  std::vector<Session*> raw_;
  std::string title_;
};

}  // namespace tv::ui
