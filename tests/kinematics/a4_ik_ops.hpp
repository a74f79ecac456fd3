// The collaborators of A4's iteration and solve (jelly/skeleton/ik.hpp) filled from A4's own
// reference (solutions/a4/): forward kinematics (A4.T0), the Jacobian (T2), the least-squares
// solve (T3), the clamp (T5) and the iteration (T4), for one chain, target and settings. What
// `jelly run` and the viewer will do with a student's slots.
#pragma once

#include <vector>

#include "jelly/a4/ik.hpp"
#include "jelly/a4/jacobian.hpp"
#include "jelly/a4/kinematics.hpp"
#include "jelly/a4/least_squares.hpp"

namespace jelly::testing {

/// IkOps for `chain` (end bone first) of `skeleton`, which must outlive them.
inline skeleton::IkOps reference_ik_ops(const skeleton::Skeleton& skeleton,
                                        const std::vector<int>& chain, const Vec3& target,
                                        const skeleton::IkSettings& settings) {
  skeleton::IkOps ops;
  const skeleton::Skeleton* s = &skeleton;
  const int end = chain.front();
  ops.end_effector = [s, end](const skeleton::Posture& p) {
    skeleton::BoneFrames f;
    a4::forward_kinematics(*s, p, f);
    return Vec3(f.end[end]);
  };
  ops.jacobian = [s, chain](const skeleton::Posture& p, skeleton::Matrix3X& J) {
    skeleton::BoneFrames f;
    a4::forward_kinematics(*s, p, f);
    a4::ik_jacobian(*s, f, chain, J);
  };
  ops.solve = [](const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
    a4::least_squares(J, e, x);
  };
  ops.clamp = [s, chain](skeleton::Posture& p) { a4::clamp_to_limits(*s, chain, p); };
  ops.iterate = [s, chain, target, settings, inner = ops](skeleton::Posture& p) {
    return a4::ik_iterate(*s, chain, target, settings, inner, p);
  };
  return ops;
}

}  // namespace jelly::testing
