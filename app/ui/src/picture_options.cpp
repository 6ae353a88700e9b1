// The picture's command line, shared by tv-render and tv-debugger.
#include "tv/ui/picture_options.hpp"

#include "tv/app/flags.hpp"
#include "tv/app/missing_value.hpp"
#include "tv/app/movers.hpp"
#include "tv/app/vocabulary.hpp"
#include "tv/app/work_limit.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "tv/error.hpp"
#include "tv/sim/scene.hpp"

namespace tv::ui {

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
  return app::parseWhole<UsageError>(flag, text);
}

// A tick to open at: within the work limit, so that a scene that never ends cannot hang the tool.
std::uint64_t parseOpeningTick(std::string_view flag, std::string_view text) {
  const std::uint64_t t = parseTick(flag, text);
  if (t > app::kMaxTicks) {
    throw UsageError{"--" + std::string(flag) + " " + std::to_string(t) +
                     ": beyond the work limit of " + std::to_string(app::kMaxTicks) + " ticks"};
  }
  return t;
}

double parseReal(std::string_view flag, std::string_view text) {
  return app::parseFinite<UsageError>(flag, text);
}

void parseWindow(std::string_view text, PictureOptions& o) {
  const std::size_t x = text.find('x');
  const auto bad = [&] {
    return UsageError{"--window: expected WxH with 64 <= W, H <= 8192 (e.g. 1280x720), but got '" +
                      std::string(text) + "'"};
  };
  if (x == std::string_view::npos) throw bad();
  std::uint64_t w = 0, h = 0;
  try {
    w = parseTick("window", text.substr(0, x));
    h = parseTick("window", text.substr(x + 1));
  } catch (const UsageError&) {
    throw bad();
  }
  if (w < 64 || h < 64 || w > 8192 || h > 8192) throw bad();
  o.width = static_cast<int>(w);
  o.height = static_cast<int>(h);
}

void parseView(std::string_view text, PictureOptions& o) {
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

PictureOptions parsePictureOptions(int argc, char** argv) {
  PictureOptions o;
  bool namedScene = false;
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
    if (arg == "--first-failure") {
      o.firstFailure = true;
      continue;
    }
    if (arg.size() < 3 || arg.substr(0, 2) != "--") {
      if (arg.ends_with(".tvrec")) {
        throw UsageError{"unexpected argument '" + std::string(arg) +
                         "': open a recording with --open " + std::string(arg)};
      }
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
        app::refuseMissingValue<UsageError>(
            name, {"map", "scene-file", "solid-layer", "scene", "mover", "compare", "tick", "ticks",
                   "window", "out", "body", "view", "render-hz", "frames", "caption", "hide",
                   "show"});
      }
      value = argv[++i];
    }
    std::string fileError;
    if (o.file.take(name, value, fileError)) {
      if (!fileError.empty()) throw UsageError{fileError};
      if (o.file.given()) o.scene = o.file.stem();
      o.sceneGiven = o.sceneGiven || o.file.given();
    } else if (name == "scene") {
      o.scene = value;
      o.sceneGiven = true;
      namedScene = true;
    } else if (name == "mover" || name == "compare") {
      if (o.moverGiven) {
        throw UsageError{"--" + name + ": give either one --mover or one --compare"};
      }
      o.moverGiven = true;
      o.compare = name == "compare";
      const std::vector<std::string> names =
          o.compare ? splitList(name, value) : std::vector<std::string>{value};
      if (o.compare && names.size() < 2) {
        throw UsageError{"--compare: expected at least two movers (A,B), but got '" + value + "'"};
      }
      o.movers.clear();
      for (const std::string& n : names) {
        const MoverSpec m = app::parseMoverFlag<UsageError>(name, n);
        for (const MoverSpec& before : o.movers) {
          if (before.name() == m.name()) {
            throw UsageError{"--compare: '" + n +
                             "' is named twice; each panel shows a different mover"};
          }
        }
        o.movers.push_back(m);
      }
    } else if (name == "tick") {
      if (o.tickGiven) throw UsageError{"--tick: the tick was already given (by --tick or --ticks)"};
      o.ticks = {parseOpeningTick(name, value)};
      o.tickGiven = true;
    } else if (name == "ticks") {
      if (o.tickGiven) throw UsageError{"--ticks: the tick was already given (by --tick or --ticks)"};
      o.ticks.clear();
      for (const std::string& t : splitList(name, value)) o.ticks.push_back(parseOpeningTick(name, t));
      std::sort(o.ticks.begin(), o.ticks.end());
      o.ticks.erase(std::unique(o.ticks.begin(), o.ticks.end()), o.ticks.end());
      o.tickGiven = true;
    } else if (name == "window") {
      parseWindow(value, o);
      o.windowGiven = true;
    } else if (name == "out") {
      if (value.empty()) throw UsageError{"--out: needs a file name"};
      if (value.size() < 4 || value.compare(value.size() - 4, 4, ".png") != 0) {
        throw UsageError{"--out: the image is written as PNG, so the name must end in .png, but was '" +
                         value + "'"};
      }
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
    } else if (name == "caption") {
      if (value.size() > 300) {
        throw UsageError{"--caption: at most 300 characters (one line), but got " +
                         std::to_string(value.size())};
      }
      o.caption = value;
    } else if (name == "hide" || name == "show") {
      auto& list = name == "hide" ? o.hide : o.show;
      for (std::string& s : splitList(name, value)) list.push_back(std::move(s));
    } else {
      app::refuseRetiredFlag<UsageError>(name);
      if (name == "size") app::refuseWindowSizeAsSize<UsageError>(value);
      o.params.emplace_back(std::move(name), std::move(value));
    }
  }
  if (namedScene && o.file.given()) {
    throw UsageError{"--scene and " + o.file.describe() +
                     ": give a built-in scene or a file, not both"};
  }
  if (o.file.strayLayers()) throw UsageError{"--solid-layer goes with --map"};
  if (o.ticks.size() > 1 && o.out && o.out->find("{tick}") == std::string::npos) {
    throw UsageError{"--out: with several ticks the file name needs {tick}, but got '" + *o.out +
                     "'"};
  }
  return o;
}

std::string sceneAndMoverList() {
  std::string out = "scenes:\n";
  char line[512];
  for (const sim::SceneDef& s : sim::builtinScenes().all()) {
    std::snprintf(line, sizeof line, "  %-16s %-11s %s\n", s.name.c_str(), s.category.c_str(),
                  s.description.c_str());
    out += line;
    // Its parameters, as flags with their defaults.
    std::string flags;
    const sim::Params defaults = s.defaults();
    for (const sim::ParamSpec& p : defaults.specs()) {
      if (!flags.empty()) flags += ' ';
      flags += "--" + p.name + ' ' + formatNumber(p.value);
    }
    std::snprintf(line, sizeof line, "  %-16s %-11s %s\n", "", "", flags.c_str());
    out += line;
  }
  out += "movers:\n";
  for (const MoverEntry& m : moverTable()) {
    std::snprintf(line, sizeof line, "  %-16s %s\n", std::string(m.name).c_str(),
                  std::string(m.description).c_str());
    out += line;
  }
  return out;
}

}  // namespace tv::ui
