#pragma once
/// The command line that names a picture: scene, mover or movers, tick, window, traced body,
/// view, render rate, overlays and scene parameters. tv-render and tv-debugger's screenshot mode
/// read the same flags, so one command line gives the same picture from either. Movers are
/// parsed here, from the mover table; the scene and its parameters are checked against the
/// registry by `Still`, with the flag named in the message.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tv/app/scene_source.hpp"
#include "tv/mover.hpp"

namespace tv::ui {

/// A bad command line: the message names the flag and echoes the value.
struct UsageError {
  std::string message;
};

enum class ViewKind { scene, follow, rect };

struct PictureOptions {
  bool help = false;
  bool list = false;
  bool timing = false;
  std::string scene = "bullets-wall";
  /// --mover or --compare, parsed where typed (each named once; a comparison has two or more).
  std::vector<MoverSpec> movers = {MoverSpec{.kind = MoverKind::continuous}};
  bool compare = false;
  std::vector<std::uint64_t> ticks = {1};  ///< increasing, no repeats
  int width = 1280, height = 720;  ///< --window WxH (--size is the body size, a parameter)
  std::optional<std::string> out;  ///< may hold {tick}; default <scene>_<mover>_<tick>.png
  std::optional<std::size_t> body = 0;
  ViewKind view = ViewKind::scene;
  double viewRect[4] = {0, 0, 0, 0};  ///< x, y, w, h for ViewKind::rect
  double renderHz = 0.0;
  int frames = 4;
  /// --first-failure: the picture opens at the run's first failure (found by the debugger's
  /// checks), its item traced, centred and zoomed, instead of at --tick / --frame.
  bool firstFailure = false;
  std::vector<std::string> hide, show;
  /// One line on what the picture shows, drawn under a comparison's title (--caption TEXT).
  std::string caption;
  std::vector<std::pair<std::string, std::string>> params;  ///< --NAME VALUE, in order
  app::SceneSource file;  ///< --map / --scene-file in place of --scene (then `scene` is its stem)
  /// Which flags were on the command line (a program with saved settings lets these win).
  bool sceneGiven = false, moverGiven = false, tickGiven = false, windowGiven = false;
};

/// Throws UsageError naming the flag. Unknown `--NAME VALUE` pairs are kept as parameters.
[[nodiscard]] PictureOptions parsePictureOptions(int argc, char** argv);

/// What --list prints, the same in tv-render and tv-debugger: every scene with its category,
/// description and parameters (as flags, with their defaults), then every mover.
[[nodiscard]] std::string sceneAndMoverList();

}  // namespace tv::ui
