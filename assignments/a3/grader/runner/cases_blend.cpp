// A3.B1 (bonus) cases: blend_motions of the course's walk into its run and of random motions.
// Besides every output frame (root translation, rotations compared as rotations), the case
// reports the number of frames your blend returned (a + |B| − b).
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

void run_blend(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  skeleton::Blend k;
  k.a = static_cast<int>(params.integer("a"));
  k.b = static_cast<int>(params.integer("b"));
  k.window = static_cast<int>(params.integer("window"));
  if (k.window < 2 || k.a < 0 || k.b < 0 ||
      k.a + k.window > static_cast<int>(in.motion.frames.size()) ||
      k.b + k.window > static_cast<int>(in.motion_b.frames.size()))
    throw std::runtime_error("params: a, b, window outside the motions");
  skeleton::Motion blended;
  skeleton_tasks(t).blend_motions(in.skeleton, in.motion, in.motion_b, k, blended);
  const std::string what = "the blend of " + in.words + " (A " +
                           std::to_string(in.motion.frames.size()) + " frames, B " +
                           std::to_string(in.motion_b.frames.size()) +
                           " frames, a = " + std::to_string(k.a) + ", b = " + std::to_string(k.b) +
                           ", W = " + std::to_string(k.window) + ")";
  out.value("frames", static_cast<double>(blended.frames.size()),
            "the number of frames of " + what + ": a + |B| − b");
  out.value("fps", blended.fps, "the blend's frames per second (A's)");
  // Every frame's root; the rotations of the window, of the frames either side of it and of
  // the first and last frame (A's prefix and B''s suffix keep their angles as read).
  const std::size_t first = static_cast<std::size_t>(std::max(k.a - 1, 0));
  const std::size_t after = static_cast<std::size_t>(k.a + k.window);
  for (std::size_t f = 0; f < blended.frames.size(); ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "f%03zu", f);
    const std::string at = "output frame " + std::to_string(f) + " of the blend";
    out.vec(std::string(name) + "_root", blended.frames[f].root_translation,
            "the root translation at " + at + (f == 0 ? " (" + what + ")" : std::string()));
    if (f == 0 || f + 1 == blended.frames.size() || (f >= first && f <= after))
      emit_rotations(out, name, posture_rotations(blended.frames[f].angles),
                     "E(θ) of your angles at " + at);
  }
}

}  // namespace

// blend: params.course (amc, amc_b, prepared) or params.random (frames, frames_b) and params.a,
// b, window; outputs frames, fps, then fNNN_root and fNNN_rotation for every output frame.
void register_blend_cases(Registry& r) {
  r.add({"blend",
         "blend_motions of two course motions (params.course) or two random ones "
         "(params.random), with params.a, b and window",
         [](const TaskTable&, const Params& p, Json& input) {
           prepare_skeleton_input(p, input, kLimitsInInput);
         },
         [](const TaskTable& t, const Params& p, const Json& input, Outputs& o) {
           run_blend(t, p, input, o);
         }});
}

}  // namespace jelly::grade
