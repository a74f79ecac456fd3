// Which student tasks look implemented: each task function called once on a tiny input whose
// correct answer is never the stub's neutral value. The viewer's hint and `jelly` use this to say
// "A1.T4 spring force is not implemented yet" instead of letting a student guess why nothing moves.
//
// A probe is a smoke test, not a grade: "implemented" means "does not return the stub's neutral
// value here", not "correct" (the test suite and the grader decide that).
#pragma once

#include <string>
#include <vector>

#include "jelly/task_table.hpp"

namespace jelly {

/// The probe's verdict on one task.
struct TaskStatus {
  std::string id;    ///< "A1.T1" … "A1.T13"
  std::string name;  ///< "structural springs", "RK4", ...
  bool implemented = false;
  std::string evidence;  ///< what the probe saw, e.g. "no springs for a 3×3×3 lattice"
};

/// Probes all 13 tasks A1.T1–A1.T13, in order. A null function pointer counts as missing.
/// Never throws for a task that returns garbage (NaN, wrong counts): that counts as implemented.
std::vector<TaskStatus> probe_tasks(const TaskTable& tasks);

/// The ids of the tasks that look missing, e.g. {"A1.T4", "A1.T5"}.
std::vector<std::string> missing_task_ids(const std::vector<TaskStatus>& statuses);

}  // namespace jelly
