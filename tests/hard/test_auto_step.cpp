// The automatic step size (jelly/auto_step.hpp): whole substeps per frame, never above the
// recommended step or the cap, and honest when no step is stable.
#include <gtest/gtest.h>

#include <cmath>

#include "hard_run.hpp"
#include "jelly/auto_step.hpp"

namespace jelly::hard {
namespace {

TEST(AutoStep, WholeSubstepsNeverAboveTheRecommendedStepOrTheCap) {
  const StabilityEstimate e = estimate_for(load_hard_scene("stiff-springs"));
  for (IntegratorKind k : kAllIntegrators) {
    const AutoStep a = choose_step(e, k, 1.0 / 60.0, 0.001);
    SCOPED_TRACE(a.message());
    EXPECT_TRUE(a.stable_step_exists);
    EXPECT_GE(a.substeps_per_frame, 1);
    EXPECT_DOUBLE_EQ(a.chosen_h * a.substeps_per_frame, 1.0 / 60.0);
    EXPECT_LE(a.chosen_h, 0.001);
    EXPECT_LE(a.chosen_h, a.recommended_step * (1.0 + 1e-12));
    // The largest such step: one substep fewer would break a bound.
    if (a.substeps_per_frame > 1) {
      const double coarser = (1.0 / 60.0) / (a.substeps_per_frame - 1);
      EXPECT_TRUE(coarser > 0.001 || coarser > a.recommended_step) << coarser;
    }
    EXPECT_FALSE(a.reason.empty());
  }
  // Stiff springs: explicit Euler's limit is about τ = kd/ks = 6e-4 s, so it needs h ≤ 3e-4.
  const AutoStep ee = choose_step(e, IntegratorKind::ExplicitEuler, 1.0 / 60.0, 0.001);
  EXPECT_NEAR(ee.critical_step, 60.0 / 1e5, 0.05 * 60.0 / 1e5);
  EXPECT_EQ(ee.substeps_per_frame, static_cast<int>(std::ceil((1.0 / 60.0) / ee.recommended_step)));
}

TEST(AutoStep, BackwardEulerKeepsTheCap) {
  const StabilityEstimate e = estimate_for(load_hard_scene("tiny-mass"));
  const AutoStep a = choose_step(e, IntegratorKind::BackwardEuler, 0.02, 0.005);
  EXPECT_TRUE(std::isinf(a.critical_step));
  EXPECT_EQ(a.substeps_per_frame, 4);
  EXPECT_DOUBLE_EQ(a.chosen_h, 0.005);
  const AutoStep big = choose_step(e, IntegratorKind::BackwardEuler, 0.004, 0.005);
  EXPECT_EQ(big.substeps_per_frame, 1);
  EXPECT_DOUBLE_EQ(big.chosen_h, 0.004);
}

TEST(AutoStep, SaysSoWhenNoStepIsStable) {
  // The undamped two-particle spring: explicit Euler and midpoint grow at every step size.
  SceneSpec s = load_hard_scene("hole-edge");
  s.terrains.clear();
  s.gravity.reset();
  s.structural.kd = 0.0;
  const StabilityEstimate e = estimate_for(s);
  for (IntegratorKind k : {IntegratorKind::ExplicitEuler, IntegratorKind::Midpoint}) {
    const AutoStep a = choose_step(e, k, 1.0 / 60.0, 0.001);
    EXPECT_FALSE(a.stable_step_exists);
    EXPECT_LE(a.chosen_h, 0.001);
    EXPECT_NE(a.reason.find("no step size"), std::string::npos) << a.reason;
  }
  const AutoStep rk4 = choose_step(e, IntegratorKind::RK4, 1.0 / 60.0, 0.1);
  EXPECT_TRUE(rk4.stable_step_exists);
  EXPECT_NEAR(rk4.critical_step * e.omega_max, 2.0 * std::sqrt(2.0), 0.01);
}

TEST(AutoStep, RejectsMeaninglessIntervals) {
  const StabilityEstimate e;
  EXPECT_THROW(choose_step(e, IntegratorKind::RK4, 0.0, 0.001), std::invalid_argument);
  EXPECT_THROW(choose_step(e, IntegratorKind::RK4, 1.0 / 60.0, -1.0), std::invalid_argument);
  EXPECT_THROW(choose_step(e, IntegratorKind::RK4, std::nan(""), 0.001), std::invalid_argument);
}

}  // namespace
}  // namespace jelly::hard
