// The one narrow interface between the framework and an assignment's student tasks: the core's
// seams.
//
// The core never calls a task function by name: it calls through a TaskTable, whose slots are
// named after what the physics needs (build the springs of a lattice, the force of one spring,
// one integrator step, ...), never after an assignment's task IDs. An assignment fills the slots
// its tasks implement (assignments/<id>/bindings/task_table.cpp, the function
// jelly::<namespace>::task_table()); its manifest (assignment.toml) says which task fills which
// slot. Slots an assignment does not fill stay null, and the effects that need them are off.
// Tests wrap a table to count calls.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "jelly/cloth.hpp"
#include "jelly/cube.hpp"
#include "jelly/spheres.hpp"
#include "jelly/spring.hpp"
#include "jelly/spring_group_pass.hpp"
#include "jelly/system.hpp"
#include "jelly/terrain.hpp"

namespace jelly {

/// Signature shared by the integrator slots (and the framework's symplectic Euler).
using StepFunction = void (*)(System& system, State& s, double h, Workspace& w);

struct TaskTable {
  // Spring builders of a cube lattice (physics contract §2).
  void (*add_structural_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_shear_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_bending_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  // The force of one spring and one damper on its particle a; the framework applies them to a
  // spring group (jelly/spring_pass.hpp).
  Vec3 (*spring_force)(const Vec3&, const Vec3&, double, double, double) = nullptr;
  Vec3 (*damper_force)(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double,
                       double) = nullptr;
  /// Optional (nullptr unless the library provides it; the reference does): makes a spring
  /// engine that does every group in one call (jelly/spring_group_pass.hpp). A World makes one
  /// when this is set and uses it instead of the framework's group-by-group pass.
  std::unique_ptr<SpringGroupPass> (*make_spring_group_pass)() = nullptr;
  // Collision response against the terrain (contract §4).
  bool (*collide_plane)(const Plane&, const Vec3&, Vec3&) = nullptr;
  bool (*collide_bowl)(const Bowl&, const Vec3&, Vec3&) = nullptr;
  // Contact and friction forces (contract §5).
  bool (*contact_plane)(const Plane&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  bool (*contact_bowl)(const Bowl&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  // Spring builders of a cloth grid (cloth contract §2): structural (1,0) (0,1), shear (1,1)
  // (1,−1), bending (2,0) (0,2), each particle owning the springs to its forward neighbours.
  void (*add_grid_structural_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  void (*add_grid_shear_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  void (*add_grid_bending_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  // Impulses between point bodies (cloth contract §4): a cloth particle (A) and a sphere (B);
  // two spheres (A = the first in scene order). Each changes the velocities it was given only
  // when the pair collides, and says what it applied.
  Impulse (*collide_particle_sphere)(PointBody&, SphereBody&, const ImpulseSettings&) = nullptr;
  Impulse (*collide_spheres)(SphereBody&, SphereBody&, const ImpulseSettings&) = nullptr;
  // Coulomb friction right after a normal impulse (cloth contract §4, the bonus): called by the
  // framework only when the scene's μ > 0, with the normal impulse, μ, w_A, w_B, v_A, v_B.
  void (*friction_impulse)(const Impulse&, double, double, double, Vec3&, Vec3&) = nullptr;
  // The course's four integrators (contract §6).
  StepFunction explicit_euler_step = nullptr;
  StepFunction implicit_euler_step = nullptr;
  StepFunction midpoint_step = nullptr;
  StepFunction rk4_step = nullptr;

  /// Where the table's functions come from: "assignments", "solutions" or "submission".
  std::string_view origin;
};

}  // namespace jelly
