#pragma once
// tv-debugger's command line: the picture's flags, exactly as tv-render reads them (the scene,
// movers, tick, size, body, view, render rate, overlays and scene parameters), plus the
// debugger's own.

#include <cstdint>
#include <optional>
#include <string>

#include "tv/ui/picture_options.hpp"
#include "tv/ui/still.hpp"

namespace tv::viewer {

struct ViewerOptions {
  ui::PictureOptions picture;
  /// A recording to open (tv-debugger FILE.tvrec [--frame N] [--call K] [--item LABEL]).
  std::optional<ui::RecordingFlags> recording;
  /// Smoke mode: render `picture.frames` frames, write tv-render's picture of the scene at the
  /// tick to this PNG and exit.
  std::optional<std::string> screenshot;
  /// The same, but the whole debugger as a person sees it (menus, timeline, windows).
  std::optional<std::string> appScreenshot;
  /// Neither read nor write the settings file.
  bool noSettings = false;
  /// UI scale; 0: the monitor's content scale.
  double uiScale = 0.0;
  /// Open the substep sweep window.
  bool sweep = false;
  /// Draw compared movers in one view instead of side by side.
  bool overlay = false;
  /// The column's tab to show first.
  std::optional<ui::Tab> tab;
  /// --listen [HOST:]PORT: wait for games streaming live (their recorder's --live).
  std::optional<std::string> listen;
  /// --keep-frames N / --keep-mb M: the frames of a live game kept (0 frames: no limit by count).
  std::uint64_t keepFrames = 0;
  std::uint64_t keepMegabytes = 256;
};

/// Throws ui::UsageError naming the flag.
[[nodiscard]] ViewerOptions parseViewerOptions(int argc, char** argv);
extern const char* const kUsage;

}  // namespace tv::viewer
