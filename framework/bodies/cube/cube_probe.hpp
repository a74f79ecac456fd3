// The smoke tests of the TaskTable slots that build a cube's springs (jelly/task_probe.hpp). Used
// by the cube's kind module only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/task_probe.hpp"

namespace jelly::bodies {

/// The slots that take a CubeLattice: add_structural_springs, add_shear_springs,
/// add_bending_springs.
std::vector<std::string_view> cube_probe_slots();

/// Probes one of them on a 3×3×3 lattice.
TaskStatus probe_cube_slot(std::string_view slot, std::string id, std::string name,
                           const TaskTable& t);

}  // namespace jelly::bodies
