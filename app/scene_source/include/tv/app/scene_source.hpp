#pragma once
/// `--map level.tmj`, `--scene-file s.json` and `--solid-layer NAME`: a scene from a file in
/// place of a built-in `--scene`, the same way in every program (tv-run, tv-render, tv-bench
/// tunnel, tv-debugger). A program offers each flag to `take` before its own parsing, then asks
/// `scene()` where it would have looked a built-in scene up.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"

namespace tv::app {

class SceneSource {
 public:
  /// The flags this class reads, for usage texts.
  static constexpr const char* kUsage =
      "  --map FILE       a Tiled JSON map (.tmj/.json) instead of --scene\n"
      "  --solid-layer N  with --map: every tile and object of layer N is solid (repeatable)\n"
      "  --scene-file F   a scene file (JSON; tv-run --export-scene writes one) instead of "
      "--scene\n";

  /// A file opened from a menu or dropped on a window: a map if it ends in .tmj, a scene file
  /// if it is JSON that says "tunnelvision-scene" near its start, else a map.
  [[nodiscard]] static SceneSource forFile(const std::string& path);

  /// True if `flag` (without "--") is one of ours, and then keeps `value`. Returns an error
  /// message in `error` for a second --map / --scene-file or both given.
  bool take(std::string_view flag, std::string_view value, std::string& error);

  /// --map or --scene-file was given.
  [[nodiscard]] bool given() const { return !map_.empty() || !sceneFile_.empty(); }
  /// The flag and file, e.g. "--map level.tmj" (for messages).
  [[nodiscard]] std::string describe() const;
  /// The file's stem ("level" for levels/level.tmj): output names and titles use it.
  [[nodiscard]] std::string stem() const;
  /// --solid-layer given without --map (a mistake worth saying).
  [[nodiscard]] bool strayLayers() const { return map_.empty() && !solidLayers_.empty(); }

  /// Loads the file on first use and keeps it (copies of this object share it, loaded before
  /// or after the copy, and keep it alive). Throws
  /// tv::Error naming the file, the JSON path and the value.
  [[nodiscard]] const sim::SceneDef& scene() const;
  /// The mover the file suggests (a scene file's "mover", a map's `mover` property; the loader
  /// has checked the name against the mover table).
  [[nodiscard]] std::optional<MoverSpec> mover() const;
  /// What the loader wants the user to know (e.g. that nothing in a map is collidable).
  [[nodiscard]] std::vector<std::string> notes() const;

 private:
  struct Loaded;
  struct Slot {
    std::shared_ptr<const Loaded> loaded;
  };
  const Loaded& load() const;

  std::string map_, sceneFile_;
  std::vector<std::string> solidLayers_;
  std::shared_ptr<Slot> slot_ = std::make_shared<Slot>();
};

}  // namespace tv::app
