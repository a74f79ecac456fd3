// Finite-difference checks (house style §10): the spring force is minus the gradient of the
// spring energy ½ ks (l − rest)², the damper force is linear in v with ∂f/∂v = −kd u uᵀ, and the
// spring Jacobian used by backward Euler matches central differences of the force.
#include <gtest/gtest.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/jacobian.hpp"
#include "jelly/spring_pass.hpp"
#include "jelly/task_table.hpp"

namespace jelly {
namespace {

constexpr double kKs = 2000.0, kKd = 60.0, kRest = 0.5, kDegenerate = 1e-12;

double spring_energy(const Vec3& xa, const Vec3& xb) {
  const double stretch = (xa - xb).norm() - kRest;
  return 0.5 * kKs * stretch * stretch;
}

// Two-particle state with a spring of rest kRest stretched or compressed by `factor`.
State pair_state(double factor) {
  State s;
  s.resize(2);
  s.x.col(0) = Vec3(0.3, -0.2, 0.1);
  s.x.col(1) = s.x.col(0) + factor * kRest * Vec3(0.48, 0.6, 0.64);  // unit direction
  s.v.col(0) = Vec3(0.7, -1.1, 0.4);
  s.v.col(1) = Vec3(-0.2, 0.5, 0.9);
  return s;
}

class ForcesFD : public ::testing::TestWithParam<double> {};

TEST_P(ForcesFD, SpringForceIsMinusEnergyGradient) {
  const State s = pair_state(GetParam());
  const Vec3 f = a1::task_table().spring_force(s.x.col(0), s.x.col(1), kKs, kRest, kDegenerate);
  const double h = 1e-6;
  for (int d = 0; d < 3; ++d) {
    Vec3 plus = s.x.col(0), minus = s.x.col(0);
    plus[d] += h;
    minus[d] -= h;
    const double grad =
        (spring_energy(plus, s.x.col(1)) - spring_energy(minus, s.x.col(1))) / (2 * h);
    EXPECT_NEAR(f[d], -grad, 1e-5 * (1.0 + std::abs(grad))) << "component " << d;
  }
}

TEST_P(ForcesFD, DamperForceMatchesItsVelocityJacobian) {
  const State s = pair_state(GetParam());
  const TaskTable t = a1::task_table();
  const Vec3 u = (s.x.col(0) - s.x.col(1)).normalized();
  const Eigen::Matrix3d dfdv = -kKd * u * u.transpose();
  const double h = 1e-6;
  for (int d = 0; d < 3; ++d) {
    Vec3 plus = s.v.col(0), minus = s.v.col(0);
    plus[d] += h;
    minus[d] -= h;
    const Vec3 fd = (t.damper_force(s.x.col(0), s.x.col(1), plus, s.v.col(1), kKd, kDegenerate) -
                     t.damper_force(s.x.col(0), s.x.col(1), minus, s.v.col(1), kKd, kDegenerate)) /
                    (2 * h);
    EXPECT_TRUE(fd.isApprox(dfdv.col(d), 1e-7))
        << fd.transpose() << " vs " << dfdv.col(d).transpose();
  }
  // And the value itself: −kd ((va − vb)·u) u.
  const Vec3 f = t.damper_force(s.x.col(0), s.x.col(1), s.v.col(0), s.v.col(1), kKd, kDegenerate);
  EXPECT_TRUE(f.isApprox(-kKd * (s.v.col(0) - s.v.col(1)).dot(u) * u, 1e-14));
}

TEST_P(ForcesFD, SpringJacobianMatchesCentralDifferences) {
  const State s = pair_state(GetParam());
  const TaskTable t = a1::task_table();
  SpringGroup g;
  g.ks = kKs;
  g.kd = kKd;
  g.degenerate_length = kDegenerate;
  g.springs.push_back({0, 1, kRest});
  ForceJacobians jac;
  jac.reset(2, {{0, 1}});
  add_spring_jacobians(g, s, {0}, jac);
  const double h = 1e-6;
  Eigen::Matrix3d fd;
  for (int d = 0; d < 3; ++d) {
    Vec3 plus = s.x.col(0), minus = s.x.col(0);
    plus[d] += h;
    minus[d] -= h;
    fd.col(d) = (t.spring_force(plus, s.x.col(1), kKs, kRest, kDegenerate) -
                 t.spring_force(minus, s.x.col(1), kKs, kRest, kDegenerate)) /
                (2 * h);
  }
  const double l = (s.x.col(0) - s.x.col(1)).norm();
  const Vec3 u = (s.x.col(0) - s.x.col(1)) / l;
  const Eigen::Matrix3d transverse = Eigen::Matrix3d::Identity() - u * u.transpose();
  if (l >= kRest) {
    // Stretched: the clamp is inactive and the Jacobian is exact.
    EXPECT_TRUE(jac.dfdx_diag[0].isApprox(fd, 1e-6)) << jac.dfdx_diag[0] << "\nvs FD\n" << fd;
  } else {
    // Compressed: the clamp drops exactly the (negative) transverse term −ks (1 − rest/l)(I − uuᵀ).
    const Eigen::Matrix3d unclamped = fd;
    const Eigen::Matrix3d dropped = -kKs * (1.0 - kRest / l) * transverse;
    EXPECT_TRUE(jac.dfdx_diag[0].isApprox(unclamped - dropped, 1e-6));
  }
  EXPECT_TRUE(jac.dfdx_off[0].isApprox(-jac.dfdx_diag[0], 1e-15));
  EXPECT_TRUE(jac.dfdv_diag[0].isApprox(-kKd * u * u.transpose(), 1e-14));
}

INSTANTIATE_TEST_SUITE_P(StretchedAndCompressed, ForcesFD, ::testing::Values(1.3, 1.0001, 0.6));

TEST(Forces, DegenerateSpringGivesZeroNotNaN) {
  const TaskTable t = a1::task_table();
  const Vec3 x(1.0, 2.0, 3.0);
  const Vec3 f = t.spring_force(x, x, kKs, kRest, 1e-12);
  EXPECT_TRUE(f.allFinite());
  EXPECT_EQ(f, Vec3::Zero());
  const Vec3 g = t.damper_force(x, x + Vec3(1e-14, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), kKd, 1e-12);
  EXPECT_EQ(g, Vec3::Zero());
}

TEST(Forces, NewtonsThirdLawInTheFrameworksSpringPass) {
  const State s = pair_state(1.2);
  SpringGroup g;
  g.ks = kKs;
  g.kd = kKd;
  g.degenerate_length = kDegenerate;
  g.springs.push_back({0, 1, kRest});
  Vec3Array f = Vec3Array::Zero(3, 2);
  const TaskTable t = a1::task_table();
  accumulate_spring_forces(g, s, f, t.spring_force, t.damper_force);
  EXPECT_TRUE((f.col(0) + f.col(1)).isZero(1e-12));
  EXPECT_GT(f.col(0).norm(), 1.0);
}

}  // namespace
}  // namespace jelly
