#include "jelly/cube.hpp"

#include <Eigen/Geometry>

namespace jelly {

CubeLattice::CubeLattice(const CubeSpec& spec, int first_index)
    : n_(spec.n), first_(first_index), spacing_(spec.edge / static_cast<double>(spec.n - 1)) {
  // Centred exactly on c0 (contract §1): offsets run from −L/2 to +L/2 in each axis.
  const double half = 0.5 * static_cast<double>(n_ - 1);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (spec.rotation_degrees != 0.0) {
    const double radians = spec.rotation_degrees * (3.14159265358979323846 / 180.0);
    rotation = Eigen::AngleAxisd(radians, spec.rotation_axis.normalized()).toRotationMatrix();
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
