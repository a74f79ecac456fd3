// Which student tasks look implemented: each task function called once on a tiny input whose
// correct answer is never the stub's neutral value. The viewer's hint and `jelly` use this to say
// "HW.T4 spring force is not implemented yet" instead of letting a student guess why nothing moves.
// The probes belong to the framework's TaskTable slots; an assignment's manifest says which of its
// tasks fills which slot (`probe = "spring_force"`) and gives the task's id and short name.
//
// A probe is a smoke test, not a grade: "implemented" means "does not return the stub's neutral
// value here", not "correct" (the test suite and the grader decide that).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/manifest.hpp"
#include "jelly/task_table.hpp"

namespace jelly {

/// The probe's verdict on one task.
struct TaskStatus {
  std::string id;    ///< the task's id in its manifest, e.g. "HW.T1"
  std::string name;  ///< its short name, e.g. "structural springs"
  bool implemented = false;
  std::string evidence;  ///< what the probe saw, e.g. "no springs for a 3×3×3 lattice"
  std::string slot;      ///< the TaskTable slot probed, e.g. "spring_force"
};

/// Probes every task of `manifest` that names a probe, in the manifest's order. A null function
/// pointer counts as missing. Never throws for a task that returns garbage (NaN, wrong counts):
/// that counts as implemented. Throws std::invalid_argument for a probe name that is no slot.
std::vector<TaskStatus> probe_tasks(const AssignmentManifest& manifest, const TaskTable& tasks);

/// Probes one slot of `tasks`, reporting it as task `id` named `name`.
TaskStatus probe_slot(std::string_view slot, std::string id, std::string name,
                      const TaskTable& tasks);

/// The slots the framework can probe (what a manifest's `probe` may name).
std::vector<std::string_view> probe_slots();

/// The ids of the tasks that look missing, e.g. {"HW.T4", "HW.T5"}.
std::vector<std::string> missing_task_ids(const std::vector<TaskStatus>& statuses);

}  // namespace jelly
