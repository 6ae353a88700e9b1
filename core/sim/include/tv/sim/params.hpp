#pragma once
/// Scene parameters: every scene declares its knobs once (name, unit, range, default), and the
/// viewer, tv-run, the tests and the benchmarks set them by name. Values are doubles; integer
/// and on/off parameters say so and are checked to be whole numbers.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tv::sim {

/// One parameter: its name, what it means and the values it accepts.
struct ParamSpec {
  std::string name;           ///< as used by `Params::set` and by tv-run's `--name value`
  std::string unit;           ///< "px/s", "px", "s", "" ...
  std::string description;    ///< one line
  double value = 0.0;         ///< the default
  double min = 0.0;           ///< smallest accepted value
  double max = 0.0;           ///< largest accepted value
  bool minExclusive = false;  ///< when true the value must be > min (e.g. speed > 0)
  bool integer = false;       ///< whole numbers only (counts, seeds, on/off switches)
};

/// The common parameters every scene has (each scene picks its own defaults and ranges).
namespace param {
inline constexpr std::string_view speed = "speed";  ///< px/s: how fast things move
inline constexpr std::string_view size = "size";    ///< px: side of the moving bodies
inline constexpr std::string_view tile = "tile";    ///< px: side of a solid tile
inline constexpr std::string_view dt = "dt";        ///< s: the fixed physics step
inline constexpr std::string_view substep =
    "substep";  ///< px: substep movers' longest piece; 0 = tile/2
inline constexpr std::string_view offset =
    "offset";  ///< px: added to every coordinate, |offset| <= 1e9
inline constexpr std::string_view count = "count";  ///< how many bodies (bullets, balls, movers...)
inline constexpr std::string_view seed = "seed";    ///< seeds the scene's random phases and layouts
inline constexpr std::string_view cell = "cell";    ///< px: the world's spatial-hash cell size
}  // namespace param

/// Values for a list of parameter specs. Setting validates: a bad value throws tv::Error naming
/// the parameter and echoing the value, and changes nothing.
class Params {
 public:
  Params() = default;
  /// Starts from every spec's default. Throws tv::Error on a duplicate name or a default that
  /// its own range rejects (a scene definition bug).
  explicit Params(std::vector<ParamSpec> specs);

  /// The value of `name`; throws tv::Error listing the valid names if there is none.
  [[nodiscard]] double get(std::string_view name) const;
  /// `get`, for parameters declared integer.
  [[nodiscard]] std::int64_t getInt(std::string_view name) const;
  /// Sets `name` to `value` after checking it (finite, in range, whole if integer).
  void set(std::string_view name, double value);
  /// True when the scene has a parameter of that name.
  [[nodiscard]] bool has(std::string_view name) const;

  /// The declarations (name, range, default...), in declaration order.
  [[nodiscard]] std::span<const ParamSpec> specs() const { return specs_; }
  /// The current values, in the same order as specs().
  [[nodiscard]] std::span<const double> values() const { return values_; }
  /// Names in declaration order.
  [[nodiscard]] std::vector<std::string_view> names() const;

  /// Checks `value` against `spec` without setting anything; throws tv::Error like `set`.
  static void validate(const ParamSpec& spec, double value);

 private:
  [[nodiscard]] std::size_t indexOf(std::string_view name) const;

  std::vector<ParamSpec> specs_;
  std::vector<double> values_;
};

}  // namespace tv::sim
