// Issue 6, "no allocation per step": once a run is warmed up (its buffers sized), a step of any
// integrator on the course scene calls the allocator zero times, in flight and in contact, with the
// stability detector on (the framework's symplectic Euler too). Backward Euler's sparse solve does
// allocate and is not tested here.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "counting_malloc.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/cube_physics.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"

namespace jelly {
namespace {

using testing::allocation_counting_available;
using testing::start_counting_allocations;
using testing::stop_counting_allocations;

// Allocations during `steps` steps, after `warm` steps that size every buffer.
long allocations_per_run(Simulator& sim, int warm, int steps) {
  for (int k = 0; k < warm; ++k) EXPECT_EQ(sim.step(), StepResult::Ok);
  start_counting_allocations();
  for (int k = 0; k < steps; ++k)
    if (sim.step() != StepResult::Ok) break;
  return stop_counting_allocations();
}

TEST(NoAllocation, TheCounterSeesAllocations) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  start_counting_allocations();
  void* volatile p = std::malloc(64);  // volatile: the compiler may not drop the pair
  std::free(p);
  Vec3Array* volatile a = new Vec3Array(3, 100);  // operator new and Eigen's aligned storage
  delete a;
  EXPECT_GE(stop_counting_allocations(), 3);
}

class NoAllocationPerStep : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(NoAllocationPerStep, InFlight) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  SceneSpec scene = course_2023_scene();
  scene.integrator = GetParam();
  Simulator sim(build_world(scene, a1::task_table()), {GetParam(), 0.001});
  EXPECT_EQ(allocations_per_run(sim, 20, 200), 0) << to_string(GetParam());
}

TEST_P(NoAllocationPerStep, InContactWithTheFloorAndTheBowl) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  SceneSpec scene = course_2023_scene();
  scene.integrator = GetParam();
  Simulator sim(build_world(scene, a1::task_table()), {GetParam(), 0.0005});
  ASSERT_EQ(sim.run_until(2.5), StepResult::Ok);  // landed on the floor, tipping into the bowl
  long touches = 0;                               // collision responses and contact forces so far
  for (long c : sim.world().counters().collisions) touches += c;
  for (long c : sim.world().counters().contacts) touches += c;
  ASSERT_GT(touches, 0);
  EXPECT_EQ(allocations_per_run(sim, 0, 200), 0) << to_string(GetParam());
}

INSTANTIATE_TEST_SUITE_P(CourseIntegrators, NoAllocationPerStep,
                         ::testing::Values(IntegratorKind::ExplicitEuler,
                                           IntegratorKind::ImplicitEuler, IntegratorKind::Midpoint,
                                           IntegratorKind::RK4, IntegratorKind::SymplecticEuler),
                         [](const auto& p) { return std::string(to_string(p.param)); });

// Four cubes, twelve spring groups: more groups than any fixed-size table would hold.
TEST(NoAllocation, ManySpringGroupsAllocateNothing) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  auto world = std::make_unique<World>(a1::task_table());
  for (int c = 0; c < 4; ++c) {
    CubeSpec spec;
    spec.n = 5;
    spec.center = Vec3(6.0 * c, 5.0, 0.0);
    const int cube = cube_physics(*world).add_cube(spec);
    for (SpringType type : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
      cube_physics(*world).build_cube_springs(cube, type, 2000.0, 60.0);
  }
  world->set_gravity(Vec3(0.0, -9.8, 0.0));
  ASSERT_EQ(world->spring_groups().size(), 12u);
  Simulator sim(std::move(world), {IntegratorKind::RK4, 0.001});
  EXPECT_EQ(allocations_per_run(sim, 5, 50), 0);
}

TEST(NoAllocation, TwoThreadsAllocateNothingEither) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  SceneSpec scene = course_2023_scene();
  auto world = build_world(scene, a1::task_table());
  world->set_force_threads(2);
  Simulator sim(std::move(world), {IntegratorKind::ExplicitEuler, 0.001});
  EXPECT_EQ(allocations_per_run(sim, 20, 100), 0);
}

}  // namespace
}  // namespace jelly
