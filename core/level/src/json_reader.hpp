#pragma once
// Reading untrusted JSON with the path of every value: each accessor checks the type and the
// range, and a bad value throws tv::Error "FILE: layers[2].data[117]: expected ..., but got -5".
// Internal to tv::level.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "tv/geometry.hpp"

namespace tv::level::detail {

using Json = nlohmann::json;

/// Parses `text`, or throws tv::Error naming the file and the byte offset of the syntax error.
Json parseJson(std::string_view text, std::string_view file);

/// A value in a parsed document and where it sits.
class JsonAt {
 public:
  JsonAt(const Json& value, std::string path, const std::string& file)
      : v_(&value), path_(std::move(path)), file_(&file) {}

  [[nodiscard]] const Json& json() const { return *v_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const std::string& file() const { return *file_; }

  [[nodiscard]] bool isObject() const { return v_->is_object(); }
  [[nodiscard]] bool isArray() const { return v_->is_array(); }
  [[nodiscard]] bool has(std::string_view key) const;
  /// The member `key` (which must exist; the value must be an object).
  [[nodiscard]] JsonAt operator[](std::string_view key) const;
  /// The member `key`, or nullopt when absent (the value must be an object).
  [[nodiscard]] std::optional<JsonAt> find(std::string_view key) const;
  /// Element `i` of an array.
  [[nodiscard]] JsonAt at(std::size_t i) const;
  /// Elements of an array (throws unless it is one).
  [[nodiscard]] std::size_t size() const;

  [[nodiscard]] double number() const;                        ///< finite
  [[nodiscard]] double number(double min, double max) const;  ///< finite, in [min, max]
  [[nodiscard]] double positive(double max = 1e9) const;      ///< finite, in (0, max]
  /// A whole number in [min, max] (an integer, or a double with no fraction).
  [[nodiscard]] std::int64_t whole(std::int64_t min, std::int64_t max) const;
  [[nodiscard]] bool boolean() const;
  [[nodiscard]] const std::string& string() const;
  /// `[x, y]` of finite numbers.
  [[nodiscard]] Vec2 vec2() const;
  /// `[x, y, w, h]`: finite, |x|, |y| <= 1e9, 0 < w, h <= 1e9.
  [[nodiscard]] Rect rect() const;

  /// Throws "FILE: PATH: WHAT, but got VALUE" (the value cut to a readable length).
  [[noreturn]] void fail(std::string_view what) const;
  /// Throws "FILE: PATH: WHAT" (no value echoed).
  [[noreturn]] void failPlain(std::string_view what) const;

 private:
  const Json* v_;
  std::string path_;
  const std::string* file_;
};

/// The value as JSON text, cut to about 60 characters.
std::string echo(const Json& v);

}  // namespace tv::level::detail
