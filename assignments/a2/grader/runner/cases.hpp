// A2's case generators, one registration function per task group (cases_*.cpp), and what they
// share.
#pragma once

#include <string>
#include <vector>

#include "harness.hpp"
#include "jelly/cloth.hpp"
#include "jelly/cloth_tasks.hpp"

namespace jelly::grade {

void register_grid_spring_cases(Registry& r);
void register_collision_cases(Registry& r);
void register_friction_cases(Registry& r);
void register_integrator_cases(Registry& r);
void register_scene_cases(Registry& r);

/// A cloth from a parameter table: n, size, center, rotation_axis, rotation_degrees (the last
/// three optional: (0,0,0), (1,0,0), 0); no pins unless `pins` lists grid coordinates [[i, k],
/// ...].
ClothSpec cloth_from_params(const Params& cloth);

/// "(3,4)" of a grid coordinate.
std::string grid_name(int i, int k);

}  // namespace jelly::grade
