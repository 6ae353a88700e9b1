#include "report.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace tv::bench {

Table::Table(std::vector<std::string> columns) {
  for (std::string& c : columns) {
    const bool right = !c.empty() && c.back() == ':';
    if (right) c.pop_back();
    right_.push_back(right);
    columns_.push_back(std::move(c));
  }
}

void Table::add(std::vector<std::string> row) {
  row.resize(columns_.size());
  rows_.push_back(std::move(row));
}

void Table::printMarkdown(std::ostream& os) const {
  os << "|";
  for (const std::string& c : columns_) os << " " << c << " |";
  os << "\n|";
  for (const bool r : right_) os << (r ? "---:|" : "---|");
  os << "\n";
  for (const auto& row : rows_) {
    os << "|";
    for (const std::string& cell : row) os << " " << cell << " |";
    os << "\n";
  }
  os << "\n";
}

namespace {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char ch : s) {
    if (ch == '"') q += '"';
    q += ch;
  }
  return q + "\"";
}

}  // namespace

std::filesystem::path Table::writeCsv(const std::filesystem::path& dir,
                                      std::string_view name) const {
  const std::filesystem::path path = dir / name;
  std::ofstream f(path);
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) f << (i ? "," : "") << csvField(cells[i]);
    f << "\n";
  };
  line(columns_);
  for (const auto& row : rows_) line(row);
  if (!f) throw std::runtime_error("could not write '" + path.string() + "'");
  return path;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string hex(std::uint64_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string percent(double part, double whole) {
  return whole > 0 ? fixed(100.0 * part / whole, 1) + "%" : "n/a";
}

std::string sig3(double v) {
  if (v == 0.0) return "0";
  char buf[64];
  const double a = std::fabs(v);
  if (a >= 1e-3 && a < 1e6) {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  } else {
    std::snprintf(buf, sizeof buf, "%.2e", v);
  }
  return buf;
}

Progress::Progress(std::string study, std::size_t total)
    : study_(std::move(study)), total_(total), enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (enabled_ && done_ > 0) std::cerr << "\r\033[K" << std::flush;
}

void Progress::step(std::string_view what) {
  ++done_;
  if (!enabled_) return;
  std::cerr << "\r\033[K" << study_ << ": " << done_ << "/" << total_ << " " << what << std::flush;
}

void printHeading(std::ostream& os, std::string_view title, std::string_view mode,
                  std::uint64_t seed, const std::filesystem::path& out) {
  os << "## " << title << "\n\n"
     << "mode: " << mode << " · seed: " << seed << " · files: " << out.string() << "\n\n";
}

}  // namespace tv::bench
