#include "options.hpp"

#include "tv/app/flags.hpp"

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
    "                   [--overlay] [--sweep] [--first-failure] [--tab T] [--ui-scale S]\n"
    "                   [--no-settings]\n"
    "                   [--frames K --screenshot FILE.png | --app-screenshot FILE.png]\n"
    "       tv-debugger GAME.tvrec [--frame N] [--call K] [--item LABEL] [--window WxH]\n"
    "                   [--what-if MOVER [--updates-as-moves]] [--first-failure]\n"
    "                   [--view scene|follow|X,Y,W,H] [--hide a,b] [--show a,b] [...as above]\n"
    "       tv-debugger --listen [HOST:]PORT [--view ...] [--hide ...]\n"
    "       tv-debugger --list\n"
    "\n"
    "The interactive debugger: a window (GLFW, OpenGL 3.3) showing a scene, a level or a\n"
    "recorded game frame by frame, what each move visited and hit and, in words, what happened;\n"
    "movers compared in lockstep, what-if re-runs, live tuning, and a Failures tab that goes\n"
    "straight to every move that failed. Press F1 in the window for every shortcut.\n"
    "The first run (no settings saved yet, nothing asked for) opens on bullets-wall at tick 2,\n"
    "discrete beside substep-discrete and continuous, body 2 followed: the tick the naive\n"
    "bullet passes the wall. The defaults below are for a run that names what it wants.\n"
    "  --scene NAME     a registered scene (default bullets-wall; --list shows them)\n"
    "  --map FILE       a Tiled JSON map (.tmj/.json) instead of --scene\n"
    "  --solid-layer N  with --map: every tile and object of layer N is solid (repeatable)\n"
    "  --scene-file F   a scene file (JSON; tv-run --export-scene writes one) instead of --scene\n"
    "  --mover NAME     the mover (default continuous)\n"
    "  --compare A,B,.. several movers in lockstep, side by side (--overlay: in one view)\n"
    "  --tick N         the tick to open at (default 1; at most 1000000, and no later than a\n"
    "                   scene's end); a run of over a second says on stderr how far it has got\n"
    "  --window WxH     window size in pixels (default 1280x720; --size is the bodies' size)\n"
    "  --body I         the body whose moves are traced and inspected (default 0; none)\n"
    "  --view V         scene: frame everything; follow: the traced move; X,Y,W,H: this rect\n"
    "  --render-hz R    draw rate: bodies drawn where a game rendering at R Hz would draw them;\n"
    "                   0 (default) draws the physics state of each tick\n"
    "  --hide a,b       overlays to turn off; --show a,b to turn on (names as in the panel:\n"
    "                   solids bodies grid occupied visited candidates sweep hull substeps hits\n"
    "                   responses history positions pixel-grid labels, or all)\n"
    "  --PARAM VALUE    any parameter of the scene (--list shows each scene's with its default):\n"
    "                   --speed --size --tile --dt --substep --offset --count --seed --cell\n"
    "                   --angle ... (as in tv-run, tv-render and the panel)\n"
    "  --overlay        compared movers in one view (default: side by side)\n"
    "  --first-failure  open at the run's first failure: its frame, the failing item traced,\n"
    "                   centred and zoomed (what the timeline's \"go\" does); for a what-if\n"
    "                   run, the first re-run move that tunnelled or ended inside a solid\n"
    "  --tab T          the column's tab shown first: inspector, calls, items, failures,\n"
    "                   counters\n"
    "  --sweep          open the substep sweep plot\n"
    "  --ui-scale S     text and widget scale, 0.5..4 (default: the monitor's content scale)\n"
    "  --no-settings    neither read nor write the settings file\n"
    "  --screenshot F   smoke mode: render K frames (--frames, default 4) of tv-render's picture\n"
    "                   of the scene at the tick, write it to F and exit; tv-render given the\n"
    "                   same flags writes the same pixels\n"
    "  --app-screenshot F  the same, of the whole debugger window\n"
    "  --list           scenes (with their parameters) and movers, one line each\n"
    "A recording (GAME.tvrec, written by tv::Recorder; or File > Open recording..., or drop the\n"
    "file on the window) opens at frame N (default 0), with call K of it selected and the item\n"
    "labelled LABEL traced; --screenshot then writes tv-render --open's picture of it.\n"
    "  --what-if MOVER  re-run the recording with MOVER beside the recorded run (Movers menu)\n"
    "  --updates-as-moves  in that run, an update that only moves an item is made a move\n"
    "A game running now (its recorder streaming: the sample with --live HOST:PORT, a game that\n"
    "calls tv::liveFromEnvironment() with TV_LIVE=HOST:PORT; or File > Listen for a game...):\n"
    "  --listen ADDR    wait for games at [HOST:]PORT (host 127.0.0.1 unless given); frames\n"
    "                   show as they arrive and the view follows the newest until you pause or\n"
    "                   scrub; Pause and Step hold the game at its next frame (when it allows\n"
    "                   it); File > Save the stream writes what is kept as a .tvrec\n"
    "  --keep-frames N  keep the newest N frames of a live game (default: no limit by count)\n"
    "  --keep-mb M      keep at most M MB of them (default 256); the oldest are dropped, and\n"
    "                   the window says so\n"
    "Settings (scene, movers, layout, overlays, window size, playback rate, tuned parameter\n"
    "values) live in\n"
    "$XDG_CONFIG_HOME/tunnelvision/debugger.txt (or ~/.config/tunnelvision/debugger.txt).\n"
    "Exit status: 0 done, 1 failed (no display, GL, a picture not written), 2 bad command line\n"
    "or a file that cannot be read or used (a map, a scene file, a recording).\n";

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
    } else if (arg == "--listen") {
      o.listen = value(i, arg);
    } else if (arg == "--keep-frames") {
      o.keepFrames = app::parseWhole<ui::UsageError>("keep-frames", value(i, arg));
    } else if (arg == "--keep-mb") {
      o.keepMegabytes = app::parseWhole<ui::UsageError>("keep-mb", value(i, arg));
      if (o.keepMegabytes < 1 || o.keepMegabytes > (std::uint64_t{1} << 20)) {
        throw ui::UsageError{"--keep-mb: expected 1..1048576 (MB), but got " +
                             std::to_string(o.keepMegabytes)};
      }
    } else if (arg == "--tab") {
      const std::string t = value(i, arg);
      if (t == "inspector") {
        o.tab = ui::Tab::inspector;
      } else if (t == "calls") {
        o.tab = ui::Tab::calls;
      } else if (t == "items") {
        o.tab = ui::Tab::items;
      } else if (t == "failures") {
        o.tab = ui::Tab::failures;
      } else if (t == "counters") {
        o.tab = ui::Tab::counters;
      } else {
        throw ui::UsageError{"--tab: expected inspector, calls, items, failures or counters, but "
                             "got '" + t + "'"};
      }
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
  ui::checkFirstFailure(o.picture, o.recording);
  if (!o.listen && (o.keepFrames != 0 || o.keepMegabytes != 256)) {
    throw ui::UsageError{"--keep-frames and --keep-mb go with --listen"};
  }
  if (o.listen && o.recording) {
    throw ui::UsageError{"--listen: a live game or a recording, not both (File > Open recording... "
                         "opens one later)"};
  }
  if (o.listen && (o.screenshot || o.appScreenshot)) {
    throw ui::UsageError{"--listen: a live game cannot be a screenshot (tv-replay --listen saves "
                         "it; open the file)"};
  }
  if (o.screenshot && o.appScreenshot) {
    throw ui::UsageError{"--screenshot: give either --screenshot or --app-screenshot"};
  }
  return o;
}

}  // namespace tv::viewer
