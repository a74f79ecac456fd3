// Reference: task A4.T2, the course's Jacobian (kinematics contract §6.2).
// Read assignments/a4/handout/T2-jacobian.md first.
#include "jelly/a4/jacobian.hpp"

#include <Eigen/Geometry>

namespace jelly::a4 {

namespace {

// Whether bone i's angle k (0 = rx, 1 = ry, 2 = rz) is a channel: the root has all three.
bool rotates_about(const skeleton::Bone& bone, int k) {
  return bone.parent < 0 || bone.has_rotation(k);
}

}  // namespace

void ik_jacobian(const skeleton::Skeleton& skeleton, const skeleton::BoneFrames& frames,
                 const std::vector<int>& chain, skeleton::Matrix3X& J) {
  J = skeleton::Matrix3X::Zero(3, 3 * static_cast<Eigen::Index>(chain.size()));
  if (chain.empty()) return;
  const Vec3 p = frames.end[chain[0]];
  for (std::size_t b = 0; b < chain.size(); ++b) {
    const int i = chain[b];
    const Vec3 arm = p - frames.start[i];  // from the joint (the bone's start) to the effector
    for (int k = 0; k < 3; ++k) {
      if (!rotates_about(skeleton.bones[i], k)) continue;
      const Vec3 axis = frames.rotation[i].col(k);
      J.col(3 * static_cast<Eigen::Index>(b) + k) = axis.cross(arm);
    }
  }
}

}  // namespace jelly::a4
