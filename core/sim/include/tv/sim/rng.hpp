#pragma once
/// SplitMix64: the same numbers on every platform and standard library (the `<random>`
/// distributions are implementation-defined, so they could not back golden hashes or the
/// benchmarks' seeded workloads).

#include <cmath>
#include <cstdint>

namespace tv::sim {

/// A seeded SplitMix64 generator: the scenes' and benchmarks' only source of randomness.
class Rng {
 public:
  /// Any seed; equal seeds give equal sequences everywhere.
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  /// The next 64 uniformly distributed bits.
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform in [0, 1), a multiple of 2^-bits: exact in sums with dyadic coordinates.
  double dyadic(int bits) { return std::ldexp(static_cast<double>(next() >> (64 - bits)), -bits); }
  /// Uniform in [0, n), n > 0.
  std::uint64_t below(std::uint64_t n) { return next() % n; }

 private:
  std::uint64_t s_;
};

}  // namespace tv::sim
