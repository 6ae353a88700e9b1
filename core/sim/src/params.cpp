#include "tv/sim/params.hpp"

#include <cmath>

#include "tv/error.hpp"

namespace tv::sim {

namespace {

constexpr std::string_view kWhere = "tv::sim::Params";

std::string range(const ParamSpec& s) {
  std::string r = s.minExclusive ? "(" : "[";
  r += formatNumber(s.min) + ", " + formatNumber(s.max) + "]";
  return r;
}

}  // namespace

Params::Params(std::vector<ParamSpec> specs) : specs_(std::move(specs)) {
  values_.reserve(specs_.size());
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (specs_[j].name == specs_[i].name) {
        fail(kWhere, "parameter '" + specs_[i].name + "' is declared twice");
      }
    }
    validate(specs_[i], specs_[i].value);
    values_.push_back(specs_[i].value);
  }
}

void Params::validate(const ParamSpec& s, double v) {
  const std::string name = s.name;
  if (!std::isfinite(v)) fail(kWhere, name + " must be finite, but was " + formatNumber(v));
  const bool low = s.minExclusive ? !(v > s.min) : !(v >= s.min);
  if (low || v > s.max) {
    fail(kWhere, name + " must be in " + range(s) + (s.unit.empty() ? "" : " " + s.unit) +
                     ", but was " + formatNumber(v));
  }
  if (s.integer && std::trunc(v) != v) {
    fail(kWhere, name + " must be a whole number, but was " + formatNumber(v));
  }
}

std::size_t Params::indexOf(std::string_view name) const {
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (specs_[i].name == name) return i;
  }
  std::string valid;
  for (const ParamSpec& s : specs_) valid += (valid.empty() ? "" : ", ") + s.name;
  fail(kWhere, "no parameter is named '" + std::string(name) + "'; valid: " + valid);
}

double Params::get(std::string_view name) const {
  return values_[indexOf(name)];
}

std::int64_t Params::getInt(std::string_view name) const {
  return static_cast<std::int64_t>(values_[indexOf(name)]);
}

void Params::set(std::string_view name, double value) {
  const std::size_t i = indexOf(name);
  validate(specs_[i], value);
  values_[i] = value;
}

bool Params::has(std::string_view name) const {
  for (const ParamSpec& s : specs_) {
    if (s.name == name) return true;
  }
  return false;
}

std::vector<std::string_view> Params::names() const {
  std::vector<std::string_view> out;
  out.reserve(specs_.size());
  for (const ParamSpec& s : specs_) out.push_back(s.name);
  return out;
}

}  // namespace tv::sim
