// tv-run: runs Tunnelvision's scenes from the command line and prints markdown.
//
//   tv-run                         every mover on bullets-wall at 1920 px/s, side by side
//   tv-run --list                  scenes and movers, one line each
//   tv-run --scene NAME [--mover NAME] [--ticks N] [--PARAM VALUE ...] [--body BODY]
//   tv-run --map level.tmj | --scene-file s.json [...]   the same for a level from a file
//   tv-run --export-scene NAME FILE [--PARAM VALUE ...]  a built-in scene as a scene file
//
// Bad flags, unknown names, bad values and files that cannot be read print a message naming the
// flag, the value or the file on stderr and exit with code 2 (as tv-render, tv-debugger and
// tv-replay do).
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tv/app/user_message.hpp"
#include "tv/app/flags.hpp"
#include "tv/app/scene_source.hpp"
#include "tv/app/vocabulary.hpp"
#include "tv/app/missing_value.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/level/scene_file.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"

namespace {

constexpr int kUsageError = 2;
constexpr std::string_view kDefaultScene = "bullets-wall";
constexpr double kDefaultSpeed = 1920.0;
/// Ticks a scene runs at most (it stops earlier once it is done) unless --ticks says otherwise.
constexpr std::uint64_t kDefaultTicks = 600;

struct UsageError {
  std::string message;
};

const char* const kUsage =
    "usage:\n"
    "  tv-run                     compare every mover on bullets-wall at 1920 px/s\n"
    "  tv-run --list              list scenes (with their parameters) and movers\n"
    "  tv-run --scene NAME [--mover NAME] [--ticks N] [--body BODY] [--PARAM VALUE ...]\n"
    "      without --mover, every mover runs the scene side by side\n"
    "      --ticks N     most ticks to run; a scene stops earlier once done (default 600)\n"
    "      --body BODY   trace body BODY's moves and report candidates per move\n"
    "      --PARAM VALUE any parameter of the scene (see --list): --speed V --size S --tile T\n"
    "                    --dt D --substep L --offset O --count N --seed S --cell C ...\n"
    "      a run whose ticks would take over a second each (a huge --speed for the substep or\n"
    "      pixel movers) is refused, with the largest speed that fits\n"
    "  tv-run --map FILE | --scene-file FILE [...]   the same for a level from a file:\n"
    "%s"
    "  tv-run --export-scene NAME FILE [--mover M] [--PARAM VALUE ...]\n"
    "      writes built-in scene NAME (with those parameters) as a scene file that runs the same\n"
    "Exit status: 0 done, 1 failed, 2 bad command line or a file that cannot be read or used.\n";

struct Options {
  bool list = false;
  bool help = false;
  std::string scene = std::string(kDefaultScene);
  bool sceneGiven = false;
  std::optional<std::string> mover;
  std::optional<std::uint64_t> ticks;
  std::optional<std::size_t> trace;
  std::vector<std::pair<std::string, std::string>> params;  // flag name (without --), value
  tv::app::SceneSource file;                                // --map, --scene-file
  std::optional<std::pair<std::string, std::string>> exportScene;  // NAME, FILE
};

std::string usage() {
  char text[4096];
  std::snprintf(text, sizeof text, kUsage, tv::app::SceneSource::kUsage);
  return text;
}

double parseNumber(std::string_view flag, std::string_view text) {
  return tv::app::parseFinite<UsageError>(flag, text);
}

std::uint64_t parseCount(std::string_view flag, std::string_view text) {
  return tv::app::parseWhole<UsageError>(flag, text);
}

Options parseArgs(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "--list") {
      o.list = true;
      continue;
    }
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      continue;
    }
    if (arg.size() < 3 || arg.substr(0, 2) != "--") {
      throw UsageError{"unexpected argument '" + std::string(arg) + "' (flags start with --)"};
    }
    if (arg == "--export-scene") {
      if (i + 2 >= argc) throw UsageError{"--export-scene needs a scene name and a file name"};
      o.exportScene.emplace(argv[i + 1], argv[i + 2]);
      i += 2;
      continue;
    }
    std::string name(arg.substr(2));
    std::string value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else {
      if (i + 1 >= argc) {
        tv::app::refuseMissingValue<UsageError>(
            name, {"map", "scene-file", "solid-layer", "scene", "mover", "ticks", "body"});
      }
      value = argv[++i];
    }
    std::string fileError;
    if (o.file.take(name, value, fileError)) {
      if (!fileError.empty()) throw UsageError{fileError};
      o.sceneGiven = true;
    } else if (name == "scene") {
      o.scene = value;
      o.sceneGiven = true;
    } else if (name == "mover") {
      o.mover = value;
    } else if (name == "ticks") {
      o.ticks = parseCount(name, value);
    } else if (name == "body") {
      o.trace = static_cast<std::size_t>(parseCount(name, value));
    } else {
      tv::app::refuseRetiredFlag<UsageError>(name);
      o.params.emplace_back(std::move(name), std::move(value));
    }
  }
  return o;
}

// [SECTION] --list --------------------------------------------------------------------------------

void printList() {
  std::cout << "## Scenes\n\n";
  for (const tv::sim::SceneDef& s : tv::sim::builtinScenes().all()) {
    std::cout << "- **" << s.name << "** (" << s.category << "): " << s.description << "\n";
    std::cout << "  ";
    const tv::sim::Params p = s.defaults();
    bool first = true;
    for (const tv::sim::ParamSpec& spec : p.specs()) {
      std::cout << (first ? "" : ", ") << "--" << spec.name << " " << tv::formatNumber(spec.value)
                << (spec.unit.empty() ? "" : " ") << spec.unit;
      first = false;
    }
    std::cout << "\n";
  }
  std::cout << "\n## Movers\n\n";
  for (const std::string_view m : tv::moverNames()) {
    std::cout << "- **" << m << "**: " << tv::moverDescription(m) << "\n";
  }
}

// [SECTION] running -------------------------------------------------------------------------------

struct Row {
  std::string mover;
  std::uint64_t ticks = 0;
  tv::sim::Counters counters;
  std::uint64_t hash = 0;
  double ms = 0.0;
  std::optional<tv::sim::TraceStats> trace;
};

Row runOne(const tv::sim::SceneDef& scene, const tv::sim::Params& params, std::string_view mover,
           const Options& o) {
  tv::sim::SimConfig config;
  config.snapshotCapacity = 2;  // tv-run never steps back
  tv::sim::Simulation sim(scene, params, tv::parseMover(mover), config);
  if (o.trace) {
    if (*o.trace >= sim.bodies().size()) {
      throw UsageError{"--body " + std::to_string(*o.trace) + ": the scene has " +
                       std::to_string(sim.bodies().size()) + " bodies"};
    }
    sim.traceBody(*o.trace);
  }
  // Until the scene is done (every bullet resolved) or the tick budget is spent.
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(o.ticks.value_or(kDefaultTicks));
  const auto t1 = std::chrono::steady_clock::now();
  Row row;
  row.mover = std::string(mover);
  row.ticks = sim.ticks();
  row.counters = sim.counters();
  row.hash = sim.stateHash();
  row.ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  if (o.trace) row.trace = sim.traceStats();
  return row;
}

struct Column {
  std::string title;
  std::uint64_t tv::sim::Counters::*field;
};

std::vector<Column> columnsFor(std::string_view scene, const std::vector<Row>& rows) {
  using C = tv::sim::Counters;
  if (scene == "bullets-wall") {
    return {
        {"tunnelled", &C::tunnelled}, {"far-side push-outs", &C::farPushOuts}, {"hits", &C::hits}};
  }
  const std::vector<Column> all = {{"hits", &C::hits},
                                   {"tunnelled", &C::tunnelled},
                                   {"far-side push-outs", &C::farPushOuts},
                                   {"misses", &C::misses},
                                   {"escapes", &C::escapes},
                                   {"overlaps", &C::overlaps},
                                   {"jitter", &C::jitter},
                                   {"snags", &C::snags},
                                   {"jumps", &C::jumps},
                                   {"landings", &C::landings},
                                   {"respawns", &C::respawns},
                                   {"drops", &C::drops},
                                   {"pops", &C::pops},
                                   {"squishes", &C::squishes},
                                   {"collisions", &C::collisions}};
  std::vector<Column> used;
  for (const Column& c : all) {
    if (std::any_of(rows.begin(), rows.end(),
                    [&](const Row& r) { return r.counters.*c.field != 0; })) {
      used.push_back(c);
    }
  }
  if (used.empty()) used.push_back({"collisions", &C::collisions});
  return used;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

void printTable(const tv::sim::SceneDef& scene, const tv::sim::Params& params,
                const std::vector<Row>& rows) {
  std::cout << "### " << scene.name << "\n\n";
  std::cout << scene.description << ".\n\n";
  std::string settings;
  for (std::size_t i = 0; i < params.specs().size(); ++i) {
    const tv::sim::ParamSpec& s = params.specs()[i];
    settings += (settings.empty() ? "" : ", ") + s.name + "=" +
                tv::formatNumber(params.values()[i]) + (s.unit.empty() ? "" : " " + s.unit);
  }
  std::cout << settings << "\n\n";
  const bool bullets = scene.name == "bullets-wall";
  const std::vector<Column> columns = columnsFor(scene.name, rows);
  std::cout << "| mover |";
  if (!bullets) std::cout << " ticks |";
  for (const Column& c : columns) std::cout << " " << c.title << " |";
  if (!bullets) std::cout << " state hash |";
  std::cout << " ms |\n|---|";
  if (!bullets) std::cout << "---:|";
  for (std::size_t i = 0; i < columns.size(); ++i) std::cout << "---:|";
  if (!bullets) std::cout << "---|";
  std::cout << "---:|\n";
  for (const Row& r : rows) {
    std::cout << "| " << r.mover << " |";
    if (!bullets) std::cout << " " << r.ticks << " |";
    for (const Column& c : columns) std::cout << " " << r.counters.*c.field << " |";
    if (!bullets) {
      std::ostringstream hex;
      hex << std::hex << r.hash;
      std::cout << " " << hex.str() << " |";
    }
    std::cout << " " << fixed(r.ms, 1) << " |\n";
  }
  for (const Row& r : rows) {
    if (!r.trace) continue;
    const double moves = static_cast<double>(std::max<std::uint64_t>(r.trace->moves, 1));
    std::cout << "\n"
              << r.mover << ": traced " << r.trace->moves << " moves, "
              << fixed(static_cast<double>(r.trace->candidates) / moves, 2) << " candidates and "
              << fixed(static_cast<double>(r.trace->cells) / moves, 2) << " cells per move";
  }
  if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.trace.has_value(); })) {
    std::cout << "\n";
  }
}

const tv::sim::SceneDef* findScene(const Options& o, const std::string& name) {
  if (o.file.given()) {
    const tv::sim::SceneDef& s = o.file.scene();  // throws tv::Error naming the file
    for (const std::string& note : o.file.notes()) std::cerr << "tv-run: note: " << note << "\n";
    return &s;
  }
  return tv::sim::builtinScenes().tryFind(name);
}

int run(const Options& o) {
  if (o.file.strayLayers()) throw UsageError{"--solid-layer goes with --map"};
  if (o.exportScene && o.file.given()) {
    throw UsageError{"--export-scene writes a built-in scene; " + o.file.describe() +
                     " is already a file"};
  }
  const std::string sceneName = o.exportScene ? o.exportScene->first : o.scene;
  const tv::sim::SceneDef* scene = findScene(o, sceneName);
  if (!scene) {
    std::string valid;
    for (const std::string_view n : tv::sim::builtinScenes().names()) {
      valid += (valid.empty() ? "" : ", ") + std::string(n);
    }
    throw UsageError{(o.exportScene ? "--export-scene " : "--scene ") + sceneName +
                     ": no such scene; valid: " + valid};
  }
  tv::sim::Params params = scene->defaults();
  if (!o.sceneGiven && !o.exportScene) params.set(tv::sim::param::speed, kDefaultSpeed);
  for (const auto& [name, value] : o.params) {
    if (!params.has(name)) {
      std::string valid;
      for (const std::string_view n : params.names())
        valid += (valid.empty() ? "--" : ", --") + std::string(n);
      throw UsageError{"--" + name + ": unknown flag (scene " + scene->name +
                       " takes --scene, --mover, --ticks, --body, --list and " + valid + ")"};
    }
    try {
      params.set(name, parseNumber(name, value));
    } catch (const tv::Error& e) {
      throw UsageError{"--" + name + " " + value + ": " + tv::app::userMessage(e)};
    }
  }
  if (o.exportScene) {
    if (o.mover) {
      try {
        (void)tv::parseMover(*o.mover);
      } catch (const tv::Error& e) {
        throw UsageError{"--mover " + *o.mover + ": " + tv::app::userMessage(e)};
      }
    }
    const std::string text =
        tv::level::writeSceneFile(tv::level::exportScene(*scene, params, o.mover));
    std::ofstream out(o.exportScene->second, std::ios::binary);
    if (!(out << text) || !out.flush()) {
      throw UsageError{"--export-scene: cannot write '" + o.exportScene->second + "'"};
    }
    std::cout << "wrote " << o.exportScene->second << " (" << scene->name << ", " << text.size()
              << " bytes)\n";
    return 0;
  }
  std::vector<std::string_view> movers;
  if (o.mover) {
    try {
      (void)tv::parseMover(*o.mover);
    } catch (const tv::Error& e) {
      throw UsageError{"--mover " + *o.mover + ": " + tv::app::userMessage(e)};
    }
    movers.push_back(*o.mover);
  } else {
    const auto names = tv::moverNames();
    movers.assign(names.begin(), names.end());
  }
  // Every mover is checked before any runs, so a refused one costs nothing.
  for (const std::string_view m : movers) {
    try {
      const tv::sim::Simulation sim(*scene, params, tv::parseMover(m));
      if (auto why = tv::app::workLimitExceeded(params, sim.moverSpec(), sim.bodies().size()))
        throw UsageError{*why};
    } catch (const tv::Error&) {
      // Reported with the mover's name when it runs, below.
    }
  }
  std::vector<Row> rows;
  for (const std::string_view m : movers) {
    try {
      rows.push_back(runOne(*scene, params, m, o));
    } catch (const tv::Error& e) {
      throw UsageError{std::string("scene ") + scene->name + " with mover " + std::string(m) +
                       ": " + tv::app::userMessage(e)};
    }
  }
  printTable(*scene, params, rows);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parseArgs(argc, argv);
    if (o.help) {
      std::cout << usage();
      return 0;
    }
    if (o.list) {
      printList();
      return 0;
    }
    return run(o);
  } catch (const UsageError& e) {
    std::cerr << "tv-run: " << e.message << "\n" << usage();
    return kUsageError;
  } catch (const tv::Error& e) {
    // A file that cannot be read or a value refused: the input, as for a bad flag.
    std::cerr << "tv-run: " << tv::app::userMessage(e) << "\n";
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "tv-run: " << tv::app::userMessage(e) << "\n";
    return 1;
  }
}
