#include "tv/app/scene_source.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "tv/level/scene_file.hpp"
#include "tv/level/tiled.hpp"

namespace tv::app {

struct SceneSource::Loaded {
  sim::SceneDef scene;
  std::optional<MoverSpec> mover;
  std::vector<std::string> notes;
};

bool SceneSource::take(std::string_view flag, std::string_view value, std::string& error) {
  if (flag == "solid-layer") {
    if (value.empty()) error = "--solid-layer: needs a layer name";
    solidLayers_.emplace_back(value);
    slot_ = std::make_shared<Slot>();
    return true;
  }
  if (flag != "map" && flag != "scene-file") return false;
  if (given()) {
    error = "--" + std::string(flag) + ": a file was already given (" + describe() +
            "); give one --map or one --scene-file";
  } else if (value.empty()) {
    error = "--" + std::string(flag) + ": needs a file name";
  } else if (value.ends_with(".tvrec")) {
    error = "--" + std::string(flag) + ": '" + std::string(value) + "' is a recording, not a " +
            (flag == "map" ? "map" : "scene file") +
            " (tv-replay, tv-debugger and tv-render --open read recordings)";
  }
  (flag == "map" ? map_ : sceneFile_) = std::string(value);
  slot_ = std::make_shared<Slot>();
  return true;
}

SceneSource SceneSource::forFile(const std::string& path) {
  SceneSource s;
  std::string ignored;
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  bool sceneFile = false;
  if (ext != ".tmj") {
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    sceneFile = head.find("tunnelvision-scene") != std::string::npos;
  }
  s.take(sceneFile ? "scene-file" : "map", path, ignored);
  return s;
}

std::string SceneSource::describe() const {
  return map_.empty() ? "--scene-file " + sceneFile_ : "--map " + map_;
}

std::string SceneSource::stem() const {
  return std::filesystem::path(map_.empty() ? sceneFile_ : map_).stem().string();
}

const SceneSource::Loaded& SceneSource::load() const {
  if (!slot_->loaded) {
    level::Level lv;
    if (!map_.empty()) {
      level::TiledOptions options;
      options.solidLayers = solidLayers_;
      lv = level::loadTiledMap(map_, options);
    } else {
      lv = level::loadSceneFile(sceneFile_);
    }
    auto l = std::make_shared<Loaded>();
    if (lv.mover) l->mover = parseMover(*lv.mover);
    l->notes = lv.notes;
    l->scene = level::makeScene(std::move(lv));
    slot_->loaded = std::move(l);
  }
  return *slot_->loaded;
}

const sim::SceneDef& SceneSource::scene() const {
  return load().scene;
}
std::optional<MoverSpec> SceneSource::mover() const {
  return load().mover;
}
std::vector<std::string> SceneSource::notes() const {
  return load().notes;
}

}  // namespace tv::app
