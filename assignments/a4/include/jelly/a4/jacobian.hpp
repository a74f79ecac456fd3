// Student task A4.T2: the course's Jacobian of the end effector with respect to the chain's
// rotation channels (kinematics contract §6.2). Handout: assignments/a4/handout/T2-jacobian.md.
#pragma once

#include <vector>

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a4 {

/// A4.T2 — J (resized to 3 × 3m for the m bones of `chain`) at `frames`, the forward kinematics
/// of the posture: p = frames.end[chain[0]]; for chain entry b (bone i) and axis k ∈ {x, y, z},
/// J[:, 3b + k] = R_i.col(k) × (p − s_i) if bone i has channel r_k (the root has all three),
/// else 0. R_i = frames.rotation[i], s_i = frames.start[i].
void ik_jacobian(const skeleton::Skeleton& skeleton, const skeleton::BoneFrames& frames,
                 const std::vector<int>& chain, skeleton::Matrix3X& J);

}  // namespace jelly::a4
