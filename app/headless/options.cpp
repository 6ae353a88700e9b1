#include "options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace tv::headless {

const char* const kUsage =
    "usage: tv-render [--scene NAME] [--mover NAME | --compare A,B[,C...]] [--tick N | --ticks "
    "a,b,c]\n"
    "                 [--size WxH] [--out FILE.png] [--body I|none] [--view scene|follow|X,Y,W,H]\n"
    "                 [--render-hz R] [--hide a,b] [--show a,b] [--frames K] [--timing]\n"
    "                 [--PARAM VALUE ...]\n"
    "       tv-render --list\n"
    "\n"
    "Renders the debugger's picture of a scene at a tick into a PNG, without a display (OSMesa).\n"
    "  --scene NAME     a registered scene (default bullets-wall; see --list)\n"
    "  --mover NAME     the mover (default continuous)\n"
    "  --compare A,B,.. the same scene and tick for several movers side by side\n"
    "  --tick N         the tick to show (default 1); --ticks a,b,c writes one image per tick\n"
    "  --size WxH       image size in pixels (default 1280x720)\n"
    "  --out FILE       output PNG; {tick} is replaced by the tick. Default:\n"
    "                   <scene>_<mover>_<tick>.png, or <scene>_<A>-vs-<B>_<tick>.png with "
    "--compare\n"
    "  --body I         the body whose moves are traced and inspected (default 0; none: no trace)\n"
    "  --view V         scene: the scene's camera (default); follow: frame the traced body's\n"
    "                   recent moves; X,Y,W,H: this world rect\n"
    "  --render-hz R    draw rate: the render position is interpolated as a game drawing at R Hz\n"
    "                   would; 0 (default) draws the physics state of the tick\n"
    "  --hide a,b       overlays to turn off; --show a,b to turn on (names as in the panel:\n"
    "                   solids bodies grid occupied visited candidates sweep hull substeps hits\n"
    "                   responses history positions pixel-grid labels, or all)\n"
    "  --frames K       ImGui frames rendered before the capture (default 4, at least 2: panels\n"
    "                   placed below auto-sized ones settle on the third)\n"
    "  --timing         print how long a frame takes (stderr; never in the image)\n"
    "  --PARAM VALUE    any parameter of the scene: --speed --size... see --list. Note --size is\n"
    "                   the image size; the bodies' size is --body-size\n"
    "  --list           scenes and movers with their one-line descriptions\n"
    "Exit status: 0 done, 1 rendering failed, 2 bad command line.\n";

namespace {

std::vector<std::string> splitList(std::string_view flag, std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string_view part = text.substr(start, comma - start);
    if (part.empty()) {
      throw UsageError{"--" + std::string(flag) + ": empty item in '" + std::string(text) + "'"};
    }
    out.emplace_back(part);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

std::uint64_t parseTick(std::string_view flag, std::string_view text) {
  std::uint64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end) {
    throw UsageError{"--" + std::string(flag) + ": expected a whole number >= 0, but got '" +
                     std::string(text) + "'"};
  }
  return v;
}

double parseReal(std::string_view flag, std::string_view text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw UsageError{"--" + std::string(flag) + ": expected a finite number, but got '" +
                     std::string(text) + "'"};
  }
  return v;
}

void parseSize(std::string_view text, Options& o) {
  const std::size_t x = text.find('x');
  const auto bad = [&] {
    return UsageError{"--size: expected WxH with 64 <= W, H <= 8192 (e.g. 1280x720), but got '" +
                      std::string(text) + "'"};
  };
  if (x == std::string_view::npos) throw bad();
  std::uint64_t w = 0, h = 0;
  try {
    w = parseTick("size", text.substr(0, x));
    h = parseTick("size", text.substr(x + 1));
  } catch (const UsageError&) {
    throw bad();
  }
  if (w < 64 || h < 64 || w > 8192 || h > 8192) throw bad();
  o.width = static_cast<int>(w);
  o.height = static_cast<int>(h);
}

void parseView(std::string_view text, Options& o) {
  if (text == "scene") {
    o.view = ViewKind::scene;
    return;
  }
  if (text == "follow") {
    o.view = ViewKind::follow;
    return;
  }
  const auto parts = splitList("view", text);
  if (parts.size() != 4) {
    throw UsageError{"--view: expected scene, follow or X,Y,W,H, but got '" + std::string(text) +
                     "'"};
  }
  for (std::size_t i = 0; i < 4; ++i) o.viewRect[i] = parseReal("view", parts[i]);
  if (!(o.viewRect[2] > 0.0 && o.viewRect[3] > 0.0)) {
    throw UsageError{"--view: W and H must be > 0, but got '" + std::string(text) + "'"};
  }
  o.view = ViewKind::rect;
}

}  // namespace

Options parseOptions(int argc, char** argv) {
  Options o;
  bool moverGiven = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      continue;
    }
    if (arg == "--list") {
      o.list = true;
      continue;
    }
    if (arg == "--timing") {
      o.timing = true;
      continue;
    }
    if (arg.size() < 3 || arg.substr(0, 2) != "--") {
      throw UsageError{"unexpected argument '" + std::string(arg) + "' (flags start with --)"};
    }
    std::string name(arg.substr(2));
    std::string value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else {
      // A flag in the value's place means the value was forgotten.
      if (i + 1 >= argc || std::string_view(argv[i + 1]).substr(0, 2) == "--") {
        throw UsageError{"--" + name + " needs a value"};
      }
      value = argv[++i];
    }
    if (name == "scene") {
      o.scene = value;
    } else if (name == "mover" || name == "compare") {
      if (moverGiven) throw UsageError{"--" + name + ": give either one --mover or one --compare"};
      moverGiven = true;
      o.compare = name == "compare";
      o.movers = o.compare ? splitList(name, value) : std::vector<std::string>{value};
      if (o.compare && o.movers.size() < 2) {
        throw UsageError{"--compare: expected at least two movers (A,B), but got '" + value + "'"};
      }
    } else if (name == "tick") {
      o.ticks = {parseTick(name, value)};
    } else if (name == "ticks") {
      o.ticks.clear();
      for (const std::string& t : splitList(name, value)) o.ticks.push_back(parseTick(name, t));
      std::sort(o.ticks.begin(), o.ticks.end());
      o.ticks.erase(std::unique(o.ticks.begin(), o.ticks.end()), o.ticks.end());
    } else if (name == "size") {
      parseSize(value, o);
    } else if (name == "out") {
      if (value.empty()) throw UsageError{"--out: needs a file name"};
      o.out = value;
    } else if (name == "body") {
      if (value == "none") {
        o.body.reset();
      } else {
        o.body = static_cast<std::size_t>(parseTick(name, value));
      }
    } else if (name == "view") {
      parseView(value, o);
    } else if (name == "render-hz") {
      o.renderHz = parseReal(name, value);
      if (o.renderHz < 0.0) {
        throw UsageError{"--render-hz: expected a rate >= 0, but got '" + value + "'"};
      }
    } else if (name == "frames") {
      const std::uint64_t k = parseTick(name, value);
      if (k < 2 || k > 100) {
        throw UsageError{"--frames: expected 2..100 (ImGui's first frame differs), but got '" +
                         value + "'"};
      }
      o.frames = static_cast<int>(k);
    } else if (name == "hide" || name == "show") {
      auto& list = name == "hide" ? o.hide : o.show;
      for (std::string& s : splitList(name, value)) list.push_back(std::move(s));
    } else if (name == "body-size") {
      o.params.emplace_back("size", std::move(value));
    } else {
      o.params.emplace_back(std::move(name), std::move(value));
    }
  }
  if (o.ticks.size() > 1 && o.out && o.out->find("{tick}") == std::string::npos) {
    throw UsageError{"--out: with several ticks the file name needs {tick}, but got '" + *o.out +
                     "'"};
  }
  return o;
}

}  // namespace tv::headless
