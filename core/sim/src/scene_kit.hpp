#pragma once
// Internal helpers shared by the built-in scenes: a deterministic random source, the common
// parameters, and small builders. Not installed; no guarantee of stability.

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/rng.hpp"
#include "tv/sim/scene.hpp"

namespace tv::sim::detail {

using tv::sim::Rng;

/// Per-scene defaults of the common parameters.
struct CommonDefaults {
  double speed = 240.0;
  double size = 16.0;
  double tile = 16.0;
  double dt = 1.0 / 60.0;
  double offset = 0.0;
  double count = 1.0;
  double maxCount = 100000.0;
  double seed = 1.0;
  double cell = 64.0;
  std::string speedMeaning = "how fast the bodies move";
  std::string sizeMeaning = "side of the moving bodies";
  std::string countMeaning = "how many bodies";
};

/// speed, size, tile, dt, substep, offset, count, seed, cell — in that order.
std::vector<ParamSpec> commonParams(const CommonDefaults& d);
ParamSpec realParam(std::string name, std::string unit, std::string description, double value,
                    double min, double max, bool minExclusive);
ParamSpec intParam(std::string name, std::string description, double value, double min, double max);

/// The common parameters, read once.
struct Common {
  double speed, size, tile, dt, substep, offset, cell;
  std::int64_t count;
  std::uint64_t seed;
};
Common readCommon(const Params& p);

/// Throws tv::Error "scene 'name': what" (for combinations a single range cannot reject).
[[noreturn]] void sceneFail(std::string_view scene, const std::string& what);

/// A body moving with `mask` collisions and `response`.
Body makeBody(Rect r, BodyRole role, std::uint32_t layer, std::uint32_t mask, ResponseId response,
              Vec2 velocity, std::uint32_t group = 0);

/// Registration, one function per source file.
void registerProjectileScenes(SceneRegistry& r);
void registerRestingScenes(SceneRegistry& r);
void registerGameScenes(SceneRegistry& r);
void registerPlatformScenes(SceneRegistry& r);

}  // namespace tv::sim::detail
