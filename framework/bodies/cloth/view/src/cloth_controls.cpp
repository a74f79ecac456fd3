#include "jelly/bodies/cloth/view/cloth_controls.hpp"
#include "jelly/cloth_physics.hpp"

#include <cmath>

namespace jelly::cloth_view {

int corner_particle(const ClothGrid& grid, int corner) {
  const int last = grid.n() - 1;
  const int i = corner >= 2 ? last : 0;
  const int k = corner % 2 == 1 ? last : 0;
  return grid.index(i, k);
}

std::optional<bool> toggle_corner_pin(World& world, int corner) {
  ClothPhysics* cloth = find_cloth_physics(world);
  if (corner < 0 || corner > 3 || !cloth || cloth->cloths().empty()) return std::nullopt;
  const int p = corner_particle(cloth->cloths().front(), corner);
  const bool pinned = !cloth->is_pinned(p);
  cloth->set_pinned(p, pinned);
  return pinned;
}

int first_kinematic_sphere(const World& world) {
  const ClothPhysics& cloth = cloth_physics(world);
  for (int i = 0; i < cloth.sphere_count(); ++i)
    if (cloth.sphere_is_kinematic(i)) return i;
  return -1;
}

Vec3 arrow_drive(const Vec3& current, Arrow arrow, double yaw_degrees, double speed) {
  // Away from the viewer: the camera sits at yaw ψ on the side (sin ψ, ·, cos ψ) of its target.
  constexpr double kPi = 3.14159265358979323846;
  const double yaw = yaw_degrees * kPi / 180.0;
  const double ax = -std::sin(yaw), az = -std::cos(yaw);
  // Snap to the nearest world axis; screen-right is forward × up = (−f_z, 0, f_x).
  Vec3 forward = std::abs(ax) > std::abs(az) ? Vec3(ax > 0 ? 1.0 : -1.0, 0.0, 0.0)
                                             : Vec3(0.0, 0.0, az > 0 ? 1.0 : -1.0);
  const Vec3 right(-forward.z(), 0.0, forward.x());
  Vec3 axis = arrow == Arrow::Up || arrow == Arrow::Down ? forward : right;
  const double sign = arrow == Arrow::Up || arrow == Arrow::Right ? 1.0 : -1.0;
  Vec3 out = current;
  // The component along the axis becomes ±speed, the other horizontal one stays.
  const int c = axis.x() != 0.0 ? 0 : 2;
  out[c] = sign * axis[c] * speed;
  return out;
}

bool drive_first_kinematic_sphere(World& world, const Vec3& velocity) {
  const int sphere = first_kinematic_sphere(world);
  if (sphere < 0) return false;
  cloth_physics(world).drive_sphere(sphere, velocity);
  return true;
}

}  // namespace jelly::cloth_view
