// A3.T3 and A3.T4 cases: time_map on hand-made and random warps (uniform and with a keyframe,
// K_in above and below K_out, two-frame motions), and warped_posture at input times the case
// computes itself (never with your time_map, so a slip there costs points in T3 only), on the
// course's motions and on random skeletons and motions (antipodal and nearly equal rotations,
// gimbal lock). Your warped posture is compared as rotations: E(θ) of your angles, never the
// triples.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

skeleton::TimeWarp warp_of(const Params& w) {
  skeleton::TimeWarp k;
  k.input_frames = static_cast<int>(w.integer("n"));
  k.output_frames = static_cast<int>(w.integer("m"));
  k.keyframe_in = static_cast<int>(w.integer("k_in", -1));
  k.keyframe_out = static_cast<int>(w.integer("k_out", -1));
  return k;
}

std::string warp_text(const skeleton::TimeWarp& w) {
  std::string s = "a warp of N = " + std::to_string(w.input_frames) +
                  " to M = " + std::to_string(w.output_frames) + " frames";
  if (w.has_keyframe())
    s += ", keyframe K_in = " + std::to_string(w.keyframe_in) +
         " -> K_out = " + std::to_string(w.keyframe_out);
  else
    s += ", uniform";
  return s;
}

// params.warps = [{ n, m, k_in?, k_out? }] and/or params.random = { seed, count, max }.
std::vector<skeleton::TimeWarp> warp_inputs(const Params& params) {
  std::vector<skeleton::TimeWarp> out;
  if (params.has("warps"))
    for (const Params& w : params.list("warps")) out.push_back(warp_of(w));
  if (params.has("random")) {
    const Params r = params.table("random");
    Sequence s(static_cast<std::uint64_t>(r.integer("seed")));
    const double max = static_cast<double>(r.integer("max"));
    for (long i = 0; i < r.integer("count"); ++i) {
      skeleton::TimeWarp w;
      w.input_frames = 3 + static_cast<int>((s.next() + 1.0) * 0.5 * (max - 3.0));
      w.output_frames = 3 + static_cast<int>((s.next() + 1.0) * 0.5 * (max - 3.0));
      if (i % 2 == 1) {
        w.keyframe_in = 1 + static_cast<int>((s.next() + 1.0) * 0.5 * (w.input_frames - 3));
        w.keyframe_out = 1 + static_cast<int>((s.next() + 1.0) * 0.5 * (w.output_frames - 3));
      }
      out.push_back(w);
    }
  }
  return out;
}

void run_time_map(const TaskTable& t, const Params& params, Outputs& out) {
  const std::vector<skeleton::TimeWarp> in = warp_inputs(params);
  for (std::size_t k = 0; k < in.size(); ++k) {
    const skeleton::TimeWarp& w = in[k];
    std::vector<double> s;
    for (int i = 0; i < w.output_frames; ++i) s.push_back(skeleton_tasks(t).time_map(i, w));
    std::vector<double> ends{s.front(), s.back()};
    if (w.has_keyframe()) ends.push_back(s[static_cast<std::size_t>(w.keyframe_out)]);
    char name[32];
    std::snprintf(name, sizeof name, "w%02zu", k);
    out.values(
        std::string(name) + "_s", s,
        "s(i) for every output frame i = 0 … M − 1 of " + warp_text(w) + " (entry i is s(i))");
    out.values(std::string(name) + "_exact", ends,
               "s(0) = 0 and s(M − 1) = N − 1" +
                   std::string(w.has_keyframe() ? ", then s(K_out) = K_in" : "") +
                   ", which must hold exactly, for " + warp_text(w));
  }
}

// The contract's time map (§5), the case's own: T4 never depends on your T3.
double contract_time(int i, const skeleton::TimeWarp& w) {
  const int n = w.input_frames, m = w.output_frames;
  if (!w.has_keyframe()) return static_cast<double>(i) * (n - 1) / (m - 1);
  if (i <= w.keyframe_out) return static_cast<double>(i) * w.keyframe_in / w.keyframe_out;
  return w.keyframe_in + static_cast<double>(i - w.keyframe_out) * (n - 1 - w.keyframe_in) /
                             (m - 1 - w.keyframe_out);
}

// params.times = [s, …], or params.warp = { m, k_in?, k_out? } over the whole input (n = its
// frames): every output frame's s.
std::vector<double> warp_times(const Params& params, int frames, std::string& how) {
  if (params.has("times")) {
    how = "at input times s given by the case";
    return params.numbers("times");
  }
  const Params w = params.table("warp");
  skeleton::TimeWarp k;
  k.input_frames = frames;
  k.output_frames = static_cast<int>(w.integer("m"));
  k.keyframe_in = static_cast<int>(w.integer("k_in", -1));
  k.keyframe_out = static_cast<int>(w.integer("k_out", -1));
  how = "for every output frame of " + warp_text(k) + " (s from the contract's time map)";
  std::vector<double> s;
  for (int i = 0; i < k.output_frames; ++i) s.push_back(contract_time(i, k));
  return s;
}

void run_warped_posture(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  SkeletonInput in = skeleton_input(params, input);
  std::string how;
  const std::vector<double> times =
      warp_times(params, static_cast<int>(in.motion.frames.size()), how);
  // Past the last frame lies a frame with a NaN root and no angles, whose memory stays there: a
  // read past the end (r not clamped at s = N − 1) gets NaN or stops on the missing angles every
  // time, never a harmless copy times t = 0.
  skeleton::Posture poison;
  poison.root_translation = Vec3::Constant(std::nan(""));
  in.motion.frames.reserve(in.motion.frames.size() + 1);
  in.motion.frames.push_back(poison);
  in.motion.frames.pop_back();
  // One posture for every output frame, as `jelly run` does: what it held before is no input.
  skeleton::Posture posture;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double s = times[k];
    if (!(s >= 0.0 && s <= static_cast<double>(in.motion.frames.size()) - 1.0))
      throw std::runtime_error("params: input time " + std::to_string(s) + " outside the motion");
    skeleton_tasks(t).warped_posture(in.skeleton, in.motion, s, posture);
    char name[32], at[128];
    std::snprintf(name, sizeof name, "f%03zu", k);
    std::snprintf(at, sizeof at, "output frame %zu (s = %.17g) ", k, s);
    const std::string what = std::string(at) + how + " of " + in.words;
    out.vec(std::string(name) + "_root", posture.root_translation,
            "the root translation (1 − t)·T_l + t·T_r at " + what);
    emit_rotations(out, name, posture_rotations(posture.angles),
                   "E(θ) of your angles at " + what +
                       (k == 0 ? " (bones " + bone_list(in.skeleton) + ")" : std::string()));
  }
}

}  // namespace

// time_map: params.warps and/or params.random; outputs wNN_s and wNN_exact.
// warped_posture: params.course (prepared) or params.random, and params.times or params.warp;
// outputs fNNN_root and fNNN_rotation for every time.
void register_warp_cases(Registry& r) {
  r.add({"time_map", "time_map on hand-made (params.warps) or random (params.random) warps",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_time_map(t, p, o);
         }});
  r.add({"warped_posture",
         "warped_posture of the course's motion (params.course) or a random one (params.random) "
         "at given times (params.times) or every frame of a warp (params.warp)",
         [](const TaskTable&, const Params& p, Json& input) {
           prepare_skeleton_input(p, input, kLimitsInInput);
         },
         [](const TaskTable& t, const Params& p, const Json& input, Outputs& o) {
           run_warped_posture(t, p, input, o);
         }});
}

}  // namespace jelly::grade
