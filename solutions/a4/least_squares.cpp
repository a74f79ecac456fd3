// Reference: task A4.T3, the minimum-norm least-squares solve (kinematics contract §6.3, decision
// §11.15), from Eigen's JacobiSVD (one-sided Jacobi rotations: accurate on rank-deficient J, only
// sqrt, and the same bits on every platform with Eigen's scalar path; docs/a4-decisions.md).
// Read assignments/a4/handout/T3-least-squares.md first.
#include "jelly/a4/least_squares.hpp"

#include <Eigen/SVD>
#include <algorithm>

namespace jelly::a4 {

namespace {

constexpr double kTwoToMinus52 = 2.220446049250313080847e-16;  // 2⁻⁵², the double's epsilon

}  // namespace

void least_squares(const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
  x = skeleton::VectorX::Zero(J.cols());
  if (J.cols() == 0) return;
  const Eigen::MatrixXd matrix = J;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(matrix, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();  // decreasing, ≥ 0
  const double size = static_cast<double>(std::max(J.rows(), J.cols()));
  // σ ≤ max(rows, cols)·2⁻⁵²·σ_max counts as zero (J = 0: every σ, so x = 0).
  const double cutoff = size * kTwoToMinus52 * sigma(0);
  for (Eigen::Index i = 0; i < sigma.size(); ++i) {
    if (!(sigma(i) > cutoff)) break;
    // x += v_i (u_iᵀ e) / σ_i
    const double along = svd.matrixU().col(i).dot(e) / sigma(i);
    x += along * svd.matrixV().col(i);
  }
}

}  // namespace jelly::a4
