// The motion-capture skeleton of assignments A3 and A4 (kinematics contract §1–§2): bones read
// from an ASF file with their derived data, the postures of an AMC file and a motion.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/types.hpp"

namespace jelly::skeleton {

using Mat3 = Eigen::Matrix3d;

/// One degree of freedom of a bone as the ASF names it (`order` of the root, `dof` of a bone).
enum class Channel { tx, ty, tz, rx, ry, rz };

/// The lowest and highest value of one channel [degrees], lo ≤ hi.
struct Limit {
  double lo = 0.0;
  double hi = 0.0;
};

/// One bone as the file gives it, and the data derived from it (contract §1).
struct Bone {
  std::string name;               ///< "root" for bone 0; case-sensitive
  int parent = -1;                ///< index of the parent bone; −1 for the root
  std::vector<int> children;      ///< in the order the hierarchy lists them
  std::vector<Channel> channels;  ///< in the order of the `dof` line (the root: `order`)
  std::vector<Limit> limits;      ///< one per channel, or empty when the file gives none
  Vec3 direction = Vec3::Zero();  ///< as written (not normalised), the file's frame; root: 0
  double length = 0.0;            ///< in the file's units; root: 0
  Vec3 axis = Vec3::Zero();       ///< `axis` angles [degrees], order XYZ; root: 0
  // Derived with the scene's scale:
  Mat3 C = Mat3::Identity();  ///< C_i = A_pᵀ·A_i with A = E(axis); the root: I
  Vec3 d = Vec3::Zero();      ///< d_i = A_iᵀ·direction_i, the direction in the bone's own frame
  double L = 0.0;             ///< L_i = length_i · scale; the root: 0

  /// Whether the bone has rotation channel rx (k = 0), ry (1) or rz (2).
  bool has_rotation(int k) const;
};

/// Bones in file order: bone 0 is the root, bone i is the ASF's `id i`.
struct Skeleton {
  std::vector<Bone> bones;
  double scale = 0.2;  ///< the scene's scale, applied to lengths and root translations

  /// The index of the bone named `name` (case-sensitive), or nullopt.
  std::optional<int> find(std::string_view name) const;
  /// The number of channels of every bone together (the root's six included).
  int channel_count() const;
};

/// Fills every bone's C, d and L from its axis, direction and length (contract §1), with the
/// parents already set. Called by the ASF reader; exposed for skeletons built in code (tests).
void derive_bone_data(Skeleton& skeleton);

/// A pose of the skeleton (contract §2).
struct Posture {
  std::vector<Vec3> angles;              ///< per bone (rx, ry, rz) [degrees]; 0 for absent channels
  Vec3 root_translation = Vec3::Zero();  ///< T = scale · (tx, ty, tz)

  /// The rest pose of a skeleton of `bone_count` bones: all angles and T zero.
  static Posture zero(std::size_t bone_count);
};

/// Postures at a fixed rate.
struct Motion {
  std::vector<Posture> frames;  ///< frame index = position from 0 (not the AMC frame number)
  double fps = 120.0;           ///< frames per second (the scene's `fps`; CMU's capture rate)
  int first_frame_number = 1;   ///< the AMC's number of frame 0
};

}  // namespace jelly::skeleton
