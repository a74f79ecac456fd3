#pragma once
// Transcendental functions that give the same bits on every platform.
//
// The C library's sin, cos, exp and pow are not the same code everywhere: glibc, macOS's libm,
// MinGW-w64's CRT (x87 fsin/fcos) and MSVC's UCRT round differently in the last bits. The core
// uses these instead wherever such a value reaches the simulation state or a printed result (the
// bodies' initial rotations, the stability detector's frequency grid, the two-particle spring's
// exact solution), so a student on Windows or macOS computes what the grader computes on Linux.
//
// They use only +, −, × and ÷ of doubles (correctly rounded by IEEE 754 on every compiler the
// project supports, with -ffp-contract=off or /fp:precise): the argument is reduced and a Taylor
// series summed in double-double arithmetic (≈ 106 bits), then rounded once. The result is the
// correctly rounded value except in cases closer than ≈ 2⁻¹⁰⁰ to a rounding boundary, so it also
// agrees with glibc wherever glibc is correctly rounded (tests/core/test_portable_math.cpp).
namespace jelly::portable {

// sin x and cos x for x in radians. Exact for x = 0; NaN for ±∞ and NaN. Intended for |x| up to
// about 10⁶ (the reduction by π/2 keeps ≈ 100 bits there); larger arguments stay deterministic
// but lose accuracy.
double sin(double x);
double cos(double x);

// √(x² + y²) without overflow or underflow in between (as std::hypot; the C libraries' differ).
double hypot(double x, double y);

// 10^y (y finite, |y| ≤ 300); +∞/0 beyond the double range, NaN for NaN.
double exp10(double y);

}  // namespace jelly::portable
