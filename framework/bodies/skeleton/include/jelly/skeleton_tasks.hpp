// The TaskTable slots of the skeleton (the kinematics contract §3–§6): the skeleton kind's part of
// an assignment's task table (TaskTable::kinds). A3's student tasks fill the first five, A4's
// forward kinematics (its T0, the student's A3 code) and the six inverse-kinematics slots; the
// skeleton kind's `jelly run` calls them frame by frame (docs/skeleton-scenes.md).
// Angles are degrees, lengths the skeleton's units times the scene's scale, y is up.
#pragma once

#include <vector>

#include "jelly/skeleton/ik.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/task_table.hpp"

namespace jelly {

namespace skeleton {

/// Every bone's global frame for one posture (contract §4), indexed like Skeleton::bones.
struct BoneFrames {
  std::vector<Mat3> rotation;  ///< R_i, the bone's global rotation
  std::vector<Vec3> start;     ///< s_i: the root's is T, another bone's its parent's end
  std::vector<Vec3> end;       ///< e_i = s_i + L_i·R_i·d_i (the root's: T)
};

/// A time warp of a motion of `input_frames` postures (N) to `output_frames` (M), contract §5:
/// uniform, or with one keyframe (input frame `keyframe_in` lands on output frame
/// `keyframe_out`). Frame indices count from 0 (§11.12).
struct TimeWarp {
  int input_frames = 0;   ///< N ≥ 2
  int output_frames = 0;  ///< M ≥ 2
  int keyframe_in = -1;   ///< K_in, 0 < K_in < N − 1; −1: no keyframe (a uniform retiming)
  int keyframe_out = -1;  ///< K_out, 0 < K_out < M − 1; −1 with keyframe_in
  bool has_keyframe() const { return keyframe_in >= 0; }
};

/// A blend of motion A into motion B (contract §5, the bonus): A's frames before `a`, `window`
/// blended frames of A[a + k] and B'[b + k], then B'[b + window …].
struct Blend {
  int a = 0;       ///< the first blended frame of A; a + window ≤ |A|
  int b = 0;       ///< the first blended frame of B; b + window ≤ |B|
  int window = 0;  ///< W ≥ 2
};

}  // namespace skeleton

/// The skeleton's slots; null where the assignment has no such task.
struct SkeletonTasks {
  /// T1, a bone's local rotation from its AMC angles (contract §3): E(rx, ry, rz) =
  /// R_z(rz)·R_y(ry)·R_x(rx), right-handed, angles in degrees.
  skeleton::Mat3 (*local_rotation)(const Vec3& degrees) = nullptr;

  /// T2, forward kinematics (§4) of `posture` over `skeleton`'s tree: resizes `out` to the bone
  /// count and fills every bone's R_i, s_i, e_i. Root: R_0 = E(θ_0), s_0 = e_0 = T. Bone i with
  /// parent p: R_i = R_p·C_i·E(θ_i), s_i = e_p, e_i = s_i + L_i·R_i·d_i (C_i, d_i, L_i are the
  /// Bone's derived data). Bones without channels have θ = 0.
  void (*forward_kinematics)(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                             skeleton::BoneFrames& out) = nullptr;

  /// T3, the time map (§5): the input time s of output frame `i` (0 ≤ i < M), in double precision
  /// and evaluated exactly as written. Uniform: s = (double) i·(N − 1)/(M − 1). Keyframe:
  /// s = (double) i·K_in/K_out for i ≤ K_out, else
  /// s = K_in + (double) (i − K_out)·(N − 1 − K_in)/(M − 1 − K_out). So s(0) = 0, s(M − 1) = N − 1.
  double (*time_map)(int i, const skeleton::TimeWarp& warp) = nullptr;

  /// T4, the warped posture at input time `s` (0 ≤ s ≤ N − 1, from time_map), read from `input`
  /// alone (never from output already written): l = ⌊s⌋, r = min(l + 1, N − 1), t = s − l; the
  /// root translation (1 − t)·T_l + t·T_r; each bone with channels
  /// θ = quaternion_to_euler(slerp(euler_to_quaternion(θ_l), euler_to_quaternion(θ_r), t))
  /// (jelly/skeleton/rotation.hpp: short path, nlerp where |q_l·q_r| > 1 − 1e-12). Bones without
  /// channels keep zero angles. Fills `out` (one angle triple per bone).
  void (*warped_posture)(const skeleton::Skeleton& skeleton, const skeleton::Motion& input,
                         double s, skeleton::Posture& out) = nullptr;

  /// The bonus, the motion blend (§5, decision §11.13): `out` becomes A[0 … a−1], then W frames
  /// k = 0 … W−1 mixing A[a + k] and B'[b + k] with w_k = (1 − cos(π(k + 1)/W))/2 (translation
  /// (1 − w)·T_A + w·T_B', rotations slerp(q_A, q_B, w) as in T4), then B'[b + W …]; B' is B with
  /// its root translation moved by Δ = T_A[a] − T_B[b], Δ.y = 0. `out.fps` is A's.
  void (*blend_motions)(const skeleton::Skeleton& skeleton, const skeleton::Motion& a_motion,
                        const skeleton::Motion& b_motion, const skeleton::Blend& blend,
                        skeleton::Motion& out) = nullptr;

  // Inverse kinematics (A4, contract §6). Chains are bone indices, end bone first.

  /// A4.T1, the chain (§6.1): if `start_bone` is `end_bone` or one of its ancestors, the bones
  /// from the end bone up to the start bone, both included; otherwise from the end bone up to the
  /// root, root included. End bone first.
  std::vector<int> (*ik_chain)(const skeleton::Skeleton& skeleton, int start_bone,
                               int end_bone) = nullptr;

  /// A4.T2, the Jacobian (§6.2) at `frames` (forward kinematics of the posture): J resized to
  /// 3 × 3m for the m bones of `chain`; p = frames.end[chain[0]]; for chain entry b (bone i) and
  /// axis k, J[:, 3b + k] = R_i.col(k) × (p − s_i) if bone i has channel r_k (the root has all
  /// three), else 0.
  void (*ik_jacobian)(const skeleton::Skeleton& skeleton, const skeleton::BoneFrames& frames,
                      const std::vector<int>& chain, skeleton::Matrix3X& J) = nullptr;

  /// A4.T3, the minimum-norm least-squares solve (§6.3): x (resized to J.cols()) = V Σ⁺ Uᵀ e,
  /// singular values σ ≤ max(3, n)·2⁻⁵²·σ_max counted as zero; J = 0 gives x = 0; finite for
  /// every finite J and e.
  void (*least_squares)(const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) = nullptr;

  /// A4.T4, the iteration (§6.4) through `ops` (end_effector, jacobian, solve; clamp after each
  /// update when settings.limits): at most settings.max_iterations updates
  /// θ_i[k] += (step·x[3b + k])·180/π of the chain's channels, stopping when |target − p| < ε.
  /// Changes only the chain's channels; returns the updates made and |target − p| after the last
  /// forward kinematics (`stable` is left to ik_solve).
  skeleton::IkResult (*ik_iterate)(const skeleton::Skeleton& skeleton,
                                   const std::vector<int>& chain, const Vec3& target,
                                   const skeleton::IkSettings& settings, const skeleton::IkOps& ops,
                                   skeleton::Posture& posture) = nullptr;

  /// A4.T5 (the bonus), §6.4's clamp: each channel of each bone of `chain` that has limits into
  /// [lo, hi] (skeleton.bones[i].limits, in the `dof` line's order); bones without limits and the
  /// root untouched.
  void (*clamp_to_limits)(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                          skeleton::Posture& posture) = nullptr;

  /// A4.T5 (the bonus), §6.5: r = ops.iterate(posture); r.stable = r.error < ε; if not stable and
  /// settings.restore, the posture becomes the input posture again, bit for bit; r.error stays the
  /// one measured before the restore (§11.14).
  skeleton::IkResult (*ik_solve)(const skeleton::IkSettings& settings, const skeleton::IkOps& ops,
                                 skeleton::Posture& posture) = nullptr;
};

/// The table's skeleton slots, made (all null) on first use.
inline SkeletonTasks& skeleton_tasks(TaskTable& t) { return t.kinds.get<SkeletonTasks>(); }
/// The table's skeleton slots, all null when the table has none.
inline const SkeletonTasks& skeleton_tasks(const TaskTable& t) {
  return t.kinds.get_or_default<SkeletonTasks>();
}

}  // namespace jelly
