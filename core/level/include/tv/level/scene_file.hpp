#pragma once
/// Scene files: a level as JSON (the format is documented in core/level/FORMAT.md, "Scene files").
/// Reading is strict: an unknown key, a wrong type or a value out of range throws tv::Error
/// naming the file, the JSON path and the value, and nothing is returned half-read.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "tv/level/level.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"

namespace tv::level {

/// Reads a scene file's text; `file` names it in errors.
[[nodiscard]] Level parseSceneFile(std::string_view text, std::string_view file);
/// Reads a scene file from disk (at most 64 MiB).
[[nodiscard]] Level loadSceneFile(const std::filesystem::path& path);

/// A scene as built from `params`: its solids and bodies, and its rules by name, so that loading
/// the file runs exactly as the scene did (same state hash, tick for tick).
[[nodiscard]] Level exportScene(const sim::SceneDef& scene, const sim::Params& params,
                                std::optional<std::string> mover = std::nullopt);
/// The level as scene-file text (numbers written so they read back bit for bit).
[[nodiscard]] std::string writeSceneFile(const Level& level);

}  // namespace tv::level
