#pragma once
// tv-bench's command line: the subcommands (studies), the flags they share, and the flags each
// study adds. Bad input is a UsageError whose message names the flag and echoes the value.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tv::bench {

/// How much work a study does: `quick` takes seconds (the CI smoke test), `normal` under a
/// minute, `full` produces the published numbers.
enum class Mode : std::uint8_t { quick, normal, full };

[[nodiscard]] std::string_view modeName(Mode m);

/// The fixed seed every study uses unless --seed says otherwise.
inline constexpr std::uint64_t kDefaultSeed = 20240601;

struct UsageError {
  std::string message;
};

/// A study-specific flag: `--name VALUE`, or `--name` alone when `takesValue` is false.
struct FlagSpec {
  std::string name;
  std::string help;
  bool takesValue = true;
};

struct Options {
  std::string study;
  Mode mode = Mode::normal;
  std::uint64_t seed = kDefaultSeed;
  std::filesystem::path out;                 ///< where CSV and plots go (created)
  std::map<std::string, std::string> extra;  ///< study flags given, by name (without --)

  [[nodiscard]] bool has(std::string_view flag) const {
    return extra.count(std::string(flag)) != 0;
  }
  /// A comma-separated list of numbers given to --flag, or `fallback` if the flag is absent.
  [[nodiscard]] std::vector<double> numbers(std::string_view flag,
                                            std::vector<double> fallback) const;
  /// A comma-separated list of names given to --flag, or `fallback`.
  [[nodiscard]] std::vector<std::string> names(std::string_view flag,
                                               std::vector<std::string> fallback) const;
  /// Picks a value by mode.
  template <class T>
  [[nodiscard]] T pick(T quick, T normal, T full) const {
    return mode == Mode::quick ? quick : (mode == Mode::full ? full : normal);
  }
};

/// Parses a number the way every flag does ("1e5", "0.25"); throws UsageError naming the flag.
[[nodiscard]] double parseNumber(std::string_view flag, std::string_view text);
/// A whole number >= 0.
[[nodiscard]] std::uint64_t parseCount(std::string_view flag, std::string_view text);

}  // namespace tv::bench
