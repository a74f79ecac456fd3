#pragma once
// Transcendental functions that give the same bits on every platform.
//
// The C library's sin, cos, atan2, exp and pow are not the same code everywhere: glibc, macOS's
// libm, MinGW-w64's CRT (x87 fsin/fcos) and MSVC's UCRT round differently in the last bits. The
// core uses these instead wherever such a value reaches the simulation state or a printed result
// (the bodies' initial rotations, the stability detector's frequency grid, the two-particle
// spring's exact solution, Euler angles of rotations), so a student on Windows or macOS computes
// what the grader computes on Linux.
//
// They use only +, −, × and ÷ of doubles (correctly rounded by IEEE 754 on every compiler the
// project supports, with -ffp-contract=off or /fp:precise): the argument is reduced and a Taylor
// series summed in double-double arithmetic (≈ 106 bits), then rounded once (atan2: a table of
// atan(k/16) and the series of atan u, |u| ≤ 1/32). The result is the correctly rounded value
// except in cases closer than ≈ 2⁻¹⁰⁰ to a rounding boundary, so it also agrees with glibc
// wherever glibc is correctly rounded (tests/stubs/test_portable_math.cpp).
//
// sin, cos, sin_cos, atan2, asin and acos first take a fast path (portable_math_fast.cpp): a table
// and a short polynomial in plain double arithmetic with a rigorous error bound. When the bound
// shows that every value within it rounds to the same double, that double is returned: it is then
// the accurate path's result too. Otherwise (about one call in a few hundred) the accurate path
// (detail::) computes it. sin, cos and sin_cos try a cheaper quick phase with a looser bound
// before that fast path (the fast path then serves ≈ 1.6 % of calls). Both give the same bits for
// every input (tests/stubs/ test_portable_math_fast.cpp compares them).
namespace jelly::portable {

// sin x and cos x for x in radians. Exact for x = 0; NaN for ±∞ and NaN. Intended for |x| up to
// about 10⁶ (the reduction by π/2 keeps ≈ 100 bits there); larger arguments stay deterministic
// but lose accuracy.
double sin(double x);
double cos(double x);
// sin x and cos x at once (the bits of sin(x) and cos(x)), sharing the reduction and the table.
void sin_cos(double x, double& s, double& c);

// √(x² + y²) without overflow or underflow in between (as std::hypot; the C libraries' differ).
double hypot(double x, double y);

// 10^y (y finite, |y| ≤ 300); +∞/0 beyond the double range, NaN for NaN.
double exp10(double y);

// The angle of (x, y) in radians, in [−π, π], with std::atan2's special values: ±0 for y = ±0
// and x > 0 or x = +0, ±π for y = ±0 and x < 0 or x = −0, ±π/2 for x = ±0 and y ≠ 0, ±π/4 and
// ±3π/4 for two infinities, NaN for NaN. Correctly rounded (as above) for every finite pair.
double atan2(double y, double x);

// asin x ∈ [−π/2, π/2] and acos x ∈ [0, π] for x ∈ [−1, 1] (NaN outside and for NaN), computed
// as the angle of (x, √(1 − x²)) with the root in double-double: correctly rounded as above.
// asin(±0) = ±0, acos(1) = +0.
double asin(double x);
double acos(double x);

namespace detail {
// The accurate path alone (double-double series), which the functions above fall back on: their
// results for every argument. For tests that compare the two paths.
double sin_accurate(double x);
double cos_accurate(double x);
double atan2_accurate(double y, double x);
double asin_accurate(double x);
double acos_accurate(double x);
// For the test of sin, cos and sin_cos's quick phase (plain doubles, a bound of ≈ 2⁻⁶⁰ relative):
// the largest, over sin r and cos r of x's reduced argument r, of (|quick − kernel| − the
// kernel's bound) / the quick phase's bound, where the kernel is the fast path's double-double
// approximation. A lower bound on the quick phase's error over its bound: ≤ 1 wherever that bound
// holds. 0 where the quick phase does not apply (|x| < 2⁻⁵⁰⁰, |x| > 2²⁰, ∞, NaN).
double sin_cos_quick_bound_use(double x);
}  // namespace detail

}  // namespace jelly::portable
