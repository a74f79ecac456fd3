// A3's runner hooks (grader/runner/harness.hpp): its case generators and its task table. T1 and
// T2 are the skeleton module's forward-kinematics cases (kinematics_cases.hpp), run with A3's case
// files (grader/cases/kinematics.toml).
#include "cases.hpp"
#include "jelly/a3/task_table.hpp"

namespace jelly::grade {

void register_assignment_cases(Registry& r) {
  register_kinematics_cases(r, kLimitsInInput);  // A3.T1, A3.T2
  register_warp_cases(r);
  register_blend_cases(r);
}

TaskTable assignment_task_table() { return a3::task_table(); }

}  // namespace jelly::grade
