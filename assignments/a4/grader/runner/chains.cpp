// A4's chains in its outputs and notes: a chain's angles alone and its bones' names
// (cases.hpp). The skeletons and postures themselves are the skeleton module's case inputs
// (skeleton_case_inputs.hpp).
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

Vec3Array chain_angles(const skeleton::Posture& p, const std::vector<int>& chain) {
  Vec3Array a(3, static_cast<Eigen::Index>(chain.size()));
  for (std::size_t b = 0; b < chain.size(); ++b)
    a.col(static_cast<Eigen::Index>(b)) = p.angles[static_cast<std::size_t>(chain[b])];
  return a;
}

std::string chain_text(const skeleton::Skeleton& s, const std::vector<int>& chain) {
  std::string out;
  for (std::size_t b = 0; b < chain.size(); ++b)
    out += (b ? " ← " : "") + s.bones[static_cast<std::size_t>(chain[b])].name;
  return out;
}

}  // namespace jelly::grade
