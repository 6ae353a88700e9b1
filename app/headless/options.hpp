#pragma once
// tv-render's command line. Parsing only checks the form of each flag; names (scene, mover,
// parameter) are checked against the registry by main, with the flag named in the message.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tv::headless {

/// A bad command line: the message names the flag and echoes the value.
struct UsageError {
  std::string message;
};

enum class ViewKind { scene, follow, rect };

struct Options {
  bool help = false;
  bool list = false;
  bool timing = false;
  std::string scene = "bullets-wall";
  std::vector<std::string> movers = {"continuous"};
  bool compare = false;
  std::vector<std::uint64_t> ticks = {1};  ///< increasing, no repeats
  int width = 1280, height = 720;
  std::optional<std::string> out;  ///< may hold {tick}; default <scene>_<mover>_<tick>.png
  std::optional<std::size_t> body = 0;
  ViewKind view = ViewKind::scene;
  double viewRect[4] = {0, 0, 0, 0};  ///< x, y, w, h for ViewKind::rect
  double renderHz = 0.0;
  int frames = 4;
  std::vector<std::string> hide, show;
  std::vector<std::pair<std::string, std::string>> params;  ///< --NAME VALUE, in order
};

[[nodiscard]] Options parseOptions(int argc, char** argv);
extern const char* const kUsage;

}  // namespace tv::headless
