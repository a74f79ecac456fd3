// The smoke tests of the TaskTable slots that build a cube's springs (jelly/task_probe.hpp).
#include "cube_probe.hpp"
#include "jelly/cube_tasks.hpp"

namespace jelly::bodies {

namespace {

using SpringBuilder = void (*)(const CubeLattice&, std::vector<Spring>&);

TaskStatus probe_builder(std::string id, std::string name, SpringBuilder fn) {
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!fn) return st;
  CubeSpec spec;
  spec.n = 3;  // 3×3×3 has structural, shear and bending springs
  spec.edge = 2.0;
  const CubeLattice lattice(spec);
  std::vector<Spring> out;
  fn(lattice, out);
  st.implemented = !out.empty();
  st.evidence = st.implemented ? std::to_string(out.size()) + " springs for a 3×3×3 lattice"
                               : "no springs for a 3×3×3 lattice";
  return st;
}

}  // namespace

std::vector<std::string_view> cube_probe_slots() {
  return {"add_structural_springs", "add_shear_springs", "add_bending_springs"};
}

TaskStatus probe_cube_slot(std::string_view slot, std::string id, std::string name,
                           const TaskTable& t) {
  SpringBuilder fn = slot == "add_structural_springs" ? cube_tasks(t).add_structural_springs
                     : slot == "add_shear_springs"    ? cube_tasks(t).add_shear_springs
                                                      : cube_tasks(t).add_bending_springs;
  return probe_builder(std::move(id), std::move(name), fn);
}

}  // namespace jelly::bodies
