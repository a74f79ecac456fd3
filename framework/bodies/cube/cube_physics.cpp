// The physics of a world with jelly cubes: the cubes' lattices and their springs (contract §2);
// the rest is the default physics of particles over terrains.
#include "jelly/cube_physics.hpp"
#include "jelly/cube_tasks.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "jelly/spring_check.hpp"
#include "jelly/world.hpp"

namespace jelly {

namespace {

// Grid coordinates of a particle of a cube.
struct GridCoord {
  int i, j, k;
};
GridCoord grid_coord(const CubeLattice& c, int index) {
  const int r = index - c.first_index();
  const int n = c.n();
  return {r / (n * n), (r / n) % n, r % n};
}

// A body diagonal joins particles whose grid coordinates differ in all three axes.
bool is_body_diagonal(const CubeLattice& c, const Spring& s) {
  const GridCoord a = grid_coord(c, s.a);
  const GridCoord b = grid_coord(c, s.b);
  return a.i != b.i && a.j != b.j && a.k != b.k;
}

}  // namespace

int CubePhysics::add_cube(const CubeSpec& spec) {
  World& w = world();
  const auto first = static_cast<int>(w.state().size());
  cubes_.emplace_back(spec, first);
  const CubeLattice& lattice = cubes_.back();
  Vec3Array velocities(3, lattice.particle_count());
  velocities.colwise() = spec.velocity;
  w.add_particles(lattice.initial_positions(), velocities, spec.mass);
  return static_cast<int>(cubes_.size()) - 1;
}

void CubePhysics::build_cube_springs(int cube, SpringType type, double ks, double kd) {
  World& w = world();
  const TaskTable& tasks = w.tasks();
  const CubeLattice& lattice = cubes_.at(static_cast<std::size_t>(cube));
  SpringGroup group;
  group.type = type;
  group.ks = ks;
  group.kd = kd;
  group.degenerate_length = degenerate_length_for(lattice.spacing());
  const char* builder = "";
  switch (type) {
    case SpringType::Structural:
      builder = "add_structural_springs";
      cube_tasks(tasks).add_structural_springs(lattice, group.springs);
      break;
    case SpringType::Bending:
      builder = "add_bending_springs";
      cube_tasks(tasks).add_bending_springs(lattice, group.springs);
      break;
    case SpringType::Shear:
    case SpringType::ShearBody: {
      builder = "add_shear_springs";
      cube_tasks(tasks).add_shear_springs(lattice, group.springs);
      if (type == SpringType::ShearBody) {
        // Keep the body diagonals here and take them out of the cube's face-shear group.
        auto& springs = group.springs;
        springs.erase(
            std::remove_if(springs.begin(), springs.end(),
                           [&](const Spring& s) { return !is_body_diagonal(lattice, s); }),
            springs.end());
        for (SpringGroup& g : spring_groups(w)) {
          if (g.type != SpringType::Shear || g.springs.empty()) continue;
          const int a = g.springs.front().a;
          if (a < lattice.first_index() || a >= lattice.first_index() + lattice.particle_count())
            continue;
          g.springs.erase(
              std::remove_if(g.springs.begin(), g.springs.end(),
                             [&](const Spring& s) { return is_body_diagonal(lattice, s); }),
              g.springs.end());
          springs_changed(w);
        }
      }
      break;
    }
  }
  // The framework never trusts a builder's output blindly: a bad index would crash the force pass.
  const int lo = lattice.first_index();
  const int hi = lo + lattice.particle_count();
  check_built_springs(group, lo, hi, builder);
  w.add_spring_group(std::move(group));
}

CubePhysics& cube_physics(World& world) {
  if (auto* physics = dynamic_cast<CubePhysics*>(&world.physics())) return *physics;
  const BodyPhysics& current = world.physics();
  if (typeid(current) != typeid(TerrainPhysics))
    throw std::logic_error("add_cube: a cube goes into a world of particles and terrains only");
  auto made = std::make_unique<CubePhysics>(world);
  CubePhysics& physics = *made;
  world.set_physics(std::move(made));
  return physics;
}

const CubePhysics* find_cube_physics(const World& world) {
  return dynamic_cast<const CubePhysics*>(&world.physics());
}

const std::vector<CubeLattice>& cubes_of(const World& world) {
  static const std::vector<CubeLattice> none;
  const CubePhysics* physics = find_cube_physics(world);
  return physics ? physics->cubes() : none;
}

}  // namespace jelly
