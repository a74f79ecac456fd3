// Student task A4.T3: the minimum-norm least-squares solution of J x = e (kinematics contract
// §6.3, decision §11.15). Handout: assignments/a4/handout/T3-least-squares.md.
#pragma once

#include "jelly/skeleton_tasks.hpp"
// Eigen::JacobiSVD<Eigen::MatrixXd> compiled once by the framework: use that type and your file
// compiles in about a second instead of five.
#include "jelly/skeleton/svd.hpp"

namespace jelly::a4 {

/// A4.T3 — x (resized to J.cols()) = V Σ⁺ Uᵀ e for the SVD J = U Σ Vᵀ, where singular values
/// σ ≤ max(rows, cols)·2⁻⁵²·σ_max count as zero; J = 0 gives x = 0. Finite for every finite J and
/// e whose answer is a finite double, rank-deficient J included (never (JᵀJ)⁻¹Jᵀ: it is singular
/// for every chain of more than one joint).
void least_squares(const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x);

}  // namespace jelly::a4
