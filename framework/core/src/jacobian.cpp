#include "jelly/jacobian.hpp"

#include <algorithm>
#include <cmath>

namespace jelly {

void ForceJacobians::reset(Eigen::Index n, std::vector<std::pair<int, int>> block_pairs) {
  pairs = std::move(block_pairs);
  dfdx_diag.assign(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  dfdv_diag.assign(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  dfdx_off.assign(pairs.size(), Eigen::Matrix3d::Zero());
  dfdv_off.assign(pairs.size(), Eigen::Matrix3d::Zero());
}

void ForceJacobians::set_zero() {
  std::fill(dfdx_diag.begin(), dfdx_diag.end(), Eigen::Matrix3d::Zero());
  std::fill(dfdv_diag.begin(), dfdv_diag.end(), Eigen::Matrix3d::Zero());
  std::fill(dfdx_off.begin(), dfdx_off.end(), Eigen::Matrix3d::Zero());
  std::fill(dfdv_off.begin(), dfdv_off.end(), Eigen::Matrix3d::Zero());
}

namespace {

void multiply(const std::vector<Eigen::Matrix3d>& diag, const std::vector<Eigen::Matrix3d>& off,
              const std::vector<std::pair<int, int>>& pairs, const Vec3Array& in, Vec3Array& out) {
  out.resize(3, in.cols());
  for (Eigen::Index i = 0; i < in.cols(); ++i)
    out.col(i) = diag[static_cast<std::size_t>(i)] * in.col(i);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [i, j] = pairs[p];
    out.col(i) += off[p] * in.col(j);
    out.col(j) += off[p].transpose() * in.col(i);
  }
}

}  // namespace

void ForceJacobians::multiply_dfdx(const Vec3Array& in, Vec3Array& out) const {
  multiply(dfdx_diag, dfdx_off, pairs, in, out);
}

void ForceJacobians::multiply_dfdv(const Vec3Array& in, Vec3Array& out) const {
  multiply(dfdv_diag, dfdv_off, pairs, in, out);
}

void add_spring_jacobians(const SpringGroup& group, const State& s,
                          const std::vector<int>& pair_of_spring, ForceJacobians& jac) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (std::size_t k = 0; k < group.springs.size(); ++k) {
    const Spring& sp = group.springs[k];
    const Vec3 d = s.x.col(sp.a) - s.x.col(sp.b);
    const double l = d.norm();
    if (l < group.degenerate_length) continue;  // no direction: contributes nothing
    const Vec3 u = d / l;
    const Eigen::Matrix3d uu = u * u.transpose();
    const double geometric = std::max(0.0, 1.0 - sp.rest_length / l);           // the clamp of §6
    const Eigen::Matrix3d kx = -group.ks * (geometric * (identity - uu) + uu);  // ∂f_a/∂x_a
    const Eigen::Matrix3d kv = -group.kd * uu;                                  // ∂f_a/∂v_a
    const int p = pair_of_spring[k];
    jac.dfdx_diag[static_cast<std::size_t>(sp.a)] += kx;
    jac.dfdx_diag[static_cast<std::size_t>(sp.b)] += kx;
    jac.dfdv_diag[static_cast<std::size_t>(sp.a)] += kv;
    jac.dfdv_diag[static_cast<std::size_t>(sp.b)] += kv;
    jac.dfdx_off[static_cast<std::size_t>(p)] -= kx;
    jac.dfdv_off[static_cast<std::size_t>(p)] -= kv;
  }
}

}  // namespace jelly
