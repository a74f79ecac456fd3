// Inverse kinematics through an assignment's SkeletonTasks slots (kinematics contract §6): the
// collaborators of the iteration and the solve (IkOps, jelly/skeleton/ik.hpp) built from the slots,
// and one chain's solve, ik_chain then ik_solve. What each slot returns is checked before it is
// used, so a wrong answer is an error naming the task, never a crash (`jelly run`, the viewer).
#pragma once

#include <string>
#include <vector>

#include "jelly/skeleton/ik.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly {

/// One solve's chain and target, and where it is (for messages: "output frame 0, chain 1").
struct IkSolveRequest {
  int start_bone = 0;
  int end_bone = 0;
  Vec3 target = Vec3::Zero();
  skeleton::IkSettings settings;
  std::string where;
  /// When set, |target − p| of each end-effector evaluation the solve asks for is appended (the
  /// viewer's plot of the error against the update); the solve's answers do not change.
  std::vector<double>* errors = nullptr;
};

/// The slot of `tasks` a solve needs that is null ("ik_jacobian"), or "" when all are filled:
/// forward_kinematics, ik_chain, ik_jacobian, least_squares, clamp_to_limits, ik_iterate,
/// ik_solve.
std::string missing_ik_slot(const SkeletonTasks& tasks);

/// IkOps for `chain` (end bone first) of `skeleton` and `request`'s target and settings, from the
/// slots of `tasks` (forward_kinematics, ik_jacobian, least_squares, clamp_to_limits,
/// ik_iterate), which must all be filled. `skeleton` and `tasks` must outlive them. Each op checks
/// what its slot returns (sizes, finite numbers) and throws std::runtime_error
/// "task <slot>, <where>: ...".
skeleton::IkOps make_ik_ops(const skeleton::Skeleton& skeleton, const SkeletonTasks& tasks,
                            const std::vector<int>& chain, const IkSolveRequest& request);

/// The chain from tasks.ik_chain, checked: not empty, bones of the skeleton, end bone first.
std::vector<int> ik_chain_of(const skeleton::Skeleton& skeleton, const SkeletonTasks& tasks,
                             const IkSolveRequest& request);

/// One solve (contract §6): the chain from ik_chain, then ik_solve through make_ik_ops, on
/// `posture`. Checks that the solve changed only the chain's channels (contract §10) and left no
/// NaN; throws std::runtime_error naming the task otherwise.
skeleton::IkResult solve_ik(const skeleton::Skeleton& skeleton, const SkeletonTasks& tasks,
                            const IkSolveRequest& request, skeleton::Posture& posture);

}  // namespace jelly
