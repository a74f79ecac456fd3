// Slot-level cases of the skeleton's forward kinematics (the local_rotation and
// forward_kinematics slots of SkeletonTasks, jelly/skeleton_tasks.hpp): the generators, keyed by
// slot, not by assignment. Every assignment whose tasks fill those slots registers them from its
// own assignments/<id>/grader/runner/ and keeps its own case files (grader/cases/*.toml), with its
// own task IDs; what differs between assignments (whether a course skeleton's limits go into the
// input) is a parameter of the registration. docs/new-assignment.md, "Shared tasks, shared case
// code".
#pragma once

#include "harness.hpp"
#include "skeleton_case_inputs.hpp"

namespace jelly::grade {

/// Generators "local_rotation" (params.angles = [{ degrees }] and/or params.random = { seed, count,
/// range }; outputs eNN_x, eNN_y, eNN_z: E's columns) and "forward_kinematics" (params.course,
/// prepared with `limits`, or params.random; outputs pNN_end, pNN_start, pNN_axis_* for every
/// posture). Rotations are compared as matrices, never as Euler triples.
void register_kinematics_cases(Registry& r, LimitsInInput limits);

}  // namespace jelly::grade
