// The World (framework/core/src/world.cpp): which student function each terrain shape goes to,
// with what, and what the World does with the answer; building springs; forces per evaluation.
// Proven with a task table that records its calls (state of this test file only).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_physics.hpp"
#include "jelly/scene.hpp"
#include "jelly/world.hpp"

namespace jelly {
namespace {

// What the recording table saw: the surface each call was given, and for which particle.
struct Call {
  char shape;   // 'p' plane, 'b' bowl
  Plane plane;  // for 'p'
  Vec3 x;
};
std::vector<Call> g_calls;
bool g_answer = false;  // what every recorded function returns

TaskTable recording_table() {
  g_calls.clear();
  TaskTable t;
  t.collide_plane = [](const Plane& p, const Vec3& x, Vec3& v) {
    g_calls.push_back({'p', p, x});
    if (g_answer) v = Vec3(0.0, 1.0, 0.0);
    return g_answer;
  };
  t.collide_bowl = [](const Bowl&, const Vec3& x, Vec3& v) {
    g_calls.push_back({'b', Plane{}, x});
    if (g_answer) v = Vec3(0.0, 2.0, 0.0);
    return g_answer;
  };
  t.contact_plane = [](const Plane& p, const Vec3& x, const Vec3&, Vec3& f) {
    g_calls.push_back({'p', p, x});
    if (g_answer) f += Vec3(0.0, 3.0, 0.0);
    return g_answer;
  };
  t.contact_bowl = [](const Bowl&, const Vec3& x, const Vec3&, Vec3& f) {
    g_calls.push_back({'b', Plane{}, x});
    if (g_answer) f += Vec3(0.0, 4.0, 0.0);
    return g_answer;
  };
  return t;
}

// Three particles at rest near the surface of the given terrain (so the broad phase runs the pass).
World world_with(Terrain terrain, const Vec3Array& x) {
  World w(recording_table());
  w.add_particles(x, Vec3Array::Zero(3, x.cols()), 2.0);
  w.add_terrain(std::move(terrain));
  return w;
}

Vec3Array points(std::initializer_list<Vec3> list) {
  Vec3Array x(3, static_cast<Eigen::Index>(list.size()));
  Eigen::Index i = 0;
  for (const Vec3& p : list) x.col(i++) = p;
  return x;
}

TEST(World, PlaneGoesToThePlaneFunctionsForEveryParticle) {
  // The course 2021 plane is y = −1.
  const Vec3Array x = points({{0.0, -0.999, 0.0}, {1.0, -0.998, 0.0}, {2.0, -0.5, 0.0}});
  World w = world_with(*terrain_preset("course-2021-plane"), x);
  g_answer = false;
  State s = w.state();
  w.apply_collisions(s);
  ASSERT_EQ(g_calls.size(), 3u);
  for (const Call& c : g_calls) EXPECT_EQ(c.shape, 'p');
  EXPECT_EQ(g_calls[0].plane.normal, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(w.counters().collision_queries[0], 3);
  EXPECT_EQ(w.counters().collisions[0], 0);
  EXPECT_EQ(s.v, w.state().v);  // nothing collided: velocities untouched
}

TEST(World, BowlGoesToTheBowlFunctions) {
  const Terrain bowl = *terrain_preset("course-2023-bowl");
  const Bowl& b = std::get<Bowl>(bowl.shape);
  const Vec3 bottom = b.center - Vec3(0.0, b.radius - 0.001, 0.0);
  World w = world_with(bowl, points({bottom, bottom + Vec3(0.1, 0.0, 0.0)}));
  g_answer = true;
  State s = w.state();
  w.apply_collisions(s);
  ASSERT_EQ(g_calls.size(), 2u);
  EXPECT_EQ(g_calls[0].shape, 'b');
  EXPECT_EQ(g_calls[1].x, bottom + Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(w.counters().collisions[0], 2);
  EXPECT_EQ(s.v.col(0), Vec3(0.0, 2.0, 0.0));  // the function's answer is kept
  EXPECT_EQ(s.v.col(1), Vec3(0.0, 2.0, 0.0));
}

// A sphere obstacle reuses the student's plane functions on its tangent plane at each particle;
// a particle at the centre has no tangent plane and is not asked about.
TEST(World, SphereGoesToThePlaneFunctionsThroughItsTangentPlane) {
  const Terrain sphere = *terrain_preset("course-2021-sphere");  // centre (0, −1, 0), radius 3
  const Vec3 c(0.0, -1.0, 0.0);
  const Vec3 side = c + Vec3(3.001, 0.0, 0.0), top = c + Vec3(0.0, 3.002, 0.0);
  World w = world_with(sphere, points({side, c, top}));
  g_answer = false;
  State s = w.state();
  w.apply_collisions(s);
  ASSERT_EQ(g_calls.size(), 2u);  // not the particle at the centre
  EXPECT_EQ(g_calls[0].shape, 'p');
  EXPECT_EQ(g_calls[0].x, side);
  EXPECT_TRUE(g_calls[0].plane.normal.isApprox(Vec3(1.0, 0.0, 0.0)));
  EXPECT_TRUE(g_calls[0].plane.point.isApprox(c + Vec3(3.0, 0.0, 0.0)));
  EXPECT_FALSE(g_calls[0].plane.has_hole);
  EXPECT_EQ(g_calls[0].plane.surface.friction, std::get<Sphere>(sphere.shape).surface.friction);
  EXPECT_TRUE(g_calls[1].plane.normal.isApprox(Vec3(0.0, 1.0, 0.0)));
  EXPECT_EQ(g_calls[1].x, top);
}

TEST(World, ContactForcesAreAddedOnlyWhereTheFunctionSaysSo) {
  const Vec3Array x = points({{0.0, -0.999, 0.0}, {5.0, -0.995, 0.0}});
  World w = world_with(*terrain_preset("course-2021-plane"), x);  // y = −1
  g_answer = true;
  Vec3Array a;
  w.acceleration(w.state(), a);  // no gravity, no springs: only contact
  ASSERT_EQ(g_calls.size(), 2u);
  EXPECT_EQ(g_calls[0].shape, 'p');
  EXPECT_EQ(w.counters().contacts[0], 2);
  EXPECT_EQ(a.col(0), Vec3(0.0, 1.5, 0.0));  // (0, 3, 0) N / 2 kg
  g_answer = false;
  w.acceleration(w.state(), a);
  EXPECT_EQ(a.col(1), Vec3::Zero());
  EXPECT_EQ(w.counters().contacts[0], 2);
}

TEST(World, BroadPhaseSkipsATerrainFarFromEveryParticle) {
  World w = world_with(*terrain_preset("course-2021-plane"), points({{0.0, 5.0, 0.0}}));
  State s = w.state();
  w.apply_collisions(s);
  Vec3Array a;
  w.acceleration(s, a);
  EXPECT_TRUE(g_calls.empty());
  EXPECT_EQ(w.counters().broadphase_skips[0], 2);
}

TEST(World, CubeSpringsGetTheDegenerateLengthOfTheirSpacing) {
  World w(a1::task_table());
  CubeSpec spec;
  spec.n = 4;
  spec.edge = 3.0;  // spacing 1 m
  cube_physics(w).build_cube_springs(cube_physics(w).add_cube(spec), SpringType::Structural, 2000.0,
                                     60.0);
  ASSERT_EQ(w.spring_groups().size(), 1u);
  EXPECT_EQ(w.spring_groups()[0].degenerate_length, degenerate_length_for(1.0));
  EXPECT_EQ(w.spring_groups()[0].springs.size(), 3u * 4u * 4u * 3u);
}

}  // namespace
}  // namespace jelly
