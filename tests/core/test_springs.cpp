// Spring builder (contract §2): counts per type for n = 2, 3, 10, rest lengths, no spring twice.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_tasks.hpp"
#include "jelly/task_table.hpp"

namespace jelly {
namespace {

struct Counts {
  std::size_t structural, shear, bending;
};

Counts expected(int n) {
  const auto N = static_cast<std::size_t>(n);
  return {3 * N * N * (N - 1), 6 * N * (N - 1) * (N - 1) + 4 * (N - 1) * (N - 1) * (N - 1),
          3 * N * N * (N - 2)};
}

class SpringBuilder : public ::testing::TestWithParam<int> {};

TEST_P(SpringBuilder, CountsMatchTheContract) {
  const int n = GetParam();
  CubeSpec spec;
  spec.n = n;
  const CubeLattice cube(spec);
  const TaskTable t = a1::task_table();
  std::vector<Spring> structural, shear, bending;
  cube_tasks(t).add_structural_springs(cube, structural);
  cube_tasks(t).add_shear_springs(cube, shear);
  cube_tasks(t).add_bending_springs(cube, bending);
  const Counts want = expected(n);
  EXPECT_EQ(structural.size(), want.structural);
  EXPECT_EQ(shear.size(), want.shear);
  EXPECT_EQ(bending.size(), want.bending);
}

TEST_P(SpringBuilder, NoSpringTwiceAndRestLengthsFromGeometry) {
  const int n = GetParam();
  CubeSpec spec;
  spec.n = n;
  spec.rotation_degrees = 30.0;  // rest lengths must come from the actual (rotated) positions
  const CubeLattice cube(spec);
  const double s = cube.spacing();
  const TaskTable t = a1::task_table();
  std::vector<Spring> all;
  cube_tasks(t).add_structural_springs(cube, all);
  cube_tasks(t).add_shear_springs(cube, all);
  cube_tasks(t).add_bending_springs(cube, all);
  std::set<std::pair<int, int>> seen;
  for (const Spring& sp : all) {
    const auto key = std::minmax(sp.a, sp.b);
    EXPECT_TRUE(seen.insert(key).second) << "spring " << sp.a << "-" << sp.b << " built twice";
    const Vec3 xa = cube.initial_positions().col(sp.a), xb = cube.initial_positions().col(sp.b);
    EXPECT_NEAR(sp.rest_length, (xa - xb).norm(), 1e-12);
    // Every rest length is s, s√2, s√3 or 2s.
    const double r = sp.rest_length / s;
    const bool known = std::abs(r - 1.0) < 1e-9 || std::abs(r - std::sqrt(2.0)) < 1e-9 ||
                       std::abs(r - std::sqrt(3.0)) < 1e-9 || std::abs(r - 2.0) < 1e-9;
    EXPECT_TRUE(known) << "rest length " << sp.rest_length << " is not s, s√2, s√3 or 2s";
  }
}

INSTANTIATE_TEST_SUITE_P(Contract, SpringBuilder, ::testing::Values(2, 3, 10));

TEST(SpringBuilder, CourseCubeHas12876Springs) {
  const Counts c = expected(10);
  EXPECT_EQ(c.structural, 2700u);
  EXPECT_EQ(c.shear, 7776u);
  EXPECT_EQ(c.bending, 2400u);
  EXPECT_EQ(c.structural + c.shear + c.bending, 12876u);
}

TEST(CubeLattice, CentredExactlyOnItsCentre) {
  CubeSpec spec;
  spec.center = Vec3(-4.8, 11.0, 0.0);
  const CubeLattice cube(spec);
  const Vec3 mean = cube.initial_positions().rowwise().mean();
  EXPECT_NEAR(mean.x(), -4.8, 1e-12);
  EXPECT_NEAR(mean.y(), 11.0, 1e-12);
  EXPECT_NEAR(mean.z(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(cube.spacing(), 4.0 / 9.0);
  // Index scheme i*n*n + j*n + k, i along x.
  EXPECT_NEAR((cube.position(1, 0, 0) - cube.position(0, 0, 0)).x(), 4.0 / 9.0, 1e-15);
  EXPECT_EQ(cube.index(1, 2, 3), 1 * 100 + 2 * 10 + 3);
}

}  // namespace
}  // namespace jelly
