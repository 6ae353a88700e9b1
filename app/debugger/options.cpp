#include "options.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

namespace tv::viewer {

const char* const kUsage =
    "usage: tv-debugger [--scene NAME | --map FILE.tmj | --scene-file FILE.json]\n"
    "                   [--mover NAME | --compare A,B[,C...]] [--tick N]\n"
    "                   [--window WxH] [--body I|none] [--view scene|follow|X,Y,W,H]\n"
    "                   [--render-hz R] [--hide a,b] [--show a,b] [--PARAM VALUE ...]\n"
    "                   [--overlay] [--sweep] [--ui-scale S] [--no-settings]\n"
    "                   [--frames K --screenshot FILE.png | --app-screenshot FILE.png]\n"
    "       tv-debugger GAME.tvrec [--frame N] [--call K] [--item LABEL] [--window WxH]\n"
    "                   [--what-if MOVER [--updates-as-moves] [--first-failure]]\n"
    "                   [--view scene|follow|X,Y,W,H] [--hide a,b] [--show a,b] [...as above]\n"
    "\n"
    "The interactive debugger: a window (GLFW, OpenGL 3.3) showing a scene frame by frame, what\n"
    "each move visited and hit, with time controls, live tuning and mover comparisons. Press F1\n"
    "in the window for every shortcut.\n"
    "  The picture's flags are tv-render's (see tv-render --help): the scene, the mover or the\n"
    "  movers to compare, the tick to open at, the window size, the traced body, the view, the\n"
    "  render rate, the overlays and any scene parameter. A level from a file: --map FILE (a\n"
    "  Tiled map; --solid-layer NAME makes a layer solid) or --scene-file FILE; in the window,\n"
    "  File > Open file... or drop the file on it.\n"
    "  --overlay        compared movers in one view (default: side by side)\n"
    "  --sweep          open the substep sweep plot\n"
    "  --ui-scale S     text and widget scale, 0.5..4 (default: the monitor's content scale)\n"
    "  --no-settings    neither read nor write the settings file\n"
    "  --screenshot F   smoke mode: render K frames (--frames, default 4) of tv-render's picture\n"
    "                   of the scene at the tick, write it to F and exit; tv-render given the\n"
    "                   same flags writes the same pixels\n"
    "  --app-screenshot F  the same, of the whole debugger window\n"
    "A recording (GAME.tvrec, written by tv::Recorder; or File > Open recording..., or drop the\n"
    "file on the window) opens at frame N (default 0), with call K of it selected and the item\n"
    "labelled LABEL traced; --screenshot then writes tv-render --open's picture of it.\n"
    "  --what-if MOVER  re-run the recording with MOVER beside the recorded run (What-if menu)\n"
    "  --updates-as-moves  in that run, an update that only moves an item is made a move\n"
    "  --first-failure  open at the first re-run move that tunnelled or ended inside a solid\n"
    "Settings (scene, movers, layout, overlays, window size, playback rate, tuned parameter\n"
    "values) live in\n"
    "$XDG_CONFIG_HOME/tunnelvision/debugger.txt (or ~/.config/tunnelvision/debugger.txt).\n"
    "Exit status: 0 done, 1 failed (no display, GL), 2 bad command line.\n";

namespace {

double parseScale(std::string_view text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v) || v < 0.5 || v > 4.0) {
    throw ui::UsageError{"--ui-scale: expected a number in 0.5..4, but got '" + std::string(text) +
                         "'"};
  }
  return v;
}

}  // namespace

ViewerOptions parseViewerOptions(int argc, char** argv) {
  ViewerOptions o;
  // A recording's flags come out first, then the debugger's own; the rest is the picture's
  // command line.
  std::vector<char*> args;
  o.recording = ui::extractRecordingFlags(argc, argv, true, args);
  argc = static_cast<int>(args.size());
  argv = args.data();
  std::vector<char*> rest = {argv[0]};
  const auto value = [&](int& i, std::string_view flag) -> std::string {
    if (i + 1 >= argc || std::string_view(argv[i + 1]).substr(0, 2) == "--") {
      throw ui::UsageError{std::string(flag) + " needs a value"};
    }
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--screenshot") {
      o.screenshot = value(i, arg);
    } else if (arg == "--app-screenshot") {
      o.appScreenshot = value(i, arg);
    } else if (arg == "--no-settings") {
      o.noSettings = true;
    } else if (arg == "--sweep") {
      o.sweep = true;
    } else if (arg == "--overlay") {
      o.overlay = true;
    } else if (arg == "--ui-scale") {
      o.uiScale = parseScale(value(i, arg));
    } else if (arg == "--out" || arg.substr(0, 6) == "--out=") {
      throw ui::UsageError{"--out: tv-debugger writes a picture with --screenshot FILE"};
    } else {
      rest.push_back(argv[i]);
    }
  }
  o.picture = ui::parsePictureOptions(static_cast<int>(rest.size()), rest.data());
  if (o.picture.ticks.size() > 1) {
    throw ui::UsageError{"--ticks: tv-debugger opens at one tick; give --tick N"};
  }
  if (o.recording) ui::rejectSceneFlags(o.picture);
  if (o.screenshot && o.appScreenshot) {
    throw ui::UsageError{"--screenshot: give either --screenshot or --app-screenshot"};
  }
  return o;
}

}  // namespace tv::viewer
