// Reference: tasks A4.T4 (the iteration, kinematics contract §6.4) and A4.T5 (the bonus: limits,
// stable and restore, §6.5, decision §11.14).
// Read assignments/a4/handout/T4-iteration.md and T5-limits-stable.md first.
#include "jelly/a4/ik.hpp"

#include <algorithm>

namespace jelly::a4 {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;  // 180/π

// Whether bone i's angle k (0 = rx, 1 = ry, 2 = rz) is a channel: the root has all three.
bool rotates_about(const skeleton::Bone& bone, int k) {
  return bone.parent < 0 || bone.has_rotation(k);
}

// θ_i[k] += (step·x[3b + k])·180/π for chain entry b (bone i) and each channel k it has.
void add_update(const skeleton::Skeleton& skeleton, const std::vector<int>& chain, double step,
                const skeleton::VectorX& x, skeleton::Posture& posture) {
  for (std::size_t b = 0; b < chain.size(); ++b) {
    const int i = chain[b];
    for (int k = 0; k < 3; ++k) {
      if (!rotates_about(skeleton.bones[i], k)) continue;
      const double radians = step * x(3 * static_cast<Eigen::Index>(b) + k);
      posture.angles[i][k] += radians * kDegreesPerRadian;
    }
  }
}

// The angle index (0 = rx, 1 = ry, 2 = rz) of a rotation channel; −1 for a translation.
int angle_of(skeleton::Channel c) {
  switch (c) {
    case skeleton::Channel::rx: return 0;
    case skeleton::Channel::ry: return 1;
    case skeleton::Channel::rz: return 2;
    default: return -1;
  }
}

}  // namespace

skeleton::IkResult ik_iterate(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                              const Vec3& target, const skeleton::IkSettings& settings,
                              const skeleton::IkOps& ops, skeleton::Posture& posture) {
  skeleton::Matrix3X J;
  skeleton::VectorX x;
  for (int updates = 0;; ++updates) {
    const Vec3 e = target - ops.end_effector(posture);
    skeleton::IkResult result;
    result.updates = updates;
    result.error = e.norm();
    if (result.error < settings.epsilon || updates >= settings.max_iterations) return result;
    ops.jacobian(posture, J);
    ops.solve(J, e, x);
    add_update(skeleton, chain, settings.step, x, posture);
    if (settings.limits) ops.clamp(posture);
  }
}

void clamp_to_limits(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                     skeleton::Posture& posture) {
  for (int i : chain) {
    const skeleton::Bone& bone = skeleton.bones[i];
    if (bone.parent < 0) continue;  // the root is never clamped
    for (std::size_t c = 0; c < bone.limits.size() && c < bone.channels.size(); ++c) {
      const int k = angle_of(bone.channels[c]);
      if (k < 0) continue;
      posture.angles[i][k] = std::clamp(posture.angles[i][k], bone.limits[c].lo, bone.limits[c].hi);
    }
  }
}

skeleton::IkResult ik_solve(const skeleton::IkSettings& settings, const skeleton::IkOps& ops,
                            skeleton::Posture& posture) {
  const skeleton::Posture input = posture;
  skeleton::IkResult result = ops.iterate(posture);
  result.stable = result.error < settings.epsilon;
  if (!result.stable && settings.restore) posture = input;
  return result;
}

}  // namespace jelly::a4
