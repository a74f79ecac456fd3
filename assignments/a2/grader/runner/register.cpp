// A2's runner hooks (grader/runner/harness.hpp): its case generators and its task table.
#include "cases.hpp"
#include "jelly/a2/task_table.hpp"
#include "mass_spring_cases.hpp"

namespace jelly::grade {

void register_assignment_cases(Registry& r) {
  register_grid_spring_cases(r);
  register_spring_force_cases(r);  // the mass_spring module's (A2.T4–T5)
  register_collision_cases(r);
  register_friction_cases(r);
  register_integrator_cases(r);
  register_scene_cases(r);
}

TaskTable assignment_task_table() { return a2::task_table(); }

}  // namespace jelly::grade
