// The smoke tests of the TaskTable slots that build a cloth's springs (jelly/task_probe.hpp).
#include "cloth_probe.hpp"

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

}  // namespace

std::vector<std::string_view> cloth_probe_slots() {
  return {"add_grid_structural_springs", "add_grid_shear_springs", "add_grid_bending_springs"};
}

TaskStatus probe_cloth_slot(std::string_view slot, std::string id, std::string name,
                            const TaskTable& t) {
  GridBuilder fn = slot == "add_grid_structural_springs" ? t.add_grid_structural_springs
                   : slot == "add_grid_shear_springs"    ? t.add_grid_shear_springs
                                                         : t.add_grid_bending_springs;
  return probe_grid_builder(std::move(id), std::move(name), fn);
}

}  // namespace jelly::bodies
