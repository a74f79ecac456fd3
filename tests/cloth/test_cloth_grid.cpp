// The cloth's grid, springs and pins (cloth contract §1, §2, §7; decisions 8, 9).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cloth_worlds.hpp"
#include "jelly/a2/springs.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cube.hpp"

namespace jelly {
namespace {

std::vector<Spring> build(void (*fn)(const ClothGrid&, std::vector<Spring>&), const ClothGrid& g) {
  std::vector<Spring> out;
  fn(g, out);
  return out;
}

TEST(ClothGrid, PositionsAreTheContractsSquareCentredOnC0) {
  ClothSpec spec;
  spec.center = Vec3(0.5, 1.0, -2.0);
  const ClothGrid g(spec, 7);
  EXPECT_EQ(g.n(), 25);
  EXPECT_EQ(g.particle_count(), 625);
  EXPECT_EQ(g.first_index(), 7);
  EXPECT_EQ(g.index(3, 4), 7 + 3 * 25 + 4);
  EXPECT_DOUBLE_EQ(g.spacing(), 1.0 / 6.0);
  for (int i = 0; i < 25; ++i)
    for (int k = 0; k < 25; ++k) {
      const Vec3 expected = spec.center + Vec3(-2.0 + i / 6.0, 0.0, -2.0 + k / 6.0);
      EXPECT_LT((g.position(i, k) - expected).norm(), 1e-15) << i << ", " << k;
    }
  // Centred exactly: the middle particle sits on c0 bit for bit.
  EXPECT_EQ(g.position(12, 12), spec.center);
}

TEST(ClothGrid, NinetyDegreesAboutXMakesAHangingCurtainWithTheCubesRotation) {
  ClothSpec spec;
  spec.n = 5;
  spec.rotation_axis = Vec3(1.0, 0.0, 0.0);
  spec.rotation_degrees = 90.0;
  const ClothGrid g(spec);
  // (i, k) → x along x, z rotated onto y: k = 0 is the top row (decision 8's edge).
  EXPECT_NEAR(g.position(0, 0).y(), 2.0, 1e-15);
  EXPECT_NEAR(g.position(0, 4).y(), -2.0, 1e-15);
  EXPECT_NEAR(g.position(0, 0).z(), 0.0, 1e-15);
  // The same bits as a cube rotated the same way (one shared rotation).
  CubeSpec cube;
  cube.n = 5;
  cube.edge = 4.0;
  cube.center = Vec3::Zero();
  cube.rotation_axis = spec.rotation_axis;
  cube.rotation_degrees = 90.0;
  const CubeLattice lattice(cube);
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 5; ++k)  // the cube's middle layer j = 2 is the cloth's plane
      EXPECT_EQ(g.position(i, k), lattice.initial_positions().col((i * 5 + 2) * 5 + k));
}

TEST(ClothSprings, CountsAndRestLengthsForN25) {
  const ClothGrid g{ClothSpec{}};
  const double s = 1.0 / 6.0;
  const auto structural = build(&a2::add_structural_springs, g);
  const auto shear = build(&a2::add_shear_springs, g);
  const auto bending = build(&a2::add_bending_springs, g);
  EXPECT_EQ(structural.size(), 1200u);
  EXPECT_EQ(shear.size(), 1152u);
  EXPECT_EQ(bending.size(), 1150u);
  for (const Spring& sp : structural) EXPECT_NEAR(sp.rest_length, s, 1e-15 * s);
  for (const Spring& sp : shear)
    EXPECT_NEAR(sp.rest_length, std::sqrt(2.0) * s, 1e-15 * std::sqrt(2.0) * s);
  for (const Spring& sp : bending) EXPECT_NEAR(sp.rest_length, 2.0 * s, 1e-15 * 2.0 * s);
}

TEST(ClothSprings, CountsForN5AndTheWorldBuildsThemThroughTheTable) {
  ClothSpec spec;
  spec.n = 5;
  const auto world = cloth_test::cloth_world(spec, 25000.0, 750.0);
  ASSERT_EQ(world->spring_groups().size(), 3u);
  EXPECT_EQ(world->spring_groups()[0].springs.size(), 40u);
  EXPECT_EQ(world->spring_groups()[1].springs.size(), 32u);
  EXPECT_EQ(world->spring_groups()[2].springs.size(), 30u);
  EXPECT_EQ(world->spring_count(), 102u);
  const double s = 1.0;
  for (const Spring& sp : world->spring_groups()[0].springs)
    EXPECT_NEAR(sp.rest_length, s, 1e-15 * s);
  // Decision 9: within a type by particle index, for each particle in the offsets' order.
  const auto& st = world->spring_groups()[0].springs;
  EXPECT_EQ(st[0].a, 0);
  EXPECT_EQ(st[0].b, 5);  // (1, 0)
  EXPECT_EQ(st[1].a, 0);
  EXPECT_EQ(st[1].b, 1);  // (0, 1)
}

TEST(ClothPins, CornersEdgeAndCoordinatesEachOnceInIndexOrder) {
  ClothSpec spec;
  spec.n = 4;
  EXPECT_EQ(resolve_pins(spec), (std::vector<GridCoord>{{0, 0}, {0, 3}, {3, 0}, {3, 3}}));
  spec.pin_sets = {"edge"};
  spec.pins = {{2, 2}, {1, 0}};
  EXPECT_EQ(resolve_pins(spec), (std::vector<GridCoord>{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {3, 0}}));
  spec.pin_sets = {};
  spec.pins = {};
  EXPECT_TRUE(resolve_pins(spec).empty());
}

TEST(ClothPins, UnknownSetsAndCoordinatesOutsideTheGridAreErrors) {
  ClothSpec spec;
  spec.n = 4;
  spec.pin_sets = {"corner"};
  try {
    resolve_pins(spec);
    FAIL() << "an unknown pin set was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"corner\""), std::string::npos) << e.what();
  }
  spec.pin_sets = {};
  spec.pins = {{4, 0}};
  EXPECT_THROW(resolve_pins(spec), std::invalid_argument);
  spec.pins = {{0, -1}};
  EXPECT_THROW(resolve_pins(spec), std::invalid_argument);
  spec.pins = {};
  spec.n = 1;
  EXPECT_THROW(resolve_pins(spec), std::invalid_argument);
  EXPECT_THROW(ClothGrid{spec}, std::invalid_argument);
}

TEST(ClothPins, PinnedParticlesHaveInverseMassZeroAndStartAtRest) {
  ClothSpec spec;
  spec.n = 5;
  spec.velocity = Vec3(1.0, 2.0, 3.0);
  const auto world = cloth_test::cloth_world(spec, 0.0, 0.0);
  for (int i = 0; i < 25; ++i) {
    const bool corner = i == 0 || i == 4 || i == 20 || i == 24;
    EXPECT_EQ(cloth_physics(*world).is_pinned(i), corner) << i;
    EXPECT_EQ(world->inverse_masses()[i], corner ? 0.0 : 1.0) << i;
    EXPECT_EQ(Vec3(world->state().v.col(i)), corner ? Vec3::Zero() : spec.velocity) << i;
  }
  EXPECT_EQ(cloth_physics(*world).cloth_particle_count(), 25);
}

}  // namespace
}  // namespace jelly
