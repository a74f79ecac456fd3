// A3's case generators (grader/runner/harness.hpp): its own (the warp, the blend) and the skeleton
// module's forward kinematics (kinematics_cases.hpp), which A3 registers with its case files. The
// skeletons and motions they play on are the skeleton module's case inputs
// (skeleton_case_inputs.hpp): the course's files or random ones made from the case's parameters.
#pragma once

#include "harness.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "kinematics_cases.hpp"
#include "skeleton_case_inputs.hpp"

namespace jelly::grade {

/// A3's tasks use no joint limits: its cases' inputs record none (as its data always had).
inline constexpr LimitsInInput kLimitsInInput = LimitsInInput::Omitted;

void register_warp_cases(Registry& r);   // A3.T3, A3.T4
void register_blend_cases(Registry& r);  // A3.B1

}  // namespace jelly::grade
