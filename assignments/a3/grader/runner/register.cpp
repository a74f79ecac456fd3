// A3's runner hooks (grader/runner/harness.hpp): its case generators and its task table.
#include "cases.hpp"
#include "jelly/a3/task_table.hpp"

namespace jelly::grade {

void register_assignment_cases(Registry& r) {
  register_kinematics_cases(r);
  register_warp_cases(r);
  register_blend_cases(r);
}

TaskTable assignment_task_table() { return a3::task_table(); }

}  // namespace jelly::grade
