// The stability estimate and detector of contract §8.
#include <gtest/gtest.h>

#include <cmath>

#include "jelly/a1/task_table.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

namespace jelly {
namespace {

TEST(StabilityEstimate, CourseCubeTopModeMatchesTheContract) {
  auto world = build_world(testing::course_2023(), a1::task_table());
  const StabilityEstimate e = estimate_stability(*world, world->state());
  // Contract §8: ω_max² ≈ 33 600 by power iteration (Gershgorin's bound is 128 000).
  EXPECT_NEAR(e.omega_max * e.omega_max, 33600.0, 0.05 * 33600.0);
  EXPECT_NEAR(e.tau, 60.0 / 2000.0, 1e-6);  // uniform kd/ks
  EXPECT_NEAR(e.zeta_top, 2.75, 0.15);      // "ζ ≈ 3 for the top mode"
  // Explicit Euler: measured stable at 0.0018, blew up at 0.002 on the course code.
  const double ee = e.critical_step(IntegratorKind::ExplicitEuler);
  EXPECT_GT(ee, 0.0018);
  EXPECT_LT(ee, 0.0023);
  // The course's implicit Euler has half of explicit Euler's real interval.
  EXPECT_NEAR(e.critical_step(IntegratorKind::ImplicitEuler), 0.5 * ee, 0.02 * ee);
  // RK4 blew up at 0.0025 (its real-axis interval is 2.785 instead of 2).
  EXPECT_NEAR(e.critical_step(IntegratorKind::RK4), ee * 2.785 / 2.0, 0.03 * ee);
  EXPECT_TRUE(std::isinf(e.critical_step(IntegratorKind::BackwardEuler)));
}

TEST(StabilityEstimate, UndampedSpringHasNoStableExplicitEulerStep) {
  SceneSpec s = testing::free_fall();
  s.structural.kd = s.shear.kd = s.bending.kd = 0.0;
  auto world = build_world(s, a1::task_table());
  const StabilityEstimate e = estimate_stability(*world, world->state());
  EXPECT_EQ(e.critical_step(IntegratorKind::ExplicitEuler), 0.0);
  EXPECT_EQ(e.critical_step(IntegratorKind::Midpoint), 0.0);
  // The course's implicit Euler keeps |hω| ≤ 1 of the imaginary axis (|1 + iy − y²|² = 1 − y² +
  // y⁴).
  EXPECT_NEAR(e.critical_step(IntegratorKind::ImplicitEuler) * e.omega_max, 1.0, 1e-12);
  // RK4 on the imaginary axis: h ω ≤ 2√2; symplectic Euler: h ω < 2.
  EXPECT_NEAR(e.critical_step(IntegratorKind::RK4) * e.omega_max, 2.0 * std::sqrt(2.0), 0.01);
  EXPECT_NEAR(e.critical_step(IntegratorKind::SymplecticEuler) * e.omega_max, 2.0, 0.01);
}

TEST(StabilityMonitor, ExplicitEulerFreeFallDriftDoesNotTripIt) {
  Simulator sim(build_world(testing::free_fall(), a1::task_table()),
                {IntegratorKind::ExplicitEuler, 0.001});
  Simulator fresh(build_world(testing::free_fall(), a1::task_table()),
                  {IntegratorKind::ExplicitEuler, 0.001});
  const double e0 = fresh.energy().total();
  EXPECT_EQ(sim.run_until(1.0), StepResult::Ok);
  // Contract §8: ½ g² h² N per unit mass (N = 1000 steps), 0.036 % of E0 here: below the margin.
  const double drift = sim.energy().total() - e0;
  EXPECT_NEAR(drift, 0.5 * 9.8 * 9.8 * 1e-6 * 1000 * 1000.0, 1e-6 * e0);
  EXPECT_LT(drift, 0.01 * e0);
}

TEST(StabilityMonitor, ExplicitEulerBeyondItsLimitIsStoppedQuickly) {
  // h = 0.0025 is beyond explicit Euler's limit (≈ 0.0021 s); the run must stop in free fall,
  // before the cube reaches the floor at ≈ 1.4 s (growth starts from rounding noise).
  Simulator sim(build_world(testing::free_fall(), a1::task_table()),
                {IntegratorKind::ExplicitEuler, 0.0025});
  ASSERT_EQ(sim.run_until(1.0), StepResult::Unstable);
  EXPECT_LT(sim.instability()->time, 1.0);
  EXPECT_LT(sim.instability()->recommended_step, 0.0025);
  EXPECT_GT(sim.instability()->recommended_step, 0.0005);
  // Refuses to step once unstable.
  const long steps = sim.steps();
  EXPECT_EQ(sim.step(), StepResult::Unstable);
  EXPECT_EQ(sim.steps(), steps);
}

TEST(StabilityMonitor, FlagsNonFiniteState) {
  StabilityMonitor m;
  m.start(100.0);
  EXPECT_FALSE(m.check(100.0, true));
  EXPECT_TRUE(m.check(100.0, false));
  EXPECT_TRUE(m.check(std::nan(""), true));
}

TEST(StabilityMonitor, FlagsEnergyAboveItsStartPlusMargin) {
  StabilityMonitor m;
  m.start(100.0);
  EXPECT_FALSE(m.check(100.9, true));
  EXPECT_TRUE(m.check(101.1, true));
}

TEST(StabilityMonitor, FlagsExponentialGrowthBelowTheMargin) {
  StabilityMonitor m;
  m.start(1000.0);
  std::optional<std::string> r;
  double e = 1000.0, inc = 1e-3;
  for (int k = 0; k < 12 && !r; ++k) {
    e += inc;
    inc *= 1.5;
    r = m.check(e, true);
  }
  ASSERT_TRUE(r.has_value());
  EXPECT_NE(r->find("exponentially"), std::string::npos);
  EXPECT_LT(e, 1010.0);  // caught before the 1 % margin
}

TEST(StabilityMonitor, LinearDriftIsNotExponential) {
  StabilityMonitor m;
  m.start(1000.0);
  for (int k = 1; k < 100; ++k) EXPECT_FALSE(m.check(1000.0 + 1e-3 * k, true));
}

}  // namespace
}  // namespace jelly
