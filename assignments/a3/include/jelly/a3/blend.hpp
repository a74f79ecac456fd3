// Student task A3.B1 (bonus): the course's 2022 motion blend (kinematics contract §5, decision
// §11.13). Handout: assignments/a3/handout/B1-blend.md.
#pragma once

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a3 {

/// A3.B1 — Blends motion A into motion B (W = blend.window ≥ 2, a + W ≤ |A|, b + W ≤ |B|):
/// `out.frames` becomes A[0 … a−1], then W blended frames, then B'[b + W …], where B' is B with
/// its root translation moved by Δ = T_A[a] − T_B[b] with Δ.y = 0. Blended frame k (k = 0 … W−1)
/// mixes A[a + k] and B'[b + k] with w_k = (1 − cos(π(k + 1)/W))/2 (so w_{W−1} = 1): translation
/// (1 − w)·T_A + w·T_B', each bone with channels
/// quaternion_to_euler(slerp(euler_to_quaternion(θ_A), euler_to_quaternion(θ_B), w)), bones
/// without channels zero. The prefix of A and the suffix of B' keep their angles as read.
/// out.fps is A's, out.first_frame_number A's.
void blend_motions(const skeleton::Skeleton& skeleton, const skeleton::Motion& a_motion,
                   const skeleton::Motion& b_motion, const skeleton::Blend& blend,
                   skeleton::Motion& out);

}  // namespace jelly::a3
