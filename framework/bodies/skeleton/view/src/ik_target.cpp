// The target's drag and pick in the viewer, without GL (ik_target.hpp).
#include "jelly/bodies/skeleton/view/ik_target.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

namespace jelly::skeleton_view {

namespace {

/// The world point at normalised device coordinates (x, y, z), through the inverse of the
/// camera's projection × view.
Vec3 unproject(const Eigen::Matrix4d& inverse, double x, double y, double z) {
  const Eigen::Vector4d p = inverse * Eigen::Vector4d(x, y, z, 1.0);
  return p.head<3>() / p.w();
}

}  // namespace

std::optional<Vec3> point_under_mouse(const render::OrbitCamera& camera, int width, int height,
                                      const Eigen::Vector2d& mouse, const Vec3& through) {
  if (width <= 0 || height <= 0) return std::nullopt;
  const Eigen::Matrix4d vp =
      (camera.projection(static_cast<double>(width) / height) * camera.view()).cast<double>();
  const Eigen::Matrix4d inverse = vp.inverse();
  const double x = 2.0 * mouse.x() / width - 1.0, y = 1.0 - 2.0 * mouse.y() / height;
  const Vec3 near = unproject(inverse, x, y, -1.0), far = unproject(inverse, x, y, 0.0);
  const Vec3 dir = far - near;
  const Vec3 normal = camera_axis(camera, 2);
  const double facing = normal.dot(dir);
  if (!(std::abs(facing) > 1e-12)) return std::nullopt;
  const double t = normal.dot(through - near) / facing;
  if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
  return Vec3(near + t * dir);
}

int target_near(const render::OrbitCamera& camera, int width, int height,
                const Eigen::Vector2d& mouse, const std::vector<Vec3>& targets, double radius) {
  int best = -1;
  double best_distance = radius;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const std::optional<Eigen::Vector2d> at = camera.project(targets[i], width, height);
    if (!at) continue;
    const double d = (*at - mouse).norm();
    if (d <= best_distance) {
      best = static_cast<int>(i);
      best_distance = d;
    }
  }
  return best;
}

Vec3 camera_axis(const render::OrbitCamera& camera, int axis) {
  const Vec3 forward = (camera.target - camera.eye()).normalized();
  const Vec3 right = forward.cross(Vec3::UnitY()).normalized();
  if (axis == 0) return right;
  if (axis == 1) return right.cross(forward);
  return forward;
}

}  // namespace jelly::skeleton_view
