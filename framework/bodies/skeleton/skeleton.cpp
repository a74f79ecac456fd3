// The skeleton's bones and their derived data (kinematics contract §1).
#include "jelly/skeleton/skeleton.hpp"

#include <algorithm>

#include "jelly/skeleton/rotation.hpp"

namespace jelly::skeleton {

bool Bone::has_rotation(int k) const {
  const Channel wanted = k == 0 ? Channel::rx : k == 1 ? Channel::ry : Channel::rz;
  return std::find(channels.begin(), channels.end(), wanted) != channels.end();
}

std::optional<int> Skeleton::find(std::string_view name) const {
  for (std::size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

int Skeleton::channel_count() const {
  int n = 0;
  for (const Bone& b : bones) n += static_cast<int>(b.channels.size());
  return n;
}

// A_i = E(axis_i); C_i = A_pᵀ·A_i (root: I); d_i = A_iᵀ·direction_i; L_i = length_i·scale.
void derive_bone_data(Skeleton& skeleton) {
  std::vector<Mat3> axis_frames;
  axis_frames.reserve(skeleton.bones.size());
  for (const Bone& b : skeleton.bones) axis_frames.push_back(euler_matrix(b.axis));
  for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
    Bone& b = skeleton.bones[i];
    const Mat3& a = axis_frames[i];
    b.C = b.parent < 0 ? Mat3::Identity() : Mat3(axis_frames[b.parent].transpose() * a);
    b.d = a.transpose() * b.direction;
    b.L = b.parent < 0 ? 0.0 : b.length * skeleton.scale;
  }
}

Posture Posture::zero(std::size_t bone_count) {
  Posture p;
  p.angles.assign(bone_count, Vec3::Zero());
  return p;
}

}  // namespace jelly::skeleton
