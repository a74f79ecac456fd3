#include "jelly/portable_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jelly::portable {

namespace {

// An unevaluated sum hi + lo with |lo| ≤ ulp(hi)/2: about 106 significant bits.
struct DD {
  double hi;
  double lo;
};

// Exact a + b = s + e (Knuth).
DD two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Exact a + b = s + e when |a| ≥ |b|.
DD quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// Exact a × b = p + e (Dekker's split; no FMA, so the same code on every target).
DD two_prod(double a, double b) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double ca = kSplitter * a;
  const double ah = ca - (ca - a);
  const double al = a - ah;
  const double cb = kSplitter * b;
  const double bh = cb - (cb - b);
  const double bl = b - bh;
  const double p = a * b;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

DD add(DD a, DD b) {
  const DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  DD r = quick_two_sum(s.hi, s.lo + t.hi);
  return quick_two_sum(r.hi, r.lo + t.lo);
}

DD neg(DD a) { return {-a.hi, -a.lo}; }

DD mul(DD a, DD b) {
  const DD p = two_prod(a.hi, b.hi);
  return quick_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

DD mul(DD a, double b) {
  const DD p = two_prod(a.hi, b);
  return quick_two_sum(p.hi, p.lo + a.lo * b);
}

DD div(DD a, double b) {
  const double q = a.hi / b;
  const DD p = two_prod(q, b);
  const double r = ((a.hi - p.hi) - p.lo + a.lo) / b;
  return quick_two_sum(q, r);
}

// π/2 in three parts (π/2 = kPio2[0] + kPio2[1] + kPio2[2] to ≈ 2⁻¹⁶⁰).
constexpr double kPio2[3] = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54, -0x1.f1976b7ed8fbcp-110};
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr DD kLn2 = {0x1.62e42fefa39efp-1, 0x1.abc9e3b39803fp-56};
constexpr DD kLog2Of10 = {0x1.a934f0979a371p+1, 0x1.7f2495fb7fa6dp-53};
// Terms of the series are summed until they fall below this fraction of the first one.
constexpr double kSeriesTolerance = 0x1p-110;

// r = x − k·π/2 in double-double, |r| ≤ π/4 (up to rounding), and the quadrant k mod 4.
DD reduce(double x, int& quadrant) {
  const double k = std::nearbyint(x * kTwoOverPi);
  DD r = two_sum(x, 0.0);
  for (double part : kPio2) r = add(r, neg(two_prod(k, part)));
  const double k4 = k - 4.0 * std::floor(k * 0.25);  // k mod 4, exact for |k| < 2^52
  quadrant = static_cast<int>(k4);
  return r;
}

// sin r and cos r for |r| ≤ π/4 + ε by their Taylor series in double-double.
DD sin_series(DD r) {
  const DD r2 = mul(r, r);
  DD term = r;
  DD sum = r;
  for (int n = 2; std::fabs(term.hi) > kSeriesTolerance * std::fabs(r.hi); n += 2) {
    term = div(mul(neg(term), r2), static_cast<double>(n) * static_cast<double>(n + 1));
    sum = add(sum, term);
  }
  return sum;
}

DD cos_series(DD r) {
  const DD r2 = mul(r, r);
  DD term = {1.0, 0.0};
  DD sum = term;
  for (int n = 1; std::fabs(term.hi) > kSeriesTolerance; n += 2) {
    term = div(mul(neg(term), r2), static_cast<double>(n) * static_cast<double>(n + 1));
    sum = add(sum, term);
  }
  return sum;
}

// sin(x + quadrant·π/2) from the reduced argument.
double sin_quadrant(DD r, int quadrant) {
  switch (quadrant) {
    case 0: return sin_series(r).hi;
    case 1: return cos_series(r).hi;
    case 2: return -sin_series(r).hi;
    default: return -cos_series(r).hi;
  }
}

}  // namespace

double sin(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return x;  // keeps the sign of −0
  int quadrant = 0;
  const DD r = reduce(x, quadrant);
  return sin_quadrant(r, quadrant);
}

double cos(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  int quadrant = 0;
  const DD r = reduce(x, quadrant);
  return sin_quadrant(r, (quadrant + 1) % 4);
}

double hypot(double x, double y) {
  x = std::fabs(x);
  y = std::fabs(y);
  if (std::isinf(x) || std::isinf(y)) return std::numeric_limits<double>::infinity();
  if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
  const double big = std::max(x, y);
  if (big == 0.0) return 0.0;
  // Scale by a power of two (exact) so that the squares neither overflow nor underflow.
  int e = 0;
  std::frexp(big, &e);
  const double xs = std::ldexp(x, -e), ys = std::ldexp(y, -e);
  const DD s = add(two_prod(xs, xs), two_prod(ys, ys));
  // One Newton step on the double-double sum: r + (s − r²)/(2r), with r² exact.
  const double r = std::sqrt(s.hi);
  const DD r2 = two_prod(r, r);
  const double correction = (((s.hi - r2.hi) - r2.lo) + s.lo) / (2.0 * r);
  return std::ldexp(r + correction, e);
}

double exp10(double y) {
  if (std::isnan(y)) return y;
  if (y > 310.0) return std::numeric_limits<double>::infinity();
  if (y < -330.0) return 0.0;
  // 10^y = 2^t with t = y·log2(10) = n + f, |f| ≤ 1/2; 2^f = e^(f·ln 2) by its series.
  const DD t = mul(kLog2Of10, y);
  const double n = std::nearbyint(t.hi);
  const DD g = mul(add(t, {-n, 0.0}), kLn2);
  DD term = {1.0, 0.0};
  DD sum = term;
  for (int k = 1; std::fabs(term.hi) > kSeriesTolerance; ++k) {
    term = div(mul(term, g), static_cast<double>(k));
    sum = add(sum, term);
  }
  return std::ldexp(sum.hi, static_cast<int>(n));  // exact scaling while the result is normal
}

}  // namespace jelly::portable
