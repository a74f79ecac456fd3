#include "jelly/render/camera.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace jelly::render {

namespace {
constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }
}  // namespace

void OrbitCamera::frame(const Bounds& b, double aspect) {
  target = b.center();
  const double half_fov = rad(fov_y_degrees) / 2.0;
  // The narrower of the vertical and horizontal half-angles must hold the bounding sphere.
  const double half_h = std::atan(std::tan(half_fov) * aspect);
  const double limiting = std::min(half_fov, half_h);
  distance = std::max(1.0, 0.9 * b.radius() / std::sin(limiting));
}

void OrbitCamera::orbit(double dx, double dy) {
  yaw_degrees = std::fmod(yaw_degrees - 0.3 * dx, 360.0);
  pitch_degrees = std::clamp(pitch_degrees + 0.3 * dy, -85.0, 85.0);
}

void OrbitCamera::zoom(double steps) {
  distance = std::clamp(distance * std::pow(0.9, steps), 0.5, 1e4);
}

Vec3 OrbitCamera::eye() const {
  const double y = rad(yaw_degrees), p = rad(pitch_degrees);
  return target +
         distance * Vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
}

Eigen::Matrix4f OrbitCamera::view() const {
  const Vec3 e = eye();
  const Vec3 f = (target - e).normalized();
  const Vec3 r = f.cross(Vec3::UnitY()).normalized();
  const Vec3 u = r.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m.cast<float>();
}

Eigen::Matrix4f OrbitCamera::projection(double aspect) const {
  const double n = std::max(0.05, distance * 0.02), f = distance * 6.0 + 100.0;
  const double t = 1.0 / std::tan(rad(fov_y_degrees) / 2.0);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (f + n) / (n - f);
  m(2, 3) = 2.0 * f * n / (n - f);
  m(3, 2) = -1.0;
  return m.cast<float>();
}

std::optional<Eigen::Vector2d> OrbitCamera::project(const Vec3& p, int w, int h) const {
  const Eigen::Vector4f clip = projection(static_cast<double>(w) / h) * view() *
                               Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1.0f);
  if (clip.w() <= 0.0f) return std::nullopt;
  const double nx = clip.x() / clip.w(), ny = clip.y() / clip.w();
  return Eigen::Vector2d((nx + 1.0) * 0.5 * w, (1.0 - ny) * 0.5 * h);
}

}  // namespace jelly::render
