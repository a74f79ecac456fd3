// Your code: tasks A3.T1 (a bone's local rotation) and A3.T2 (forward kinematics).
// Read assignments/a3/handout/T1-local-rotation.md and T2-forward-kinematics.md first.
// Check yourself with: tools/selfcheck
#include "jelly/a3/kinematics.hpp"

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

skeleton::Mat3 local_rotation(const Vec3& degrees) {
  // TODO(A3.T1): return E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx), the angles in degrees.
  // Convert to radians (π/180) and take sines and cosines from portable::sin_cos.
  // assignments/a3/handout/T1-local-rotation.md.
  (void)degrees;
  return skeleton::Mat3::Identity();
}

void forward_kinematics(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                        skeleton::BoneFrames& out) {
  const std::size_t n = skeleton.bones.size();
  out.rotation.assign(n, skeleton::Mat3::Identity());
  out.start.assign(n, Vec3::Zero());
  out.end.assign(n, Vec3::Zero());
  // TODO(A3.T2): fill every bone's global rotation R_i, start s_i and end e_i: the root from
  // the posture's angles and translation, every other bone from its parent's R_p and e_p (visit
  // a parent before its children). E(θ) is the framework's skeleton::euler_matrix.
  // assignments/a3/handout/T2-forward-kinematics.md.
  (void)posture;
}

}  // namespace jelly::a3
