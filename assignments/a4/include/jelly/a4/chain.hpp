// Student task A4.T1: the chain of bones an inverse-kinematics solve moves (kinematics contract
// §6.1). Handout: assignments/a4/handout/T1-chain.md.
#pragma once

#include <vector>

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a4 {

/// A4.T1 — the chain from `end_bone` towards `start_bone`, bone indices, end bone first: if
/// `start_bone` is `end_bone` or one of its ancestors, the bones from the end bone up to the start
/// bone, both included; otherwise the bones from the end bone up to the root, root included.
std::vector<int> ik_chain(const skeleton::Skeleton& skeleton, int start_bone, int end_bone);

}  // namespace jelly::a4
