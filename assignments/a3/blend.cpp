// Your code: the bonus task A3.B1, the motion blend.
// Read assignments/a3/handout/B1-blend.md first. Check yourself with: tools/selfcheck
#include "jelly/a3/blend.hpp"

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"

namespace jelly::a3 {

void blend_motions(const skeleton::Skeleton& skeleton, const skeleton::Motion& a_motion,
                   const skeleton::Motion& b_motion, const skeleton::Blend& blend,
                   skeleton::Motion& out) {
  out.frames.clear();
  out.fps = a_motion.fps;
  out.first_frame_number = a_motion.first_frame_number;
  // TODO(A3.B1, bonus): A's frames before blend.a, then blend.window frames mixing A[a + k] and
  // B'[b + k] with w_k = (1 − cos(π(k + 1)/W))/2, then B'[b + W …] (B' is B moved so that its
  // root starts where A's is at frame a, height kept). assignments/a3/handout/B1-blend.md.
  (void)skeleton, (void)b_motion, (void)blend;
}

}  // namespace jelly::a3
