// Contract §7: only what the scene calls for is simulated. Proven with the world's effect counters
// and with a task table wrapped to count calls — not with timings.
#include <gtest/gtest.h>

#include <atomic>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/cube_tasks.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

namespace jelly {
namespace {

// Call counts of a wrapped task table (a test-only recording pipeline).
struct Calls {
  long structural = 0, shear = 0, bending = 0, spring_force = 0, collide_plane = 0,
       collide_bowl = 0, contact_plane = 0, contact_bowl = 0;
};
Calls g_calls;
TaskTable g_inner;

TaskTable counting_table() {
  g_inner = a1::task_table();
  g_calls = {};
  TaskTable t = g_inner;
  cube_tasks(t).add_structural_springs = [](const CubeLattice& c, std::vector<Spring>& o) {
    ++g_calls.structural;
    cube_tasks(g_inner).add_structural_springs(c, o);
  };
  cube_tasks(t).add_shear_springs = [](const CubeLattice& c, std::vector<Spring>& o) {
    ++g_calls.shear;
    cube_tasks(g_inner).add_shear_springs(c, o);
  };
  cube_tasks(t).add_bending_springs = [](const CubeLattice& c, std::vector<Spring>& o) {
    ++g_calls.bending;
    cube_tasks(g_inner).add_bending_springs(c, o);
  };
  t.spring_force = [](const Vec3& xa, const Vec3& xb, double ks, double rest, double degenerate) {
    ++g_calls.spring_force;
    return g_inner.spring_force(xa, xb, ks, rest, degenerate);
  };
  t.make_spring_group_pass = nullptr;  // count group by group (the engine gives the same forces)
  t.collide_plane = [](const Plane& p, const Vec3& x, Vec3& v) {
    ++g_calls.collide_plane;
    return g_inner.collide_plane(p, x, v);
  };
  t.collide_bowl = [](const Bowl& b, const Vec3& x, Vec3& v) {
    ++g_calls.collide_bowl;
    return g_inner.collide_bowl(b, x, v);
  };
  t.contact_plane = [](const Plane& p, const Vec3& x, const Vec3& v, Vec3& f) {
    ++g_calls.contact_plane;
    return g_inner.contact_plane(p, x, v, f);
  };
  t.contact_bowl = [](const Bowl& b, const Vec3& x, const Vec3& v, Vec3& f) {
    ++g_calls.contact_bowl;
    return g_inner.contact_bowl(b, x, v, f);
  };
  return t;
}

TEST(Effects, StructuralOnlyCubeBuildsAndEvaluatesOnlyStructuralSprings) {
  SceneSpec scene = testing::free_fall();
  scene.shear.enabled = false;
  scene.bending.enabled = false;
  Simulator sim(build_world(scene, counting_table()), {IntegratorKind::RK4, 0.001});
  EXPECT_EQ(g_calls.structural, 1);
  EXPECT_EQ(g_calls.shear, 0);
  EXPECT_EQ(g_calls.bending, 0);
  EXPECT_EQ(sim.world().spring_count(), 2700u);
  sim.run_until(0.01);
  const EffectCounters& c = sim.world().counters();
  EXPECT_EQ(c.acceleration_evaluations, 40);  // 10 RK4 steps
  EXPECT_EQ(c.spring_group_evaluations[static_cast<int>(SpringType::Structural)], 40);
  EXPECT_EQ(c.spring_group_evaluations[static_cast<int>(SpringType::Shear)], 0);
  EXPECT_EQ(c.spring_group_evaluations[static_cast<int>(SpringType::Bending)], 0);
  EXPECT_EQ(c.springs_evaluated, 40 * 2700);
  EXPECT_EQ(g_calls.spring_force, 40 * 2700);  // the framework's pass: once per spring
}

TEST(Effects, NoTerrainMeansNoCollisionOrContactPass) {
  Simulator sim(build_world(testing::free_fall(), counting_table()),
                {IntegratorKind::Midpoint, 0.001});
  sim.run_until(0.05);
  const EffectCounters& c = sim.world().counters();
  EXPECT_EQ(c.collision_passes, 0);
  EXPECT_TRUE(c.collision_queries.empty());
  EXPECT_EQ(
      g_calls.collide_plane + g_calls.collide_bowl + g_calls.contact_plane + g_calls.contact_bowl,
      0);
  EXPECT_EQ(c.gravity_applications, c.acceleration_evaluations);
}

TEST(Effects, NoGravityMeansNoGravityTerm) {
  SceneSpec scene = testing::free_fall();
  scene.gravity.reset();
  Simulator sim(build_world(scene, counting_table()), {IntegratorKind::ExplicitEuler, 0.001});
  sim.run_until(0.05);
  EXPECT_EQ(sim.world().counters().gravity_applications, 0);
  EXPECT_GT(sim.world().counters().acceleration_evaluations, 0);
  // Nothing moves: no gravity, springs at rest.
  EXPECT_NEAR(sim.state().x.row(1).mean(), 11.0, 1e-12);
}

TEST(Effects, TerrainWithCollisionOffIsNeverAskedForCollision) {
  SceneSpec scene = testing::course_2023();
  cube_spec(scene).center =
      Vec3(-6.0, 2.05, 0.0);  // resting just above the floor, outside the hole
  scene.terrains[0].collision = false;
  scene.terrains[1].contact = false;
  Simulator sim(build_world(scene, counting_table()), {IntegratorKind::ExplicitEuler, 0.001});
  sim.run_until(0.2);
  EXPECT_EQ(g_calls.collide_plane, 0);
  EXPECT_GT(g_calls.contact_plane, 0);
  EXPECT_EQ(g_calls.contact_bowl, 0);
}

TEST(Effects, BroadPhaseSkipsTerrainsTheCubeCannotTouch) {
  // In free fall above the floor no particle is within ε of any terrain: nothing is queried.
  Simulator sim(build_world(testing::course_2023(), counting_table()),
                {IntegratorKind::ExplicitEuler, 0.001});
  sim.run_until(0.1);
  const EffectCounters& c = sim.world().counters();
  EXPECT_EQ(c.collision_queries[0] + c.collision_queries[1], 0);
  EXPECT_EQ(c.contact_queries[0] + c.contact_queries[1], 0);
  EXPECT_GT(c.broadphase_skips[0], 0);
  EXPECT_EQ(g_calls.collide_plane + g_calls.contact_plane, 0);
}

}  // namespace
}  // namespace jelly
