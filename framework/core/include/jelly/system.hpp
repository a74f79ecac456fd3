// What an integrator advances: a system that can evaluate the acceleration a(x, v).
#pragma once

#include <array>

#include "jelly/types.hpp"

namespace jelly {

/// A system of particles whose acceleration the framework knows how to evaluate.
///
/// The jelly world (gravity, springs, dampers, contact), a free particle, a lone spring and the
/// linearised lattice are all Systems, so every integrator can be stepped on any of them.
class System {
 public:
  virtual ~System() = default;

  /// Evaluates a(x, v) at state `s` for every particle and writes it to `a` (3×N) [m/s²].
  /// One evaluation computes gravity, spring and damper forces, then contact forces, and divides
  /// by the mass (contract §6). It never changes `s`. `a` is resized if its size is wrong.
  virtual void acceleration(const State& s, Vec3Array& a) = 0;

  /// Number of particles.
  virtual Eigen::Index particle_count() const = 0;
};

/// Buffers an integrator may use so that a step allocates nothing. The framework sizes every
/// array to the system's particle count before each step; an integrator may also ignore them.
struct Workspace {
  std::array<State, 3> state;      ///< scratch states (e.g. a predictor, a midpoint, RK stages)
  std::array<Vec3Array, 4> accel;  ///< scratch accelerations (e.g. a_n, RK4's four stages)

  /// Sizes every buffer for n particles (no allocation when already that size).
  void resize(Eigen::Index n) {
    for (State& s : state) s.resize(n);
    for (Vec3Array& a : accel) a.resize(3, n);
  }
};

}  // namespace jelly
