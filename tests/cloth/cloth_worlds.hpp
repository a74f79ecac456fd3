// Cloth worlds built in code with the settings of the course's scenes (cloth contract §6), for the
// tests of the cloth in the core. The scene loader builds the same worlds from scenes/*.toml.
#pragma once

#include <memory>

#include "jelly/a2/task_table.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/simulator.hpp"
#include "jelly/world.hpp"

namespace jelly::cloth_test {

/// A cloth world with the reference's tasks: a cloth of `spec`, its three spring types at ks, kd
/// (none when ks = 0), gravity g (none when null).
inline std::unique_ptr<World> cloth_world(const ClothSpec& spec, double ks, double kd,
                                          std::optional<Vec3> g = Vec3(0.0, -9.8, 0.0)) {
  auto world = std::make_unique<World>(a2::task_table());
  cloth_physics(*world).add_cloth(spec);
  if (ks > 0.0)
    for (SpringType t : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
      cloth_physics(*world).build_cloth_springs(0, t, ks, kd);
  world->set_gravity(g);
  return world;
}

/// cloth-2022: the cloth at y = 0, corners pinned, ks 25000, kd 750, k_air 3.4e-4, four dynamic
/// spheres r = 0.5 at (±0.75, 1, ±0.75), x-major, e_cloth 0, e_sphere 0.8, ε 0.01.
inline std::unique_ptr<World> cloth_2022() {
  ClothSpec spec;
  spec.air_drag = 3.4e-4;
  auto world = cloth_world(spec, 25000.0, 750.0);
  for (double x : {-0.75, 0.75})
    for (double z : {-0.75, 0.75}) {
      SphereSpec s;
      s.center = Vec3(x, 1.0, z);
      s.radius = 0.5;
      cloth_physics(*world).add_sphere(s);
    }
  ClothCollisionSettings c;
  c.cloth_restitution = 0.0;
  c.sphere_restitution = 0.8;
  c.tolerance = 0.01;
  cloth_physics(*world).set_cloth_collisions(c);
  return world;
}

/// cloth-2024: the cloth at y = 1, corners pinned, ks 20000, kd 750, k_air 3.4e-4, one kinematic
/// sphere r = 1 at the origin on the schedule 0: 0; 0.5: (2,0,0); 1.0: (−2,0,0); 1.5: 0.
inline std::unique_ptr<World> cloth_2024() {
  ClothSpec spec;
  spec.center = Vec3(0.0, 1.0, 0.0);
  spec.air_drag = 3.4e-4;
  auto world = cloth_world(spec, 20000.0, 750.0);
  SphereSpec s;
  s.kinematic = true;
  s.center = Vec3::Zero();
  s.radius = 1.0;
  s.schedule = {{0.0, Vec3::Zero()},
                {0.5, Vec3(2.0, 0.0, 0.0)},
                {1.0, Vec3(-2.0, 0.0, 0.0)},
                {1.5, Vec3::Zero()}};
  cloth_physics(*world).add_sphere(s);
  ClothCollisionSettings c;
  c.cloth_restitution = 0.0;
  c.tolerance = 0.01;
  cloth_physics(*world).set_cloth_collisions(c);
  return world;
}

}  // namespace jelly::cloth_test
