// Your code: task A4.T3, the minimum-norm least-squares solve of J x = e.
// Read assignments/a4/handout/T3-least-squares.md first.
#include "jelly/a4/least_squares.hpp"

namespace jelly::a4 {

void least_squares(const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
  x = skeleton::VectorX::Zero(J.cols());
  // TODO(A4.T3): x = V Σ⁺ Uᵀ e from an SVD of J, singular values σ ≤ max(rows, cols)·2⁻⁵²·σ_max
  // counted as zero (J = 0 gives x = 0). Not (JᵀJ)⁻¹Jᵀ e: JᵀJ is singular.
  // assignments/a4/handout/T3-least-squares.md.
  (void)e;
}

}  // namespace jelly::a4
