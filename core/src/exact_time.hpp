#pragma once
// Times along a move kept as fractions num/den (den > 0), or ±infinity, and compared exactly:
// a·b is formed as p + e with p = a·b rounded and e = fma(a, b, -p) its exact error, so two
// products compare without rounding. This is what makes corner hits and grazes exact.

#include <cmath>

namespace tv::detail {

struct Time {
  double num = 0.0;
  double den = 1.0;
  int inf = 0;  // -1: -infinity, +1: +infinity, 0: num / den

  static constexpr Time neg() { return {0.0, 1.0, -1}; }
  static constexpr Time pos() { return {0.0, 1.0, 1}; }
  [[nodiscard]] double value() const { return inf == 0 ? num / den : inf * HUGE_VAL; }
};

/// Sign of a·b − c·d, exactly (barring underflow below 2^-969, far from any world coordinate).
inline int compareProducts(double a, double b, double c, double d) {
  const double p = a * b, q = c * d;
  if (p != q) return p < q ? -1 : 1;
  const double e = std::fma(a, b, -p), f = std::fma(c, d, -q);
  if (e != f) return e < f ? -1 : 1;
  return 0;
}

inline int compare(const Time& s, const Time& t) {
  if (s.inf != 0 || t.inf != 0) return (s.inf > t.inf) - (s.inf < t.inf);
  return compareProducts(s.num, t.den, t.num, s.den);
}

inline const Time& later(const Time& s, const Time& t) { return compare(s, t) >= 0 ? s : t; }
inline const Time& earlier(const Time& s, const Time& t) { return compare(s, t) <= 0 ? s : t; }

}  // namespace tv::detail
