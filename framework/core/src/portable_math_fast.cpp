// The fast path of the portable sin, cos, atan2, asin and acos (Ziv's strategy). Each function
// computes an approximation hi + lo of the exact value (hi = hi + lo rounded) in plain double
// arithmetic from a table and a short polynomial, together with a rigorous bound `err` on
// |exact − (hi + lo)|. The accurate path (portable_math.cpp) returns its double-double result
// rounded to nearest, within 2⁻¹⁰⁰·|value| of the exact value (its documented accuracy; taken as
// 2⁻⁹⁶ here). If rounding to nearest gives hi at both ends of [hi + lo − e, hi + lo + e] (e the
// sum of both bounds), it gives hi everywhere in between (rounding is monotone), in particular at
// the accurate path's result: hi is returned. Otherwise the accurate path is called. So the result
// is the accurate path's for every argument.
//
// sin, cos and sin_cos first try a quick phase of the same form with a cheaper approximation and a
// looser bound (plain products, no two_prod; ≈ 2⁻⁶⁰ relative, see "the quick phase" below); where
// it cannot decide (≈ 1.6 % of random arguments), the kernel below, then the accurate path.
//
// Error analysis, with u = 2⁻⁵³ (the rounding error of one operation):
// - two_sum and two_prod (Dekker, no FMA) are exact; the table entries are exact values rounded to
//   double-doubles (relative error ≤ 2⁻¹⁰⁶).
// - Every "small term" t_i below is computed from exact or table inputs with at most ~12 roundings
//   in products and Horner steps whose terms shrink (|B²|, |u²| ≤ 2⁻¹⁰), so |error| ≤ 12u·|t_i|,
//   and summing up to 8 of them adds ≤ 8u·Σ|t_i|. The bound used, 2⁻⁴⁷·Σ|t_i| = 64u·Σ|t_i|, has
//   a margin of 3 for this and for Σ|t_i| itself being rounded.
// - Truncated series, terms left out (named where they are) and the errors of the reduced
//   argument's and quotients' last bits are each ≤ 2⁻⁶⁸ relative to the result; the bound adds
//   2⁻⁶⁵·|hi|.
// A bound of ≈ 2⁻⁶² relative, against a rounding gap of 2⁻⁵³…2⁻⁵², sends about one argument in 500
// to the accurate path.
#include <cstdint>
#include <limits>

#include "double_double.hpp"
#include "jelly/portable_math.hpp"

namespace jelly::portable {

namespace {

using namespace dd;  // NOLINT: the arithmetic of this file

// hi + lo (hi = hi + lo rounded) within err of the exact value.
struct Approx {
  double hi;
  double lo;
  double err;
};

// The relative error of the accurate path, with a margin (see the top of the file).
constexpr double kAccurateError = 0x1p-96;
constexpr double kArithmeticBound = 0x1p-47;  // × Σ|t_i|
constexpr double kLumpBound = 0x1p-65;        // × |hi|

// True (and `out` = ±hi) when every value within the bounds rounds to hi. With bound =
// a.err + 2⁻⁹⁶·|hi|, e = 1.125·bound is computed within 3u, so e ≥ 1.12·bound; lo ± e is rounded
// within u·(|lo| + e) ≤ 2⁻¹⁰⁶·|hi| + u·e ≤ (2⁻¹⁰ + u)·e (|lo| ≤ 2⁻⁵³·|hi|, bound ≥ 2⁻⁹⁶·|hi|),
// so it still lies beyond lo ± bound, and hi + (lo ± e) rounding to hi means (rounding is
// monotone) that everything in [hi + lo − bound, hi + lo + bound] does.
bool margin_rounds_to_hi(double hi, double lo, double e) {
  return hi + (lo + e) == hi && hi + (lo - e) == hi;
}

bool rounds_to_hi(const Approx& a) {
  return margin_rounds_to_hi(a.hi, a.lo, 1.125 * (a.err + kAccurateError * std::fabs(a.hi)));
}

bool rounds_surely(const Approx& a, bool negate, double& out) {
  if (!rounds_to_hi(a)) return false;
  out = negate ? -a.hi : a.hi;
  return true;
}

// big + Σ small, where big = b1 + b2 exactly (two_sum) and |big| ≥ |Σ small|.
Approx combine(DD big, double small, double small_magnitude, double value_scale) {
  const DD s = quick_two_sum(big.hi, big.lo + small);
  return {s.hi, s.lo,
          kArithmeticBound * (small_magnitude + std::fabs(big.lo)) + kLumpBound * value_scale};
}

// ---- sin and cos -------------------------------------------------------------------------------

// sin(j/64) and cos(j/64) for j = 0 … 52 as double-doubles (300-bit mpmath, rounded to hi + lo).
struct SinCosEntry {
  DD sin;
  DD cos;
};
constexpr SinCosEntry kSinCos64[53] = {
    {{0.0, 0.0}, {0x1.0000000000000p+0, 0.0}},
    {{0x1.fffaaaaeeeed5p-7, -0x1.2ab639a9f0776p-63}, {0x1.fff000155549fp-1, 0x1.28a28a03a5ef3p-55}},
    {{0x1.ffeaaaeeee86fp-6, -0x1.cd406fb224ae2p-60},
     {0x1.ffc00155527d3p-1, -0x1.3b54492d89b5bp-55}},
    {{0x1.7fdc01032fba9p-5, -0x1.599bdf46e997ap-59},
     {0x1.ff7006bfdf99fp-1, -0x1.8b3b560648d5fp-56}},
    {{0x1.ffaaaeeed4edbp-5, -0x1.2d16d32684b69p-59}, {0x1.ff0015549f4d3p-1, 0x1.328387b99426fp-55}},
    {{0x1.3facb12d1755bp-4, -0x1.921915299468bp-58},
     {0x1.fe7034129ef6fp-1, -0x1.cbf4337c96f97p-57}},
    {{0x1.7f701032550e4p-4, 0x1.afc2d1800501ap-60}, {0x1.fdc06bf7e6b9bp-1, 0x1.31902b535f8dbp-55}},
    {{0x1.bf1b78568391dp-4, 0x1.e91841dea4cc8p-58}, {0x1.fcf0c800e99b1p-1, 0x1.ea3d786d186acp-57}},
    {{0x1.feaaeee86ee36p-4, -0x1.afcb2bcc6f03bp-59}, {0x1.fc015527d5bd3p-1, 0x1.b68f35094efb8p-55}},
    {{0x1.1f0d3d7afceafp-3, -0x1.6ef95099769a5p-57},
     {0x1.faf22263c4bd3p-1, -0x1.52ace133a2769p-58}},
    {{0x1.3eb312c5d66cbp-3, 0x1.47d666b66cb91p-57}, {0x1.f9c340a7cc428p-1, 0x1.c5b6b063b7462p-55}},
    {{0x1.5e44fcfa126f3p-3, -0x1.6f443063f89b6p-57},
     {0x1.f874c2e1eecf6p-1, -0x1.c6514e1332b16p-55}},
    {{0x1.7dc102fbaf2b5p-3, 0x1.5ab50e23c97c3p-59}, {0x1.f706bdf9ece1cp-1, -0x1.698c80c36dcb4p-55}},
    {{0x1.9d252d0cec312p-3, 0x1.9c43d80b1137dp-58}, {0x1.f57948cff6797p-1, 0x1.e3a0d3e03b1d4p-57}},
    {{0x1.bc6f84edc6199p-3, 0x1.9c1a56a7b0cabp-57}, {0x1.f3cc7c3b3d16ep-1, -0x1.21a3ad28a3494p-57}},
    {{0x1.db9e15fb5a5d0p-3, -0x1.32e20d6cc6fc2p-57}, {0x1.f20073086649fp-1, 0x1.b940416c1984bp-56}},
    {{0x1.faaeed4f31577p-3, -0x1.15d88508e32b8p-57}, {0x1.f01549f7deea1p-1, 0x1.d3c1e99e5cafdp-55}},
    {{0x1.0cd00cef36436p-2, -0x1.9fb0a0c93e2b4p-56},
     {0x1.ee0b1fbc0f11cp-1, -0x1.bfd2380bbc3b1p-59}},
    {{0x1.1c37d64c6b876p-2, 0x1.46076fe0dcff4p-56}, {0x1.ebe214f76efa8p-1, -0x1.02f9f12ba543ep-55}},
    {{0x1.2b8ddc43eb49fp-2, 0x1.1553899f2d807p-57}, {0x1.e99a4c3a7cd83p-1, -0x1.2264b1bc53ce8p-55}},
    {{0x1.3ad129769d3d8p-2, 0x1.03d550487839ap-63}, {0x1.e733ea0193d40p-1, -0x1.6428b3546ce13p-55}},
    {{0x1.4a00c9b0f3d20p-2, 0x1.823ba6bb08eadp-56}, {0x1.e4af14b2a449cp-1, -0x1.68ca02e8a6833p-55}},
    {{0x1.591bc9fa2f597p-2, 0x1.7c74bac3fe0cbp-57}, {0x1.e20bf49acd6c1p-1, -0x1.660aec7ef636bp-58}},
    {{0x1.682138a38d7f7p-2, -0x1.d889202444aadp-56},
     {0x1.df4ab3ebd875ep-1, -0x1.e2d8a7e6736c4p-55}},
    {{0x1.7710255764214p-2, -0x1.6ead7314bb6cep-57}, {0x1.dc6b7eb995912p-1, 0x1.4b364776dcd35p-58}},
    {{0x1.85e7a12826949p-2, 0x1.8a40e9b5face0p-56}, {0x1.d96e82f71a9dcp-1, 0x1.ff61bd5d2039dp-55}},
    {{0x1.94a6be9f546c5p-2, -0x1.69ce13e683f58p-56},
     {0x1.d653f073e4040p-1, -0x1.76236434bec37p-55}},
    {{0x1.a34c91cc50ccap-2, -0x1.a310e3b50cecdp-58}, {0x1.d31bf8d8d7c06p-1, 0x1.e60dd3089cbddp-56}},
    {{0x1.b1d8305321617p-2, -0x1.ae242cb99f519p-56}, {0x1.cfc6cfa52ad9fp-1, 0x1.8b5b5508f2a0dp-55}},
    {{0x1.c048b17b140a3p-2, 0x1.19fe6757e9fa7p-57}, {0x1.cc54aa2b2972ep-1, 0x1.4ee162ba83a98p-57}},
    {{0x1.ce9d2e3d4a51fp-2, -0x1.2fc8a12dae298p-57}, {0x1.c8c5bf8ce1a84p-1, 0x1.ab3d1a1590123p-56}},
    {{0x1.dcd4c15329c9ap-2, 0x1.0d4c6e171fd9ap-56}, {0x1.c51a48b8b175ep-1, -0x1.1bbb43b9aa880p-57}},
    {{0x1.eaee8744b05f0p-2, -0x1.789b43c9b027dp-58},
     {0x1.c1528065b7d50p-1, -0x1.892111312e828p-55}},
    {{0x1.f8e99e76abc97p-2, 0x1.9d950af2d00a3p-58}, {0x1.bd6ea310294f5p-1, 0x1.31bbcc88c109dp-56}},
    {{0x1.0362939c69955p-1, -0x1.2d8cd78397b01p-55}, {0x1.b96eeef58840ep-1, 0x1.45a3cc78fade0p-58}},
    {{0x1.0a4021e9e1001p-1, -0x1.6f643a13914f6p-55}, {0x1.b553a410c104ep-1, 0x1.8ff7947027a15p-58}},
    {{0x1.110d0c4b69c3bp-1, 0x1.d918998809981p-55}, {0x1.b11d04162a4c6p-1, 0x1.1dd561efbc0c2p-56}},
    {{0x1.17c8e5f2eedb0p-1, 0x1.35e57102e2488p-57}, {0x1.accb526f69de5p-1, 0x1.8fb6a8dd6b6ccp-55}},
    {{0x1.1e7343236574cp-1, 0x1.22a3fa4f41d5ap-56}, {0x1.a85ed4373e02dp-1, 0x1.9be06385ec792p-57}},
    {{0x1.250bb93788bbbp-1, 0x1.ea3d02457bccep-56}, {0x1.a3d7d0352bdcfp-1, -0x1.68dbaeca19669p-55}},
    {{0x1.2b91dea88421ep-1, -0x1.fa371db216ab0p-55},
     {0x1.9f368ed912f85p-1, -0x1.1d200c5791606p-55}},
    {{0x1.32054b148bc4fp-1, 0x1.f6b42095a135bp-55}, {0x1.9a7b5a36a6514p-1, 0x1.722cfcc9fa7a9p-55}},
    {{0x1.386597456282bp-1, -0x1.10fada93b07a8p-56},
     {0x1.95a67e00cb1fdp-1, -0x1.0befda21f862dp-55}},
    {{0x1.3eb25d36cd53ap-1, -0x1.be570e1570fc0p-58},
     {0x1.90b84784ddaf7p-1, -0x1.0feb10ab93b87p-56}},
    {{0x1.44eb381cf386bp-1, -0x1.3ed6c1e6a5505p-55}, {0x1.8bb105a5dc900p-1, 0x1.863e03e9474c1p-55}},
    {{0x1.4b0fc46aab761p-1, 0x1.0da05738cc59cp-61}, {0x1.869108d77a6c6p-1, 0x1.338ffe2bfe9ddp-56}},
    {{0x1.511f9fd7b351cp-1, -0x1.5c0e861c48831p-55},
     {0x1.8158a31916d5dp-1, -0x1.de8b90b8228dep-57}},
    {{0x1.571a6966d59b3p-1, 0x1.c843b4d0fb197p-58}, {0x1.7c0827f09e54fp-1, -0x1.c73d6d72aee68p-57}},
    {{0x1.5cffc16bf8f0dp-1, 0x1.96cb370eb578ap-55}, {0x1.769fec655211fp-1, -0x1.827d5cf8c68c5p-57}},
    {{0x1.62cf49921ac79p-1, -0x1.edd9855b6241ap-55}, {0x1.712046fa77678p-1, 0x1.425b0a5029c81p-55}},
    {{0x1.6888a4e134b2fp-1, -0x1.6b7d37644d5e6p-55}, {0x1.6b898fa9efb5dp-1, 0x1.15ac786ccf4b2p-56}},
    {{0x1.6e2b77c40bde1p-1, -0x1.0e729857fad53p-56},
     {0x1.65dc1fdeb8cbap-1, -0x1.97c1b47337c77p-58}},
    {{0x1.73b7680dea578p-1, -0x1.2248306dc12a2p-56}, {0x1.6018526f563dfp-1, 0x1.46ca5e0e432d0p-55}},
};

// The reduced argument r = x − k·π/2 (|r| ≤ π/4 + ε), the quadrant k mod 4 and a bound on
// |r − r_acc|, r_acc being the accurate path's reduced argument (its Taylor series are of r_acc;
// sin and cos change by at most that much). k is the accurate path's: x·(2/π) rounded to nearest
// even, here by adding and subtracting 1.5·2⁵² (exact for |k| < 2⁵¹). Where k = 0, r = r_acc = x.
// Otherwise (|x| ≤ 2²⁰, so |k| < 2²⁰) Cody and Waite's reduction with
// π/2 = kP1 + kP2 + kP3 + δ, kP1 and kP2 of 33 bits, |δ| ≤ 2⁻¹²²: k·kP1 and k·kP2 are exact;
// x − k·kP1 is exact (both are multiples of 2⁻⁵³, the difference below 1); its sum with −k·kP2
// is a two_sum. Errors: k·kP3 and the next subtraction ≤ 2⁻¹⁰¹ each, k·δ ≤ 2⁻¹⁰²; r_acc is
// within 9·2⁻¹⁰⁶·|r| + 2⁻¹³⁵ of the exact x − k·π/2 (three double-double additions, each within
// 3·2⁻¹⁰⁶ of its exact sum, Joldes, Muller and Popescu 2017). So |r − r_acc| ≤ 2⁻⁹⁸ (returned)
// + 2⁻¹⁰²·|r| (in the kernel's 2⁻⁶⁵·|value|).
struct Reduced {
  DD r;
  int quadrant;
  double err;
};

Reduced reduce_fast(double x) {
  if (std::fabs(x) < 0.78) return {{x, 0.0}, 0, 0.0};
  constexpr double kRound = 0x1.8p52;
  constexpr double kP1 = 0x1.921fb544p+0, kP2 = 0x1.0b4611a6p-34, kP3 = 0x1.3198a2e037073p-69;
  const double k = (x * kTwoOverPi + kRound) - kRound;
  const DD s = two_sum(x - k * kP1, -(k * kP2));
  const DD r = two_sum(s.hi, s.lo - k * kP3);
  // 2⁻⁹⁸ × 1.125, the rounding test's factor, so that the quick phase adds it as it is
  return {r, static_cast<int>(static_cast<std::int64_t>(k) & 3), 0x1.2p-98};
}

// r = rh + rl (|rh| ≤ 0.8) split as r = a + B, a = j/64 (j = rh·64 rounded), B = b + rl with
// |B| ≤ 2⁻⁷ (1 + 2⁻⁵²), and what both sin r and cos r need of it.
struct Split {
  DD sin_a, cos_a;
  double b, rl;
  double sin_b_minus_b, cos_b_minus_1;
};

Split split(DD r) {
  constexpr double kRound = 0x1.8p52;
  const double j = (r.hi * 64.0 + kRound) - kRound;
  const double b = r.hi - j * (1.0 / 64.0);  // exact: a multiple of ulp(rh) below 2⁻⁷
  const int index = static_cast<int>(j);
  const SinCosEntry& entry = kSinCos64[index < 0 ? -index : index];
  const double sign = j < 0.0 ? -1.0 : 1.0;  // sin(−a) = −sin a, by an exact product
  const double b2 = b * b + 2.0 * b * r.lo;  // B², leaving out rl² ≤ 2⁻¹⁰⁶·B²
  const double b4 = b2 * b2;
  // sin B − B and cos B − 1: Taylor polynomials, truncated below |B|⁹/9! ≤ 2⁻⁷⁴·|B| and
  // B¹⁰/10! ≤ 2⁻⁹¹; their terms shrink by 2⁻¹⁰ or more, so each is within ≈ 6u of its value.
  const double sin_b_minus_b =
      (b + r.lo) * b2 * ((-1.0 / 6.0 + b2 * (1.0 / 120.0)) - b4 * (1.0 / 5040.0));
  const double cos_b_minus_1 =
      b2 * ((-0.5 + b2 * (1.0 / 24.0)) + b4 * (-1.0 / 720.0 + b2 * (1.0 / 40320.0)));
  return {
      {sign * entry.sin.hi, sign * entry.sin.lo}, entry.cos, b, r.lo, sin_b_minus_b, cos_b_minus_1};
}

// ---- the quick phase of sin and cos: plain doubles, one static-form bound ---------------------
//
// Tried before the kernel below, from the same reduction and split: r = a + B, a = j/64,
// B = b + rl, (S, C) = (sin a, cos a) = (S.hi + S.lo, C.hi + C.lo) from the table, sbmb and cm1
// the split's sin B − B and cos B − 1. Then
//   sin r = (S.hi + b) + t,  t ≈ (C − 1)·b + [e + S.lo + C.hi·(rl + sbmb) + S.hi·cm1],
//   cos r = C.hi + t,        t ≈ −S.hi·b + [C.lo − S.lo·b + C.hi·cm1 − S.hi·(rl + sbmb)],
// where S.hi + b = h + e exactly (quick_two_sum: |S.hi| ≥ sin(1/64) > 2⁻⁷ ≥ |b| for j ≠ 0, S = 0
// for j = 0), C.hi − 1 is exact (Sterbenz) and hi + lo = h + t (or C.hi + t) exactly
// (quick_two_sum: |t| ≤ 2⁻⁷·|value|). No two_prod: the large term of t is a plain product.
// Claim, V the exact value, u = 2⁻⁵³: |V − (hi + lo)| ≤ 4u·|t| + 2⁻⁶¹·|hi| + red.err.
// Sizes: for sin with j ≠ 0, |r| ≥ |a| − 2⁻⁷ − 2⁻⁵³ ≥ 0.49·|a| and |V| ≥ 0.89·|r|, so
// |S| ≤ 2.3·|V| and |B| ≤ 1.2·|V|; for j = 0, V ≈ B; for cos, |r| ≤ 0.786, |V| ≥ 0.706, |S| ≤ 0.71.
// Hence the bracket m (rounded terms in it) has Σ|m_i| ≤ 2⁻¹³·⁵·|V| (|S·cm1| ≤ 2.3·2⁻¹⁵·|V|,
// |C·cm1| ≤ 1.42·2⁻¹⁵·|V|, |sbmb| ≤ |B|³/6, |rl| ≤ u·|rh|, |e|, |S.lo|, |C.lo| ≤ 2.3u·|V|).
// 1. The large term L: sin, fl(fl((C.hi − 1) + C.lo)·b), within (2u + u²)·|(C − 1)·b|; cos,
//    fl(S.hi·b), within u·|S.hi·b|. The last addition t = fl(L + m) errs by ≤ u·|t|. As
//    |L| ≤ |t| + |m| + (those errors), 1 gives ≤ 3.01u·|t| + 2.01u·|m| ≤ 3.01u·|t| + 2⁻⁶⁵·|V|.
// 2. The bracket: each term after ≤ 10 roundings (sbmb and cm1 within ≈ 6u, see split; products;
//    rl + sbmb), summed with 2 more: ≤ 14u·Σ|m_i| ≤ 2⁻⁶³·|V|.
// 3. Left out: C.lo·(rl + sbmb), S.lo·(rl + sbmb) (≤ 2⁻⁵⁴·(u + 2⁻¹⁶)·2.3·|V|), C.lo·cm1 in cos
//    (≤ 2⁻⁵⁴·2⁻¹⁵/0.706 ≤ 2⁻⁶⁸·|V|), the series' truncation (≤ 2⁻⁷⁴·|B| ≤ 2⁻⁷³·|V|), rl² in B²
//    and the table's rounding (2⁻¹⁰⁶·(|S| + |C|)): ≤ 2⁻⁶⁷·|V| together.
// 4. The reduction (reduce_fast): red.err + 2⁻¹⁰²·|r| ≤ red.err + 2⁻¹⁰⁰·|V|.
// Sum: 3.01u·|t| + (2⁻⁶⁵ + 2⁻⁶³ + 2⁻⁶⁷ + 2⁻¹⁰⁰)·|V| + red.err; with |V| ≤ 1.01·|hi| and the bound
// itself computed within 3u, 4u·|t| + 2⁻⁶¹·|hi| + red.err covers it with room. Relative to V it
// is ≤ 2⁻⁵⁹ (sin: |t| ≤ 2⁻⁸·|V|; cos: ≤ 2⁻⁷·|V|), ≈ 2⁻⁶⁰·⁵ on average: about one argument in 60
// goes on to the kernel below (1.6 % of 10⁶ random ones on [−π, π] and on [−1000, 1000]).
// tests/stubs/test_portable_math_fast.cpp checks the bound against the kernel's on every argument
// it draws.
//
// The rounding test's margin e (rounds_to_hi) is computed directly: 1.125 × (that bound + the
// accurate path's 2⁻⁹⁶·|hi|) ≤ 1.125·4u·|t| + 0x1.3p-61·|hi| + red.err (red.err already holds the
// factor 1.125); for cos, |hi| ≤ 1 makes the middle term a constant.
struct Quick {
  double hi, lo, margin;
};
constexpr double kQuickTail = 0x1.2p-51;  // 1.125·4u, × |t|
constexpr double kQuickLump = 0x1.3p-61;  // ≥ 1.125·(2⁻⁶¹ + 2⁻⁹⁶), × |hi|

// sin r by the quick phase.
Quick quick_sin_r(const Split& p, double red_err) {
  const DD h = quick_two_sum(p.sin_a.hi, p.b);
  const double large = ((p.cos_a.hi - 1.0) + p.cos_a.lo) * p.b;
  const double rest =
      (h.lo + p.sin_a.lo) + (p.cos_a.hi * (p.rl + p.sin_b_minus_b) + p.sin_a.hi * p.cos_b_minus_1);
  const double t = large + rest;
  const DD s = quick_two_sum(h.hi, t);
  return {s.hi, s.lo, kQuickTail * std::fabs(t) + kQuickLump * std::fabs(s.hi) + red_err};
}

// cos r by the quick phase.
Quick quick_cos_r(const Split& p, double red_err) {
  const double large = p.sin_a.hi * p.b;
  const double rest = (p.cos_a.lo - p.sin_a.lo * p.b) +
                      (p.cos_a.hi * p.cos_b_minus_1 - p.sin_a.hi * (p.rl + p.sin_b_minus_b));
  const double t = rest - large;
  const DD s = quick_two_sum(p.cos_a.hi, t);
  return {s.hi, s.lo, kQuickTail * std::fabs(t) + (kQuickLump + red_err)};
}

// sin(x + shift·π/2) by the quick phase alone (sin or cos, not both) into `out`, or false.
bool quick_shifted(const Reduced& red, const Split& p, int shift, double& out) {
  constexpr double kSign[4] = {1.0, 1.0, -1.0, -1.0};
  const int quadrant = (red.quadrant + shift) & 3;
  const Quick a = (quadrant & 1) != 0 ? quick_cos_r(p, red.err) : quick_sin_r(p, red.err);
  out = kSign[quadrant] * a.hi;
  return margin_rounds_to_hi(a.hi, a.lo, a.margin);
}

// sin r and cos r by the quick phase, indexed by the quadrant's parity.
struct QuickSinCos {
  Quick of[2];
};

QuickSinCos quick_sin_cos_r(const Reduced& red, const Split& p) {
  return {{quick_sin_r(p, red.err), quick_cos_r(p, red.err)}};
}

// sin(x + shift·π/2) = ±(sin r or cos r) into `out`, or false. Selected by index and sign
// product, not by branches on the quadrant (random angles would mispredict them).
bool quick_decides(const QuickSinCos& q, const Reduced& red, int shift, double& out) {
  constexpr double kSign[4] = {1.0, 1.0, -1.0, -1.0};
  const int quadrant = (red.quadrant + shift) & 3;
  const Quick& a = q.of[quadrant & 1];
  out = kSign[quadrant] * a.hi;
  return margin_rounds_to_hi(a.hi, a.lo, a.margin);
}

// sin(r + q·π/2) for q = quadrant: sin r, cos r, −sin r, −cos r. With (F, G) = (sin a, cos a)
// for sin r and (cos a, −sin a) for cos r: F + G·B + F·(cos B − 1) + G·(sin B − B), the
// sign applied by rounds_surely. Left out: G.lo·rl and G.lo·(sin B − B), below 2⁻⁶⁸ of the
// value (for sin with j ≠ 0, |value| ≥ max(|sin a|, |B|)/2.3; for j = 0 the value is ≈ B; for
// cos, |value| ≥ 0.68).
inline Approx sin_cos_kernel(const Split& p, int quadrant) {
  const bool cosine = (quadrant & 1) != 0;
  const DD f = cosine ? p.cos_a : p.sin_a;
  const DD g = cosine ? neg(p.sin_a) : p.cos_a;
  const DD gb = two_prod(g.hi, p.b);
  const double t[7] = {gb.lo,
                       f.lo,
                       g.hi * p.rl,
                       g.lo * p.b,
                       f.hi * p.cos_b_minus_1,
                       f.lo * p.cos_b_minus_1,
                       g.hi * p.sin_b_minus_b};
  const double small = ((t[0] + t[1]) + (t[2] + t[3])) + ((t[4] + t[5]) + t[6]);
  const double magnitude =
      ((std::fabs(t[0]) + std::fabs(t[1])) + (std::fabs(t[2]) + std::fabs(t[3]))) +
      ((std::fabs(t[4]) + std::fabs(t[5])) + std::fabs(t[6]));
  return combine(two_sum(f.hi, gb.hi), small, magnitude, std::fabs(gb.hi) + std::fabs(f.hi));
}

// sin(x + shift·π/2) by the fast path into `out`, or false.
bool sin_shifted(const Reduced& red, const Split& p, int shift, double& out) {
  const int quadrant = (red.quadrant + shift) & 3;
  Approx a = sin_cos_kernel(p, quadrant);
  a.err += red.err;
  return rounds_surely(a, quadrant >= 2, out);
}

// sin(x + shift·π/2) where the quick phase could not decide: the kernel, else the accurate path.
double kernel_shifted(double x, const Reduced& red, const Split& p, int shift) {
  double out = 0.0;
  if (sin_shifted(red, p, shift, out)) return out;
  return shift == 0 ? detail::sin_accurate(x) : detail::cos_accurate(x);
}

// The smallest |x| whose sine takes the fast path. Down to 2⁻⁵⁰⁰ the kernel's analysis holds with
// j = 0, F = 0, G = 1, B = x: x² ≥ 2⁻¹⁰⁰⁰ is normal; x³/6 and higher terms may underflow, adding at
// most a few 2⁻¹⁰⁷⁴ absolute (≤ 2⁻⁵⁷⁰·|x|, inside the 2⁻⁶⁸ lumped in kLumpBound). The accurate
// path there sums x + (−x³/6 + …) in double-doubles, where r² and its terms may underflow the same
// way: within 2⁻⁵⁷⁰·|x| too. Motion-capture files are full of such angles (punch_kick.amc has
// 1 800 of ≈ 10⁻¹³ degrees among its 26 550 non-zero ones): before, below 2⁻²⁶ every sine took
// the accurate path (≈ 330 ns).
constexpr double kSinFastMin = 0x1p-500;

// ---- atan2, asin, acos -------------------------------------------------------------------------

// n/d for double-doubles n, d > 0 (|d.lo| ≤ 4u·d.hi) with one division: q = n.hi·(1/d.hi) (within
// 3u of n/d, so n.hi − p.hi is exact) and the remainder's correction, also times 1/d.hi. The
// remainder is ≤ 9u·|n| and computed within 36u²·|n|, its quotient within 54u²·t: relative error
// ≤ 2⁻⁹⁹.
DD quotient(DD n, DD d) {
  const double inv = 1.0 / d.hi;
  const double q = n.hi * inv;
  const DD p = two_prod(q, d.hi);
  const double r = (((n.hi - p.hi) - p.lo) + n.lo) - q * d.lo;
  return quick_two_sum(q, r * inv);
}

// atan(n/d) for n, d > 0 in [2⁻³⁰⁰, 2³⁰⁰] with n.hi ≤ d.hi: c = k/16 near q = n.hi/d.hi and
// u = (n − c·d)/(d + c·n) = (t − c)/(1 + t·c), t = n/d, |u| ≤ |t − c| ≤ 0.51/16 + 2⁻⁵²;
// atan t = atan c + atan u. k ≥ 1 only where q ≥ 0.51/16, so n.hi/(c·d.hi) ∈ [0.509, 1.52] and
// n.hi − (c·d.hi).hi is exact (Sterbenz). The other parts of n − c·d and d + c·n are within
// 2⁻¹⁰²·d, which moves u and atan by ≤ 2⁻¹⁰², ≤ 2⁻⁹⁷ of atan t ≥ atan(0.509/16) when k ≥ 1 (for
// k = 0 they are n and d exactly). The quotient's 2⁻⁹⁹ moves atan u by ≤ 2⁻⁹⁹·|u|, and
// |u| ≤ 1.01·atan t.
Approx atan_ratio(DD n, DD d) {
  const int k = static_cast<int>((n.hi / d.hi) * 16.0 + 0.49);
  const double c = k * 0.0625;
  const DD cd = two_prod(c, d.hi), cn = two_prod(c, n.hi);
  const DD num = two_sum(n.hi - cd.hi, (n.lo - cd.lo) - c * d.lo);
  const DD d1 = two_sum(d.hi, cn.hi);
  const DD den = {d1.hi, ((d1.lo + d.lo) + cn.lo) + c * n.lo};  // |den.lo| ≤ 4u·den.hi
  const DD u = quotient(num, den);
  // atan u − u = u³·(−1/3 + u²/5 − …) truncated below |u|¹⁵/15 ≤ 2⁻⁷³·|u|, at u.hi (Estrin's
  // scheme, terms shrinking by 2⁻¹⁰); u.lo's effect through u³ is −u²·u.lo (the rest
  // ≤ u⁴·|u.lo| ≤ 2⁻⁷³·|u|).
  const double s = u.hi * u.hi, s2 = s * s;
  const double poly = (-1.0 / 3.0 + s * (1.0 / 5.0)) +
                      s2 * ((-1.0 / 7.0 + s * (1.0 / 9.0)) + s2 * (-1.0 / 11.0 + s * (1.0 / 13.0)));
  const double t[4] = {kAtanSixteenths[k].lo, u.lo, u.hi * s * poly, -s * u.lo};
  const double small = (t[0] + t[1]) + (t[2] + t[3]);
  const double magnitude =
      (std::fabs(t[0]) + std::fabs(t[1])) + (std::fabs(t[2]) + std::fabs(t[3]));
  return combine(two_sum(kAtanSixteenths[k].hi, u.hi), small, magnitude,
                 std::fabs(kAtanSixteenths[k].hi) + std::fabs(u.hi));
}

// c − a for c = π/2 or π (double-double) and 0 ≤ a ≤ c/2 (up to rounding).
Approx subtract_from(DD c, const Approx& a) {
  Approx r = combine(two_sum(c.hi, -a.hi), c.lo - a.lo, std::fabs(c.lo) + std::fabs(a.lo),
                     std::fabs(c.hi));
  r.err += a.err;
  return r;
}

// The angle of (x, y) in [0, π/2] for x, y > 0 in [2⁻³⁰⁰, 2³⁰⁰].
Approx angle_first_quadrant(DD y, DD x) {
  if (y.hi <= x.hi) return atan_ratio(y, x);
  return subtract_from(kHalfPi, atan_ratio(x, y));
}

// √(1 − x²) for 0 ≤ x < 1 (relative error ≤ 2⁻¹⁰²).
DD cosine_of(double ax) { return sqrt_dd(mul(two_sum(1.0, -ax), two_sum(1.0, ax))); }

// Where the fast atan2 applies: both magnitudes in [2⁻³⁰⁰, 2³⁰⁰] (false for 0, ∞ and NaN), so no
// product or quotient above overflows or leaves the normal range where it matters.
bool moderate(double a) { return a >= 0x1p-300 && a <= 0x1p300; }

}  // namespace

double sin(double x) {
  const double ax = std::fabs(x);
  // 0, tiny, huge, ∞, NaN: the accurate path
  if (!(ax >= kSinFastMin && ax <= 0x1p20)) return detail::sin_accurate(x);
  const Reduced red = reduce_fast(x);
  const Split p = split(red.r);
  double out = 0.0;
  return quick_shifted(red, p, 0, out) ? out : kernel_shifted(x, red, p, 0);
}

double cos(double x) {
  if (x == 0.0) return 1.0;  // absent channels' angles: no kernel
  if (!(std::fabs(x) <= 0x1p20)) return detail::cos_accurate(x);  // huge, ∞, NaN
  const Reduced red = reduce_fast(x);
  const Split p = split(red.r);
  double out = 0.0;
  return quick_shifted(red, p, 1, out) ? out : kernel_shifted(x, red, p, 1);
}

void sin_cos(double x, double& s, double& c) {
  if (x == 0.0) {  // absent channels' angles: no kernel
    s = x;         // keeps the sign of −0, as sin does
    c = 1.0;
    return;
  }
  const double ax = std::fabs(x);
  if (!(ax <= 0x1p20)) {
    s = detail::sin_accurate(x);
    c = detail::cos_accurate(x);
    return;
  }
  // sin x = sin(r + q·π/2), cos x = sin(r + (q + 1)·π/2): one needs sin r, the other cos r. Both
  // quick phases before either decision, so that their dependency chains overlap; the kernel
  // only for the one whose rounding the quick phase could not decide.
  const Reduced red = reduce_fast(x);
  const Split p = split(red.r);
  const QuickSinCos q = quick_sin_cos_r(red, p);
  if (ax < kSinFastMin)
    s = detail::sin_accurate(x);
  else if (!quick_decides(q, red, 0, s))
    s = kernel_shifted(x, red, p, 0);
  if (!quick_decides(q, red, 1, c)) c = kernel_shifted(x, red, p, 1);
}

double detail::sin_cos_quick_bound_use(double x) {
  const double ax = std::fabs(x);
  if (!(ax >= kSinFastMin && ax <= 0x1p20)) return 0.0;
  const Reduced red = reduce_fast(x);
  const Split p = split(red.r);
  double worst = 0.0;
  for (int quadrant = 0; quadrant < 2; ++quadrant) {  // sin r, cos r
    const Quick quick = quadrant == 0 ? quick_sin_r(p, red.err) : quick_cos_r(p, red.err);
    Approx kernel = sin_cos_kernel(p, quadrant);
    kernel.err += red.err;
    const double apart = std::fabs((quick.hi - kernel.hi) + (quick.lo - kernel.lo));
    const double use = (apart - kernel.err) / (quick.margin / 1.125);
    if (use > worst) worst = use;
  }
  return worst;
}

double atan2(double y, double x) {
  if (!moderate(std::fabs(y)) || !moderate(std::fabs(x))) return detail::atan2_accurate(y, x);
  Approx a = angle_first_quadrant({std::fabs(y), 0.0}, {std::fabs(x), 0.0});
  if (x < 0.0) a = subtract_from(kPi, a);
  double out = 0.0;
  return rounds_surely(a, y < 0.0, out) ? out : detail::atan2_accurate(y, x);
}

double asin(double x) {
  const double ax = std::fabs(x);
  if (!(ax >= 0x1p-300 && ax < 1.0)) return detail::asin_accurate(x);
  double out = 0.0;
  const Approx a = angle_first_quadrant({ax, 0.0}, cosine_of(ax));
  return rounds_surely(a, x < 0.0, out) ? out : detail::asin_accurate(x);
}

double acos(double x) {
  const double ax = std::fabs(x);
  if (!(ax >= 0x1p-300 && ax < 1.0)) return detail::acos_accurate(x);
  Approx a = angle_first_quadrant(cosine_of(ax), {ax, 0.0});
  if (x < 0.0) a = subtract_from(kPi, a);
  double out = 0.0;
  return rounds_surely(a, false, out) ? out : detail::acos_accurate(x);
}

}  // namespace jelly::portable
