#include "settings.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tv/error.hpp"

namespace tv::viewer {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

}  // namespace

std::optional<std::filesystem::path> Settings::defaultPath() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return std::filesystem::path(xdg) / "tunnelvision" / "debugger.txt";
  const char* home = std::getenv("HOME");
  if (home && *home)
    return std::filesystem::path(home) / ".config" / "tunnelvision" / "debugger.txt";
  return std::nullopt;
}

bool Settings::load(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    values_[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  return true;
}

bool Settings::save(const std::filesystem::path& path, std::string& error) const {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  // Written beside and renamed over, so a crash mid-write never leaves half a file.
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) {
      error = "cannot write " + tmp.string();
      return false;
    }
    out << "# tv-debugger settings, written on exit (delete this file to start afresh)\n";
    for (const auto& [k, v] : values_) out << k << " = " << v << "\n";
    if (!out) {
      error = "cannot write " + tmp.string();
      return false;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    error = "cannot replace " + path.string() + ": " + ec.message();
    return false;
  }
  return true;
}

std::optional<std::string> Settings::get(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

bool Settings::getBool(const std::string& key, bool fallback) const {
  const auto v = get(key);
  if (!v) return fallback;
  if (*v == "1" || *v == "true") return true;
  if (*v == "0" || *v == "false") return false;
  return fallback;
}

double Settings::getNumber(const std::string& key, double fallback) const {
  const auto v = get(key);
  if (!v) return fallback;
  std::istringstream in(*v);
  double d = 0.0;
  if (!(in >> d)) return fallback;
  return d;
}

void Settings::set(const std::string& key, std::string value) {
  values_[key] = std::move(value);
}

void Settings::setNumber(const std::string& key, double value) {
  set(key, formatNumber(value));
}

}  // namespace tv::viewer
