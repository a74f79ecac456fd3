// The rotation of a body's initial grid about its centre (physics contract §1, and each body
// kind's contract that reuses it), shared by the kinds so that all turn their particles with the
// same bits.
#pragma once

#include "jelly/portable_math.hpp"
#include "jelly/types.hpp"

namespace jelly::detail {

// The rotation by `radians` about the unit `axis` (Rodrigues), term for term as Eigen's
// AngleAxis::toRotationMatrix computes it, but with the core's portable sin and cos: the C
// library's differ between Linux, macOS and Windows in the last bits, and these positions are
// the whole simulation's starting point.
inline Eigen::Matrix3d axis_angle_rotation(const Vec3& axis, double radians) {
  const Vec3 sin_axis = portable::sin(radians) * axis;
  const double c = portable::cos(radians);
  const Vec3 cos1_axis = (1.0 - c) * axis;
  Eigen::Matrix3d r;
  double tmp = cos1_axis.x() * axis.y();
  r(0, 1) = tmp - sin_axis.z();
  r(1, 0) = tmp + sin_axis.z();
  tmp = cos1_axis.x() * axis.z();
  r(0, 2) = tmp + sin_axis.y();
  r(2, 0) = tmp - sin_axis.y();
  tmp = cos1_axis.y() * axis.z();
  r(1, 2) = tmp - sin_axis.x();
  r(2, 1) = tmp + sin_axis.x();
  r.diagonal() = (cos1_axis.cwiseProduct(axis)).array() + c;
  return r;
}

/// The initial rotation of a body: identity at 0° (no rounding at all), else the rotation by
/// `degrees` about the normalised `axis`.
inline Eigen::Matrix3d initial_rotation(const Vec3& axis, double degrees) {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (degrees != 0.0) {
    const double radians = degrees * (3.14159265358979323846 / 180.0);
    rotation = axis_angle_rotation(axis.normalized(), radians);
  }
  return rotation;
}

}  // namespace jelly::detail
