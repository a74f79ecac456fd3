// The smoke tests of the cloth's TaskTable slots (jelly/task_probe.hpp). Used
// by the cloth's kind module only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/task_probe.hpp"

namespace jelly::bodies {

/// The cloth's slots: add_grid_structural_springs, add_grid_shear_springs,
/// add_grid_bending_springs, collide_particle_sphere, collide_spheres, friction_impulse.
std::vector<std::string_view> cloth_probe_slots();

/// Probes one of them: a builder on a 3×3 cloth, an impulse on a pair that collides.
TaskStatus probe_cloth_slot(std::string_view slot, std::string id, std::string name,
                            const TaskTable& t);

}  // namespace jelly::bodies
