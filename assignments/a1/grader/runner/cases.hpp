// A1's case generators, one registration function per task group (cases_*.cpp).
#pragma once

#include "harness.hpp"
#include "jelly/cube.hpp"

namespace jelly::grade {

void register_spring_cases(Registry& r);
void register_force_cases(Registry& r);
void register_terrain_cases(Registry& r);
void register_integrator_cases(Registry& r);
void register_scene_cases(Registry& r);

// ----- the cube the cases build (cube_cases.cpp) -----

/// A cube from a parameter table: n, edge, center, rotation_axis, rotation_degrees (the last three
/// optional: (0,0,0), (1,0,1), 0).
CubeSpec cube_from_params(const Params& cube);
/// prepare(): the REFERENCE springs of the cube in params["cube"], per type, into input["springs"].
void prepare_cube_springs(const TaskTable& reference, const Params& params, Json& input);
/// Adds the cube params["cube"]'s particles and the spring groups stored in input["springs"] to a
/// world, every group with the given coefficients (no student builder involved).
void add_prepared_cube(World& world, const Params& params, const Json& input, double ks, double kd);

}  // namespace jelly::grade
