// Checked reading of untrusted JSON, every error naming the file, the JSON path and the value.
#include "json_reader.hpp"

#include <cmath>

#include "tv/error.hpp"

namespace tv::level::detail {

Json parseJson(std::string_view text, std::string_view file) {
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    // nlohmann's message repeats its own prefix; keep the part that says what was expected.
    std::string what = e.what();
    if (const auto colon = what.rfind("syntax error"); colon != std::string::npos) {
      what = what.substr(colon);
    }
    tv::fail(std::string(file), "byte " + std::to_string(e.byte) + ": not JSON (" + what + ")");
  } catch (const Json::exception& e) {
    // e.g. a number too large for a double ("1e999"): nlohmann reports it without a position.
    std::string what = e.what();
    if (const auto close = what.find("] "); close != std::string::npos)
      what = what.substr(close + 2);
    tv::fail(std::string(file), "not JSON we can read (" + what + ")");
  }
}

std::string echo(const Json& v) {
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

void JsonAt::fail(std::string_view what) const {
  tv::fail(*file_, (path_.empty() ? std::string("(document)") : path_) + ": " + std::string(what) +
                       ", but got " + echo(*v_));
}

void JsonAt::failPlain(std::string_view what) const {
  tv::fail(*file_, (path_.empty() ? std::string("(document)") : path_) + ": " + std::string(what));
}

bool JsonAt::has(std::string_view key) const {
  return v_->is_object() && v_->contains(key);
}

std::optional<JsonAt> JsonAt::find(std::string_view key) const {
  if (!v_->is_object()) fail("expected an object");
  const auto it = v_->find(key);
  if (it == v_->end()) return std::nullopt;
  return JsonAt(*it, path_.empty() ? std::string(key) : path_ + "." + std::string(key), *file_);
}

JsonAt JsonAt::operator[](std::string_view key) const {
  if (auto m = find(key)) return *m;
  failPlain("missing \"" + std::string(key) + "\"");
}

std::size_t JsonAt::size() const {
  if (!v_->is_array()) fail("expected an array");
  return v_->size();
}

JsonAt JsonAt::at(std::size_t i) const {
  return JsonAt((*v_)[i], path_ + "[" + std::to_string(i) + "]", *file_);
}

double JsonAt::number() const {
  if (!v_->is_number()) fail("expected a number");
  const double d = v_->get<double>();
  if (!std::isfinite(d)) fail("expected a finite number");
  return d;
}

double JsonAt::number(double min, double max) const {
  const double d = number();
  if (d < min || d > max) {
    fail("expected a number in [" + formatNumber(min) + ", " + formatNumber(max) + "]");
  }
  return d;
}

double JsonAt::positive(double max) const {
  const double d = number();
  if (!(d > 0.0) || d > max) fail("expected a number in (0, " + formatNumber(max) + "]");
  return d;
}

std::int64_t JsonAt::whole(std::int64_t min, std::int64_t max) const {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::to_string(...).
  std::string range = "[";
  range += std::to_string(min);
  range += ", ";
  range += std::to_string(max);
  range += "]";
  if (v_->is_number_unsigned()) {
    const std::uint64_t u = v_->get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(max)) fail("expected a whole number in " + range);
    const auto i = static_cast<std::int64_t>(u);
    if (i < min) fail("expected a whole number in " + range);
    return i;
  }
  if (v_->is_number_integer()) {
    const std::int64_t i = v_->get<std::int64_t>();
    if (i < min || i > max) fail("expected a whole number in " + range);
    return i;
  }
  if (v_->is_number_float()) {
    const double d = v_->get<double>();
    if (std::isfinite(d) && d == std::floor(d) && d >= static_cast<double>(min) &&
        d <= static_cast<double>(max)) {
      return static_cast<std::int64_t>(d);
    }
  }
  fail("expected a whole number in " + range);
}

bool JsonAt::boolean() const {
  if (!v_->is_boolean()) fail("expected true or false");
  return v_->get<bool>();
}

const std::string& JsonAt::string() const {
  if (!v_->is_string()) fail("expected a string");
  return v_->get_ref<const std::string&>();
}

Vec2 JsonAt::vec2() const {
  if (!v_->is_array() || v_->size() != 2) fail("expected [x, y]");
  return {at(0).number(), at(1).number()};
}

Rect JsonAt::rect() const {
  if (!v_->is_array() || v_->size() != 4) fail("expected [x, y, w, h]");
  return {at(0).number(-1e9, 1e9), at(1).number(-1e9, 1e9), at(2).positive(), at(3).positive()};
}

}  // namespace tv::level::detail
