// The smoke tests of the TaskTable slots that build a cloth's springs (jelly/task_probe.hpp). Used
// by the cloth's kind module only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/task_probe.hpp"

namespace jelly::bodies {

/// The slots that take a ClothGrid: add_grid_structural_springs, add_grid_shear_springs,
/// add_grid_bending_springs.
std::vector<std::string_view> cloth_probe_slots();

/// Probes one of them on a 3×3 cloth.
TaskStatus probe_cloth_slot(std::string_view slot, std::string id, std::string name,
                            const TaskTable& t);

}  // namespace jelly::bodies
