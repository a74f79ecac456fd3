// Reference: a bone's local rotation and forward kinematics, exactly the kinematics contract §3
// and §4. Not shipped to students.
//
// Part of the task module kinematics (solutions/tasks/kinematics/), named by no assignment: the one
// reference of tasks that several assignments share (same signatures, same contract section). The
// build writes this file out once for each assignment whose manifest lists the module in
// `task_modules` and this file in `files` (cmake/JellyAssignments.cmake, _jelly_module_task_file):
// into build/assignments/<id>/reference/, with the assignment's namespace in place of the word
// below that names it. The copy includes the assignment's own header (a signature that drifted from
// it is a compile error there) and is exactly the file the assignment would hold itself: the
// assignment's reference library compiles it, and the grader grades and mutates it as the
// reference. Each assignment keeps its own stub, header and bindings.
#include "jelly/JELLY_TASKS_NAMESPACE/kinematics.hpp"

#include <vector>

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::JELLY_TASKS_NAMESPACE {

namespace {

constexpr double kPiOver180 = 3.14159265358979323846 / 180.0;  // radians per degree

// The right-handed rotation about axis k (0 = x, 1 = y, 2 = z) by `degrees`.
skeleton::Mat3 axis_rotation(double degrees, int k) {
  double sine = 0.0, cosine = 0.0;
  portable::sin_cos(degrees * kPiOver180, sine, cosine);
  // The plane the rotation turns: axes a → b (x → y about z, y → z about x, z → x about y).
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  skeleton::Mat3 turn = skeleton::Mat3::Identity();
  turn(a, a) = cosine;
  turn(a, b) = -sine;
  turn(b, a) = sine;
  turn(b, b) = cosine;
  return turn;
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
  if (skeleton.bones.empty()) return;
  // Depth first from the root: a parent is placed before its children.
  std::vector<int> to_visit{0};
  while (!to_visit.empty()) {
    const int i = to_visit.back();
    to_visit.pop_back();
    place_bone(skeleton, posture, i, out);
    for (int child : skeleton.bones[i].children) to_visit.push_back(child);
  }
}

}  // namespace jelly::JELLY_TASKS_NAMESPACE
