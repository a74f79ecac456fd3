#include "jelly/portable_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "double_double.hpp"

namespace jelly::portable {

namespace {

using namespace dd;  // NOLINT: the arithmetic of this file

// r = x − k·π/2 in double-double, |r| ≤ π/4 (up to rounding), and the quadrant k mod 4.
DD reduce(double x, int& quadrant) {
  const double k = std::nearbyint(x * kTwoOverPi);
  const DD r = reduce_by(x, k);
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

// atan r for 0 ≤ r ≤ 1: atan r = atan c + atan u with c = k/16 the nearest sixteenth and
// u = (r − c)/(1 + r·c), |u| ≤ 1/32, whose series u − u³/3 + u⁵/5 − … is summed.
DD atan_unit(DD r) {
  const int k = static_cast<int>(std::nearbyint(r.hi * 16.0));
  const double c = k / 16.0;
  const DD u = div(add(r, {-c, 0.0}), add({1.0, 0.0}, mul(r, c)));
  const DD u2 = mul(u, u);
  DD power = u;
  DD sum = u;
  for (int n = 3; std::fabs(power.hi) > kSeriesTolerance * std::fabs(u.hi); n += 2) {
    power = neg(mul(power, u2));
    sum = add(sum, div(power, static_cast<double>(n)));
  }
  return add(kAtanSixteenths[k], sum);
}

// The angle of (x, y) for x, y ≥ 0, not both zero, in [0, π/2].
DD atan2_first_quadrant(DD y, DD x) {
  if (!less(x, y)) return atan_unit(div(y, x));
  return add(kHalfPi, neg(atan_unit(div(x, y))));
}

// atan2 where x or y is infinite (the other not NaN), as C's atan2 defines it.
double atan2_infinite(double y, double x) {
  double angle = 0.0;
  if (std::isinf(y)) {
    angle = !std::isinf(x) ? kHalfPi.hi
            : x > 0.0      ? kHalfPi.hi * 0.5
                           : add(kPi, neg(mul(kHalfPi, 0.5))).hi;
  } else {
    angle = x > 0.0 ? 0.0 : kPi.hi;
  }
  return std::copysign(angle, y);
}

// atan2 where y = ±0 or x = ±0 (both finite).
double atan2_zero(double y, double x) {
  if (y != 0.0) return std::copysign(kHalfPi.hi, y);
  return std::signbit(x) ? std::copysign(kPi.hi, y) : y;
}

// |y| and |x| finite, non-zero: scaled by the larger's power of two (exact) so that the double-
// double steps neither overflow nor underflow. A ratio below 2⁻⁶⁰⁰ leaves atan r = r (and π/2 − r,
// π − r = π/2, π) to far below the rounding.
double atan2_finite(double y, double x) {
  const double ay = std::fabs(y), ax = std::fabs(x);
  const int gap = std::ilogb(ay) - std::ilogb(ax);
  double angle = 0.0;
  if (gap < -600) {
    angle = x > 0.0 ? ay / ax : kPi.hi;
  } else if (gap > 600) {
    angle = kHalfPi.hi;
  } else {
    int e = 0;
    std::frexp(std::max(ay, ax), &e);
    DD a = atan2_first_quadrant({std::ldexp(ay, -e), 0.0}, {std::ldexp(ax, -e), 0.0});
    if (x < 0.0) a = add(kPi, neg(a));
    angle = a.hi;
  }
  return std::copysign(angle, y);
}

// √(1 − x²) for |x| ≤ 1 in double-double: 1 − |x| and 1 + |x| are exact double-doubles.
DD cosine_of_sine(double ax) { return sqrt_dd(mul(two_sum(1.0, -ax), two_sum(1.0, ax))); }

}  // namespace

double detail::sin_accurate(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return x;  // keeps the sign of −0
  int quadrant = 0;
  const DD r = reduce(x, quadrant);
  return sin_quadrant(r, quadrant);
}

double detail::cos_accurate(double x) {
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

double detail::atan2_accurate(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(x) || std::isinf(y)) return atan2_infinite(y, x);
  if (x == 0.0 || y == 0.0) return atan2_zero(y, x);
  return atan2_finite(y, x);
}

double detail::asin_accurate(double x) {
  if (!(std::fabs(x) <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return x;  // keeps the sign of −0
  const double ax = std::fabs(x);
  return std::copysign(atan2_first_quadrant({ax, 0.0}, cosine_of_sine(ax)).hi, x);
}

double detail::acos_accurate(double x) {
  if (!(std::fabs(x) <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
  const double ax = std::fabs(x);
  const DD a = atan2_first_quadrant(cosine_of_sine(ax), {ax, 0.0});
  return (x < 0.0 ? add(kPi, neg(a)) : a).hi;
}

}  // namespace jelly::portable
