// Integrators against the contract's reference numbers (§9): free fall to 1e-9 and observed
// convergence orders on the two-particle spring.
#include <gtest/gtest.h>

#include <cmath>

#include "jelly/a1/task_table.hpp"
#include "jelly/simulator.hpp"
#include "jelly/test_systems.hpp"
#include "scenes_in_code.hpp"

namespace jelly {
namespace {

double mean_y(const State& s) { return s.x.row(1).mean(); }

// y after N steps of size h from y0 under g = −9.8 (contract §9).
double free_fall_expected(IntegratorKind k, double y0, double h, long n) {
  const double g = -9.8, N = static_cast<double>(n);
  switch (k) {
    case IntegratorKind::ExplicitEuler: return y0 + g * h * h * N * (N - 1) / 2;
    case IntegratorKind::Midpoint:
    case IntegratorKind::RK4: return y0 + g * (N * h) * (N * h) / 2;
    default: return y0 + g * h * h * N * (N + 1) / 2;  // implicit, symplectic, backward Euler
  }
}

class FreeFall : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(FreeFall, CourseCubeMatchesClosedFormAfterHalfASecond) {
  const IntegratorKind kind = GetParam();
  Simulator sim(build_world(testing::free_fall(kind), a1::task_table()), {kind, 0.001});
  const State start = sim.state();
  ASSERT_EQ(sim.run_until(0.5), StepResult::Ok);
  ASSERT_EQ(sim.steps(), 500);
  const double expected = free_fall_expected(kind, 11.0, 0.001, 500);
  EXPECT_NEAR(mean_y(sim.state()), expected, 1e-9);
  // Every particle fell by the same amount, and nothing moved sideways.
  for (Eigen::Index i = 0; i < start.size(); ++i) {
    EXPECT_NEAR(sim.state().x(1, i) - start.x(1, i), expected - 11.0, 1e-9);
    EXPECT_NEAR(sim.state().x(0, i), start.x(0, i), 1e-9);
  }
}

TEST(FreeFall, ContractTableValues) {
  EXPECT_NEAR(free_fall_expected(IntegratorKind::ExplicitEuler, 11, 0.001, 500), 9.77745, 1e-12);
  EXPECT_NEAR(free_fall_expected(IntegratorKind::RK4, 11, 0.001, 500), 9.775, 1e-12);
  EXPECT_NEAR(free_fall_expected(IntegratorKind::ImplicitEuler, 11, 0.001, 500), 9.77255, 1e-12);
}

TEST_P(FreeFall, FreeFallSystemGivesTheSameNumbers) {
  const IntegratorKind kind = GetParam();
  if (kind == IntegratorKind::BackwardEuler)
    GTEST_SKIP() << "backward Euler steps Worlds via the Simulator";
  FreeFallSystem sys(1, Vec3(0.0, -9.8, 0.0));
  State s;
  s.resize(1);
  s.x.col(0) = Vec3(0.0, 11.0, 0.0);
  s.v.setZero();
  Workspace w;
  w.resize(1);
  const TaskTable t = a1::task_table();
  StepFunction step = kind == IntegratorKind::ExplicitEuler   ? t.explicit_euler_step
                      : kind == IntegratorKind::ImplicitEuler ? t.implicit_euler_step
                      : kind == IntegratorKind::Midpoint      ? t.midpoint_step
                      : kind == IntegratorKind::RK4           ? t.rk4_step
                                                              : &symplectic_euler_step;
  for (int n = 0; n < 500; ++n) step(sys, s, 0.001, w);
  EXPECT_NEAR(s.x(1, 0), free_fall_expected(kind, 11.0, 0.001, 500), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, FreeFall, ::testing::ValuesIn(kAllIntegrators),
                         testing::integrator_param_name);

// ---- convergence on the two-particle spring ----

using testing::error_at_one_second;

struct OrderCase {
  IntegratorKind kind;
  double order;
};

class Convergence : public ::testing::TestWithParam<OrderCase> {};

TEST_P(Convergence, ObservedOrderWithinPointThreeOfTheory) {
  const auto [kind, order] = GetParam();
  const double e3 = error_at_one_second(kind, 2.5e-3);
  const double e4 = error_at_one_second(kind, 1.25e-3);
  const double observed = std::log2(e3 / e4);
  EXPECT_NEAR(observed, order, 0.3) << "errors " << e3 << " " << e4;
  // The error also really shrinks from the coarsest step.
  EXPECT_LT(e4, error_at_one_second(kind, 1e-2));
}

INSTANTIATE_TEST_SUITE_P(TwoParticleSpring, Convergence,
                         ::testing::Values(OrderCase{IntegratorKind::ExplicitEuler, 1},
                                           OrderCase{IntegratorKind::ImplicitEuler, 1},
                                           OrderCase{IntegratorKind::Midpoint, 2},
                                           OrderCase{IntegratorKind::RK4, 4},
                                           OrderCase{IntegratorKind::SymplecticEuler, 1},
                                           OrderCase{IntegratorKind::BackwardEuler, 1}),
                         [](const ::testing::TestParamInfo<OrderCase>& p) {
                           return std::string(to_string(p.param.kind));
                         });

TEST(LinearTwoParticleSpring, MatchesTheNonlinearSpringAlongItsAxis) {
  auto lin = make_linear_two_particle_spring(0.1);
  State s = TwoParticleSpring::initial_state(0.1);
  Workspace w;
  w.resize(2);
  for (int n = 0; n < 400; ++n) a1::task_table().rk4_step(*lin, s, 2.5e-3, w);
  EXPECT_NEAR(s.x(0, 1), TwoParticleSpring::exact_x1(1.0), 1e-9);
  EXPECT_NEAR(s.x(0, 0), -TwoParticleSpring::exact_x1(1.0), 1e-9);
}

}  // namespace
}  // namespace jelly
