#pragma once
// What the debugger remembers between runs: a small "key = value" text file in the user's
// config directory ($XDG_CONFIG_HOME/tunnelvision/debugger.txt, else
// ~/.config/tunnelvision/debugger.txt). Unknown keys and bad lines are skipped, so an old or
// hand-edited file never stops the debugger from starting.

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace tv::viewer {

class Settings {
 public:
  /// The file's path; none when neither XDG_CONFIG_HOME nor HOME is set.
  [[nodiscard]] static std::optional<std::filesystem::path> defaultPath();

  /// Reads `path`; returns false (and stays empty) when there is no such file.
  bool load(const std::filesystem::path& path);
  /// Writes every value; returns false with `error` set when it cannot.
  bool save(const std::filesystem::path& path, std::string& error) const;

  [[nodiscard]] std::optional<std::string> get(const std::string& key) const;
  [[nodiscard]] bool getBool(const std::string& key, bool fallback) const;
  [[nodiscard]] double getNumber(const std::string& key, double fallback) const;
  void set(const std::string& key, std::string value);
  void setBool(const std::string& key, bool value) { set(key, value ? "1" : "0"); }
  void setNumber(const std::string& key, double value);

 private:
  std::map<std::string, std::string> values_;
};

}  // namespace tv::viewer
