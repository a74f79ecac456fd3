// Your code: tasks A3.T3 (the time map) and A3.T4 (the warped posture).
// Read assignments/a3/handout/T3-time-map.md and T4-warped-posture.md first.
// Check yourself with: tools/selfcheck
#include "jelly/a3/time_warp.hpp"

#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

double time_map(int i, const skeleton::TimeWarp& warp) {
  // TODO(A3.T3): the input time s of output frame i, uniform or with the keyframe
  // warp.keyframe_in -> warp.keyframe_out, in double precision (mind integer division).
  // assignments/a3/handout/T3-time-map.md.
  (void)i, (void)warp;
  return 0.0;
}

void warped_posture(const skeleton::Skeleton& skeleton, const skeleton::Motion& input, double s,
                    skeleton::Posture& out) {
  out = skeleton::Posture::zero(skeleton.bones.size());
  // TODO(A3.T4): interpolate input frames l = ⌊s⌋ and r = min(l + 1, N − 1) at t = s − l: lerp
  // the root translation, slerp every bone's rotation (skeleton::euler_to_quaternion, slerp,
  // quaternion_to_euler). assignments/a3/handout/T4-warped-posture.md.
  (void)input, (void)s;
}

}  // namespace jelly::a3
