// The physics of a world with jelly cubes (assignment A1, contract §5, §6): the default physics of
// particles over terrains (jelly/terrain_physics.hpp), plus the cubes' lattices and the building of
// their springs. The cube kind (cube_kind.cpp) installs it when it builds a world; code that builds
// or reads a cube world reaches it through cube_physics(world).
#pragma once

#include <vector>

#include "jelly/cube.hpp"
#include "jelly/spring.hpp"
#include "jelly/terrain_physics.hpp"

namespace jelly {

class World;

class CubePhysics : public TerrainPhysics {
 public:
  using TerrainPhysics::TerrainPhysics;

  /// Adds the particles of a cube; returns its index in cubes(). Springs are added separately.
  int add_cube(const CubeSpec& spec);
  /// Builds the springs of `type` in cube `cube` with the student's builder (through the task
  /// table) and adds them as a group. ShearBody takes the body diagonals out of the shear builder's
  /// output (call it after Shear when the scene sets body diagonals apart).
  void build_cube_springs(int cube, SpringType type, double ks, double kd);
  const std::vector<CubeLattice>& cubes() const { return cubes_; }

 private:
  std::vector<CubeLattice> cubes_;
};

/// The cube physics of `world`, installed in place of the default (particles and terrains the
/// world holds stay). Throws std::logic_error for a world with another kind's physics.
CubePhysics& cube_physics(World& world);
/// The cube physics of `world`, or nullptr when it has none (no cube was added).
const CubePhysics* find_cube_physics(const World& world);
/// The cubes of `world`, in the order they were added; none when it has no cube physics.
const std::vector<CubeLattice>& cubes_of(const World& world);

}  // namespace jelly
