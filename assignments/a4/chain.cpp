// Your code: task A4.T1, the chain of bones an inverse-kinematics solve moves.
// Read assignments/a4/handout/T1-chain.md first.
#include "jelly/a4/chain.hpp"

namespace jelly::a4 {

std::vector<int> ik_chain(const skeleton::Skeleton& skeleton, int start_bone, int end_bone) {
  // TODO(A4.T1): walk from end_bone up the parents (skeleton.bones[i].parent, −1 above the root):
  // stop at start_bone when it is on the way (end_bone itself included), else at the root. End
  // bone first, both ends included. assignments/a4/handout/T1-chain.md.
  (void)skeleton;
  (void)start_bone;
  (void)end_bone;
  return {};
}

}  // namespace jelly::a4
