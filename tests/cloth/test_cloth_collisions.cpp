// The impulse response of a cloth world (cloth contract §4; decisions 1, 2, 7, 8, 11): the pairs'
// order, head-on spheres, kinematic spheres, friction and push-out.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cloth_worlds.hpp"
#include "jelly/a2/collision.hpp"
#include "jelly/a2/friction.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_tasks.hpp"

namespace jelly {
namespace {

using cloth_test::cloth_world;

// A world of spheres only (no cloth particle): n = 0 is impossible, so a 2×2 cloth far away.
std::unique_ptr<World> far_cloth_world(const TaskTable& tasks) {
  auto world = std::make_unique<World>(tasks);
  ClothSpec spec;
  spec.n = 2;
  spec.size = 0.1;
  spec.center = Vec3(0.0, -100.0, 0.0);
  cloth_physics(*world).add_cloth(spec);
  return world;
}

TEST(SpherePairs, EqualSpheresHeadOnAtPlusMinusOneLeaveAtMinusPlusPointEight) {
  auto world = far_cloth_world(a2::task_table());
  SphereSpec a, b;
  a.center = Vec3(-0.5, 0.0, 0.0);
  a.velocity = Vec3(1.0, 0.0, 0.0);
  b.center = Vec3(0.5, 0.0, 0.0);
  b.velocity = Vec3(-1.0, 0.0, 0.0);
  cloth_physics(*world).add_sphere(a);
  cloth_physics(*world).add_sphere(b);
  ClothCollisionSettings c;  // e_sphere 0.8 (decision 10)
  cloth_physics(*world).set_cloth_collisions(c);
  world->apply_collisions(world->state());
  EXPECT_NEAR(cloth_physics(*world).sphere(0).velocity.x(), -0.8, 1e-15);
  EXPECT_NEAR(cloth_physics(*world).sphere(1).velocity.x(), 0.8, 1e-15);
  EXPECT_EQ(cloth_physics(*world).cloth_counters().sphere_pair_tests, 1);
  EXPECT_EQ(world->counters().impulses, 1);
  // Leaving: a second pass does nothing.
  world->apply_collisions(world->state());
  EXPECT_EQ(world->counters().impulses, 1);
  EXPECT_EQ(cloth_physics(*world).kinematic_work(), 0.0);  // no kinematic sphere: no work
}

TEST(SpherePairs, TwoKinematicSpheresPassThroughEachOther) {
  auto world = far_cloth_world(a2::task_table());
  SphereSpec a, b;
  a.kinematic = b.kinematic = true;
  a.schedule = {{0.0, Vec3(1.0, 0.0, 0.0)}};
  b.schedule = {{0.0, Vec3(-1.0, 0.0, 0.0)}};
  a.center = Vec3(-0.5, 0.0, 0.0);
  b.center = Vec3(0.5, 0.0, 0.0);
  cloth_physics(*world).add_sphere(a);
  cloth_physics(*world).add_sphere(b);
  world->begin_step(0, 0.1);
  world->apply_collisions(world->state());
  world->end_step(0.1);
  EXPECT_EQ(cloth_physics(*world).sphere(0).velocity, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(cloth_physics(*world).sphere(1).velocity, Vec3(-1.0, 0.0, 0.0));
  EXPECT_NEAR(cloth_physics(*world).sphere(0).center.x(), -0.4, 1e-15);
  EXPECT_EQ(world->counters().impulses, 0);
}

TEST(SpherePairs, ADynamicSphereBouncesOffAKinematicOneWhoseWorkIsCounted) {
  auto world = far_cloth_world(a2::task_table());
  SphereSpec k, d;
  k.kinematic = true;
  k.schedule = {{0.0, Vec3(1.0, 0.0, 0.0)}};
  k.center = Vec3(-0.5, 0.0, 0.0);
  d.center = Vec3(0.5, 0.0, 0.0);
  d.radius = 0.5;
  cloth_physics(*world).add_sphere(k);
  cloth_physics(*world).add_sphere(d);
  world->begin_step(0, 1e-4);
  world->apply_collisions(world->state());
  // e = 0.8 against an immovable wall moving at +1: the dynamic sphere leaves at 1.8 m/s.
  EXPECT_NEAR(cloth_physics(*world).sphere(1).velocity.x(), 1.8, 1e-15);
  EXPECT_NEAR(cloth_physics(*world).kinematic_work(), 0.5 * 125.0 * 1.8 * 1.8, 1e-10);
}

// Records the order in which the framework offers pairs to the tasks.
std::vector<std::string>* g_log = nullptr;
Impulse logging_particle_sphere(PointBody& p, SphereBody& s, const ImpulseSettings& e) {
  g_log->push_back("p" + std::to_string(static_cast<int>(std::lround(p.position.x() * 10))) + "s" +
                   std::to_string(static_cast<int>(std::lround(s.radius * 100))));
  return a2::collide_particle_sphere(p, s, e);
}
Impulse logging_spheres(SphereBody& a, SphereBody& b, const ImpulseSettings& e) {
  g_log->push_back("s" + std::to_string(static_cast<int>(std::lround(a.radius * 100))) + "s" +
                   std::to_string(static_cast<int>(std::lround(b.radius * 100))));
  return a2::collide_spheres(a, b, e);
}

TEST(ClothCollisions, SphereSpherePairsFirstThenEachSphereOverEveryParticleInIndexOrder) {
  std::vector<std::string> log;
  g_log = &log;
  TaskTable t = a2::task_table();
  cloth_tasks(t).collide_particle_sphere = &logging_particle_sphere;
  cloth_tasks(t).collide_spheres = &logging_spheres;
  auto world = std::make_unique<World>(t);
  ClothSpec spec;
  spec.n = 2;
  spec.size = 1.0;  // particles at x = ±0.5: (0,0) (0,1) at −0.5, (1,0) (1,1) at +0.5
  spec.pin_sets = {};
  cloth_physics(*world).add_cloth(spec);
  for (double r : {1.1, 1.2, 1.3}) {  // every particle within reach of every sphere
    SphereSpec s;
    s.radius = r;
    s.center = Vec3(0.0, -0.2, 0.0);
    cloth_physics(*world).add_sphere(s);
  }
  world->apply_collisions(world->state());
  const std::vector<std::string> expected = {
      "s110s120", "s110s130", "s120s130",            // i < j in scene order
      "p-5s110",  "p-5s110",  "p5s110",   "p5s110",  // sphere 0, particles 0..3
      "p-5s120",  "p-5s120",  "p5s120",   "p5s120", "p-5s130", "p-5s130", "p5s130", "p5s130"};
  EXPECT_EQ(log, expected);
  g_log = nullptr;
}

TEST(ClothCollisions, ParticleMeetingAKinematicSphereWithEZeroLeavesWithItsNormalVelocity) {
  auto world = far_cloth_world(a2::task_table());
  ClothSpec spec;
  auto w = std::make_unique<World>(a2::task_table());
  spec.n = 2;
  spec.size = 2.0;  // particles at (±1, 1.005, ±1)
  spec.center = Vec3(0.0, 1.005, 0.0);
  spec.pin_sets = {};
  spec.velocity = Vec3(0.3, -2.0, 0.1);
  cloth_physics(*w).add_cloth(spec);
  SphereSpec s;
  s.kinematic = true;
  s.center = Vec3(1.0, 0.0, 1.0);  // under particle (1, 1), 1.005 below it
  s.radius = 1.0;
  s.schedule = {{0.0, Vec3(0.0, 0.5, 0.0)}};
  cloth_physics(*w).add_sphere(s);
  w->begin_step(0, 1e-4);
  w->apply_collisions(w->state());
  const Vec3 v = w->state().v.col(3);
  EXPECT_NEAR(v.y(), 0.5, 1e-15);  // the sphere's normal velocity (N = +y here)
  EXPECT_NEAR(v.x(), 0.3, 1e-15);  // tangential velocity kept (μ = 0)
  EXPECT_NEAR(v.z(), 0.1, 1e-15);
  EXPECT_EQ(Vec3(w->state().v.col(0)), spec.velocity);  // far from the sphere: untouched
  EXPECT_EQ(cloth_physics(*w).sphere(0).velocity, Vec3(0.0, 0.5, 0.0));
  EXPECT_NEAR(cloth_physics(*w).kinematic_work(), 0.5 * (0.5 * 0.5 - 2.0 * 2.0), 1e-12);
}

TEST(ClothCollisions, FrictionSlowsButNeverReversesTheSliding) {
  for (double mu : {0.1, 0.5, 10.0}) {
    auto w = std::make_unique<World>(a2::task_table());
    ClothSpec spec;
    spec.n = 2;
    spec.size = 2.0;
    spec.center = Vec3(0.0, 1.005, 0.0);
    spec.pin_sets = {};
    spec.velocity = Vec3(0.3, -2.0, 0.0);
    cloth_physics(*w).add_cloth(spec);
    SphereSpec s;
    s.kinematic = true;
    s.center = Vec3(1.0, 0.0, 1.0);
    s.radius = 1.0;
    cloth_physics(*w).add_sphere(s);
    ClothCollisionSettings c;
    c.friction = mu;
    cloth_physics(*w).set_cloth_collisions(c);
    w->begin_step(0, 1e-4);
    w->apply_collisions(w->state());
    const Vec3 v = w->state().v.col(3);
    EXPECT_GE(v.x(), 0.0) << "μ = " << mu;
    EXPECT_LT(v.x(), 0.3) << "μ = " << mu;
    EXPECT_NEAR(v.x(), std::max(0.0, 0.3 - mu * 2.0), 1e-15) << "μ = " << mu;
    EXPECT_EQ(cloth_physics(*w).cloth_counters().friction_impulses, 1);
  }
}

TEST(ClothCollisions, PushOutMovesFreeParticlesOutAndNeverAPinOrASphere) {
  auto w = std::make_unique<World>(a2::task_table());
  ClothSpec spec;
  spec.n = 3;
  spec.size = 1.0;
  spec.center = Vec3(0.0, 0.9, 0.0);  // the middle particle 0.1 inside a unit sphere
  spec.pin_sets = {};
  spec.pins = {{0, 0}};
  cloth_physics(*w).add_cloth(spec);
  SphereSpec s;
  s.center = Vec3(-0.5, 0.0, -0.5);  // under the pinned corner (0, 0): it is inside too
  s.radius = 1.0;
  cloth_physics(*w).add_sphere(s);
  ClothCollisionSettings c;
  c.push_out = 0.5;
  cloth_physics(*w).set_cloth_collisions(c);
  const State before = w->state();
  w->apply_collisions(w->state());
  EXPECT_EQ(Vec3(w->state().x.col(0)), Vec3(before.x.col(0)));  // the pin
  EXPECT_EQ(Vec3(w->state().x.col(9)), Vec3(before.x.col(9)));  // the sphere's centre
  // Particle (1, 0) at (0, 0.9, −0.5): d = (0.5, 0.9, 0), |d| ≈ 1.0296 > 1: outside, untouched.
  // Particle (0, 1) at (−0.5, 0.9, 0): same. Particle (1, 1) at (0, 0.9, 0): |d| ≈ 1.1446.
  // Particle (0, 0) is pinned. Every particle inside moved by β·|φ| along N.
  int moved = 0;
  for (int i = 1; i < 9; ++i) {
    const Vec3 x0 = before.x.col(i), d = x0 - s.center;
    const double phi = d.norm() - 1.0;
    if (phi < 0.0) {
      ++moved;
      EXPECT_LT((Vec3(w->state().x.col(i)) - (x0 - 0.5 * phi * d.normalized())).norm(), 1e-15);
    } else {
      EXPECT_EQ(Vec3(w->state().x.col(i)), x0);
    }
  }
  EXPECT_EQ(cloth_physics(*w).cloth_counters().push_outs, moved);
}

}  // namespace
}  // namespace jelly
