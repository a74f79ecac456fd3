#include "jelly/cube.hpp"

#include "rotation.hpp"

namespace jelly {

CubeLattice::CubeLattice(const CubeSpec& spec, int first_index)
    : n_(spec.n), first_(first_index), spacing_(spec.edge / static_cast<double>(spec.n - 1)) {
  // Centred exactly on c0 (contract §1): offsets run from −L/2 to +L/2 in each axis.
  const double half = 0.5 * static_cast<double>(n_ - 1);
  const Eigen::Matrix3d rotation =
      detail::initial_rotation(spec.rotation_axis, spec.rotation_degrees);
  initial_.resize(3, n_ * n_ * n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j)
      for (int k = 0; k < n_; ++k) {
        const Vec3 local((i - half) * spacing_, (j - half) * spacing_, (k - half) * spacing_);
        initial_.col((i * n_ + j) * n_ + k) = spec.center + rotation * local;
      }
}

}  // namespace jelly
