// Reference: tasks A3.T3 (the time map) and A3.T4 (the warped posture), exactly the kinematics
// contract §5.
// Read assignments/a3/handout/T3-time-map.md and T4-warped-posture.md first.
// Check yourself with: tools/selfcheck
#include "jelly/a3/time_warp.hpp"

#include <algorithm>
#include <cmath>

#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

double time_map(int i, const skeleton::TimeWarp& warp) {
  const int n = warp.input_frames;
  const int m = warp.output_frames;
  if (!warp.has_keyframe()) return static_cast<double>(i) * (n - 1) / (m - 1);
  const int k_in = warp.keyframe_in;
  const int k_out = warp.keyframe_out;
  if (i <= k_out) return static_cast<double>(i) * k_in / k_out;
  return k_in + static_cast<double>(i - k_out) * (n - 1 - k_in) / (m - 1 - k_out);
}

void warped_posture(const skeleton::Skeleton& skeleton, const skeleton::Motion& input, double s,
                    skeleton::Posture& out) {
  const int last = static_cast<int>(input.frames.size()) - 1;
  const int l = static_cast<int>(std::floor(s));
  const int r = std::min(l + 1, last);
  const double t = s - l;
  const skeleton::Posture& left = input.frames[l];
  const skeleton::Posture& right = input.frames[r];
  out = skeleton::Posture::zero(skeleton.bones.size());
  out.root_translation = (1.0 - t) * left.root_translation + t * right.root_translation;
  for (std::size_t b = 0; b < skeleton.bones.size(); ++b) {
    if (skeleton.bones[b].channels.empty()) continue;
    const skeleton::Quaternion q_l = skeleton::euler_to_quaternion(left.angles[b]);
    const skeleton::Quaternion q_r = skeleton::euler_to_quaternion(right.angles[b]);
    out.angles[b] = skeleton::quaternion_to_euler(skeleton::slerp(q_l, q_r, t));
  }
}

}  // namespace jelly::a3
