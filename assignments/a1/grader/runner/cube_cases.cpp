// The cube A1's cases build: from a case's parameters, with the reference's springs stored in its
// input (moved from the general harness: only A1's cases build cubes).
#include "cases.hpp"
#include "jelly/cube_physics.hpp"
#include "jelly/cube_tasks.hpp"

namespace jelly::grade {

CubeSpec cube_from_params(const Params& cube) {
  CubeSpec s;
  s.n = static_cast<int>(cube.integer("n"));
  s.edge = cube.number("edge");
  s.center = cube.vec("center", Vec3::Zero());
  s.rotation_axis = cube.vec("rotation_axis", Vec3(1.0, 0.0, 1.0));
  s.rotation_degrees = cube.number("rotation_degrees", 0.0);
  return s;
}

void prepare_cube_springs(const TaskTable& reference, const Params& params, Json& input) {
  const CubeLattice cube(cube_from_params(params.table("cube")), 0);
  std::vector<Spring> structural, shear, bending;
  cube_tasks(reference).add_structural_springs(cube, structural);
  cube_tasks(reference).add_shear_springs(cube, shear);
  cube_tasks(reference).add_bending_springs(cube, bending);
  input["springs"] = {{"structural", springs_to_json(structural)},
                      {"shear", springs_to_json(shear)},
                      {"bending", springs_to_json(bending)}};
}

void add_prepared_cube(World& world, const Params& params, const Json& input, double ks,
                       double kd) {
  const int cube = cube_physics(world).add_cube(cube_from_params(params.table("cube")));
  const double spacing = cubes_of(world).at(static_cast<std::size_t>(cube)).spacing();
  const std::pair<const char*, SpringType> types[] = {{"structural", SpringType::Structural},
                                                      {"shear", SpringType::Shear},
                                                      {"bending", SpringType::Bending}};
  for (const auto& [key, type] : types) {
    SpringGroup g;
    g.type = type;
    g.ks = ks;
    g.kd = kd;
    g.degenerate_length = degenerate_length_for(spacing);
    g.springs = springs_from_json(input.at("springs").at(key));
    world.add_spring_group(std::move(g));
  }
}

}  // namespace jelly::grade
