// Internal to the skeleton kind: the study of inverse kinematics' accuracy against its cost (the
// kinematics contract §10; docs/ik-studies.md). It runs §6.4's iteration on one chain and target
// with its own loop, whose parts are the task table's slots (forward kinematics, the Jacobian, the
// least-squares solve, the clamp) or the study's own variants of them: damped least squares, the
// Jacobian transpose and the exact Jacobian of the Euler angles. It records the error after every
// update and the processor time to reach it, over step sizes, epsilons, solvers and hard cases.
#pragma once

#include <string>
#include <vector>

#include "jelly/skeleton/ik.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly::bodies {

/// How a variant turns J and e into the update x.
enum class IkStudySolver {
  MinimumNorm,  ///< the tasks' least_squares (the course's, §6.3)
  Damped,       ///< damped least squares: x = Jᵀ (J Jᵀ + λ² I)⁻¹ e
  Transpose,    ///< the Jacobian transpose: x = α Jᵀ e, α = (e · J Jᵀ e) / |J Jᵀ e|²
};

/// One variant of the iteration.
struct IkStudyVariant {
  IkStudySolver solver = IkStudySolver::MinimumNorm;
  double lambda = 0.0;          ///< λ of the damped solve [scene units]
  bool exact_jacobian = false;  ///< the derivative of p by the Euler angles, not §6.2's columns
  /// A short name: "minimum-norm", "dls-0.1", "transpose", with "+exact" for the exact Jacobian.
  std::string name() const;
};

/// One solve's inputs: the start posture, the chain (end bone first) and the target.
struct IkStudyProblem {
  skeleton::Posture posture;
  std::vector<int> chain;
  Vec3 target = Vec3::Zero();
};

/// One solve of the study.
struct IkStudyRun {
  std::string
      group;  ///< "step", "epsilon", "solver", "unreachable", "straight", "straight-off", "limits"
  std::string name;  ///< unique within a study
  IkStudyVariant variant;
  skeleton::IkSettings settings;
  int updates = 0;
  double initial_error = 0.0;
  double final_error = 0.0;  ///< |x* − p| after the last update (before any restore)
  bool stable = false;       ///< final_error < ε
  bool finite = true;        ///< every angle and error finite throughout
  bool restored = false;     ///< unstable, and the tasks' ik_solve gave the input posture back
  bool checked = false;      ///< the course's variant, solved again by the tasks' ik_solve
  bool tasks_agree = false;  ///< ... with the same updates, error (bit for bit) and `stable`
  double max_change_degrees = 0.0;  ///< the largest |Δθ| of the final posture from the input [°]
  std::vector<double> error;        ///< |x* − p| after 0 … updates updates
  std::vector<double> cpu_us;       ///< processor time to reach each, the median of the repeats
};

/// Runs the iteration of one variant, `repeats` times for its times. Throws std::runtime_error
/// when a slot it needs is null.
IkStudyRun run_ik_variant(const skeleton::Skeleton& skeleton, const IkStudyProblem& problem,
                          const IkStudyVariant& variant, const skeleton::IkSettings& settings,
                          const SkeletonTasks& tasks, int repeats);

/// The exact Jacobian of the end effector by the chain's Euler angles (radians) at `frames` and
/// `posture`: 3 × 3m, the rx columns as §6.2's, ry's and rz's about the axes before the later
/// rotations (R_i·R_x(rx)ᵀ·e_y and R_i·R_x(rx)ᵀ·R_y(ry)ᵀ·e_z); 0 where the bone has no channel.
void exact_euler_jacobian(const skeleton::Skeleton& skeleton, const skeleton::BoneFrames& frames,
                          const skeleton::Posture& posture, const std::vector<int>& chain,
                          skeleton::Matrix3X& J);

/// The study's inputs: the skeleton and the course problem (hw3-ik by default), with the straight
/// arm's chain and posture for the singular case.
struct IkStudyInputs {
  skeleton::Skeleton skeleton;
  IkStudyProblem problem;       ///< the course's solve (IK.amc frame 0, lowerback → rfingers)
  IkStudyProblem straight_arm;  ///< every angle zero, rhumerus → rfingers (a straight arm)
  std::vector<double> steps{0.01, 0.03, 0.1, 0.3, 1.0};
  std::vector<double> epsilons{1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<double> lambdas{0.01, 0.1, 0.5};
};

/// The course's files: `asf` at `scale`, frame `frame` of `amc`, the chain `start_bone` →
/// `end_bone` (tasks.ik_chain) and `target`; the straight arm from the same skeleton. Throws
/// std::runtime_error for a file that cannot be read, a bone not found or a slot not filled.
IkStudyInputs read_ik_study_inputs(const std::string& asf, const std::string& amc, int frame,
                                   double scale, const std::string& start_bone,
                                   const std::string& end_bone, const Vec3& target,
                                   const SkeletonTasks& tasks);

/// Every run of the study: the steps (minimum norm, ε = 1e-3), the epsilons (step 0.1), the
/// solvers at step 0.1 and 1, and the hard cases (an unreachable target, a straight arm with the
/// target on its line and just off it, hw3-ik with limits) for the same six variants.
std::vector<IkStudyRun> study_ik(const IkStudyInputs& in, const SkeletonTasks& tasks, int repeats);

/// Writes PREFIX-runs.csv (one row per run) and PREFIX-trace.csv (one row per run and update
/// count, from 0) and returns the report. Throws std::system_error when a file cannot be written.
std::string write_ik_study(const std::vector<IkStudyRun>& runs, const std::string& prefix);

}  // namespace jelly::bodies
