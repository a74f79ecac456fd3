// The viewer's runs honour simulation.auto_dt as `jelly run --auto-dt` does: the step comes from
// the stability estimate (capped by the scene's dt), and the run says what it chose.
#include <gtest/gtest.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::session {
namespace {

SceneSpec stiff_scene(bool auto_dt) {
  SceneSpec s = course_2023_scene();
  cube_spec(s).n = 4;
  for (SpringSettings* sp : {&s.structural, &s.shear, &s.bending}) sp->ks = 1e5;
  s.integrator = IntegratorKind::ExplicitEuler;
  s.dt = 0.005;  // far above explicit Euler's limit for ks = 1e5
  s.auto_dt = auto_dt;
  return s;
}

TEST(SessionAutoStep, FixedStepWithoutAutoDt) {
  SimulationRun run(RunSetup::from_scene(stiff_scene(false)), a1::task_table());
  ASSERT_TRUE(run.ok()) << run.error();
  EXPECT_FALSE(run.auto_step().has_value());
  EXPECT_EQ(run.step(), 0.005);
}

TEST(SessionAutoStep, AutoDtChoosesTheEstimatedStableStepAndRunsStable) {
  const SceneSpec scene = stiff_scene(true);
  SimulationRun run(RunSetup::from_scene(scene), a1::task_table());
  ASSERT_TRUE(run.ok()) << run.error();
  ASSERT_TRUE(run.auto_step().has_value());
  const AutoStep& a = *run.auto_step();
  EXPECT_EQ(run.step(), a.chosen_h);
  EXPECT_LT(a.chosen_h, 0.005);
  EXPECT_LE(a.chosen_h, a.recommended_step);
  EXPECT_NE(a.message().find("auto step"), std::string::npos);
#if !JELLY_SESSION_WITH_SOLUTIONS
  GTEST_SKIP() << "the stability half needs the reference's forces (a student release has stubs)";
#endif
  run.advance_to(0.2);
  EXPECT_FALSE(run.unstable());
  EXPECT_NEAR(run.time(), 0.2, a.chosen_h);
  // The same scene at its fixed step blows up: the automatic step is what kept it stable.
  SimulationRun fixed(RunSetup::from_scene(stiff_scene(false)), a1::task_table());
  fixed.advance_to(1.0);
  EXPECT_TRUE(fixed.unstable());
}

}  // namespace
}  // namespace jelly::session
