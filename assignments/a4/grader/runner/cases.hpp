// A4's case generators (grader/runner/harness.hpp): its own (T1–T5) and the skeleton module's
// forward kinematics (kinematics_cases.hpp, its T0), which A4 registers with its case files. The
// skeletons and postures they play on are the skeleton module's case inputs
// (skeleton_case_inputs.hpp): the course's files or random ones made from the case's parameters.
// The iteration and the solve run through scripted IkOps (ik_script.cpp): answers recorded from the
// reference when the data was generated, or a toy the case describes; never the reference itself,
// which is not linked with a submission.
#pragma once

#include <string>
#include <vector>

#include "harness.hpp"
#include "jelly/skeleton/ik.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "kinematics_cases.hpp"
#include "skeleton_case_inputs.hpp"

namespace jelly::grade {

void register_chain_cases(Registry& r);          // A4.T1
void register_jacobian_cases(Registry& r);       // A4.T2
void register_least_squares_cases(Registry& r);  // A4.T3
void register_iterate_cases(Registry& r);        // A4.T4
void register_limits_cases(Registry& r);         // A4.T5

/// A4's clamp reads the course skeleton's joint limits: its cases' inputs record them.
inline constexpr LimitsInInput kLimitsInInput = LimitsInInput::Recorded;

// ----- chains (chains.cpp) -----

/// The chain's angles (3×n, column b = (rx, ry, rz) of the chain's bone b).
Vec3Array chain_angles(const skeleton::Posture& p, const std::vector<int>& chain);
/// "rfingers ← rwrist ← … ← lowerback" for notes.
std::string chain_text(const skeleton::Skeleton& s, const std::vector<int>& chain);

// ----- scripted collaborators (ik_script.cpp) -----

/// What the iteration's collaborators answer, call after call: recorded from the reference's own
/// solve when the data was generated, or a toy the case describes. Each op answers its k-th call
/// with its k-th answer (the last one past the end) and records what it was given.
struct IkScript {
  std::vector<Vec3> effector;            ///< p of each end_effector call
  std::vector<skeleton::Matrix3X> J;     ///< J of each jacobian call
  std::vector<skeleton::VectorX> x;      ///< x of each solve call
  std::vector<skeleton::Posture> clamp;  ///< the posture each clamp call leaves
};
Json script_json(const IkScript& s);
IkScript json_script(const Json& j, std::size_t bones);

/// What the scripted ops were given.
struct IkLog {
  std::vector<skeleton::Posture> effector;  ///< the posture of each end_effector call
  std::vector<Vec3> e;                      ///< the e of each solve call
  std::vector<skeleton::Posture> clamp;     ///< the posture each clamp call got
  int jacobian_calls = 0;
};

/// Ops that answer from `script` and write into `log` (both outlive the ops).
skeleton::IkOps scripted_ops(const IkScript& script, IkLog& log);

/// The reference's own ops (the tasks of `t`, the reference at generate-reference time) for one
/// chain and target, recording every answer into `script`.
skeleton::IkOps recording_ops(const TaskTable& t, const skeleton::Skeleton& s,
                              const std::vector<int>& chain, IkScript& script);

/// Settings from params.settings = { step, epsilon, max_iterations, limits, restore } (the
/// course's defaults for those it leaves out).
skeleton::IkSettings settings_of(const Params& params);

}  // namespace jelly::grade
