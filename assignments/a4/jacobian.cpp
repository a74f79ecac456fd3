// Your code: task A4.T2, the course's Jacobian of the end effector.
// Read assignments/a4/handout/T2-jacobian.md first.
#include "jelly/a4/jacobian.hpp"

namespace jelly::a4 {

void ik_jacobian(const skeleton::Skeleton& skeleton, const skeleton::BoneFrames& frames,
                 const std::vector<int>& chain, skeleton::Matrix3X& J) {
  J = skeleton::Matrix3X::Zero(3, 3 * static_cast<Eigen::Index>(chain.size()));
  // TODO(A4.T2): p = frames.end[chain[0]]; for chain entry b (bone i) and axis k, the column
  // 3b + k is R_i.col(k) × (p − s_i) when bone i has channel r_k (Bone::has_rotation; the root
  // has all three), else it stays zero. assignments/a4/handout/T2-jacobian.md.
  (void)skeleton;
  (void)frames;
}

}  // namespace jelly::a4
