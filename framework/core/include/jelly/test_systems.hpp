// Framework-provided systems to step integrators on without any student force code: a free
// particle and linear spring networks (the two-particle spring, a linearised lattice). The grader
// tests integrators on these, so a bug in a student's springs cannot fail an integrator test.
#pragma once

#include <memory>

#include "jelly/jacobian.hpp"
#include "jelly/world.hpp"

namespace jelly {

/// Particles under constant acceleration g and nothing else (contract §9 free fall).
class FreeFallSystem : public JacobianSystem {
 public:
  FreeFallSystem(Eigen::Index particles, const Vec3& g, double mass = 1.0);
  void acceleration(const State& s, Vec3Array& a) override;
  Eigen::Index particle_count() const override { return mass_.size(); }
  const Eigen::VectorXd& masses() const override { return mass_; }
  std::vector<std::pair<int, int>> jacobian_pattern() const override { return {}; }
  void force_jacobians(const State& s, ForceJacobians& jac) override;

 private:
  Vec3 g_;
  Eigen::VectorXd mass_;
};

/// A linear spring network: f = m g − K (x − x_eq) − C v with constant block matrices K and C
/// (the negated Jacobians of a World's springs at an equilibrium configuration x_eq). Exact for a
/// two-particle spring moving along its axis; the small-motion model of a lattice.
class LinearSystem : public JacobianSystem {
 public:
  /// Linearises `world`'s springs at configuration x_eq (springs at rest there), with the world's
  /// masses and gravity; terrains are ignored (linear systems are contact-free).
  LinearSystem(World& world, const Vec3Array& x_eq);
  void acceleration(const State& s, Vec3Array& a) override;
  Eigen::Index particle_count() const override { return mass_.size(); }
  const Eigen::VectorXd& masses() const override { return mass_; }
  std::vector<std::pair<int, int>> jacobian_pattern() const override { return jac_.pairs; }
  void force_jacobians(const State& s, ForceJacobians& jac) override;
  /// Energy ½ Σ m v² + ½ (x−x_eq)ᵀ K (x−x_eq) − Σ m g·(x − x_eq) [J].
  double energy(const State& s) const;

 private:
  ForceJacobians jac_;  // dfdx = −K, dfdv = −C
  Vec3Array x_eq_;
  Eigen::VectorXd mass_;
  Vec3 g_ = Vec3::Zero();
  Vec3Array tmp_, tmp2_;
};

/// The two-particle spring of contract §9: two unit masses on the x axis, ks = 10, kd = 0, rest
/// length 1, stretched by `stretch`, no gravity, no terrain. Exact solution
/// l(t) = 1 + stretch · cos(√20 t). Returned as a World (student springs) scene-free.
struct TwoParticleSpring {
  static constexpr double kStiffness = 10.0;
  static constexpr double kRestLength = 1.0;
  /// Initial state: particle 0 at (−l0/2, 0, 0), particle 1 at (+l0/2, 0, 0), at rest.
  static State initial_state(double stretch = 0.1);
  /// Exact spring length at time t.
  static double exact_length(double t, double stretch = 0.1);
  /// Exact position of particle 1 (x component) at time t.
  static double exact_x1(double t, double stretch = 0.1);
};

/// The linear two-particle spring as a LinearSystem (no student code involved).
std::unique_ptr<LinearSystem> make_linear_two_particle_spring(double stretch = 0.1);

}  // namespace jelly
