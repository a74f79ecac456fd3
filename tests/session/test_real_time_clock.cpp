// The viewer's clock with real runs: simulated time follows wall time × factor whatever the frame
// rate, and when stepping is too slow the clock says so.
#include <gtest/gtest.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/session/real_time_clock.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::session {
namespace {

SceneSpec course_scene() {
  SceneResult r = resolve_scene("course-2023", default_scenes_dir());
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.scene : course_2023_scene();
}

// Simulated time follows wall time × factor whatever the frame rate: 1 s of wall time at 60 Hz and
// at 144 Hz reaches the same simulated time (to within one step).
TEST(RealTimeClock, SimulatedTimeDoesNotDependOnTheFrameRate) {
  for (double factor : {0.5, 1.0, 2.0}) {
    double reached[2];
    int k = 0;
    const SceneSpec scene = course_scene();
    for (double hz : {60.0, 144.0}) {
      SimulationRun run(RunSetup::from_scene(scene), a1::task_table());
      RealTimeClock clock;
      clock.factor = factor;
      clock.budget_ms = 1e9;  // this test is about time, not speed
      for (int frame = 0; frame < static_cast<int>(hz * 0.5); ++frame) {  // 0.5 s of wall time
        const double before = run.time();
        run.advance_to(clock.target(before, 1.0 / hz));
        clock.reached(before, run.time(), run.budget_hit());
      }
      EXPECT_FALSE(clock.behind());
      reached[k++] = run.time();
    }
    // Whole steps only: within half a step of the asked time.
    EXPECT_NEAR(reached[0], 0.5 * factor, 0.5 * scene.dt + 1e-12) << factor << "x at 60 Hz";
    EXPECT_NEAR(reached[1], 0.5 * factor, 0.5 * scene.dt + 1e-12) << factor << "x at 144 Hz";
  }
}

// When stepping is slower than real time the clock says so and reports the achieved rate, and
// the debt is dropped instead of growing.
TEST(RealTimeClock, ReportsWhenItCannotKeepUp) {
  SimulationRun run(RunSetup::from_scene(course_scene()), a1::task_table());
  RealTimeClock clock;
  clock.factor = 4.0;
  clock.budget_ms = 0.0;  // one step per frame at most: far below 4× real time at 60 Hz
  for (int frame = 0; frame < 120; ++frame) {
    const double before = run.time();
    run.advance_to(clock.target(before, 1.0 / 60.0), clock.budget_ms);
    clock.reached(before, run.time(), run.budget_hit());
  }
  EXPECT_TRUE(clock.behind());
  EXPECT_NEAR(clock.achieved_factor(), run.setup().dt * 60.0, 1e-9);  // one step per frame
  EXPECT_EQ(run.simulator()->steps(), 120);
}

}  // namespace
}  // namespace jelly::session
