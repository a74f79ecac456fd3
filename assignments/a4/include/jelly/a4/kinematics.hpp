// Student task A4.T0: forward kinematics, your A3 code (kinematics contract §3, §4, §6.6): a bone's
// local rotation and every bone's global frame. No points of its own: the iteration and the solve
// use it, and their tests say so first when it fails. Angles are degrees, y is up, lengths the
// skeleton's units times the scene's scale. Handout:
// assignments/a4/handout/T0-forward-kinematics.md.
#pragma once

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a4 {

/// A4.T0 — E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx) for the angles (rx, ry, rz) = `degrees`
/// (contract §3), right-handed, a degrees = a·π/180 radians. Sines and cosines from
/// jelly/portable_math.hpp (portable::sin_cos), never <cmath>. Your A3.T1.
skeleton::Mat3 local_rotation(const Vec3& degrees);

/// A4.T0 — forward kinematics (contract §4) of `posture` over `skeleton`: resizes `out.rotation`,
/// `out.start` and `out.end` to the bone count and fills, for every bone i, the root's
/// R_0 = E(θ_0), s_0 = e_0 = T, and for bone i with parent p R_i = R_p·C_i·E(θ_i), s_i = e_p,
/// e_i = s_i + L_i·R_i·d_i, with E the framework's skeleton::euler_matrix. Your A3.T2.
void forward_kinematics(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                        skeleton::BoneFrames& out);

}  // namespace jelly::a4
