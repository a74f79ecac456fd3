// True backward Euler (Baraff & Witkin 1998), a framework integrator (contract §6).
#pragma once

#include <Eigen/SparseCore>

#include "jelly/jacobian.hpp"

namespace jelly {

/// Solves (M − h ∂f/∂v − h² ∂f/∂x) Δv = h (f_n + h ∂f/∂x v_n) by Jacobi-preconditioned conjugate
/// gradient on an Eigen sparse matrix, then v ← v + Δv, x ← x + h v. Contact forces are part of
/// f_n but not differentiated. The matrix pattern is built once; values are refilled every step.
class BackwardEulerSolver {
 public:
  struct Options {
    double tolerance = 1e-10;   ///< relative residual |r| / |b|
    int max_iterations = 2000;  ///< cap; hitting it is counted and reported, not fatal
  };
  BackwardEulerSolver() = default;
  explicit BackwardEulerSolver(Options options) : options_(options) {}

  /// One step of size h.
  void step(JacobianSystem& system, State& s, double h);

  int last_iterations() const { return last_iterations_; }
  double last_residual() const { return last_residual_; }
  long total_iterations() const { return total_iterations_; }
  long capped_steps() const { return capped_steps_; }

 private:
  void build_pattern(JacobianSystem& system);
  // The steps of step(), in order: f_n and its Jacobians (with ∂f/∂x v_n), the matrix A in its
  // pattern, the right-hand side b, the fixed particles' rows (Δv = 0), Δv by preconditioned CG,
  // then v ← v + Δv, x ← x + h v.
  void evaluate_forces(JacobianSystem& system, const State& s);
  void fill_matrix(const Eigen::VectorXd& m, Eigen::Index n, double h);
  void fill_rhs(Eigen::Index n, double h);
  void pin_fixed(JacobianSystem& system, Eigen::Index n);
  void solve(Eigen::Index n);
  void advance(State& s, double h) const;

  Options options_;
  bool built_ = false;
  ForceJacobians jac_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> A_;
  std::vector<Eigen::Index> diag_offset_;  // per particle: valuePtr offset of row 3i, col 3i
  std::vector<Eigen::Index> off_ij_;       // per pair: offset of row 3i, col 3j
  std::vector<Eigen::Index> off_ji_;       // per pair: offset of row 3j, col 3i
  Vec3Array accel_, force_, dfdx_v_;
  Eigen::VectorXd b_, dv_, r_, z_, p_, q_, inv_diag_;
  int last_iterations_ = 0;
  double last_residual_ = 0.0;
  long total_iterations_ = 0;
  long capped_steps_ = 0;
};

}  // namespace jelly
