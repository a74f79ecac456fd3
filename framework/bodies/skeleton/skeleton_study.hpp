// Internal to the skeleton kind: the accuracy study of a skeleton warp scene (the kinematics
// contract §10, accuracy against cost; docs/skeleton-studies.md). Every output frame of the scene's
// warp is computed twice from the same time map: by the task table's warped posture (slerp, §5)
// and by linear interpolation of the Euler angles (the shortcut §9 lists as a mistake). Per bone
// it measures the angle between the two rotations, and the time per frame of each.
#pragma once

#include <string>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "skeleton_play.hpp"

namespace jelly::bodies {

/// The angle between one bone's slerp rotation and its Euler-lerp rotation, over the output frames.
struct BoneInterpolationError {
  int bone = 0;
  std::string name;
  int channels = 0;
  double max_degrees = 0.0;   ///< largest angle over the frames [°]
  double mean_degrees = 0.0;  ///< mean over the frames [°]
  int worst_frame = 0;        ///< the output frame of the largest angle
  double worst_s = 0.0;       ///< its input time s
};

/// One warp's comparison of slerp with the Euler lerp.
struct InterpolationStudy {
  int input_frames = 0, output_frames = 0;
  std::vector<BoneInterpolationError> bones;  ///< the bones with channels, in bone order
  std::vector<double> frame_max_degrees;      ///< per output frame, the largest angle over bones
  std::vector<double> frame_s;                ///< per output frame, its input time s
  double max_degrees = 0.0;                   ///< over bones and frames
  double mean_degrees = 0.0;                  ///< over bones with channels and frames
  int worst_bone = 0, worst_frame = 0;
  // Processor time per output frame, the median of the repeats [µs]:
  double slerp_us_per_frame = 0.0;  ///< the tasks' warped_posture
  double lerp_us_per_frame = 0.0;   ///< the Euler lerp
  double fk_us_per_frame = 0.0;     ///< the tasks' forward_kinematics of a warped posture
};

/// The angle [°] between the rotations of two Euler triples (degrees): 2·atan2(|v|, |w|) of
/// q_a⁻¹·q_b, exact for small angles and for either sign.
double rotation_angle_degrees(const Vec3& a, const Vec3& b);

/// The posture at input time s by linear interpolation of the root translation and of every
/// bone's Euler angles: l = ⌊s⌋, r = min(l + 1, N − 1), t = s − l, θ = (1 − t)·θ_l + t·θ_r.
void euler_lerp_posture(const skeleton::Motion& input, double s, skeleton::Posture& out);

/// Compares slerp (tasks.warped_posture) with the Euler lerp on every output frame of `warp`
/// (times from tasks.time_map), and times each over `repeats` runs. Throws std::runtime_error
/// when a slot it needs is null or returns a time outside 0 ≤ s ≤ N − 1.
InterpolationStudy study_interpolation(const SkeletonInputs& in, const skeleton::TimeWarp& warp,
                                       const SkeletonTasks& tasks, int repeats);

/// The study of a skeleton warp scene (bench/skeleton_study.cpp): the scene's warp, through
/// `tasks`, written to PREFIX-bones.csv and PREFIX-frames.csv; returns the report. Throws
/// std::runtime_error for a bad scene or file, a scene that is not a warp or a slot not filled,
/// std::system_error when an output file cannot be written.
std::string study_skeleton_scene(const SceneSpec& scene, const TaskTable& tasks,
                                 const std::string& prefix, int repeats);

}  // namespace jelly::bodies
