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
#include "tv/sim/scene.hpp"

namespace tv::sim::detail {

/// SplitMix64: the same numbers on every platform and standard library (the <random>
/// distributions are implementation-defined, so they could not back golden hashes).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [0, 1), a multiple of 2^-bits: exact in sums with dyadic coordinates.
  double dyadic(int bits) { return std::ldexp(static_cast<double>(next() >> (64 - bits)), -bits); }
  /// Uniform in [0, n), n > 0.
  std::uint64_t below(std::uint64_t n) { return next() % n; }

 private:
  std::uint64_t s_;
};

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

}  // namespace tv::sim::detail
