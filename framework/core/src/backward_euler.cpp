#include "jelly/backward_euler.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jelly {

namespace {

// Dot product in a fixed, sequential order (Eigen's vectorised reductions would change the
// summation order, and so the bits, with the vector width).
double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

// Offset in A's value array of entry (row, col); the pattern guarantees it exists.
Eigen::Index offset_of(const Eigen::SparseMatrix<double, Eigen::RowMajor>& A, Eigen::Index row,
                       Eigen::Index col) {
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const auto* begin = inner + outer[row];
  const auto* end = inner + outer[row + 1];
  const auto* it = std::lower_bound(begin, end, static_cast<int>(col));
  return static_cast<Eigen::Index>(it - inner);
}

}  // namespace

void BackwardEulerSolver::build_pattern(JacobianSystem& system) {
  const Eigen::Index n = system.particle_count();
  jac_.reset(n, system.jacobian_pattern());
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(9 * n) + 18 * jac_.pairs.size());
  auto add_block = [&](Eigen::Index bi, Eigen::Index bj) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) triplets.emplace_back(3 * bi + r, 3 * bj + c, 1.0);
  };
  for (Eigen::Index i = 0; i < n; ++i) add_block(i, i);
  for (const auto& [i, j] : jac_.pairs) {
    add_block(i, j);
    add_block(j, i);
  }
  A_.resize(3 * n, 3 * n);
  A_.setFromTriplets(triplets.begin(), triplets.end());
  A_.makeCompressed();
  // Within a row a 3×3 block's three columns are consecutive, so one offset per block row suffices.
  diag_offset_.resize(static_cast<std::size_t>(3 * n));
  for (Eigen::Index i = 0; i < n; ++i)
    for (int r = 0; r < 3; ++r)
      diag_offset_[static_cast<std::size_t>(3 * i + r)] = offset_of(A_, 3 * i + r, 3 * i);
  off_ij_.resize(3 * jac_.pairs.size());
  off_ji_.resize(3 * jac_.pairs.size());
  for (std::size_t p = 0; p < jac_.pairs.size(); ++p) {
    const auto [i, j] = jac_.pairs[p];
    for (int r = 0; r < 3; ++r) {
      off_ij_[3 * p + r] = offset_of(A_, 3 * i + r, 3 * j);
      off_ji_[3 * p + r] = offset_of(A_, 3 * j + r, 3 * i);
    }
  }
  const auto size = 3 * n;
  b_.resize(size);
  dv_.resize(size);
  r_.resize(size);
  z_.resize(size);
  p_.resize(size);
  q_.resize(size);
  inv_diag_.resize(size);
  built_ = true;
}

void BackwardEulerSolver::step(JacobianSystem& system, State& s, double h) {
  if (!built_ || jac_.dfdx_diag.size() != static_cast<std::size_t>(s.size())) build_pattern(system);
  const Eigen::Index n = s.size();
  evaluate_forces(system, s);
  fill_matrix(system.masses(), n, h);
  fill_rhs(n, h);
  pin_fixed(system, n);
  solve(n);
  advance(s, h);
}

void BackwardEulerSolver::evaluate_forces(JacobianSystem& system, const State& s) {
  // f_n (gravity, springs, dampers, contact) and its Jacobians at the current state.
  const Eigen::Index n = s.size();
  const Eigen::VectorXd& m = system.masses();
  system.acceleration(s, accel_);
  force_.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) force_.col(i) = m[i] * accel_.col(i);
  system.force_jacobians(s, jac_);
  jac_.multiply_dfdx(s.v, dfdx_v_);
}

void BackwardEulerSolver::fill_matrix(const Eigen::VectorXd& m, Eigen::Index n, double h) {
  // A = M − h ∂f/∂v − h² ∂f/∂x, filled into the fixed pattern.
  double* values = A_.valuePtr();
  std::fill(values, values + A_.nonZeros(), 0.0);
  const double h2 = h * h;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Matrix3d block = -h * jac_.dfdv_diag[static_cast<std::size_t>(i)] -
                                  h2 * jac_.dfdx_diag[static_cast<std::size_t>(i)];
    for (int r = 0; r < 3; ++r) {
      double* row = values + diag_offset_[static_cast<std::size_t>(3 * i + r)];
      for (int c = 0; c < 3; ++c) row[c] = block(r, c) + (r == c ? m[i] : 0.0);
    }
  }
  for (std::size_t p = 0; p < jac_.pairs.size(); ++p) {
    const Eigen::Matrix3d block = -h * jac_.dfdv_off[p] - h2 * jac_.dfdx_off[p];
    for (int r = 0; r < 3; ++r) {
      double* row_ij = values + off_ij_[3 * p + r];
      double* row_ji = values + off_ji_[3 * p + r];
      for (int c = 0; c < 3; ++c) {
        row_ij[c] = block(r, c);
        row_ji[c] = block(c, r);
      }
    }
  }
}

void BackwardEulerSolver::fill_rhs(Eigen::Index n, double h) {
  // b = h (f_n + h ∂f/∂x v_n)
  for (Eigen::Index i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) b_[3 * i + d] = h * (force_(d, i) + h * dfdx_v_(d, i));
}

void BackwardEulerSolver::pin_fixed(JacobianSystem& system, Eigen::Index n) {
  // Fixed particles (pinned particles, w = 0) keep Δv = 0: their rows and columns become
  // the identity's and their right-hand side zero, so the free particles see them as walls.
  bool any_fixed = false;
  for (Eigen::Index i = 0; i < n && !any_fixed; ++i) any_fixed = system.is_fixed(i);
  if (!any_fixed) return;
  double* values = A_.valuePtr();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!system.is_fixed(i)) continue;
    for (int r = 0; r < 3; ++r) {
      double* row = values + diag_offset_[static_cast<std::size_t>(3 * i + r)];
      for (int c = 0; c < 3; ++c) row[c] = r == c ? 1.0 : 0.0;
      b_[3 * i + r] = 0.0;
    }
  }
  for (std::size_t p = 0; p < jac_.pairs.size(); ++p) {
    const auto [i, j] = jac_.pairs[p];
    if (!system.is_fixed(i) && !system.is_fixed(j)) continue;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        values[off_ij_[3 * p + r] + c] = 0.0;
        values[off_ji_[3 * p + r] + c] = 0.0;
      }
  }
}

void BackwardEulerSolver::solve(Eigen::Index n) {
  // Jacobi-preconditioned conjugate gradient from Δv = 0.
  const double* values = A_.valuePtr();
  for (Eigen::Index k = 0; k < 3 * n; ++k) {
    const double diag = values[diag_offset_[static_cast<std::size_t>(k)] + k % 3];
    inv_diag_[k] = diag != 0.0 ? 1.0 / diag : 1.0;
  }
  dv_.setZero();
  r_ = b_;
  const double b_norm = std::sqrt(dot(b_, b_));
  int it = 0;
  double residual = 0.0;
  if (b_norm > 0.0) {
    z_ = r_.cwiseProduct(inv_diag_);
    p_ = z_;
    double rz = dot(r_, z_);
    residual = 1.0;
    while (it < options_.max_iterations) {
      q_.noalias() = A_ * p_;
      const double pq = dot(p_, q_);
      if (!(pq > 0.0)) break;  // not positive definite along p (should not happen with the clamp)
      const double alpha = rz / pq;
      dv_ += alpha * p_;
      r_ -= alpha * q_;
      ++it;
      residual = std::sqrt(dot(r_, r_)) / b_norm;
      if (residual <= options_.tolerance) break;
      z_ = r_.cwiseProduct(inv_diag_);
      const double rz_next = dot(r_, z_);
      p_ = z_ + (rz_next / rz) * p_;
      rz = rz_next;
    }
  }
  last_iterations_ = it;
  last_residual_ = residual;
  total_iterations_ += it;
  if (it >= options_.max_iterations) ++capped_steps_;
}

void BackwardEulerSolver::advance(State& s, double h) const {
  // v ← v + Δv, x ← x + h v
  const Eigen::Index n = s.size();
  for (Eigen::Index i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) s.v(d, i) += dv_[3 * i + d];
  s.x += h * s.v;
}

}  // namespace jelly
