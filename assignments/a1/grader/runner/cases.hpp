// A1's case generators, one registration function per task group (cases_*.cpp).
#pragma once

#include "harness.hpp"

namespace jelly::grade {

void register_spring_cases(Registry& r);
void register_force_cases(Registry& r);
void register_terrain_cases(Registry& r);
void register_integrator_cases(Registry& r);
void register_scene_cases(Registry& r);

}  // namespace jelly::grade
