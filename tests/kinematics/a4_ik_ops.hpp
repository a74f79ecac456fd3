// The collaborators of A4's iteration and solve (jelly/skeleton/ik.hpp) for A4's own reference
// (solutions/a4/), for one chain, target and settings: the framework's make_ik_ops
// (jelly/skeleton_ik.hpp) on A4's task table, as `jelly run` and the viewer build them from a
// student's slots (forward kinematics A4.T0, the Jacobian T2, the least-squares solve T3, the
// clamp T5 and the iteration T4), each answer checked.
#pragma once

#include <vector>

#include "jelly/a4/task_table.hpp"
#include "jelly/skeleton_ik.hpp"

namespace jelly::testing {

/// IkOps for `chain` (end bone first) of `skeleton`, which must outlive them.
inline skeleton::IkOps reference_ik_ops(const skeleton::Skeleton& skeleton,
                                        const std::vector<int>& chain, const Vec3& target,
                                        const skeleton::IkSettings& settings) {
  static const TaskTable table = a4::task_table();
  IkSolveRequest request;
  request.end_bone = chain.front();
  request.target = target;
  request.settings = settings;
  request.where = "the reference";
  return make_ik_ops(skeleton, skeleton_tasks(table), chain, request);
}

}  // namespace jelly::testing
