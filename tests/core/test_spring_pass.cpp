// The reference's one-call spring pass (TaskTable::accumulate_spring_groups) must give the same
// bits as accumulate_spring_forces group by group, in the World's group order, for one thread or
// two, with or without springs that fall outside the dense offset runs. The World uses it whenever
// the library provides it, so the grader's reference data and the viewer depend on this.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

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
  const TaskTable t = linked_tasks();
  Fixture fx;
  const double ks[] = {2000.0, 1500.0, 700.0}, kd[] = {60.0, 45.0, 13.0};
  for (int k = 0; k < 3; ++k) {
    SpringGroup g;
    g.type = static_cast<SpringType>(k);
    g.ks = ks[k];
    g.kd = kd[k];
    g.degenerate_length = 1e-12 * cube.spacing();
    if (k == 0) t.add_structural_springs(cube, g.springs);
    if (k == 1) t.add_shear_springs(cube, g.springs);
    if (k == 2) t.add_bending_springs(cube, g.springs);
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
  const TaskTable t = linked_tasks();
  Vec3Array f = fx.f0;
  for (const SpringGroup& g : fx.groups) t.accumulate_spring_forces(g, fx.s, f);
  return f;
}

Vec3Array one_call(const Fixture& fx) {
  const TaskTable t = linked_tasks();
  Vec3Array f = fx.f0;
  t.accumulate_spring_groups(fx.groups.data(), fx.groups.size(), fx.s, f);
  return f;
}

bool same_bits(const Vec3Array& a, const Vec3Array& b) {
  return a.cols() == b.cols() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

TEST(SpringPass, ReferenceProvidesTheOneCallPass) {
  ASSERT_NE(linked_tasks().accumulate_spring_groups, nullptr);
}

TEST(SpringPass, OneCallEqualsGroupByGroupBitForBit) {
  Fixture fx = cube_fixture();
  const Vec3Array expected = group_by_group(fx);
  EXPECT_GT((expected - fx.f0).cwiseAbs().maxCoeff(), 1.0);  // the springs did something
  EXPECT_TRUE(same_bits(one_call(fx), expected));
  // Swapping two groups changes the order of the sums, and so (here) the bits: the test above
  // would see a pass that ignored the group order.
  std::swap(fx.groups[0], fx.groups[2]);
  EXPECT_FALSE(same_bits(one_call(fx), expected));
  EXPECT_TRUE(same_bits(one_call(fx), group_by_group(fx)));
}

TEST(SpringPass, TwoThreadsGiveTheSameBits) {
  Fixture fx = cube_fixture();
  const Vec3Array expected = group_by_group(fx);
  for (SpringGroup& g : fx.groups) g.threads = 2;
  EXPECT_TRUE(same_bits(one_call(fx), expected));
  EXPECT_TRUE(same_bits(group_by_group(fx), expected));
}

TEST(SpringPass, SpringsOutsideTheDenseRunsKeepTheirPlace) {
  Fixture fx = cube_fixture();
  // A duplicate spring and a long sparse one (an offset used once) take the scalar path.
  SpringGroup& shear = fx.groups[1];
  shear.springs.push_back(shear.springs[17]);
  shear.springs.push_back(Spring{3, 996, 1.7});
  shear.task_cache.reset();
  const Vec3Array expected = group_by_group(fx);
  EXPECT_TRUE(same_bits(one_call(fx), expected));
  for (SpringGroup& g : fx.groups) g.threads = 2;
  EXPECT_TRUE(same_bits(one_call(fx), expected));
}

TEST(SpringPass, EmptyGroupsAndNoGroupsAddNothing) {
  Fixture fx = cube_fixture();
  fx.groups[1].springs.clear();
  fx.groups[1].task_cache.reset();
  EXPECT_TRUE(same_bits(one_call(fx), group_by_group(fx)));
  Vec3Array f = fx.f0;
  linked_tasks().accumulate_spring_groups(fx.groups.data(), 0, fx.s, f);
  EXPECT_TRUE(same_bits(f, fx.f0));
}

}  // namespace
}  // namespace jelly
