#pragma once
// Double-double arithmetic (an unevaluated sum hi + lo of two doubles, ≈ 106 bits) and the
// constants and argument reduction shared by the portable functions' accurate path
// (portable_math.cpp) and fast path (portable_math_fast.cpp). Only +, −, ×, ÷ and √ of doubles:
// the same bits on every platform that compiles it with -ffp-contract=off.
#include <cmath>

namespace jelly::portable::dd {

// An unevaluated sum hi + lo with |lo| ≤ ulp(hi)/2: about 106 significant bits.
struct DD {
  double hi;
  double lo;
};

// Exact a + b = s + e (Knuth).
inline DD two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Exact a + b = s + e when |a| ≥ |b|.
inline DD quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// Exact a × b = p + e (Dekker's split; no FMA, so the same code on every target).
inline DD two_prod(double a, double b) {
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

inline DD add(DD a, DD b) {
  const DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  DD r = quick_two_sum(s.hi, s.lo + t.hi);
  return quick_two_sum(r.hi, r.lo + t.lo);
}

inline DD neg(DD a) { return {-a.hi, -a.lo}; }

inline DD mul(DD a, DD b) {
  const DD p = two_prod(a.hi, b.hi);
  return quick_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

inline DD mul(DD a, double b) {
  const DD p = two_prod(a.hi, b);
  return quick_two_sum(p.hi, p.lo + a.lo * b);
}

inline DD div(DD a, double b) {
  const double q = a.hi / b;
  const DD p = two_prod(q, b);
  const double r = ((a.hi - p.hi) - p.lo + a.lo) / b;
  return quick_two_sum(q, r);
}

// a / b for double-doubles: three quotient digits, each correcting the remainder.
inline DD div(DD a, DD b) {
  const double q1 = a.hi / b.hi;
  DD r = add(a, neg(mul(b, q1)));
  const double q2 = r.hi / b.hi;
  r = add(r, neg(mul(b, q2)));
  const double q3 = r.hi / b.hi;
  return add(quick_two_sum(q1, q2), {q3, 0.0});
}

// √a for a double-double a ≥ 0: the double root and one Newton step (r² exact).
inline DD sqrt_dd(DD a) {
  const double r = std::sqrt(a.hi);
  if (r == 0.0) return {0.0, 0.0};
  const DD r2 = two_prod(r, r);
  return quick_two_sum(r, (((a.hi - r2.hi) - r2.lo) + a.lo) / (2.0 * r));
}

inline bool less(DD a, DD b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }

// π/2 in three parts (π/2 = kPio2[0] + kPio2[1] + kPio2[2] to ≈ 2⁻¹⁶⁰).
constexpr double kPio2[3] = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54, -0x1.f1976b7ed8fbcp-110};
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr DD kLn2 = {0x1.62e42fefa39efp-1, 0x1.abc9e3b39803fp-56};
constexpr DD kLog2Of10 = {0x1.a934f0979a371p+1, 0x1.7f2495fb7fa6dp-53};
constexpr DD kPi = {0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};
constexpr DD kHalfPi = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
// atan(k/16) for k = 0 … 16 in double-double (300-bit mpmath, rounded to hi + lo).
constexpr DD kAtanSixteenths[17] = {
    {0.0, 0.0},
    {0x1.ff55bb72cfdeap-5, -0x1.c934d86d23f1dp-60},
    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
    {0x1.7b97b4bce5b02p-3, 0x1.347b0b4f881cap-58},
    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0x1.362773707ebccp-2, -0x1.963a544b672d8p-57},
    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
    {0x1.a64eec3cc23fdp-2, -0x1.24dec1b50b7ffp-56},
    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0x1.0657e94db30d0p-1, -0x1.d5b495f6349e6p-56},
    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
    {0x1.345f01cce37bbp-1, 0x1.1021137c71102p-55},
    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {0x1.5d58987169b18p-1, 0x1.0028e4bc5e7cap-57},
    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
    {0x1.819d0b7158a4dp-1, -0x1.bf76229d3b917p-56},
    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
};
// Terms of the series are summed until they fall below this fraction of the first one.
constexpr double kSeriesTolerance = 0x1p-110;

// x − k·π/2 in double-double for a whole number k.
inline DD reduce_by(double x, double k) {
  DD r = two_sum(x, 0.0);
  for (double part : kPio2) r = add(r, neg(two_prod(k, part)));
  return r;
}

}  // namespace jelly::portable::dd
