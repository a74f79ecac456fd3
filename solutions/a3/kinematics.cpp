// Reference: tasks A3.T1 (a bone's local rotation) and A3.T2 (forward kinematics), exactly the
// kinematics contract §3 and §4.
// Read assignments/a3/handout/T1-local-rotation.md and T2-forward-kinematics.md first.
// Check yourself with: tools/selfcheck
#include "jelly/a3/kinematics.hpp"

#include <vector>

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// The right-handed rotation about axis k (0 = x, 1 = y, 2 = z) by `degrees`.
skeleton::Mat3 axis_rotation(double degrees, int k) {
  double s = 0.0, c = 0.0;
  portable::sin_cos(degrees * kRadiansPerDegree, s, c);
  skeleton::Mat3 r;
  if (k == 0) {
    r << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  } else if (k == 1) {
    r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  } else {
    r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  }
  return r;
}

// Bone i's frame from its parent's (contract §4).
void place_bone(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture, int i,
                skeleton::BoneFrames& out) {
  const skeleton::Bone& bone = skeleton.bones[i];
  const skeleton::Mat3 local = skeleton::euler_matrix(posture.angles[i]);
  if (bone.parent < 0) {
    out.rotation[i] = local;
    out.start[i] = posture.root_translation;
    out.end[i] = posture.root_translation;
    return;
  }
  const skeleton::Mat3 parent_and_axis = out.rotation[bone.parent] * bone.C;
  out.rotation[i] = parent_and_axis * local;
  out.start[i] = out.end[bone.parent];
  const Vec3 along = out.rotation[i] * bone.d;
  out.end[i] = out.start[i] + bone.L * along;
}

}  // namespace

skeleton::Mat3 local_rotation(const Vec3& degrees) {
  const skeleton::Mat3 zy = axis_rotation(degrees.z(), 2) * axis_rotation(degrees.y(), 1);
  return zy * axis_rotation(degrees.x(), 0);
}

void forward_kinematics(const skeleton::Skeleton& skeleton, const skeleton::Posture& posture,
                        skeleton::BoneFrames& out) {
  const std::size_t n = skeleton.bones.size();
  out.rotation.assign(n, skeleton::Mat3::Identity());
  out.start.assign(n, Vec3::Zero());
  out.end.assign(n, Vec3::Zero());
  if (n == 0) return;
  // Depth first from the root: a parent is placed before its children.
  std::vector<int> to_visit{0};
  while (!to_visit.empty()) {
    const int i = to_visit.back();
    to_visit.pop_back();
    place_bone(skeleton, posture, i, out);
    for (int child : skeleton.bones[i].children) to_visit.push_back(child);
  }
}

}  // namespace jelly::a3
