#include "cli.hpp"

#include "tv/app/flags.hpp"

#include <charconv>
#include <cmath>

namespace tv::bench {

std::string_view modeName(Mode m) {
  switch (m) {
    case Mode::quick:
      return "quick";
    case Mode::normal:
      return "default";
    case Mode::full:
      return "full";
  }
  return "?";
}

double parseNumber(std::string_view flag, std::string_view text) {
  return tv::app::parseFinite<UsageError>(flag, text);
}

std::uint64_t parseCount(std::string_view flag, std::string_view text) {
  return tv::app::parseWhole<UsageError>(flag, text);
}

namespace {

std::vector<std::string> split(std::string_view text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t stop = comma == std::string_view::npos ? text.size() : comma;
    parts.emplace_back(text.substr(start, stop - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return parts;
}

}  // namespace

std::vector<double> Options::numbers(std::string_view flag, std::vector<double> fallback) const {
  const auto it = extra.find(std::string(flag));
  if (it == extra.end()) return fallback;
  std::vector<double> values;
  for (const std::string& part : split(it->second)) values.push_back(parseNumber(flag, part));
  return values;
}

std::vector<std::string> Options::names(std::string_view flag,
                                        std::vector<std::string> fallback) const {
  const auto it = extra.find(std::string(flag));
  if (it == extra.end()) return fallback;
  std::vector<std::string> list = split(it->second);
  for (const std::string& n : list) {
    if (n.empty()) {
      throw UsageError{"--" + std::string(flag) + ": empty name in '" + it->second + "'"};
    }
  }
  return list;
}

}  // namespace tv::bench
