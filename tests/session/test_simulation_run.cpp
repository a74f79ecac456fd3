// A run as the viewer and `jelly render` hold it: its history for the plots, and the front end's
// per-world data (the renderer's draw proxies), dropped whenever the run rebuilds its world.
#include <gtest/gtest.h>

#include <memory>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::session {
namespace {

SceneSpec small_scene() {
  SceneSpec s = course_2023_scene();
  cube_spec(s).n = 3;
  return s;
}

TEST(RunHistory, SamplesEnergyHeightAndCost) {
  SimulationRun run(RunSetup::from_scene(small_scene()), a1::task_table());
  run.advance_to(0.2);
  ASSERT_GE(run.history().size(), 2u);
  EXPECT_DOUBLE_EQ(run.history().front().time, 0.0);
  EXPECT_NEAR(run.history().back().time, 0.2, 1e-9);
  EXPECT_NEAR(run.history().front().com_height, cube_spec(run.setup().scene).center.y(), 1e-9);
  EXPECT_GT(run.ms_per_step(), 0.0);
}

/// Counts how many are alive, to see the run drop them.
struct CountedAttachment : RunAttachment {
  explicit CountedAttachment(int& alive) : alive_(alive) { ++alive_; }
  ~CountedAttachment() override { --alive_; }
  int& alive_;
};

TEST(RunAttachment, KeptUntilTheWorldIsRebuilt) {
  SimulationRun run(RunSetup::from_scene(small_scene()), a1::task_table());
  ASSERT_TRUE(run.ok()) << run.error();
  EXPECT_EQ(run.attachment(), nullptr);
  int alive = 0;
  run.attach(std::make_unique<CountedAttachment>(alive));
  ASSERT_NE(run.attachment(), nullptr);
  run.advance_to(0.01);  // stepping keeps it: the world is the same
  EXPECT_EQ(alive, 1);
  run.reset();  // a new world: the proxies of the old one must go
  EXPECT_EQ(run.attachment(), nullptr);
  EXPECT_EQ(alive, 0);
  run.attach(std::make_unique<CountedAttachment>(alive));
  RunSetup other = run.setup();
  other.integrator = IntegratorKind::RK4;
  run.reset(other);
  EXPECT_EQ(alive, 0);
}

}  // namespace
}  // namespace jelly::session
