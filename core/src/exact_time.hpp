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

// -- exact signs of sums of products ----------------------------------------------------------

/// a + b = s + e exactly (Knuth's TwoSum), barring overflow.
inline void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

/// Sign of the exact sum of `n` doubles (n <= 32): Shewchuk's Grow-Expansion keeps the partial
/// sum as non-overlapping terms of increasing magnitude, whose largest carries its sign.
inline int signOfSum(const double* v, int n) {
  double h[32];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    double q = v[i];
    int k = 0;
    for (int j = 0; j < m; ++j) {
      double s = 0.0, e = 0.0;
      twoSum(q, h[j], s, e);
      q = s;
      if (e != 0.0) h[k++] = e;
    }
    if (q != 0.0) h[k++] = q;
    m = k;
  }
  return m == 0 ? 0 : (h[m - 1] > 0.0 ? 1 : -1);
}

/// Sign of (a − b)·(c − d) − (e − f)·(g − h), exactly: each difference is split into its rounded
/// value and its rounding error, and the sixteen products into value and error (fma). Exact
/// while nothing overflows (every operand within tv's coordinate range, see geometry.hpp) and
/// no product of two differences falls below 2^-969.
inline int compareDifferenceProducts(double a, double b, double c, double d, double e, double f,
                                     double g, double h) {
  double x1, x0, y1, y0, z1, z0, w1, w0;
  twoSum(a, -b, x1, x0);
  twoSum(c, -d, y1, y0);
  twoSum(e, -f, z1, z0);
  twoSum(g, -h, w1, w0);
  // Every difference exact (any grid of dyadic sizes): one exact product comparison.
  if (x0 == 0.0 && y0 == 0.0 && z0 == 0.0 && w0 == 0.0) return compareProducts(x1, y1, z1, w1);
  double terms[16];
  int n = 0;
  const auto add = [&](double p, double q, double sign) {
    const double r = p * q;
    terms[n++] = sign * r;
    terms[n++] = sign * std::fma(p, q, -r);
  };
  add(x1, y1, 1.0);
  add(x1, y0, 1.0);
  add(x0, y1, 1.0);
  add(x0, y0, 1.0);
  add(z1, w1, -1.0);
  add(z1, w0, -1.0);
  add(z0, w1, -1.0);
  add(z0, w0, -1.0);
  return signOfSum(terms, n);
}

inline const Time& later(const Time& s, const Time& t) { return compare(s, t) >= 0 ? s : t; }
inline const Time& earlier(const Time& s, const Time& t) { return compare(s, t) <= 0 ? s : t; }

}  // namespace tv::detail
