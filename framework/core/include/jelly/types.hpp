// Basic value types of the simulation: vectors, per-particle arrays and the dynamic state.
#pragma once

#include <Eigen/Core>

namespace jelly {

/// A point or vector in world space. Units depend on use: [m], [m/s], [N].
using Vec3 = Eigen::Vector3d;

/// One 3-vector per particle: a 3×N matrix whose column i belongs to particle i.
/// Whole-array arithmetic works (`s.x += h * s.v;`), and so does one particle (`s.x.col(i)`).
using Vec3Array = Eigen::Matrix3Xd;

/// The dynamic state the integrators advance: positions and velocities of every particle.
struct State {
  Vec3Array x;  ///< positions [m], 3×N
  Vec3Array v;  ///< velocities [m/s], 3×N

  /// Number of particles.
  Eigen::Index size() const { return x.cols(); }

  /// Resizes both arrays to n particles (contents unspecified).
  void resize(Eigen::Index n) {
    x.resize(3, n);
    v.resize(3, n);
  }
};

}  // namespace jelly
