// The cloth of assignment A2: a square n×n grid of particles, some of them pinned (cloth contract
// §1). Its springs are built by the student's grid builders (TaskTable) from a ClothGrid.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "jelly/types.hpp"

namespace jelly {

/// Grid coordinates (i, k) of one cloth particle: i along x, k along z before rotation.
using GridCoord = std::array<int, 2>;

/// How to build a cloth: the scene's `body` parameters when `body.kind = "cloth"`.
struct ClothSpec {
  int n = 25;                         ///< particles per edge (≥ 2)
  double size = 4.0;                  ///< side L [m]; spacing s = L / (n − 1)
  double mass = 1.0;                  ///< mass of every particle [kg]
  Vec3 center{0.0, 0.0, 0.0};         ///< centre c0 [m]; the grid is centred exactly on it
  Vec3 rotation_axis{1.0, 0.0, 0.0};  ///< initial rotation axis (normalised when used)
  double rotation_degrees = 0.0;  ///< about rotation_axis through c0 [deg] (90 about x: curtain)
  Vec3 velocity{0.0, 0.0, 0.0};   ///< initial velocity of every unpinned particle [m/s]
  /// Named pin sets: "corners" (the four corners), "edge" (the row k = 0, decision 8).
  std::vector<std::string> pin_sets{"corners"};
  std::vector<GridCoord> pins;  ///< further pins by grid coordinates
  double air_drag = 0.0;        ///< k_air: drag force −k_air·v on every cloth particle [N·s/m]
};

/// The pinned particles of a cloth: the named sets, then the listed coordinates, each once, in
/// index order (i·n + k ascending). Throws std::invalid_argument for an unknown set or a
/// coordinate outside the grid.
std::vector<GridCoord> resolve_pins(const ClothSpec& spec);

/// The particle grid of one cloth as the spring builders see it. Particle (i, k) has index
/// first + i·n + k and starts at c0 + R·(−L/2 + i·s, 0, −L/2 + k·s) (cloth contract §1).
class ClothGrid {
 public:
  explicit ClothGrid(const ClothSpec& spec, int first_index = 0);

  /// Particles per edge.
  int n() const { return n_; }
  /// Grid spacing s = L / (n − 1) [m].
  double spacing() const { return spacing_; }
  /// Number of particles, n².
  int particle_count() const { return n_ * n_; }
  /// True when 0 ≤ i, k < n.
  bool contains(int i, int k) const { return i >= 0 && k >= 0 && i < n_ && k < n_; }
  /// Index of particle (i, k) in the state arrays. Requires contains(i, k).
  int index(int i, int k) const { return first_ + i * n_ + k; }
  /// Position of particle (i, k) when the cloth was built [m].
  Vec3 position(int i, int k) const { return initial_.col(i * n_ + k); }
  /// Positions of all particles when built, 3×n², in index order (relative to the first index).
  const Vec3Array& initial_positions() const { return initial_; }
  /// Index of the first particle of this cloth.
  int first_index() const { return first_; }

 private:
  int n_;
  int first_;
  double spacing_;
  Vec3Array initial_;
};

}  // namespace jelly
