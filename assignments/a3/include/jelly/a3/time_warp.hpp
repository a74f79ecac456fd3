// Student tasks A3.T3 and A3.T4: time warping a motion, uniformly or with one keyframe (kinematics
// contract §5). Handout: assignments/a3/handout/T3-time-map.md, T4-warped-posture.md.
#pragma once

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a3 {

/// A3.T3 — The input time s of output frame i (0 ≤ i < M) of a warp of N = warp.input_frames
/// postures to M = warp.output_frames (contract §5), in double precision and evaluated exactly as
/// written:
/// - uniform (no keyframe): s = (double) i·(N − 1)/(M − 1);
/// - keyframe K_in → K_out: s = (double) i·K_in/K_out for i ≤ K_out, else
///   s = K_in + (double) (i − K_out)·(N − 1 − K_in)/(M − 1 − K_out).
/// So s(0) = 0, s(K_out) = K_in and s(M − 1) = N − 1 exactly.
double time_map(int i, const skeleton::TimeWarp& warp);

/// A3.T4 — The warped posture at input time `s` (0 ≤ s ≤ N − 1), read from `input` alone
/// (contract §5): l = ⌊s⌋, r = min(l + 1, N − 1), t = s − l;
/// - the root translation (1 − t)·T_l + t·T_r;
/// - each bone with channels (the root included):
///   θ = quaternion_to_euler(slerp(euler_to_quaternion(θ_l), euler_to_quaternion(θ_r), t)),
///   with the framework's functions of jelly/skeleton/rotation.hpp (slerp takes the short path);
/// - bones without channels keep zero angles.
/// `out` gets one angle triple per bone.
void warped_posture(const skeleton::Skeleton& skeleton, const skeleton::Motion& input, double s,
                    skeleton::Posture& out);

}  // namespace jelly::a3
