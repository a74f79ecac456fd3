// Reference: task A4.T1, the chain (kinematics contract §6.1).
// Read assignments/a4/handout/T1-chain.md first.
#include "jelly/a4/chain.hpp"

#include <algorithm>

namespace jelly::a4 {

std::vector<int> ik_chain(const skeleton::Skeleton& skeleton, int start_bone, int end_bone) {
  // The path from the end bone up to the root, end bone first.
  std::vector<int> path;
  for (int i = end_bone; i >= 0; i = skeleton.bones[i].parent) path.push_back(i);
  // Cut it after the start bone when the start bone is on it.
  const auto start = std::find(path.begin(), path.end(), start_bone);
  if (start != path.end()) path.erase(start + 1, path.end());
  return path;
}

}  // namespace jelly::a4
