// The course 2023 scene (contract §6, §8): which integrators run 10 s, which end in the bowl, and
// the course's implicit Euler diverging at h = 0.001 (caught and explained) but not at 0.0005.
#include <gtest/gtest.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/recorder.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

namespace jelly {
namespace {

class CourseScene : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(CourseScene, RunsTenSecondsWithoutTheDetectorFiring) {
  const IntegratorKind kind = GetParam();
  Simulator sim(build_world(testing::course_2023(kind), a1::task_table()), {kind, 0.001});
  const StepResult r = sim.run_until(10.0);
  ASSERT_EQ(r, StepResult::Ok) << (sim.instability() ? sim.instability()->message() : "");
  EXPECT_EQ(sim.steps(), 10000);
  const FrameSummary end = summarize(sim.world(), sim.state(), sim.time());
  EXPECT_TRUE(sim.state().x.allFinite());
  if (kind != IntegratorKind::ExplicitEuler) {
    // Midpoint, RK4, symplectic and backward Euler come to rest in the bowl.
    EXPECT_LT(end.com.y(), 0.0) << "centre of mass not in the bowl";
    EXPECT_LT(end.max_speed, 0.25) << "still moving at t = 10 s";
  }
}

INSTANTIATE_TEST_SUITE_P(StableAtOneMillisecond, CourseScene,
                         ::testing::Values(IntegratorKind::ExplicitEuler, IntegratorKind::Midpoint,
                                           IntegratorKind::RK4, IntegratorKind::SymplecticEuler,
                                           IntegratorKind::BackwardEuler),
                         testing::integrator_param_name);

TEST(CourseScene, CourseImplicitEulerDivergesAtOneMillisecondAndTheDetectorSaysWhy) {
  const IntegratorKind kind = IntegratorKind::ImplicitEuler;
  Simulator sim(build_world(testing::course_2023(kind), a1::task_table()), {kind, 0.001});
  const StepResult r = sim.run_until(10.0);
  ASSERT_EQ(r, StepResult::Unstable) << "the course's implicit Euler should diverge at h = 0.001";
  ASSERT_TRUE(sim.instability().has_value());
  const InstabilityReport& rep = *sim.instability();
  EXPECT_EQ(rep.integrator, kind);
  EXPECT_DOUBLE_EQ(rep.step_size, 0.001);
  // Soon after impact (the cube reaches the floor at about 1.4 s), not in free fall.
  EXPECT_GT(rep.time, 1.0);
  EXPECT_LT(rep.time, 4.0);
  // The estimate recommends a smaller step, and at most half of h.
  EXPECT_GT(rep.recommended_step, 0.0);
  EXPECT_LE(rep.recommended_step, 0.0006);
  const std::string text = rep.message();
  EXPECT_NE(text.find("Implicit Euler"), std::string::npos) << text;
  EXPECT_NE(text.find("h = 0.001"), std::string::npos) << text;
  EXPECT_NE(text.find("step"), std::string::npos) << text;
}

TEST(CourseScene, CourseImplicitEulerIsStableAtHalfAMillisecond) {
  const IntegratorKind kind = IntegratorKind::ImplicitEuler;
  Simulator sim(build_world(testing::course_2023(kind, 0.0005), a1::task_table()), {kind, 0.0005});
  const StepResult r = sim.run_until(10.0);
  EXPECT_EQ(r, StepResult::Ok) << (sim.instability() ? sim.instability()->message() : "");
  EXPECT_TRUE(sim.state().x.allFinite());
}

}  // namespace
}  // namespace jelly
