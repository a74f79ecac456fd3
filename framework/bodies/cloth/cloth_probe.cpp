// The smoke tests of the cloth's TaskTable slots (jelly/cloth_tasks.hpp, jelly/task_probe.hpp): its
// spring builders, its impulses and its friction.
#include "cloth_probe.hpp"

#include "jelly/cloth_tasks.hpp"

namespace jelly::bodies {

namespace {

using GridBuilder = void (*)(const ClothGrid&, std::vector<Spring>&);

TaskStatus probe_grid_builder(std::string id, std::string name, GridBuilder fn) {
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!fn) return st;
  ClothSpec spec;
  spec.n = 3;  // 3×3 has structural, shear and bending springs
  spec.size = 2.0;
  const ClothGrid grid(spec);
  std::vector<Spring> out;
  fn(grid, out);
  st.implemented = !out.empty();
  st.evidence = st.implemented ? std::to_string(out.size()) + " springs for a 3×3 cloth"
                               : "no springs for a 3×3 cloth";
  return st;
}

TaskStatus probe_particle_sphere(std::string id, std::string name, const TaskTable& t) {
  // A particle 5 mm above a resting sphere of inverse mass 0, falling at 1 m/s: φ < ε, approaching.
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!cloth_tasks(t).collide_particle_sphere) return st;
  const Vec3 incoming(0.0, -1.0, 0.0);
  PointBody p{Vec3(0.0, 1.005, 0.0), incoming, 1.0};
  SphereBody sphere{Vec3::Zero(), Vec3::Zero(), 1.0, 0.0};
  const Impulse imp = cloth_tasks(t).collide_particle_sphere(p, sphere, ImpulseSettings{});
  st.implemented = imp.applied || p.velocity != incoming;
  st.evidence = st.implemented ? "a particle falling onto a sphere responded"
                               : "a particle falling onto a sphere did not collide";
  return st;
}

TaskStatus probe_spheres(std::string id, std::string name, const TaskTable& t) {
  // Two spheres of radius 0.5, 5 mm apart, meeting at ±1 m/s.
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!cloth_tasks(t).collide_spheres) return st;
  SphereBody a{Vec3(-0.5025, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), 0.5, 1.0};
  SphereBody b{Vec3(0.5025, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0), 0.5, 1.0};
  const Impulse imp = cloth_tasks(t).collide_spheres(a, b, ImpulseSettings{0.8, 0.01});
  st.implemented =
      imp.applied || a.velocity != Vec3(1.0, 0.0, 0.0) || b.velocity != Vec3(-1.0, 0.0, 0.0);
  st.evidence = st.implemented ? "two spheres meeting head-on responded"
                               : "two spheres meeting head-on did not collide";
  return st;
}

TaskStatus probe_friction(std::string id, std::string name, const TaskTable& t) {
  // A particle sliding at 1 m/s along a resting sphere's surface after a normal impulse of 1 N·s.
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!cloth_tasks(t).friction_impulse) return st;
  const Vec3 sliding(1.0, 0.0, 0.0);
  Vec3 va = sliding, vb = Vec3::Zero();
  cloth_tasks(t).friction_impulse(Impulse{true, Vec3(0.0, 1.0, 0.0), 1.0}, 0.5, 1.0, 0.0, va, vb);
  st.implemented = va != sliding || vb != Vec3::Zero();
  st.evidence = st.implemented ? "a sliding particle was slowed"
                               : "a sliding particle kept its tangential velocity";
  return st;
}

}  // namespace

std::vector<std::string_view> cloth_probe_slots() {
  return {"add_grid_structural_springs", "add_grid_shear_springs", "add_grid_bending_springs",
          "collide_particle_sphere",     "collide_spheres",        "friction_impulse"};
}

TaskStatus probe_cloth_slot(std::string_view slot, std::string id, std::string name,
                            const TaskTable& t) {
  if (slot == "collide_particle_sphere")
    return probe_particle_sphere(std::move(id), std::move(name), t);
  if (slot == "collide_spheres") return probe_spheres(std::move(id), std::move(name), t);
  if (slot == "friction_impulse") return probe_friction(std::move(id), std::move(name), t);
  GridBuilder fn = slot == "add_grid_structural_springs"
                       ? cloth_tasks(t).add_grid_structural_springs
                   : slot == "add_grid_shear_springs" ? cloth_tasks(t).add_grid_shear_springs
                                                      : cloth_tasks(t).add_grid_bending_springs;
  return probe_grid_builder(std::move(id), std::move(name), fn);
}

}  // namespace jelly::bodies
