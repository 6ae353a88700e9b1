#pragma once
/// Reading a flag's value as a number, the same way in every program: the whole text must be
/// the number, and a bad one throws the program's own usage-error type, built from a message
/// that names the flag and echoes the text ("--speed: expected a finite number, but got 'fast'").

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace tv::app {

namespace detail {
inline std::string badValue(std::string_view flag, std::string_view expected,
                            std::string_view text) {
  std::string m = "--";
  m += flag;
  m += ": expected ";
  m += expected;
  m += ", but got '";
  m += text;
  m += "'";
  return m;
}
}  // namespace detail

/// A finite double ("1e5", "0.25", "-3"); `UsageError{message}` otherwise.
template <class UsageError>
[[nodiscard]] double parseFinite(std::string_view flag, std::string_view text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw UsageError{detail::badValue(flag, "a finite number", text)};
  }
  return v;
}

/// A whole number >= 0 ("0", "600"); `UsageError{message}` otherwise.
template <class UsageError>
[[nodiscard]] std::uint64_t parseWhole(std::string_view flag, std::string_view text) {
  std::uint64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end) {
    throw UsageError{detail::badValue(flag, "a whole number >= 0", text)};
  }
  return v;
}

}  // namespace tv::app
