// The TaskTable slots that take a cloth grid, point bodies and spheres (cloth contract §2, §4): the
// cloth kind's part of an assignment's task table (TaskTable::kinds), filled by an assignment's
// bindings and called by ClothPhysics and the cloth's probes.
#pragma once

#include <vector>

#include "jelly/cloth.hpp"
#include "jelly/spheres.hpp"
#include "jelly/spring.hpp"
#include "jelly/task_table.hpp"

namespace jelly {

/// The cloth's slots; null where the assignment has no such task.
struct ClothTasks {
  // Spring builders of a cloth grid: structural (1,0) (0,1), shear (1,1) (1,−1), bending (2,0)
  // (0,2), each particle owning the springs to its forward neighbours.
  void (*add_grid_structural_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  void (*add_grid_shear_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  void (*add_grid_bending_springs)(const ClothGrid&, std::vector<Spring>&) = nullptr;
  // Impulses between point bodies: a cloth particle (A) and a sphere (B); two spheres (A = the
  // first in scene order). Each changes the velocities it was given only when the pair collides,
  // and says what it applied.
  Impulse (*collide_particle_sphere)(PointBody&, SphereBody&, const ImpulseSettings&) = nullptr;
  Impulse (*collide_spheres)(SphereBody&, SphereBody&, const ImpulseSettings&) = nullptr;
  // Coulomb friction right after a normal impulse (the bonus): called by the framework only when
  // the scene's μ > 0, with the normal impulse, μ, w_A, w_B, v_A, v_B.
  void (*friction_impulse)(const Impulse&, double, double, double, Vec3&, Vec3&) = nullptr;
};

/// The table's cloth slots, made (all null) on first use.
inline ClothTasks& cloth_tasks(TaskTable& t) { return t.kinds.get<ClothTasks>(); }
/// The table's cloth slots, all null when the table has none.
inline const ClothTasks& cloth_tasks(const TaskTable& t) {
  return t.kinds.get_or_default<ClothTasks>();
}

}  // namespace jelly
