// The cloth view module's controls without a window (jelly/bodies/cloth/view/cloth_controls.hpp):
// keys 1–4 flip the corner pins of a World built in code, the arrows' drive follows the view and
// moves the first kinematic sphere, S stops it.
#include <gtest/gtest.h>

#include <memory>

#include "jelly/a2/task_table.hpp"
#include "jelly/bodies/cloth/view/cloth_controls.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_scene.hpp"
#include "jelly/render/captions.hpp"
#include "jelly/simulator.hpp"

namespace jelly::cloth_view {
namespace {

using render::caption;
using session::RunSetup;
using session::SimulationRun;

/// A 5×5 cloth (corners pinned) and, when asked, a kinematic sphere below it and a dynamic one.
std::unique_ptr<World> cloth_world(bool spheres) {
  auto w = std::make_unique<World>(a2::task_table());
  ClothSpec c;
  c.n = 5;
  c.size = 1.0;
  cloth_physics(*w).add_cloth(c);
  cloth_physics(*w).build_cloth_springs(0, SpringType::Structural, 100.0, 1.0);
  if (spheres) {
    SphereSpec dynamic;
    dynamic.center = Vec3(0.0, 2.0, 0.0);
    dynamic.radius = 0.2;
    cloth_physics(*w).add_sphere(dynamic);
    SphereSpec kinematic;
    kinematic.kinematic = true;
    kinematic.center = Vec3(0.0, -1.0, 0.0);
    kinematic.radius = 0.3;
    kinematic.schedule = {{0.0, Vec3(0.0, 0.0, 1.0)}};
    cloth_physics(*w).add_sphere(kinematic);
  }
  return w;
}

TEST(ClothControls, CornersAreTheFourGridCornersInKeyOrder) {
  ClothSpec c;
  c.n = 4;
  const ClothGrid grid(c, 7);
  EXPECT_EQ(corner_particle(grid, 0), 7 + 0);   // (0, 0)
  EXPECT_EQ(corner_particle(grid, 1), 7 + 3);   // (0, n−1)
  EXPECT_EQ(corner_particle(grid, 2), 7 + 12);  // (n−1, 0)
  EXPECT_EQ(corner_particle(grid, 3), 7 + 15);  // (n−1, n−1)
}

TEST(ClothControls, PinKeysFlipEachCornerAndOnlyIt) {
  auto w = cloth_world(false);
  const ClothGrid& grid = cloth_physics(*w).cloths().front();
  for (int corner = 0; corner < 4; ++corner) {
    const int p = corner_particle(grid, corner);
    ASSERT_TRUE(cloth_physics(*w).is_pinned(p)) << "the scene pins the corners";
    EXPECT_EQ(toggle_corner_pin(*w, corner), std::optional<bool>(false));
    EXPECT_FALSE(cloth_physics(*w).is_pinned(p));
    for (int other = 0; other < 4; ++other) {
      if (other != corner) {
        EXPECT_TRUE(cloth_physics(*w).is_pinned(corner_particle(grid, other)));
      }
    }
    EXPECT_EQ(toggle_corner_pin(*w, corner), std::optional<bool>(true));
    EXPECT_TRUE(cloth_physics(*w).is_pinned(p));
  }
  EXPECT_FALSE(toggle_corner_pin(*w, 4).has_value());
  EXPECT_FALSE(toggle_corner_pin(*w, -1).has_value());
}

TEST(ClothControls, AFreedCornerFallsAndAPinnedOneStays) {
  Simulator sim(cloth_world(false), Simulator::Options(IntegratorKind::SymplecticEuler, 1e-3));
  sim.world().set_gravity(Vec3(0.0, -9.8, 0.0));
  const ClothGrid& grid = cloth_physics(sim.world()).cloths().front();
  const int freed = corner_particle(grid, 0), kept = corner_particle(grid, 3);
  const Vec3 x_freed = sim.state().x.col(freed), x_kept = sim.state().x.col(kept);
  toggle_corner_pin(sim.world(), 0);
  sim.run_until(0.1);
  EXPECT_LT(sim.state().x(1, freed), x_freed.y() - 0.01);
  EXPECT_EQ(sim.state().x.col(kept), x_kept);  // bitwise: a pinned particle never moves
}

TEST(ClothControls, ArrowsFollowTheViewSnappedToTheAxes) {
  const Vec3 zero = Vec3::Zero();
  // yaw 0: the camera on the +z side looking along −z: up is −z, right is +x.
  EXPECT_EQ(arrow_drive(zero, Arrow::Up, 0.0, 2.0), Vec3(0.0, 0.0, -2.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Down, 0.0, 2.0), Vec3(0.0, 0.0, 2.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Right, 0.0, 2.0), Vec3(2.0, 0.0, 0.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Left, 0.0, 2.0), Vec3(-2.0, 0.0, 0.0));
  // yaw 30 (the default camera) still snaps to the same axes; yaw 90: looking along −x.
  EXPECT_EQ(arrow_drive(zero, Arrow::Up, 30.0, 2.0), Vec3(0.0, 0.0, -2.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Up, 90.0, 2.0), Vec3(-2.0, 0.0, 0.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Right, 90.0, 2.0), Vec3(0.0, 0.0, -2.0));
  // Behind the scene (yaw 180, as the course's camera at z = −10): up is +z, left is +x, as the
  // course's keys were.
  EXPECT_EQ(arrow_drive(zero, Arrow::Up, 180.0, 5.0), Vec3(0.0, 0.0, 5.0));
  EXPECT_EQ(arrow_drive(zero, Arrow::Left, 180.0, 5.0), Vec3(5.0, 0.0, 0.0));
  // A key sets its own component and keeps the other (so Up then Right goes diagonally).
  EXPECT_EQ(arrow_drive(Vec3(0.0, 0.0, -2.0), Arrow::Right, 0.0, 2.0), Vec3(2.0, 0.0, -2.0));
  EXPECT_EQ(arrow_drive(Vec3(2.0, 0.5, -2.0), Arrow::Left, 0.0, 2.0), Vec3(-2.0, 0.5, -2.0));
}

TEST(ClothControls, DriveMovesTheKinematicSphereInsteadOfItsSchedule) {
  Simulator sim(cloth_world(true), Simulator::Options(IntegratorKind::SymplecticEuler, 1e-3));
  World& w = sim.world();
  ASSERT_EQ(first_kinematic_sphere(w), 1);  // the dynamic sphere comes first
  const Vec3 c0 = cloth_physics(w).sphere(1).center;
  sim.run_until(0.1);  // the schedule: +z at 1 m/s
  EXPECT_NEAR((cloth_physics(w).sphere(1).center - c0).z(), 0.1, 1e-9);
  const Vec3 c1 = cloth_physics(w).sphere(1).center;
  ASSERT_TRUE(drive_first_kinematic_sphere(w, Vec3(kDriveSpeed, 0.0, 0.0)));
  sim.run_until(0.2);
  const Vec3 moved = cloth_physics(w).sphere(1).center - c1;
  EXPECT_NEAR(moved.x(), kDriveSpeed * 0.1, 1e-9);
  EXPECT_NEAR(moved.z(), 0.0, 1e-12);
  ASSERT_TRUE(drive_first_kinematic_sphere(w, Vec3::Zero()));  // S
  const Vec3 c2 = cloth_physics(w).sphere(1).center;
  sim.run_until(0.3);
  EXPECT_EQ(cloth_physics(w).sphere(1).center, c2);
}

TEST(ClothControls, NothingToDriveOrPinWithoutACloth) {
  auto plain = cloth_world(false);
  EXPECT_EQ(first_kinematic_sphere(*plain), -1);
  EXPECT_FALSE(drive_first_kinematic_sphere(*plain, Vec3(1.0, 0.0, 0.0)));
  World empty(a2::task_table());
  EXPECT_FALSE(toggle_corner_pin(empty, 0).has_value());
}

// The frame's caption counts the spheres in words that agree with the count (issue 28: "1
// spheres").
TEST(ClothCaption, SaysOneSphereAndTwoSpheres) {
  SceneSpec scene;
  scene.body_kind = kClothKind;
  SphereSpec kinematic;
  kinematic.kinematic = true;
  sphere_specs(scene) = {kinematic};
  const std::string one = caption(RunSetup::from_scene(scene), 0.0);
  EXPECT_NE(one.find("\n1 sphere (1 kinematic)"), std::string::npos) << one;
  sphere_specs(scene).push_back(SphereSpec{});
  const std::string two = caption(RunSetup::from_scene(scene), 0.0);
  EXPECT_NE(two.find("\n2 spheres (1 kinematic)"), std::string::npos) << two;
}

}  // namespace
}  // namespace jelly::cloth_view
