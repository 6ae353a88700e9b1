#include "tv/error.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "tv/geometry.hpp"

namespace tv {

std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

void fail(std::string_view where, std::string_view what) {
  std::string msg(where);
  msg += ": ";
  msg += what;
  throw Error(msg);
}

void requireFinite(std::string_view where, std::string_view name, double v) {
  if (!std::isfinite(v)) {
    fail(where, std::string(name) + " must be finite, but was " + formatNumber(v));
  }
}

void requirePositive(std::string_view where, std::string_view name, double v) {
  if (!std::isfinite(v) || !(v > 0.0)) {
    fail(where, std::string(name) + " must be finite and > 0, but was " + formatNumber(v));
  }
}

void requireInRange(std::string_view where, std::string_view name, double v) {
  if (!inRange(v)) {
    fail(where, std::string(name) + " must be within ±2^500 (about 3.27e150), but was " +
                    formatNumber(v));
  }
}

}  // namespace tv
