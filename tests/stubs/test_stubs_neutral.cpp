// The student stubs fail softly (style §7): every stub returns its neutral value, and the course
// scene runs with them from day one (the jelly falls through the floor without crashing).
// Linked with jelly::tasks_assignments; also runs in a student release.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "jelly/a1/collision.hpp"
#include "jelly/a1/contact.hpp"
#include "jelly/a1/forces.hpp"
#include "jelly/a1/integrators.hpp"
#include "jelly/a1/springs.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"
#include "jelly/spring_pass.hpp"
#include "jelly/test_systems.hpp"

namespace jelly {
namespace {

// The course's 2023 scene, built in code (jelly::course_2023_scene) so that this test needs neither
// scene files nor the loader; stepped with the framework's symplectic Euler (the scenes' default).
SceneSpec course_scene() { return course_2023_scene(); }

// An entry the builders must leave alone: they append, never clear or overwrite.
const Spring kSentinel{7, 11, 0.25};

// A1.T1–A1.T3: the stubs add no spring (and keep what the vector already held).
TEST(StubsNeutral, A1_T1_T3_SpringBuildersAddNothing) {
  CubeSpec spec;
  spec.n = 4;
  const CubeLattice cube(spec);
  using Builder = void (*)(const CubeLattice&, std::vector<Spring>&);
  const Builder builders[] = {&a1::add_structural_springs, &a1::add_shear_springs,
                              &a1::add_bending_springs};
  for (Builder build : builders) {
    std::vector<Spring> out{kSentinel};
    build(cube, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].a, kSentinel.a);
    EXPECT_EQ(out[0].b, kSentinel.b);
    EXPECT_EQ(out[0].rest_length, kSentinel.rest_length);
  }
}

// A1.T4–A1.T5: zero force, even for a stretched, moving spring.
TEST(StubsNeutral, A1_T4_T5_ForcesAreZero) {
  const Vec3 xa(0.0, 0.0, 0.0), xb(2.0, 0.5, -1.0);
  const Vec3 va(1.0, 2.0, 3.0), vb(-1.0, 0.0, 0.5);
  EXPECT_EQ(a1::spring_force(xa, xb, 2000.0, 1.0, 1e-12), Vec3::Zero());
  EXPECT_EQ(a1::damper_force(xa, xb, va, vb, 60.0, 1e-12), Vec3::Zero());
}

// The provided loop stays provided: with zero task forces it adds nothing to f.
TEST(StubsNeutral, AccumulateAddsNothingWithStubForces) {
  SpringGroup g;
  g.ks = 2000.0;
  g.kd = 60.0;
  g.degenerate_length = 1e-12;
  g.springs.push_back(Spring{0, 1, 1.0});
  State s;
  s.resize(2);
  s.x << 0.0, 3.0, 0.0, 0.0, 0.0, 0.0;
  s.v << 1.0, -1.0, 0.0, 0.0, 0.0, 0.0;
  Vec3Array f = Vec3Array::Constant(3, 2, 0.5);
  accumulate_spring_forces(g, s, f, &a1::spring_force, &a1::damper_force);
  EXPECT_EQ(f, Vec3Array::Constant(3, 2, 0.5));
}

// A1.T6–A1.T9: no collision, no contact: false, and v and f untouched, even for a particle deep in
// the surface and moving into it (where the reference would act).
TEST(StubsNeutral, A1_T6_T9_CollisionAndContactDoNothing) {
  Plane plane;  // y = 0, normal +y, no hole
  Bowl bowl;
  bowl.center = Vec3(0.0, 5.0, 0.0);
  bowl.radius = 5.0;
  bowl.rim_height = 4.0;
  const Vec3 x_plane(0.3, -0.005, 0.2), x_bowl(0.0, 0.0, 0.0);
  const Vec3 v_in(0.5, -2.0, 0.1), f_in(0.0, -9.8, 0.0);

  Vec3 v = v_in;
  EXPECT_FALSE(a1::collide_plane(plane, x_plane, v));
  EXPECT_EQ(v, v_in);
  v = v_in;
  EXPECT_FALSE(a1::collide_bowl(bowl, x_bowl, v));
  EXPECT_EQ(v, v_in);

  Vec3 f = f_in;
  EXPECT_FALSE(a1::contact_plane(plane, x_plane, v_in, f));
  EXPECT_EQ(f, f_in);
  f = f_in;
  EXPECT_FALSE(a1::contact_bowl(bowl, x_bowl, v_in, f));
  EXPECT_EQ(f, f_in);
}

// A1.T10–A1.T13: every integrator stub leaves the state exactly as it was.
TEST(StubsNeutral, A1_T10_T13_IntegratorsLeaveStateUnchanged) {
  FreeFallSystem system(3, Vec3(0.0, -9.8, 0.0));
  State start;
  start.resize(3);
  start.x << 0.0, 1.0, 2.0, 5.0, 6.0, 7.0, -1.0, 0.0, 1.0;
  start.v << 0.5, 0.0, -0.5, 1.0, 2.0, 3.0, 0.0, 0.0, 0.25;
  const StepFunction steps[] = {&a1::explicit_euler_step, &a1::implicit_euler_step,
                                &a1::midpoint_step, &a1::rk4_step};
  for (StepFunction step : steps) {
    State s = start;
    Workspace w;
    w.resize(s.size());
    step(system, s, 0.001, w);
    EXPECT_EQ(s.x, start.x);
    EXPECT_EQ(s.v, start.v);
  }
}

// Day one: the course scene with the stubs and the framework's symplectic Euler builds no spring,
// has no collision, and the jelly falls through the floor in free fall, without NaN or a crash.
TEST(StubsNeutral, CourseSceneFallsThroughTheFloor) {
  const SceneSpec scene = course_scene();
  auto world = build_world(scene, a1::task_table());
  ASSERT_TRUE(world);
  EXPECT_EQ(world->spring_count(), 0u);
  Simulator::Options options;
  options.integrator = scene.integrator;
  options.dt = scene.dt;
  Simulator sim(std::move(world), options);

  const double y0 = sim.state().x.row(1).mean();
  ASSERT_NEAR(y0, 11.0, 1e-9);
  double previous = y0;
  long falling_checks = 0;
  bool fell_below_floor = false;
  // 2 s: free fall from y = 11 crosses y = 0 at t ≈ 1.5 s.
  sim.run_until(2.0, [&](const Simulator& s) {
    if (s.steps() % 100 != 0) return;
    const double y = s.state().x.row(1).mean();
    EXPECT_LT(y, previous) << "centre of mass stopped falling at t = " << s.time();
    previous = y;
    ++falling_checks;
    if (y < 0.0) fell_below_floor = true;
  });
  EXPECT_FALSE(sim.instability().has_value());
  EXPECT_EQ(sim.steps(), 2000);
  EXPECT_EQ(falling_checks, 20);
  EXPECT_TRUE(fell_below_floor);
  EXPECT_TRUE(sim.state().x.allFinite());
  EXPECT_TRUE(sim.state().v.allFinite());
  // Free fall with symplectic Euler: y_N = y_0 + g_y h² N(N+1)/2 (contract §9).
  const double h = scene.dt, n = 2000.0;
  EXPECT_NEAR(previous, y0 - 9.8 * h * h * n * (n + 1.0) / 2.0, 1e-9);
  EXPECT_EQ(sim.world().counters().collisions.at(0), 0);
  EXPECT_EQ(sim.world().counters().collisions.at(1), 0);
}

}  // namespace
}  // namespace jelly
