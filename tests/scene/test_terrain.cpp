// The framework's own terrain geometry (framework/core/src/terrain.cpp,
// jelly/terrain_geometry.hpp): signed distance, normal, extent, lowest point and the broad phase's
// bounds, on the course's terrains (the 2023 floor with its hole, the 2023 bowl) and a sphere. The
// viewer draws with these, the projection effect moves particles with them and the energy is
// measured from lowest_point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "jelly/scene.hpp"
#include "jelly/terrain_geometry.hpp"

namespace jelly {
namespace {

const double kHoleRadius = 9.0 / std::sqrt(2.0);  // course 2023: hole radius = bowl rim radius

Terrain floor_with_hole() { return *terrain_preset("course-2023-floor"); }
Terrain bowl_2023() { return *terrain_preset("course-2023-bowl"); }

TEST(Terrain, PlaneWithHoleHeightAndNormal) {
  const Terrain t = floor_with_hole();
  const Vec3 above(-8.0, 0.75, 3.0), below(10.0, -0.5, -4.0);
  EXPECT_DOUBLE_EQ(signed_distance(t, above), 0.75);
  EXPECT_DOUBLE_EQ(signed_distance(t, below), -0.5);
  EXPECT_EQ(surface_normal(t, above), Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(surface_normal(t, below), Vec3(0.0, 1.0, 0.0));
}

TEST(Terrain, PlaneHoleIsOutsideTheExtentMeasuredInThePlane) {
  const Terrain t = floor_with_hole();
  const Vec3 centre(2.0, 0.0, 1.0);
  EXPECT_FALSE(in_extent(t, centre));
  EXPECT_FALSE(in_extent(t, centre + Vec3(0.0, -5.0, 0.0)));  // height does not count
  EXPECT_FALSE(in_extent(t, centre + Vec3(kHoleRadius * 0.999, 0.3, 0.0)));
  EXPECT_TRUE(in_extent(t, centre + Vec3(0.0, 0.3, kHoleRadius * 1.001)));
  EXPECT_TRUE(in_extent(t, Vec3(-20.0, 0.0, 0.0)));
  Terrain solid = t;
  std::get<Plane>(solid.shape).has_hole = false;
  EXPECT_TRUE(in_extent(solid, centre));
}

TEST(Terrain, LowestPointOnlyForBoundedTerrains) {
  EXPECT_FALSE(lowest_point(floor_with_hole()).has_value());  // particles fall through the hole
  EXPECT_EQ(lowest_point(*terrain_preset("course-2021-plane")), -1.0);
  EXPECT_FALSE(lowest_point(*terrain_preset("course-2021-tilted")).has_value());
  EXPECT_FALSE(lowest_point(*terrain_preset("course-2021-sphere")).has_value());
  EXPECT_DOUBLE_EQ(*lowest_point(bowl_2023()), kHoleRadius - 9.0);
}

TEST(Terrain, BowlHeightAndNormalInsideTheSphere) {
  const Terrain t = bowl_2023();
  const Bowl& b = std::get<Bowl>(t.shape);
  const Vec3 bottom = b.center - Vec3(0.0, b.radius, 0.0);
  EXPECT_NEAR(signed_distance(t, bottom), 0.0, 1e-15);
  EXPECT_NEAR(signed_distance(t, bottom + Vec3(0.0, 0.5, 0.0)), 0.5, 1e-14);  // inside: free side
  EXPECT_NEAR(signed_distance(t, bottom - Vec3(0.0, 0.5, 0.0)), -0.5, 1e-14);
  EXPECT_TRUE(surface_normal(t, bottom).isApprox(Vec3(0.0, 1.0, 0.0), 1e-15));
  // On the wall the normal points at the centre.
  const Vec3 wall = b.center + b.radius * Vec3(1.0, -1.0, 0.0).normalized();
  EXPECT_TRUE(surface_normal(t, wall).isApprox(Vec3(-1.0, 1.0, 0.0).normalized(), 1e-14));
  EXPECT_NEAR(surface_normal(t, wall).norm(), 1.0, 1e-15);
}

TEST(Terrain, BowlExtentIsTheCapBelowTheRim) {
  const Terrain t = bowl_2023();
  const Bowl& b = std::get<Bowl>(t.shape);
  EXPECT_NEAR(b.rim_radius(), kHoleRadius, 1e-12);
  const Vec3 axis(b.center.x(), 0.0, b.center.z());
  EXPECT_TRUE(in_extent(t, axis + Vec3(0.0, -1.0, 0.0)));
  EXPECT_TRUE(in_extent(t, axis + Vec3(0.0, b.surface.epsilon, 0.0)));  // up to ε above the rim
  EXPECT_FALSE(in_extent(t, axis + Vec3(0.0, 2.0 * b.surface.epsilon, 0.0)));
  EXPECT_FALSE(in_extent(t, axis + Vec3(b.rim_radius() * 1.001, -0.1, 0.0)));
  const Vec3 lo(-1.0, 0.5, -1.0), hi(1.0, 2.0, 1.0);
  EXPECT_TRUE(box_outside_extent(t, lo, hi));  // the whole box above the rim
  EXPECT_FALSE(box_outside_extent(t, lo - Vec3(0.0, 1.0, 0.0), hi));
}

TEST(Terrain, SphereObstacleIsFreeOutside) {
  const Terrain t = *terrain_preset("course-2021-sphere");  // centre (0, −1, 0), radius 3
  EXPECT_DOUBLE_EQ(signed_distance(t, Vec3(0.0, 4.0, 0.0)), 2.0);
  EXPECT_DOUBLE_EQ(signed_distance(t, Vec3(0.0, -1.0, 1.0)), -2.0);
  EXPECT_TRUE(surface_normal(t, Vec3(4.0, -1.0, 0.0)).isApprox(Vec3(1.0, 0.0, 0.0)));
  EXPECT_TRUE(in_extent(t, Vec3(100.0, 0.0, 0.0)));
}

// The broad phase may skip a pass only when no point of the box can be closer than its bound:
// the bound must be ≤ φ everywhere in the box and reached at a corner or face point.
TEST(Terrain, MinSignedDistanceBoundsEveryPointOfTheBox) {
  Terrain tilted = *terrain_preset("course-2021-tilted");
  std::get<Plane>(tilted.shape).normal.normalize();
  const Terrain terrains[] = {floor_with_hole(), bowl_2023(), tilted,
                              *terrain_preset("course-2021-sphere")};
  const Vec3 lo(-1.5, 0.25, -0.5), hi(2.0, 3.0, 1.25);
  for (const Terrain& t : terrains) {
    const double bound = min_signed_distance(t, lo, hi);
    double smallest = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j)
        for (int k = 0; k <= 8; ++k) {
          const Vec3 f(i / 8.0, j / 8.0, k / 8.0);
          const Vec3 x = lo + f.cwiseProduct(hi - lo);
          const double phi = signed_distance(t, x);
          EXPECT_GE(phi, bound - 1e-12) << t.name;
          smallest = std::min(smallest, phi);
        }
    EXPECT_NEAR(smallest, bound, 0.2) << t.name << ": the bound is not far below the true minimum";
  }
}

}  // namespace
}  // namespace jelly
