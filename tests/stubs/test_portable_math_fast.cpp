// The portable functions' fast path (framework/core/src/portable_math_fast.cpp) returns the
// accurate path's bits for every argument: it is compared with portable::detail::*_accurate on a
// few hundred thousand arguments drawn (with a fixed seed) across the ranges the course meets and
// the ones where rounding is hardest: |x| up to 10⁶, angles in degrees converted to radians, tiny
// (down to 2⁻⁵²⁰, and motion capture's ≈ 10⁻¹³ degrees) and huge arguments, arguments within a few
// ulps of multiples of π/2, ratios y/x of every scale for atan2 and near ±1 for asin and acos.
// Needs no task: part of the stub suite.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "jelly/portable_math.hpp"

namespace jelly {
namespace {

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Arguments from a fixed seed; mt19937_64's output is the same on every platform.
class Draw {
 public:
  double unit() { return static_cast<double>(gen_() >> 11) * 0x1p-53; }  // [0, 1)
  double sym(double a) { return (2.0 * unit() - 1.0) * a; }              // [−a, a)
  double log_uniform(int lo, int hi) {                                   // ± 2^[lo, hi)
    const double mantissa = 1.0 + unit();  // one draw per statement: the same order everywhere
    const double m = std::ldexp(mantissa, lo + static_cast<int>(gen_() % (hi - lo)));
    return (gen_() & 1) != 0 ? -m : m;
  }
  double ulps(double x, int n) {  // x moved by up to ±n ulps
    const int steps = static_cast<int>(gen_() % (2 * n + 1)) - n;
    for (int i = 0; i < steps; ++i) x = std::nextafter(x, 1e300);
    for (int i = 0; i > steps; --i) x = std::nextafter(x, -1e300);
    return x;
  }
  std::int64_t integer(std::int64_t n) {
    return static_cast<std::int64_t>(gen_() % (2 * n + 1)) - n;
  }

 private:
  std::mt19937_64 gen_{20261128};
};

constexpr double kHalfPi = 0x1.921fb54442d18p+0;
constexpr double kRadiansPerDegree = 0x1.1df46a2529d39p-6;

// Arguments for sin and cos: each kind of a cycle of five.
double trig_argument(Draw& d, int i) {
  switch (i % 5) {
    case 0: return d.sym(1e6);
    case 1: return d.log_uniform(-40, 21);
    case 2: return static_cast<double>(d.integer(72000)) / 100.0 * kRadiansPerDegree;
    case 3: return d.ulps(static_cast<double>(d.integer(600000)) * kHalfPi, 40);
    default: return d.sym(8.0);
  }
}

#define EXPECT_SAME_BITS(fast, accurate, what)                                            \
  do {                                                                                    \
    const double f_ = (fast), a_ = (accurate);                                            \
    ASSERT_EQ(bits(f_), bits(a_)) << std::hexfloat << what << ": " << f_ << " vs " << a_; \
  } while (0)

// sin, cos and both halves of sin_cos at x: the accurate path's bits (a fatal failure at the
// first that differs; callers wrap it in ASSERT_NO_FATAL_FAILURE to stop there too).
void expect_sines_are_the_accurate_paths(double x) {
  EXPECT_SAME_BITS(portable::sin(x), portable::detail::sin_accurate(x), "sin " << x);
  EXPECT_SAME_BITS(portable::cos(x), portable::detail::cos_accurate(x), "cos " << x);
  double s = 0.0, c = 0.0;
  portable::sin_cos(x, s, c);
  EXPECT_SAME_BITS(s, portable::detail::sin_accurate(x), "sin_cos (sin) " << x);
  EXPECT_SAME_BITS(c, portable::detail::cos_accurate(x), "sin_cos (cos) " << x);
}

TEST(PortableMathFast, SinCosAndSinCosGiveTheAccuratePathsBits) {
  Draw d;
  for (int i = 0; i < 80000; ++i) {
    const double x = trig_argument(d, i);
    EXPECT_SAME_BITS(portable::sin(x), portable::detail::sin_accurate(x), "sin " << x);
    EXPECT_SAME_BITS(portable::cos(x), portable::detail::cos_accurate(x), "cos " << x);
  }
  for (int i = 0; i < 20000; ++i) {
    const double x = trig_argument(d, i);
    double s = 0.0, c = 0.0;
    portable::sin_cos(x, s, c);
    EXPECT_SAME_BITS(s, portable::detail::sin_accurate(x), "sin_cos (sin) " << x);
    EXPECT_SAME_BITS(c, portable::detail::cos_accurate(x), "sin_cos (cos) " << x);
  }
  for (double x : {0.0, -0.0, 0x1p-1074, -0x1p-1030, 0x1p-26, 0x1.fffffffffffffp-27, 0x1p28, 1e7,
                   1e300, kHalfPi, 2 * kHalfPi, 0.78, -0.78, 0x1.8fffffffffffp-1}) {
    ASSERT_NO_FATAL_FAILURE(expect_sines_are_the_accurate_paths(x));
  }
}

// Tiny arguments, where the sine's fast path starts at 2⁻⁵⁰⁰ (motion capture's ≈ 10⁻¹³ degrees)
// and its cubic term underflows. The last fixed one is 10⁻¹³ degrees in radians.
TEST(PortableMathFast, TinyArgumentsGiveTheAccuratePathsBits) {
  Draw d;
  std::vector<double> args = {0x1p-500,
                              -0x1p-500,
                              0x1.fffffffffffffp-501,
                              0x1.fffffffffffffp-500,
                              0x1p-340,
                              -1.7453292519943295e-15};
  for (int i = 0; i < 20000; ++i)
    args.push_back(i % 2 == 0 ? d.log_uniform(-520, -20) : d.sym(1e-12) * kRadiansPerDegree);
  for (double x : args) {
    ASSERT_NO_FATAL_FAILURE(expect_sines_are_the_accurate_paths(x));
  }
}

// Arguments where the sines' quick phase (plain doubles) branches or is closest to its bound:
// near the table's points a = j/64 and midpoints (j + 1/2)/64 (|b| = 0 or 2⁻⁷, both for x itself
// and for x − k·π/2), near multiples of π/2, and motion capture's angles (degrees with six
// decimals, as in CMU's .amc files).
double quick_phase_argument(Draw& d, int i) {
  const double j = static_cast<double>(d.integer(50));
  const double half = (i % 2 == 0) ? 0.0 : 0.5;
  switch (i % 4) {
    case 0: return d.ulps((j + half) / 64.0, 8);
    case 1: {
      const double k = static_cast<double>(d.integer(4000)) * kHalfPi;  // one draw per statement
      return d.ulps(k + (j + half) / 64.0, 8);
    }
    case 2: return d.ulps(static_cast<double>(d.integer(600000)) * kHalfPi, 2000);
    default: return static_cast<double>(d.integer(180000000)) / 1e6 * kRadiansPerDegree;
  }
}

TEST(PortableMathFast, SinesQuickPhaseGivesTheAccuratePathsBits) {
  Draw d;
  for (int i = 0; i < 40000; ++i) {
    const double x = quick_phase_argument(d, i);
    ASSERT_NO_FATAL_FAILURE(expect_sines_are_the_accurate_paths(x));
  }
}

// The quick phase's rigorous bound against the double-double kernel's: on every argument the
// quick value must be within its bound of the kernel's interval (a use ≤ 1), and the largest use
// seen must come within 8× of the bound, so that a bound 8 times tighter would fail here.
TEST(PortableMathFast, SinesQuickPhaseBoundHoldsAndIsNotSlack) {
  Draw d;
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double x = (i % 2 == 0) ? trig_argument(d, i / 2) : quick_phase_argument(d, i / 2);
    const double use = portable::detail::sin_cos_quick_bound_use(x);
    ASSERT_LE(use, 1.0) << std::hexfloat << x;
    if (use > worst) worst = use;
  }
  EXPECT_GT(worst, 0.125);
  EXPECT_EQ(portable::detail::sin_cos_quick_bound_use(0x1p-501), 0.0);  // outside: no quick phase
  EXPECT_EQ(portable::detail::sin_cos_quick_bound_use(0x1p21), 0.0);
}

TEST(PortableMathFast, Atan2GivesTheAccuratePathsBits) {
  Draw d;
  for (int i = 0; i < 80000; ++i) {
    double y = 0.0, x = 0.0;
    switch (i % 4) {
      case 0: y = d.sym(1.0), x = d.sym(1.0); break;  // rotation entries
      case 1: y = d.log_uniform(-320, 320), x = d.log_uniform(-320, 320); break;  // every scale
      case 2: x = d.log_uniform(-60, 60), y = d.ulps(x, 3); break;                // |y| ≈ |x|
      default:  // ratios near k/16, where the table's interval changes
        x = d.log_uniform(-10, 10);
        y = d.ulps(x * static_cast<double>(d.integer(16)) / 16.0, 1000);
        y *= 1.0 + d.sym(0x1p-40);
    }
    EXPECT_SAME_BITS(portable::atan2(y, x), portable::detail::atan2_accurate(y, x),
                     "atan2 " << y << ", " << x);
  }
}

TEST(PortableMathFast, AsinAndAcosGiveTheAccuratePathsBits) {
  Draw d;
  for (int i = 0; i < 30000; ++i) {
    double x = 0.0;
    switch (i % 3) {
      case 0: x = d.sym(1.0); break;
      case 1: {  // within 2⁻¹ … 2⁻¹⁰⁵ of ±1 (one draw per statement: the same order everywhere)
        const double below = d.unit();
        x = (1.0 - std::ldexp(below, -static_cast<int>(d.integer(52) + 53))) * (i % 2 ? 1 : -1);
        break;
      }
      default: x = d.log_uniform(-330, 0);
    }
    EXPECT_SAME_BITS(portable::asin(x), portable::detail::asin_accurate(x), "asin " << x);
    EXPECT_SAME_BITS(portable::acos(x), portable::detail::acos_accurate(x), "acos " << x);
  }
  for (double x : {0.0, -0.0, 1.0, -1.0, 0x1.fffffffffffffp-1, 0x1p-300, 0x1p-1074, 2.0}) {
    EXPECT_SAME_BITS(portable::asin(x), portable::detail::asin_accurate(x), "asin " << x);
    EXPECT_SAME_BITS(portable::acos(x), portable::detail::acos_accurate(x), "acos " << x);
  }
}

}  // namespace
}  // namespace jelly
