// The jelly cube: a regular n×n×n grid of particles (physics contract §1).
#pragma once

#include "jelly/types.hpp"

namespace jelly {

/// How to build a cube: the scene's `body` parameters.
struct CubeSpec {
  int n = 10;                         ///< particles per edge (≥ 2)
  double edge = 4.0;                  ///< edge length L [m]
  double mass = 1.0;                  ///< mass of every particle [kg]
  Vec3 center{0.0, 9.0, 0.0};         ///< initial centre c0 [m]; the grid is centred exactly on it
  Vec3 rotation_axis{1.0, 0.0, 1.0};  ///< initial rotation axis (normalised when used)
  double rotation_degrees = 0.0;      ///< right-hand rule, about rotation_axis through c0 [deg]
  Vec3 velocity{0.0, 0.0, 0.0};       ///< initial velocity of every particle, not rotated [m/s]
};

/// The particle grid of one cube as the spring builder sees it: grid coordinates (i, j, k), the
/// particle index of each, and the positions at construction. i runs along x, j along y, k along z
/// (before rotation); particle (i, j, k) has index first + i·n² + j·n + k.
class CubeLattice {
 public:
  CubeLattice(const CubeSpec& spec, int first_index = 0);

  /// Particles per edge.
  int n() const { return n_; }
  /// Grid spacing s = L / (n − 1) [m].
  double spacing() const { return spacing_; }
  /// Number of particles, n³.
  int particle_count() const { return n_ * n_ * n_; }
  /// True when 0 ≤ i, j, k < n.
  bool contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < n_ && j < n_ && k < n_;
  }
  /// Index of particle (i, j, k) in the state arrays. Requires contains(i, j, k).
  int index(int i, int j, int k) const { return first_ + (i * n_ + j) * n_ + k; }
  /// Position of particle (i, j, k) when the cube was built [m].
  Vec3 position(int i, int j, int k) const { return initial_.col(index(i, j, k) - first_); }
  /// Positions of all particles when built, 3×n³, in index order (relative to first index).
  const Vec3Array& initial_positions() const { return initial_; }
  /// Index of the first particle of this cube.
  int first_index() const { return first_; }

 private:
  int n_;
  int first_;
  double spacing_;
  Vec3Array initial_;
};

}  // namespace jelly
