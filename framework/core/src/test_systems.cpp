#include "jelly/test_systems.hpp"

#include "jelly/portable_math.hpp"

#include <cmath>

namespace jelly {

FreeFallSystem::FreeFallSystem(Eigen::Index particles, const Vec3& g, double mass)
    : g_(g), mass_(Eigen::VectorXd::Constant(particles, mass)) {}

void FreeFallSystem::acceleration(const State& s, Vec3Array& a) {
  a.resize(3, s.size());
  a.colwise() = g_;
}

void FreeFallSystem::force_jacobians(const State& /*s*/, ForceJacobians& jac) { jac.set_zero(); }

LinearSystem::LinearSystem(World& world, const Vec3Array& x_eq)
    : x_eq_(x_eq), mass_(world.masses()) {
  if (world.gravity()) g_ = *world.gravity();
  State at;
  at.x = x_eq;
  at.v = Vec3Array::Zero(3, x_eq.cols());
  jac_.reset(x_eq.cols(), world.jacobian_pattern());
  world.force_jacobians(at, jac_);
}

void LinearSystem::acceleration(const State& s, Vec3Array& a) {
  // a = g + M⁻¹ (∂f/∂x (x − x_eq) + ∂f/∂v v)
  tmp2_ = s.x - x_eq_;
  jac_.multiply_dfdx(tmp2_, tmp_);
  jac_.multiply_dfdv(s.v, tmp2_);
  a.resize(3, s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i)
    a.col(i) = g_ + (tmp_.col(i) + tmp2_.col(i)) / mass_[i];
}

void LinearSystem::force_jacobians(const State& /*s*/, ForceJacobians& jac) {
  jac.dfdx_diag = jac_.dfdx_diag;
  jac.dfdv_diag = jac_.dfdv_diag;
  jac.dfdx_off = jac_.dfdx_off;
  jac.dfdv_off = jac_.dfdv_off;
}

double LinearSystem::energy(const State& s) const {
  Vec3Array dx = s.x - x_eq_, kdx;
  jac_.multiply_dfdx(dx, kdx);
  double e = -0.5 * (dx.array() * kdx.array()).sum();
  for (Eigen::Index i = 0; i < s.size(); ++i)
    e += 0.5 * mass_[i] * s.v.col(i).squaredNorm() - mass_[i] * g_.dot(dx.col(i));
  return e;
}

State TwoParticleSpring::initial_state(double stretch) {
  State s;
  s.resize(2);
  const double l0 = kRestLength + stretch;
  s.x.col(0) = Vec3(-0.5 * l0, 0.0, 0.0);
  s.x.col(1) = Vec3(0.5 * l0, 0.0, 0.0);
  s.v.setZero();
  return s;
}

double TwoParticleSpring::exact_length(double t, double stretch) {
  // Reduced mass ½: ω = √(2 ks / m) = √20 for ks = 10, m = 1.
  return kRestLength + stretch * portable::cos(std::sqrt(2.0 * kStiffness) * t);
}

double TwoParticleSpring::exact_x1(double t, double stretch) {
  return 0.5 * exact_length(t, stretch);
}

std::unique_ptr<LinearSystem> make_linear_two_particle_spring(double stretch) {
  World world{TaskTable{}};
  const State s = TwoParticleSpring::initial_state(stretch);
  world.add_particles(s.x, s.v, 1.0);
  SpringGroup g;
  g.type = SpringType::Structural;
  g.ks = TwoParticleSpring::kStiffness;
  g.kd = 0.0;
  g.degenerate_length = degenerate_length_for(TwoParticleSpring::kRestLength);
  g.springs.push_back({0, 1, TwoParticleSpring::kRestLength});
  world.add_spring_group(std::move(g));
  Vec3Array x_eq(3, 2);
  x_eq.col(0) = Vec3(-0.5 * TwoParticleSpring::kRestLength, 0.0, 0.0);
  x_eq.col(1) = Vec3(0.5 * TwoParticleSpring::kRestLength, 0.0, 0.0);
  return std::make_unique<LinearSystem>(world, x_eq);
}

}  // namespace jelly
