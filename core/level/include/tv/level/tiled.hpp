#pragma once
/// Tiled JSON maps (.tmj / .json), orthogonal, as levels.
///
/// Solid: every tile of a tile layer whose `collidable` property is true or whose name is in
/// `TiledOptions::solidLayers`, and every tile whose tileset tile has `collidable` true (STI's
/// convention); every rectangle object whose layer is solid that way or whose own `collidable`
/// is true. Objects of class (Tiled 1.9+) or type `player`, `walker`, `bullet` or `spawner`
/// become bodies (their properties: core/level/FORMAT.md, "Tiled maps"). Tile data: CSV arrays
/// or base64 (uncompressed, zlib, gzip), finite or infinite (chunks); flip flags are masked off.
/// Anything else that matters (isometric, hexagonal or staggered maps, zstd, XML tilesets,
/// rotated or non-rectangular collidable objects) throws tv::Error naming it as unsupported.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tv/level/level.hpp"

namespace tv::level {

/// What a Tiled map cannot say for itself: layers to treat as solid, and how to read the
/// external tilesets it names.
struct TiledOptions {
  /// Layers (by name) all of whose tiles and objects are solid, whatever their properties say.
  std::vector<std::string> solidLayers;
  /// Reads an external tileset (`source` as written in the map) and returns its text; unset:
  /// external tilesets are an error. loadTiledMap reads them beside the map.
  std::function<std::string(const std::string& source)> readTileset;
};

/// Reads a map's text; `file` names it in errors.
[[nodiscard]] Level parseTiledMap(std::string_view text, std::string_view file,
                                  const TiledOptions& options = {});
/// Reads a map from disk (at most 64 MiB), with its external .tsj tilesets.
[[nodiscard]] Level loadTiledMap(const std::filesystem::path& path, TiledOptions options = {});

}  // namespace tv::level
