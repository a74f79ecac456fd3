// Issue 20: a step of a cloth world allocates nothing either, once warmed up: cloth-2022 with its
// spheres on the cloth (impulses every step) and cloth-2024 with its driven sphere, under the
// four course integrators and the framework's symplectic Euler, detector on. Its own binary: it
// runs A2's reference (tests/alloc/test_no_allocation.cpp runs A1's).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "counting_malloc.hpp"
#include "jelly/a2/task_table.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/simulator.hpp"

namespace jelly {
namespace {

using testing::allocation_counting_available;
using testing::start_counting_allocations;
using testing::stop_counting_allocations;

// cloth-2022 (year 2022) or cloth-2024 with the scenes' settings, built in code.
std::unique_ptr<World> cloth_scene(int year) {
  auto world = std::make_unique<World>(a2::task_table());
  ClothSpec spec;
  spec.center = Vec3(0.0, year == 2022 ? 0.0 : 1.0, 0.0);
  spec.air_drag = 3.4e-4;
  cloth_physics(*world).add_cloth(spec);
  for (SpringType t : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
    cloth_physics(*world).build_cloth_springs(0, t, year == 2022 ? 25000.0 : 20000.0, 750.0);
  world->set_gravity(Vec3(0.0, -9.8, 0.0));
  if (year == 2022) {
    for (double x : {-0.75, 0.75})
      for (double z : {-0.75, 0.75}) {
        SphereSpec s;
        s.center = Vec3(x, 1.0, z);
        s.radius = 0.5;
        cloth_physics(*world).add_sphere(s);
      }
  } else {
    SphereSpec s;
    s.kinematic = true;
    s.radius = 1.0;
    s.schedule = {{0.0, Vec3::Zero()}, {0.5, Vec3(2.0, 0.0, 0.0)}};
    cloth_physics(*world).add_sphere(s);
  }
  ClothCollisionSettings c;
  c.friction = 0.3;  // the bonus's friction and push-out too
  c.push_out = 0.5;
  cloth_physics(*world).set_cloth_collisions(c);
  return world;
}

class NoAllocationPerClothStep : public ::testing::TestWithParam<std::tuple<int, IntegratorKind>> {
};

TEST_P(NoAllocationPerClothStep, WithTheSpheresOnTheCloth) {
  if (!allocation_counting_available()) GTEST_SKIP() << "needs glibc";
  const auto [year, kind] = GetParam();
  Simulator sim(cloth_scene(year), Simulator::Options(kind, 1e-4));
  // cloth-2022: the spheres are on the cloth by 0.7 s; cloth-2024 touches from the start and
  // its sphere moves from 0.5 s.
  ASSERT_EQ(sim.run_until(year == 2022 ? 0.7 : 0.5), StepResult::Ok);
  const auto impulses = sim.world().counters().impulses;
  start_counting_allocations();
  for (int k = 0; k < 200; ++k)
    if (sim.step() != StepResult::Ok) break;
  const long allocations = stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(sim.world().counters().impulses, impulses);  // the response was at work
}

INSTANTIATE_TEST_SUITE_P(
    Cloth, NoAllocationPerClothStep,
    ::testing::Combine(::testing::Values(2022, 2024),
                       ::testing::Values(IntegratorKind::ExplicitEuler,
                                         IntegratorKind::ImplicitEuler, IntegratorKind::Midpoint,
                                         IntegratorKind::RK4, IntegratorKind::SymplecticEuler)),
    [](const ::testing::TestParamInfo<std::tuple<int, IntegratorKind>>& p) {
      return "cloth_" + std::to_string(std::get<0>(p.param)) + "_" +
             std::string(to_string(std::get<1>(p.param)));
    });

}  // namespace
}  // namespace jelly
