#pragma once
/// Errors at the API boundary: bad user input throws `tv::Error` whose message names the
/// argument and echoes its value, and the call changes nothing. Programmer errors inside tv
/// are `assert`s.

#include <stdexcept>
#include <string>
#include <string_view>

namespace tv {

/// What every call of tv throws on bad input; `what()` names the call, the argument and its
/// value ("tv::World::add: w must be finite and > 0, but was -1").
class Error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Shortest text that reads back to the same double ("8.1", "nan", "-inf", "1e+300").
[[nodiscard]] std::string formatNumber(double v);

/// Each throws `Error` like "tv::World::add: w must be finite and > 0, but was -1".
void requireFinite(std::string_view where, std::string_view name, double v);
/// Throws unless `v` is finite and > 0: "<where>: <name> must be finite and > 0, but was <v>".
void requirePositive(std::string_view where, std::string_view name, double v);
/// "x must be within ±2^500 (about 3.27e150), but was 1e+155": the range of geometry.hpp.
void requireInRange(std::string_view where, std::string_view name, double v);
/// Throws `Error("<where>: <what>")`.
[[noreturn]] void fail(std::string_view where, std::string_view what);

}  // namespace tv
