// The smoke tests of the skeleton's TaskTable slots (jelly/task_probe.hpp: "does not return the
// stub's neutral value"), on a two-bone skeleton made in code. Used by the skeleton kind only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/task_probe.hpp"

namespace jelly::bodies {

/// local_rotation, forward_kinematics, time_map, warped_posture, blend_motions, and the
/// inverse-kinematics ik_chain, ik_jacobian, least_squares, ik_iterate, ik_solve.
std::vector<std::string_view> skeleton_probe_slots();

/// Probes one of them, reporting it as task `id` named `name`.
TaskStatus probe_skeleton_slot(std::string_view slot, std::string id, std::string name,
                               const TaskTable& t);

}  // namespace jelly::bodies
