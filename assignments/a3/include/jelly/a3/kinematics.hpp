// Student tasks A3.T1 and A3.T2: a bone's local rotation and forward kinematics over the
// skeleton's tree (kinematics contract §3, §4). Angles are degrees, y is up, lengths the
// skeleton's units times the scene's scale. Handout: assignments/a3/handout/T1-local-rotation.md,
// T2-forward-kinematics.md.
#pragma once

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a3 {

/// A3.T1 — E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx) for the angles (rx, ry, rz) = `degrees`
/// (contract §3): R_x, R_y, R_z are right-handed rotations about the axes by a degrees, that is
/// a·π/180 radians. Sines and cosines from jelly/portable_math.hpp (portable::sin_cos), never
/// <cmath>, so every platform gives the same bits.
skeleton::Mat3 local_rotation(const Vec3& degrees);

/// A3.T2 — Forward kinematics (contract §4) of `posture` over `skeleton`: resizes `out.rotation`,
/// `out.start` and `out.end` to the bone count and fills, for every bone i:
/// - the root (bone 0): R_0 = E(θ_0), s_0 = e_0 = T (the posture's root translation);
/// - bone i with parent p: R_i = R_p·C_i·E(θ_i), s_i = e_p, e_i = s_i + L_i·R_i·d_i,
/// where θ_i = posture.angles[i] (zero for channels the bone lacks), E is the framework's
/// skeleton::euler_matrix (jelly/skeleton/rotation.hpp, the same E as your T1: use the framework's,
/// so that a slip in T1 costs points in T1 only), and C_i, d_i, L_i are the bone's derived data
/// (skeleton.bones[i].C, .d, .L). Any order that visits a parent before its
/// children gives the same numbers (bones[i].children lists them; the file order does not
/// promise it).
void forward_kinematics(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                        skeleton::BoneFrames& out);

}  // namespace jelly::a3
