// Your code: task A4.T0, forward kinematics: a bone's local rotation and every bone's frame. Bring
// your A3 code (A3.T1 local_rotation, A3.T2 forward_kinematics): the iteration and the solve use
// it. Read assignments/a4/handout/T0-forward-kinematics.md first.
#include "jelly/a4/kinematics.hpp"

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::a4 {

skeleton::Mat3 local_rotation(const Vec3& degrees) {
  // TODO(A4.T0): your A3.T1: return E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx), the angles in
  // degrees. Convert to radians (π/180) and take sines and cosines from portable::sin_cos.
  // assignments/a4/handout/T0-forward-kinematics.md.
  (void)degrees;
  return skeleton::Mat3::Identity();
}

void forward_kinematics(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                        skeleton::BoneFrames& out) {
  const std::size_t n = skeleton.bones.size();
  out.rotation.assign(n, skeleton::Mat3::Identity());
  out.start.assign(n, Vec3::Zero());
  out.end.assign(n, Vec3::Zero());
  // TODO(A4.T0): your A3.T2: fill every bone's global rotation R_i, start s_i and end e_i: the
  // root from the posture's angles and translation, every other bone from its parent's R_p and
  // e_p (visit a parent before its children). E(θ) is the framework's skeleton::euler_matrix.
  // assignments/a4/handout/T0-forward-kinematics.md.
  (void)posture;
}

}  // namespace jelly::a4
