// The reference's spring engine (TaskTable::make_spring_group_pass, solutions/spring_engine.cpp):
// the World uses it whenever the library provides one, so the viewer, the CLI and the grader's
// reference data depend on it. It must apply spring_force + damper_force to every spring (the
// same forces as accumulate_spring_forces group by group, summed in its own fixed order), give the
// same bits for one thread or two, and notice when the springs it has laid out change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_tasks.hpp"
#include "jelly/spring_pass.hpp"
#include "jelly/task_table.hpp"

namespace jelly {
namespace {

struct Fixture {
  std::vector<SpringGroup> groups;
  State s;
  Vec3Array f0;  // what the pass adds to (gravity, in the World)
};

// A 10×10×10 cube (1000 particles: above the reference's threshold for threads) with the three
// spring types at different coefficients, so that the order of the groups shows in the bits.
Fixture cube_fixture() {
  CubeSpec spec;
  spec.n = 10;
  const CubeLattice cube(spec);
  const TaskTable t = a1::task_table();
  Fixture fx;
  const double ks[] = {2000.0, 1500.0, 700.0}, kd[] = {60.0, 45.0, 13.0};
  for (int k = 0; k < 3; ++k) {
    SpringGroup g;
    g.type = static_cast<SpringType>(k);
    g.ks = ks[k];
    g.kd = kd[k];
    g.degenerate_length = degenerate_length_for(cube.spacing());
    if (k == 0) cube_tasks(t).add_structural_springs(cube, g.springs);
    if (k == 1) cube_tasks(t).add_shear_springs(cube, g.springs);
    if (k == 2) cube_tasks(t).add_bending_springs(cube, g.springs);
    fx.groups.push_back(std::move(g));
  }
  fx.s.resize(cube.particle_count());
  fx.s.x = cube.initial_positions();
  fx.f0.resize(3, fx.s.size());
  for (Eigen::Index i = 0; i < fx.s.size(); ++i) {
    fx.s.x.col(i) += 0.01 * Vec3(std::sin(1.0 * i), std::cos(2.0 * i), std::sin(3.0 * i));
    fx.s.v.col(i) = Vec3(std::cos(5.0 * i), std::sin(7.0 * i), std::cos(11.0 * i));
    fx.f0.col(i) = Vec3(0.3 * std::sin(13.0 * i), -9.8, 0.1 * std::cos(17.0 * i));
  }
  return fx;
}

Vec3Array group_by_group(const Fixture& fx) {
  const TaskTable t = a1::task_table();
  Vec3Array f = fx.f0;
  for (const SpringGroup& g : fx.groups)
    accumulate_spring_forces(g, fx.s, f, t.spring_force, t.damper_force);
  return f;
}

std::unique_ptr<SpringGroupPass> new_engine(int threads = 1) {
  auto engine = a1::task_table().make_spring_group_pass();
  engine->set_threads(threads);
  return engine;
}

Vec3Array one_call(const Fixture& fx, SpringGroupPass& engine) {
  Vec3Array f = fx.f0;
  engine.accumulate(fx.groups.data(), fx.groups.size(), fx.s, f);
  return f;
}

Vec3Array fresh_one_call(const Fixture& fx, int threads = 1) {
  return one_call(fx, *new_engine(threads));
}

bool same_bits(const Vec3Array& a, const Vec3Array& b) {
  return a.cols() == b.cols() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// Equal up to the order of the sums: a few ulps of the largest force.
void expect_same_forces(const Vec3Array& a, const Vec3Array& b) {
  ASSERT_EQ(a.cols(), b.cols());
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-13 * b.cwiseAbs().maxCoeff());
}

TEST(SpringPass, ReferenceProvidesAnEngine) {
  ASSERT_NE(a1::task_table().make_spring_group_pass, nullptr);
  EXPECT_NE(a1::task_table().make_spring_group_pass(), nullptr);
}

TEST(SpringPass, EngineGivesTheForcesOfTheProvidedLoop) {
  Fixture fx = cube_fixture();
  const Vec3Array expected = group_by_group(fx);
  EXPECT_GT((expected - fx.f0).cwiseAbs().maxCoeff(), 1.0);  // the springs did something
  expect_same_forces(fresh_one_call(fx), expected);
}

// A lone spring has one term per particle: there the bits must be spring_force + damper_force's.
TEST(SpringPass, LoneSpringHasTheBitsOfTheTaskFunctions) {
  Fixture fx = cube_fixture();
  const TaskTable t = a1::task_table();
  const SpringGroup& shear = fx.groups[1];
  SpringGroup one = shear;
  one.springs = {shear.springs[5]};
  const Spring& sp = one.springs[0];
  Vec3Array f = Vec3Array::Zero(3, fx.s.size());
  new_engine()->accumulate(&one, 1, fx.s, f);
  const Vec3 xa = fx.s.x.col(sp.a), xb = fx.s.x.col(sp.b);
  const Vec3 fa =
      t.spring_force(xa, xb, one.ks, sp.rest_length, one.degenerate_length) +
      t.damper_force(xa, xb, fx.s.v.col(sp.a), fx.s.v.col(sp.b), one.kd, one.degenerate_length);
  EXPECT_GT(fa.norm(), 0.0);
  EXPECT_EQ(f.col(sp.a), fa);
  EXPECT_EQ(f.col(sp.b), -fa);
}

TEST(SpringPass, TwoThreadsGiveTheSameBits) {
  Fixture fx = cube_fixture();
  const Vec3Array one_thread = fresh_one_call(fx);
  EXPECT_TRUE(same_bits(fresh_one_call(fx, 2), one_thread));
  auto engine = new_engine();
  EXPECT_TRUE(same_bits(one_call(fx, *engine), one_thread));
  engine->set_threads(2);
  EXPECT_TRUE(same_bits(one_call(fx, *engine), one_thread));
}

// The engine keeps a layout per group position: groups given in another order must be laid out
// again (the sums then run in the new order, as group by group does).
TEST(SpringPass, GroupsInAnotherOrderAreLaidOutAgain) {
  Fixture fx = cube_fixture();
  auto engine = new_engine();
  const Vec3Array before = one_call(fx, *engine);
  std::swap(fx.groups[0], fx.groups[2]);
  const Vec3Array swapped = one_call(fx, *engine);
  EXPECT_FALSE(same_bits(swapped, before));  // the order of the sums shows in the bits
  EXPECT_TRUE(same_bits(swapped, fresh_one_call(fx)));
  expect_same_forces(swapped, group_by_group(fx));
}

TEST(SpringPass, SpringsOutsideTheDenseRunsKeepTheirPlace) {
  Fixture fx = cube_fixture();
  auto engine = new_engine();
  (void)one_call(fx, *engine);  // laid out before the list grows
  // A duplicate spring and a long sparse one (an offset used once) take the scalar path.
  SpringGroup& shear = fx.groups[1];
  shear.springs.push_back(shear.springs[17]);
  shear.springs.push_back(Spring{3, 996, 1.7});
  const Vec3Array expected = fresh_one_call(fx);
  expect_same_forces(expected, group_by_group(fx));
  EXPECT_FALSE(same_bits(expected, fresh_one_call(cube_fixture())));
  EXPECT_TRUE(same_bits(one_call(fx, *engine), expected));
  EXPECT_TRUE(same_bits(fresh_one_call(fx, 2), expected));
}

// Springs changed in place (same list, same size) are the owner's to announce.
TEST(SpringPass, SpringsChangedInPlaceAreLaidOutAgainWhenAnnounced) {
  Fixture fx = cube_fixture();
  auto engine = new_engine();
  const Vec3Array before = one_call(fx, *engine);
  for (Spring& sp : fx.groups[0].springs) sp.rest_length *= 1.25;
  const Vec3Array expected = fresh_one_call(fx);
  EXPECT_FALSE(same_bits(expected, before));
  engine->springs_changed();
  EXPECT_TRUE(same_bits(one_call(fx, *engine), expected));
}

TEST(SpringPass, EmptyGroupsAndNoGroupsAddNothing) {
  Fixture fx = cube_fixture();
  auto engine = new_engine();
  (void)one_call(fx, *engine);
  fx.groups[1].springs.clear();
  EXPECT_TRUE(same_bits(one_call(fx, *engine), fresh_one_call(fx)));
  expect_same_forces(one_call(fx, *engine), group_by_group(fx));
  Vec3Array f = fx.f0;
  engine->accumulate(fx.groups.data(), 0, fx.s, f);
  EXPECT_TRUE(same_bits(f, fx.f0));
}

}  // namespace
}  // namespace jelly
