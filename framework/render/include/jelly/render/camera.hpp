// The orbit camera and the projection the renderer and the tests share.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "jelly/types.hpp"

namespace jelly::render {

/// Axis-aligned bounds of what a scene shows [m].
struct Bounds {
  Vec3 lo{0.0, 0.0, 0.0};
  Vec3 hi{0.0, 0.0, 0.0};
  Vec3 center() const { return 0.5 * (lo + hi); }
  double radius() const { return 0.5 * (hi - lo).norm(); }
};

/// A camera orbiting a target point: yaw about +y, pitch above the horizon, distance.
class OrbitCamera {
 public:
  Vec3 target{0.0, 0.0, 0.0};   ///< [m]
  double yaw_degrees = 30.0;    ///< 0: looking along −z; positive: the camera swings to +x
  double pitch_degrees = 28.0;  ///< above the horizon, clamped to [−85, 85]
  double distance = 30.0;       ///< [m] from the target
  double fov_y_degrees = 40.0;  ///< vertical field of view

  /// Frames `b`: target at its centre, distance so its bounding sphere fits the view.
  void frame(const Bounds& b, double aspect);
  /// Mouse drag by (dx, dy) pixels: orbit (0.3° per pixel).
  void orbit(double dx, double dy);
  /// Wheel by `steps` notches: each notch moves 10 % closer (positive) or farther.
  void zoom(double steps);

  Vec3 eye() const;
  /// World → camera (right-handed, looking along −z).
  Eigen::Matrix4f view() const;
  /// Camera → clip space, OpenGL convention; near/far chosen from the distance.
  Eigen::Matrix4f projection(double aspect) const;
  /// Pixel coordinates of a world point in a viewport of w×h pixels (x right, y down, origin at
  /// the viewport's top-left corner); nullopt when the point is behind the camera.
  std::optional<Eigen::Vector2d> project(const Vec3& world, int w, int h) const;
};

}  // namespace jelly::render
