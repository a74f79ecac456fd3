// Force Jacobians ∂f/∂x and ∂f/∂v in 3×3 blocks, for backward Euler and the stability estimate.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "jelly/spring.hpp"
#include "jelly/system.hpp"

namespace jelly {

/// Block-sparse, symmetric force Jacobians of N particles: one diagonal 3×3 block per particle and
/// one off-diagonal block per interacting pair (i < j). For a spring the off-diagonal block is
/// ∂f_i/∂x_j = −∂f_i/∂x_i, and ∂f_j/∂x_i is its transpose (the blocks are symmetric).
struct ForceJacobians {
  std::vector<std::pair<int, int>> pairs;  ///< off-diagonal block (i, j), i < j; fixed pattern
  std::vector<Eigen::Matrix3d> dfdx_diag;  ///< ∂f_i/∂x_i [N/m], one per particle
  std::vector<Eigen::Matrix3d> dfdv_diag;  ///< ∂f_i/∂v_i [N·s/m]
  std::vector<Eigen::Matrix3d> dfdx_off;   ///< ∂f_i/∂x_j, one per pair
  std::vector<Eigen::Matrix3d> dfdv_off;   ///< ∂f_i/∂v_j

  /// Sets the pattern for n particles and the given pairs; all blocks zero.
  void reset(Eigen::Index n, std::vector<std::pair<int, int>> block_pairs);
  /// Sets every block to zero, keeping the pattern.
  void set_zero();
  /// out = (∂f/∂x) · in, both 3×N.
  void multiply_dfdx(const Vec3Array& in, Vec3Array& out) const;
  /// out = (∂f/∂v) · in, both 3×N.
  void multiply_dfdv(const Vec3Array& in, Vec3Array& out) const;
};

/// A System that can also give its particle masses and its force Jacobians (for backward Euler
/// and the §8 stability estimate).
class JacobianSystem : public System {
 public:
  /// Mass of every particle [kg].
  virtual const Eigen::VectorXd& masses() const = 0;
  /// The block pattern this system's Jacobians use (constant over a run).
  virtual std::vector<std::pair<int, int>> jacobian_pattern() const = 0;
  /// Writes ∂f/∂x and ∂f/∂v at state s into `jac` (whose pattern is jacobian_pattern()).
  virtual void force_jacobians(const State& s, ForceJacobians& jac) = 0;
  /// Whether particle i is held fixed (inverse mass 0: a pinned particle). The stability
  /// estimate is that of the other particles, and backward Euler leaves fixed ones at rest.
  /// Default: no particle is fixed.
  virtual bool is_fixed(Eigen::Index i) const {
    (void)i;
    return false;
  }
};

/// Adds the Jacobian blocks of every spring of `group` at state s, with the clamp of contract §6:
///   ∂f_a/∂x_a = −ks [ max(0, 1 − rest/l)(I − u uᵀ) + u uᵀ ],  ∂f_a/∂v_a = −kd u uᵀ
/// (the damper's dependence on position is dropped). `pair_of_spring[k]` is the index into
/// jac.pairs of spring k's (a, b) pair.
void add_spring_jacobians(const SpringGroup& group, const State& s,
                          const std::vector<int>& pair_of_spring, ForceJacobians& jac);

}  // namespace jelly
