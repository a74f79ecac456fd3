#include "jelly/cube.hpp"

#include "jelly/portable_math.hpp"

namespace jelly {

namespace {

// The rotation by `radians` about the unit `axis` (Rodrigues), term for term as Eigen's
// AngleAxis::toRotationMatrix computes it, but with the core's portable sin and cos: the C
// library's differ between Linux, macOS and Windows in the last bits, and these positions are
// the whole simulation's starting point.
Eigen::Matrix3d axis_angle_rotation(const Vec3& axis, double radians) {
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

}  // namespace

CubeLattice::CubeLattice(const CubeSpec& spec, int first_index)
    : n_(spec.n), first_(first_index), spacing_(spec.edge / static_cast<double>(spec.n - 1)) {
  // Centred exactly on c0 (contract §1): offsets run from −L/2 to +L/2 in each axis.
  const double half = 0.5 * static_cast<double>(n_ - 1);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (spec.rotation_degrees != 0.0) {
    const double radians = spec.rotation_degrees * (3.14159265358979323846 / 180.0);
    rotation = axis_angle_rotation(spec.rotation_axis.normalized(), radians);
  }
  initial_.resize(3, n_ * n_ * n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j)
      for (int k = 0; k < n_; ++k) {
        const Vec3 local((i - half) * spacing_, (j - half) * spacing_, (k - half) * spacing_);
        initial_.col((i * n_ + j) * n_ + k) = spec.center + rotation * local;
      }
}

}  // namespace jelly
