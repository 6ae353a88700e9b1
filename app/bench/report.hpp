#pragma once
// What every study prints and writes: markdown tables on stdout, the same tables as CSV in the
// output folder, and progress on stderr (only when stderr is a terminal, so logs stay clean).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace tv::bench {

/// A table of text cells: printed as markdown, written as CSV.
class Table {
 public:
  /// A column title ending in ':' is right-aligned in markdown (the ':' is not shown).
  explicit Table(std::vector<std::string> columns);
  void add(std::vector<std::string> row);
  [[nodiscard]] std::size_t rows() const { return rows_.size(); }
  void printMarkdown(std::ostream& os) const;
  /// Writes `dir/name` and returns its path; throws std::runtime_error if it cannot.
  std::filesystem::path writeCsv(const std::filesystem::path& dir, std::string_view name) const;

 private:
  std::vector<std::string> columns_;
  std::vector<bool> right_;
  std::vector<std::vector<std::string>> rows_;
};

/// Fixed decimals ("12.35").
[[nodiscard]] std::string fixed(double v, int decimals);
/// Sixteen hex digits ("00ff12…"), for hashes.
[[nodiscard]] std::string hex(std::uint64_t v);
/// A percentage with one decimal ("38.2%").
[[nodiscard]] std::string percent(double part, double whole);
/// Three significant digits, plain or with an exponent when tiny ("0.0123", "1.2e-13", "0").
[[nodiscard]] std::string sig3(double v);

/// Progress on stderr when it is a terminal: "tunnel: 12/64 2x2 horizontal 960 px/s".
class Progress {
 public:
  Progress(std::string study, std::size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void step(std::string_view what);

 private:
  std::string study_;
  std::size_t total_, done_ = 0;
  bool enabled_;
};

/// Seconds since construction on the steady clock.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  [[nodiscard]] double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Keeps the optimizer from deleting a computation whose result is otherwise unused.
template <class T>
inline void keep(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

/// The study's heading: what it measures, the mode, the seed and where the files go.
void printHeading(std::ostream& os, std::string_view title, std::string_view mode,
                  std::uint64_t seed, const std::filesystem::path& out);

}  // namespace tv::bench
