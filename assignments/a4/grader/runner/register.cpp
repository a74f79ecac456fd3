// A4's runner hooks (grader/runner/harness.hpp): its case generators and its task table.
#include "cases.hpp"
#include "jelly/a4/task_table.hpp"

namespace jelly::grade {

void register_assignment_cases(Registry& r) {
  register_kinematics_cases(r);
  register_chain_cases(r);
  register_jacobian_cases(r);
  register_least_squares_cases(r);
  register_iterate_cases(r);
  register_limits_cases(r);
}

TaskTable assignment_task_table() { return a4::task_table(); }

}  // namespace jelly::grade
