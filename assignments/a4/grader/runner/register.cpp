// A4's runner hooks (grader/runner/harness.hpp): its case generators and its task table. T0 (your
// A3 code, no points of its own) is the skeleton module's forward-kinematics cases
// (kinematics_cases.hpp), run with A4's case files (grader/cases/kinematics.toml) as A3 grades
// them. The report lists T0 first: when it fails, what uses your FK (the viewer, `jelly run`)
// fails too, while T1–T5 are graded on recorded frames and answers and cost nothing for it.
#include "cases.hpp"
#include "jelly/a4/task_table.hpp"

namespace jelly::grade {

void register_assignment_cases(Registry& r) {
  register_kinematics_cases(r, kLimitsInInput);  // A4.T0
  register_chain_cases(r);
  register_jacobian_cases(r);
  register_least_squares_cases(r);
  register_iterate_cases(r);
  register_limits_cases(r);
}

TaskTable assignment_task_table() { return a4::task_table(); }

}  // namespace jelly::grade
