// Reference: the bonus task A3.B1, the motion blend, exactly the kinematics contract §5 and
// decision §11.13.
// Read assignments/a3/handout/B1-blend.md first. Check yourself with: tools/selfcheck
#include "jelly/a3/blend.hpp"

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

namespace {

constexpr double kHalfTurn = 3.14159265358979323846;  // π radians

// (1 − w)·A + w·B: the translation lerped, each bone with channels slerped.
skeleton::Posture mix(const skeleton::Skeleton& skeleton, const skeleton::Posture& a,
                      const skeleton::Posture& b, double w) {
  skeleton::Posture out = skeleton::Posture::zero(skeleton.bones.size());
  out.root_translation = (1.0 - w) * a.root_translation + w * b.root_translation;
  for (std::size_t bone = 0; bone < skeleton.bones.size(); ++bone) {
    if (skeleton.bones[bone].channels.empty()) continue;
    const skeleton::Quaternion q_a = skeleton::euler_to_quaternion(a.angles[bone]);
    const skeleton::Quaternion q_b = skeleton::euler_to_quaternion(b.angles[bone]);
    out.angles[bone] = skeleton::quaternion_to_euler(skeleton::slerp(q_a, q_b, w));
  }
  return out;
}

}  // namespace

void blend_motions(const skeleton::Skeleton& skeleton, const skeleton::Motion& a_motion,
                   const skeleton::Motion& b_motion, const skeleton::Blend& blend,
                   skeleton::Motion& out) {
  out.frames.clear();
  out.fps = a_motion.fps;
  out.first_frame_number = a_motion.first_frame_number;
  Vec3 delta =
      a_motion.frames[blend.a].root_translation - b_motion.frames[blend.b].root_translation;
  delta.y() = 0.0;
  for (int i = 0; i < blend.a; ++i) out.frames.push_back(a_motion.frames[i]);
  for (std::size_t j = blend.b; j < b_motion.frames.size(); ++j) {
    skeleton::Posture moved = b_motion.frames[j];
    moved.root_translation += delta;
    const int k = static_cast<int>(j) - blend.b;
    if (k < blend.window) {
      const double w = (1.0 - portable::cos(kHalfTurn * (k + 1) / blend.window)) / 2.0;
      moved = mix(skeleton, a_motion.frames[blend.a + k], moved, w);
    }
    out.frames.push_back(moved);
  }
}

}  // namespace jelly::a3
