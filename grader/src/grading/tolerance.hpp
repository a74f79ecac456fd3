// The grader's one tolerance test: a number a passes against the reference b when
// |a − b| ≤ atol + rtol·|b| (docs/grader.md; the named tolerances of cases/tolerances.toml).
#pragma once

#include <cmath>

namespace jelly::grade {

/// How far from the reference value `b` a number may be: atol + rtol·|b|.
inline double allowed_difference(double b, double atol, double rtol) {
  return atol + rtol * std::abs(b);
}

/// |a − b| ≤ atol + rtol·|b|; false when a or b is NaN (or the difference is).
inline bool within_tolerance(double a, double b, double atol, double rtol) {
  return std::abs(a - b) <= allowed_difference(b, atol, rtol);
}

}  // namespace jelly::grade
